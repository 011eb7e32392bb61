#pragma once
// ProgramSession: the loaded program — its text, its toolpath, its plan, every error and
// warning — and loading it in a worker thread so that even a multi-million-line file never
// stalls a front end. One load reads the file, indexes its lines, checks it (interpretProgram:
// every error with line and column, from the work offsets and the machine's position), lets the
// front end derive its view of the toolpath (the GUI's 3-D scene, setViewBuilder), and plans it
// for the profile at the feed override (planProgram, with the planned speed and line times).
// reload() does it all again: after the offsets, the profile or the machine's position changed.
// Progress is polled every 100 ms from an atomic counter (no signal flood); the result arrives
// by a queued call. Qt Core only; the GUI renders program() and its view.

#include "session/loadstages.h"
#include "session/plannedspeed.h"
#include "session/probefollow.h"
#include "session/programplanner.h"
#include "session/programtext.h"
#include "session/runfromline.h"
#include "session/workoffsets.h"

#include "gcode/heightmap.h"
#include "gcode/toolpath.h"
#include "machine/machineconfig.h"
#include "machine/planner.h"
#include "machine/unitprogram.h"

#include <QObject>
#include <QPointer>
#include <QString>
#include <QTimer>

#include <array>
#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

class QThread;

namespace frezka::session {

// What a front end derives from the toolpath while the program loads (the GUI: its scene).
struct ProgramView
{
    virtual ~ProgramView() = default;
};

// Builds the view in the loading thread: progress(fraction 0..1); cancel aborts.
using ViewBuilder = std::function<std::shared_ptr<const ProgramView>(
    const gcode::Toolpath &, const std::function<void(double)> &progress,
    const std::atomic_bool *cancel)>;

struct LoadedProgram
{
    QString path;
    std::shared_ptr<const ProgramText> text;
    std::shared_ptr<const gcode::Toolpath> toolpath;
    std::shared_ptr<const ProgramView> view;                 // the front end's, or null
    std::vector<ProgramMessage> errors;                      // non-empty: nothing runs
    std::vector<ProgramMessage> warnings;                    // runs, but the user should know
    std::shared_ptr<const machine::UnitProgram> unitProgram; // planned for the active profile
    machine::PlanStats planStats;
    std::vector<SpeedSample> speed; // planned speed along the path (at most 4000 samples)
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
    // Run from a line (ProgramSession::setStartLine): the state taken there and the approach;
    // toolpath and unitProgram are then that job (the approach, then the program's rest).
    std::optional<FromLine> fromLine;
    // The tool table as the program's G10 L1/L10/L11 leave it: written back once it has run.
    std::optional<gcode::ToolTable> changedToolTable;
    // G54..G59.3 as the program's G10 L2/L20 leave them: the window's own once it has run.
    std::optional<OffsetTable> changedWorkOffsets;
    // A program that probes for itself (session/probefollow.h): its path after the probe entry
    // provisionalEntry (on provisionalLine) depends on where that probe stops (none: kNoEntry
    // and 0). The load then plans only the part up to and including that probe (unitProgram,
    // estimatedS, lineEndS are that part's), and followRequest is how the program was
    // interpreted, for the ProbeFollow that runs it; null for other programs. After a probe has
    // run (ProgramSession::showFollowed) toolpath is the program as interpreted with the results
    // so far, the plan that of the part that runs now, and probesFollowed counts them.
    std::size_t provisionalEntry = gcode::Result::kNoEntry;
    std::uint32_t provisionalLine = 0;
    std::shared_ptr<const InterpretRequest> followRequest;
    int probesFollowed = 0;
    bool provisional() const { return provisionalEntry != gcode::Result::kNoEntry; }
    // How long each stage of the load took and the memory it held (bench_gui_load prints it).
    std::vector<LoadStage> stages;
};

class ProgramSession : public QObject
{
    Q_OBJECT

public:
    explicit ProgramSession(QObject *parent = nullptr);
    ~ProgramSession() override;

