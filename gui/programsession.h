#pragma once
// ProgramSession: the loaded program — its text, its toolpath, the display scene, the planned
// speed profile and every error — and loading it in a worker thread so that even a
// multi-million-line file never stalls the window. Progress is polled every 50 ms from an
// atomic counter (no signal flood); the result arrives by a queued call.

#include "programtext.h"
#include "speedplot.h"
#include "toolpathscene.h"

#include "gcode/toolpath.h"
#include "machine/planner.h"
#include "machine/unitprogram.h"
#include "session/programplanner.h"
#include "session/workoffsets.h"

#include <QObject>
#include <QString>
#include <QTimer>

#include <array>
#include <atomic>
#include <functional>
#include <memory>

class QThread;

namespace frezka::gui {

using session::ProgramMessage;

struct LoadedProgram
{
    QString path;
    std::shared_ptr<const ProgramText> text;
    std::shared_ptr<const gcode::Toolpath> toolpath;
    std::shared_ptr<const ToolpathScene> scene;
    std::vector<ProgramMessage> errors;                      // non-empty: nothing runs
    std::vector<ProgramMessage> warnings;                    // runs, but the user should know
    std::shared_ptr<const machine::UnitProgram> unitProgram; // planned for the active profile
    machine::PlanStats planStats;
    std::vector<SpeedSample> speed; // planned speed along the path
    double estimatedS = -1;         // planner's exact duration, < 0 = unknown
    double lengthMm = 0;
    bool ok() const { return errors.empty() && toolpath != nullptr; }
    bool runnable() const { return ok() && unitProgram != nullptr; }
    // Toolpath entry of the last motion on a source line (for the cut colouring), or kNone.
    std::uint32_t entryOfLine(std::uint32_t line) const;
    std::vector<std::uint32_t> lineToEntry; // index = source line
    // Planned seconds from the start to the end of each source line (index = line), scaled to the
    // planner's estimate; empty when not planned. remainingS() reads it for the ETA.
    std::vector<float> lineEndS;
    double remainingS(std::uint32_t line) const;
};

using session::InterpretOutcome;
using session::InterpretRequest;

// The interpreter step, set by whoever links the G-code interpreter (defaultInterpreter()).
using InterpretFn = std::function<InterpretOutcome(const InterpretRequest &)>;
// Analysis after interpretation (planner: speed profile, duration, soft-limit check).
using AnalyseFn = std::function<void(LoadedProgram &, const std::atomic_bool *cancel)>;

class ProgramSession : public QObject
{
    Q_OBJECT

public:
    explicit ProgramSession(QObject *parent = nullptr);
    ~ProgramSession() override;

    void setInterpreter(InterpretFn fn) { m_interpret = std::move(fn); }
    void setAnalyser(AnalyseFn fn) { m_analyse = std::move(fn); }
    void setMaxSceneSegments(std::size_t n) { m_maxSegments = n; }
    void setSceneGlVertices(bool on) { m_glVertices = on; }
    void setWorkOffsets(const session::OffsetState &offsets) { m_offsets = offsets; }
    // Machine position the next interpretation starts from (mm X Y Z A).
    void setStartPosition(const std::array<double, 4> &mm) { m_startMm = mm; }
    const session::OffsetState &workOffsets() const { return m_offsets; }

    // Loads (replacing any load in progress). loaded() or loadFailed() follows.
    void load(const QString &path);
    // Re-interprets the current file (after a work-offset change).
    void reload();
    void cancel();
    bool isLoading() const { return m_thread != nullptr; }
    const LoadedProgram &program() const { return m_program; }
    bool hasProgram() const { return m_program.toolpath != nullptr && m_program.ok(); }

signals:
    void loadStarted(const QString &path);
    void loadProgress(double fraction, const QString &stage);
    void loaded();                       // program() holds the result (maybe with errors)
    void loadFailed(const QString &why); // file unreadable, cancelled

private:
    void finish(std::shared_ptr<LoadedProgram> result, QString failure);

    InterpretFn m_interpret;
    AnalyseFn m_analyse;
    std::size_t m_maxSegments = 1'500'000;
    bool m_glVertices = false;
    session::OffsetState m_offsets;
    std::array<double, 4> m_startMm{};
    LoadedProgram m_program;
    QThread *m_thread = nullptr;
    std::shared_ptr<std::atomic_bool> m_cancel;
    std::shared_ptr<std::atomic_int> m_progress; // permille
    std::shared_ptr<std::atomic_int> m_stage;    // 0 read, 1 index, 2 interpret, 3 scene, 4 plan
    QTimer m_poll;
    quint64 m_generation = 0;
};

} // namespace frezka::gui
