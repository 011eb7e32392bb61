#pragma once
// frezka-cli run, internal: the parsed arguments, and the job run by the session's run workflow
// on the emulator's virtual clock or on a real link (runjob.cpp); cmd_run.cpp parses, plans and
// reports.

#include "programoptions.h"

#include "driver/link/coretypes.h"
#include "driver/link/emulatorport.h"
#include "machine/machineconfig.h"
#include "machine/unitprogram.h"
#include "session/probefollow.h"
#include "session/remainingtime.h"

#include <QCoreApplication>
#include <QString>

#include <array>
#include <cstdint>
#include <memory>
#include <optional>

namespace frezka::cli {

// The run command's messages (Czech and English in translations/).
struct RunCli
{
    Q_DECLARE_TR_FUNCTIONS(RunCli)
};

// The command line of frezka-cli run, as parseArgs (cmd_run.cpp) reads it.
struct RunArgs
{
    QString file;
    ProgramOptions program; // --machine, --offset, --work-zero
    QString port = QStringLiteral("sim");
    int baud = 0; // 0 = the profile's
    double latencyMs = 0;
    double faults = 0;
    quint32 seed = 1;
    bool virtualClock = true;
    bool clockGiven = false;
    bool home = false;
    bool returnToPath = false;
    int feedOverride = 0; // 0 = unchanged
    int holdAtLine = 0;   // 0 = no scripted hold
    bool lift = false;
    bool continueAtStops = false; // M0 / M1 / M6 continue at once (else: wait for Enter)
    int fromLine = 0;             // run from this line (session/runfromline.h), 0 = the whole
    // Run from a line (virtual clock): the approach's safe height (machine mm); the outcome says
    // where the emulator's counters first went below it.
    std::optional<double> watchBelowZMm;
    QString traceFile; // --trace: the serial trace is saved here when the run ends
    // --surface SPEC: the emulator's work top for probing (driver/emulator/surface.h), sim only.
    QString surface;
    // --cut-depth (with --surface): the tool's depth below the surface sampled while it cuts.
    bool cutDepth = false;
    // Set by the command, not parsed: the program probes for itself (session/probefollow.h); the
    // run workflow plans each job up to the next probe and the rest again after it.
    std::shared_ptr<session::ProbeFollow> follow;
};

// --cut-depth: the tool tip's depth below the simulated surface (mm, positive below), sampled
// from the emulator's counters every kCutSampleS of the virtual clock while the tool moves in
// X/Y no higher than kCutBandMm above the surface (a cut; rapids above the work and vertical
// plunges and retracts are left out).
struct CutDepth
{
    static constexpr double kCutSampleS = 0.002;
    static constexpr double kCutBandMm = 0.5;
    int samples = 0;
    double minMm = 0, maxMm = 0;
    std::array<double, 3> minAtMm{}, maxAtMm{}; // where the tool was (machine X, Y, Z)
};

// What a run came to: the driver's job report and the unit's end state (emulator: its counters).
struct RunOutcome
{
    bool ok = false;
    driver::JobReport report;
    std::array<std::int64_t, 4> finalSteps{};
    std::optional<emulator::Stats> unitStats;
    std::optional<bool> spindleOnAtEnd; // the emulator's spindle when the job ended
    std::optional<std::array<std::int64_t, 4>> unitSteps; // the emulator's own counters at the end
    int programStops = 0;                                 // M0 / M1 / M6 the run continued after
    std::optional<std::array<std::int64_t, 4>> firstBelowSteps; // RunArgs::watchBelowZMm's
    std::optional<std::array<std::int64_t, 4>> probeSteps;      // the last probe's trip point
    std::optional<CutDepth> cutDepth;                           // RunArgs::cutDepth's
    int probesFollowed = 0; // RunArgs::follow: probes after which the rest was planned again
    std::int64_t plannedRestarts = 0; // session::RunWorkflow::plannedRestarts of the run
    std::optional<std::array<std::int64_t, 4>> lastPlanEnd; // ... where the last job's plan ends
    QString error;
};

// The in-process emulator on a virtual clock (SimLink), the run workflow turning it; workTopMm:
// the highest Z a feed move reaches (the emulator's work surface), if any; remaining: the
// planner's model of the time left, for the progress bar.
RunOutcome runVirtual(const RunArgs &a, const machine::MachineConfig &config,
                      const machine::UnitProgram &program, std::optional<double> workTopMm,
                      session::RemainingTime remaining);
// A serial port / pty, or the emulator in real time: the link worker on this thread's event
// loop, exactly as the GUI drives it (without the extra thread), the run workflow driving it.
RunOutcome runReal(const RunArgs &a, const machine::MachineConfig &config,
                   const machine::UnitProgram &program, session::RemainingTime remaining);

} // namespace frezka::cli
