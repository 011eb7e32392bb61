#pragma once
// ProbeFollow: runs a program that probes for itself (issue 19 item 4), one implementation for
// both front ends (the run workflow calls it, session/runworkflow.h).
//
// A program such as pcb2gcode's autolevel output probes a grid (G38.2), keeps the trip points
// (#5061..#5063) in parameters and computes the cuts' Z from them, or sets a work offset from a
// probe (G10 L20 after G38.2). Interpreted before it runs, every probe is taken to end at its
// programmed end, so the path after the first probe is provisional (gcode::Result::
// provisionalLine) and must not be sent to the machine. So each job is planned only up to and
// including the next probe that has not run (start()): nothing follows the probe in the job,
// the driver runs it and the job ends there, the machine standing where the probe stopped
// (MachineState::probeSteps, probeTripped). afterProbe() then interprets the program again with
// the real results of every probe run so far (gcode::Options::probeResults) and plans its rest,
// the entries after that probe up to the next one, from the trip point, with the spindle,
// coolant and path mode in force there, for the next job. Nothing moves twice: each job starts
// where the machine stands. A probe the program runs in a loop or a subroutine counts in the
// order it runs. A probe that fails (a G38.2 that never touched) fails its job as any probe.
//
// Not for a run from a line (its probes before the line have not run). Texts in the user's
// language.

#include "session/programplanner.h"

#include "gcode/interpreter.h"
#include "gcode/toolpath.h"
#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <QCoreApplication>
#include <QString>

#include <array>
#include <memory>
#include <optional>
#include <vector>

namespace frezka::session {

class ProbeFollow
{
    Q_DECLARE_TR_FUNCTIONS(ProbeFollow)

public:
    // request: how the program is interpreted (its text, offsets, tool table; startMm is set
    // by start()); config and feedOverride: how its jobs are planned.
    ProbeFollow(InterpretRequest request, machine::MachineConfig config, double feedOverride = 1.0);

    struct Next
    {
        std::shared_ptr<const machine::UnitProgram> plan; // the next job; null: error says why
        std::shared_ptr<const gcode::Toolpath> whole;     // the program with the results so far
        std::shared_ptr<const gcode::Toolpath> job;       // what plan was planned from
        bool endsAtProbe = false;          // the job's last move is a probe not run yet
        std::uint32_t provisionalLine = 0; // that probe's line (0: none)
        std::size_t provisionalEntry =
            gcode::Result::kNoEntry; // its entry in whole (none: kNoEntry)
        PlanOutcome planned;         // the planner's figures, warnings and errors
        // What the program's G10 leave with the results so far (InterpretOutcome): the tool
        // table (G10 L1/L10/L11) and G54..G59.3 (G10 L2/L20), when changed.
        std::optional<gcode::ToolTable> toolTable;
        std::optional<std::array<std::array<double, 4>, 9>> workOffsetsMm;
        QString error;
    };
    // The program from its start at startMm (machine mm), no probe run yet: the first job.
    Next start(const std::array<double, 4> &startMm);
    // The job ended after its probe move, the machine standing at atMm (machine mm), the probe
    // tripped or not: the program interpreted with that result too, its rest planned from there.
    Next afterProbe(const gcode::Point4 &atMm, bool tripped);
    const std::vector<gcode::ProbeResult> &results() const { return m_results; }

private:
    // Interprets with m_results; the entry of the last probe run (none: first) in *probeEntry.
    Next interpret(std::size_t *probeEntry);
    void plan(Next *next, std::shared_ptr<gcode::Toolpath> job);

    InterpretRequest m_request;
    machine::MachineConfig m_config;
    double m_feedOverride = 1.0;
    std::vector<gcode::ProbeResult> m_results;
    std::size_t m_lastProvisional = 0; // the last interpretation's provisionalEntry
};

// Why a program that probes for itself (its path depends on the probe of line probeLine) cannot
// run from line startLine (0: from its start) or with a height map applied: the probes before
// the line would not run, and the map cannot bend a path not yet known. Empty when it can run
// (whole, without a map). The window's load and `frezka-cli run` refuse with it.
QString selfProbingRefusal(std::uint32_t probeLine, std::uint32_t startLine, bool heightMap);

// Whether anything moves after the probe entry provisionalEntry (gcode::Result's; kNoEntry:
// none): the path then depends on where that probe stops.
bool dependsOnProbe(const gcode::Toolpath &whole, std::size_t provisionalEntry);

// The entries of `whole` after its probe entry `probeEntry` up to `end` (exclusive), starting
// at that probe's end, after the events that put back the path mode, spindle and coolant in
// force there (on the probe's line). Pure.
std::shared_ptr<gcode::Toolpath>
restAfterProbe(const gcode::Toolpath &whole, std::size_t probeEntry,
               std::size_t end = std::numeric_limits<std::size_t>::max());

} // namespace frezka::session
