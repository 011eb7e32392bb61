#pragma once
// The program's check and plan in the session's terms, one implementation for both front
// ends: interpretProgram() runs the G-code interpreter in check mode (every error of the file,
// each with line, column and what to do) from the work offsets (nine systems, G92) and the
// machine's position; planProgram() plans the toolpath for the machine profile at a feed
// override and words the planner's errors and warnings. The GUI's program session calls both
// in its loading thread (with progress and cancel); frezka-cli run calls them in place. Pure
// functions: no state, no thread of their own.

#include "session/workoffsets.h"

#include "gcode/interpreter.h"
#include "gcode/linestate.h"
#include "gcode/toolpath.h"
#include "gcode/tooltable.h"
#include "machine/machineconfig.h"
#include "machine/planner.h"

#include <QByteArray>
#include <QString>

#include <atomic>
#include <functional>
#include <memory>
#include <optional>
#include <vector>

namespace frezka::session {

struct ProgramMessage
{
    int line = 0;   // 1-based, 0 = whole file
    int column = 0; // 1-based, 0 = none
    QString text;   // complete, in the user's language: what, where, what to do
    friend bool operator==(const ProgramMessage &, const ProgramMessage &) = default;
};

struct InterpretRequest
{
    QByteArray text;
    QString fileName;
    OffsetState offsets;                      // G54..G59.3, G92 and the active system
    std::array<double, 4> startMm{};          // machine position the program starts from
    const std::atomic_bool *cancel = nullptr; // set: the interpreter stops soon (cancelled)
    std::function<void(double)> progress;     // fraction 0..1 of this step
    machine::ProgramConfig limits;            // the profile's bounds on a program that never ends
    std::size_t maxErrors = 200; // errors kept (the window's list); the rest are counted
    std::uint32_t startLine = 0; // run from this line: its state in the outcome's mark (0: none)
    // The machine's tool table (nullopt: none, every tool has length 0). toolTableError, when
    // set, is the table file's own error: it is the outcome's first error (the program must not
    // run with lengths that could not be read).
    std::optional<gcode::ToolTable> toolTable;
    QString toolTableError;
    // Where o<name> call finds name.ngc: the program's folder, then the profile's
    // program.subroutinePath folders (machine::subroutineFolders).
    std::string programDirectory;
    std::vector<std::string> subroutinePath;
    // Splines (G5, G5.1, G5.2) are cut as chords within this of the curve: the profile's
    // motion.chordToleranceMm, the tolerance arcs are chorded with.
    double splineToleranceMm = 0.002;
    // The results of the probe moves already run (gcode::Options::probeResults).
    std::vector<gcode::ProbeResult> probeResults;
};

struct InterpretOutcome
{
    std::shared_ptr<gcode::Toolpath> toolpath;
    std::vector<ProgramMessage> errors;
    // The interpreter's warnings and notes (the program runs; "FILE:LINE:COL: warning: ..."),
    // the last one saying how many more were not shown.
    std::vector<ProgramMessage> warnings;
    std::uint64_t linesRead = 0;
    bool cancelled = false; // InterpretRequest::cancel stopped it: the outcome is incomplete
    std::uint64_t errorsNotShown = 0; // beyond the interpreter's cap; errors' last line says so
    gcode::LineMark mark;             // InterpretRequest::startLine's (session/runfromline.h)
    // The tool table after the program's G10 L1/L10/L11 (changed: to be written back once the
    // program has run).
    gcode::ToolTable toolTable;
    bool toolTableChanged = false;
    // G54..G59.3 as the program's G10 L2/L20 leave them (changed: to be kept once the program
    // has run; gcode::Result::workOffsetsMm).
    std::array<std::array<double, 4>, 9> workOffsetsMm{};
    bool workOffsetsChanged = false;
    // Where the path starts to depend on a probe not run yet (gcode::Result): the toolpath entry
    // of that probe and its line (gcode::Result::kNoEntry / 0: none); probes executed.
    std::size_t provisionalEntry = gcode::Result::kNoEntry;
    std::uint32_t provisionalLine = 0;
    std::size_t probes = 0;
};

InterpretOutcome interpretProgram(const InterpretRequest &request);

struct PlanOutcome
{
    std::shared_ptr<machine::UnitProgram> program; // null when there are errors
    machine::PlanStats stats;
    std::vector<ProgramMessage> errors;
    std::vector<ProgramMessage> warnings;
    bool ok() const { return program != nullptr; }
};

PlanOutcome planProgram(const gcode::Toolpath &toolpath, const machine::MachineConfig &config,
                        const QString &fileName, double feedOverride = 1.0);

} // namespace frezka::session