    // Plans every load for this profile at this feed override (fraction); without a profile a
    // program is only checked.
    void setProfile(const machine::MachineConfig &config, double feedOverride = 1.0);
    void setViewBuilder(ViewBuilder build) { m_buildView = std::move(build); }
    void setWorkOffsets(const OffsetState &offsets) { m_offsets = offsets; }
    // Machine position the next interpretation starts from (mm X Y Z A).
    void setStartPosition(const std::array<double, 4> &mm) { m_startMm = mm; }
    const OffsetState &workOffsets() const { return m_offsets; }
    // Run from this line (session/runfromline.h) from the next load on; 0 = the whole program.
    // A line that cannot be a start is the load's error (with the line to choose instead).
    void setStartLine(std::uint32_t line) { m_startLine = line; }
    // The machine's tool table from the next load on (session/tooltablefile.h); its error, when
    // the file cannot be read, is every load's first error.
    void setToolTable(std::optional<gcode::ToolTable> table, const QString &error = {})
    {
        m_toolTable = std::move(table);
        m_toolTableError = error;
    }
    const std::optional<gcode::ToolTable> &toolTable() const { return m_toolTable; }
    // The folders o<name> call searches after the program's own (machine::subroutineFolders of
    // the profile), from the next load on.
    void setSubroutinePath(std::vector<std::string> folders)
    {
        m_subroutinePath = std::move(folders);
    }
    std::uint32_t startLine() const { return m_startLine; }
    // A height map (gcode/heightmap.h) from the next load on: the interpreted toolpath is bent
    // to it before the view and the plan (a cut outside it is the load's error at its line);
    // nullopt: none. The listing keeps the program's own lines.
    void setHeightMap(std::optional<gcode::HeightMap> map) { m_heightMap = std::move(map); }
    const std::optional<gcode::HeightMap> &heightMap() const { return m_heightMap; }
    // Each load's stages (LoadedProgram::stages) with the peak memory of each, which resets the
    // process's high-water mark at every stage (bench_gui_load; off by default).
    void setMeasurePeaks(bool on) { m_measurePeaks = on; }

    // Loads (replacing any load in progress). loaded() or loadFailed() follows.
    void load(const QString &path);
    // Loads the current file again: checked from the offsets and position, planned for the
    // profile as they are now.
    void reload();
    // Stops the load in progress, if any, at once: the program loaded before stays, and
    // loadCancelled() follows. The load's thread is not waited for (reading, interpreting and
    // the view stop within a few thousand lines; a plan of millions of moves ends its pass in
    // the background, its result dropped), so the window never stalls.
    void cancel();
    bool isLoading() const { return m_thread != nullptr; }
    // A probe of a program that probes for itself has run and the run goes on with `next`
    // (RunWorkflow::probeFollowed): program() becomes the program as interpreted with the probe
    // results so far (its view built again here), planned as the part that runs now; the
    // program as loaded is kept for restoreAsLoaded(). probeFollowShown() follows.
    void showFollowed(const ProbeFollow::Next &next);
    // The program as it was loaded, before any probe was followed (a new run starts there);
    // false when nothing was followed.
    bool restoreAsLoaded();
    const LoadedProgram &program() const { return m_program; }
    bool hasProgram() const { return m_program.toolpath != nullptr && m_program.ok(); }

signals:
    void loadStarted(const QString &path);
    void loadProgress(double fraction, const QString &stage);
    void loaded();                           // program() holds the result (maybe with errors)
    void loadFailed(const QString &why);     // file unreadable
    void loadCancelled(const QString &path); // cancel() stopped the load of this file
    void probeFollowShown();                 // showFollowed() or restoreAsLoaded() changed it

private:
    void finish(std::shared_ptr<LoadedProgram> result, QString failure);
    // Stops the load in progress without waiting for its thread (kept in m_ending); false when
    // none ran.
    bool stopLoad();

    ViewBuilder m_buildView;
    std::optional<machine::MachineConfig> m_profile;
    std::vector<std::string> m_subroutinePath;
    double m_feedOverride = 1.0;
    OffsetState m_offsets;
    std::array<double, 4> m_startMm{};
    std::uint32_t m_startLine = 0;
    std::optional<gcode::ToolTable> m_toolTable;
    QString m_toolTableError;
    std::optional<gcode::HeightMap> m_heightMap;
    bool m_measurePeaks = false;
    LoadedProgram m_program;
    std::optional<LoadedProgram> m_asLoaded; // before showFollowed(), until the next load
    QThread *m_thread = nullptr;
    QString m_loadingPath;
    std::vector<QPointer<QThread>> m_ending; // stopped loads still ending; waited for at the end
    std::shared_ptr<std::atomic_bool> m_cancel;
    std::shared_ptr<std::atomic_int> m_progress; // permille
    std::shared_ptr<std::atomic_int> m_stage;    // 0 read, 1 index, 2 interpret, 3 view, 4 plan
    QTimer m_poll;
    quint64 m_generation = 0;
};

} // namespace frezka::session
