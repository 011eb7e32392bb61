#pragma once
// Random jobs for the stream property test and its soak (tests/bench/planner/stream_soak.cpp):
// a G-code program, a machine profile and a serial link, all drawn from one seed, and the judge
// that plans the program, streams it through the driver to the in-process emulator on a virtual
// clock and checks what the plan and the stream promise (docs/planner.md §9):
//
//   - the plan: no vertex over an axis's velocity-jump limit, no brake violation in the unit's
//     model, estimated_s not below the time-optimal bound and not above 1.02 times it;
//   - on the emulated link: no brake violation, no starvation stop (the unit never runs dry
//     inside a chain), no vertex over the jump limit as the unit passed it, the final counters
//     exactly the plan's last position, every vector executed exactly once (after a path fault,
//     the re-traced ones once more), and the job time within 2 % of estimated_s on a clean link.
//
// Programs: dense 3D rasters, arcs and helices, short zig-zags, long rapids and lines, spindle,
// coolant and dwells, G20 and G21, A-axis moves on 4-axis units, feeds from 1 % to 300 % of the
// axes' maxima. Profiles: every variant and pulse rate, steps/mm, speeds, accelerations and jump
// limits drawn per axis across their schema ranges (docs/machine-profile.md), VK/VN/auto, packets
// on and off. Links: the variant's baud rates, 0-16 ms latency, clean or 1 byte error in 1000.
// The operator: one job in four at a feed override (XM) of 50 to 200 %, set before the run (the
// estimate is the plan's at 100 %, so those jobs are judged on everything but their time).

#include "driver/link/emulatorport.h"
#include "machine/machineconfig.h"
#include "machine/planner.h"

#include <cstdint>
#include <string>
#include <vector>

namespace frezka::machine::test {

struct RandomJob
{
    std::uint64_t seed = 0;
    MachineConfig config; // link.baud/latencyMs/packets as the wire below
    driver::WireOptions wire;
    std::string program;       // G-code text
    std::string summary;       // one line: what was drawn
    int overridePercent = 100; // the operator's feed override (XM), set before the run (drawn)
};

// Draws a job; maxLines bounds the program's size (the property test keeps it small).
RandomJob drawJob(std::uint64_t seed, int maxLines = 1200);

struct JobOutcome
{
    bool planned = false;
    PlanStats stats;
    double jobS = 0; // from run() to the job's end, virtual seconds
    std::int64_t vectorsPlanned = 0;
    std::int64_t rests = 0; // PC-side waits for the queue to drain (WaitIdle, Dwell, ...)
    std::int64_t vectorsExecuted = 0;
    std::int64_t brakeViolations = 0;
    std::int64_t starvationStops = 0;
    std::size_t jumpOverLimit = 0; // vertices the unit passed with a speed step over a limit
    double maxJumpRatio = 0;
    bool exact = false;
    std::int64_t pathFaults = 0;
    std::int64_t leadInHolds = 0; // chains the driver held the unit at (driver/link/leadinhold.h)
    std::int64_t dryHolds = 0;    // chains halted where the unit would have run dry (ditto)
    double resendShare = 0;       // resent commands / commands sent in the job
    // Where the job's time went against the estimate: the unit's moving time (the emulator's)
    // against the plan's model (runUnitModel's motionS); the rest is time the unit stood (rests,
    // T pauses, holds, dwells) against the estimate's waits and the link's part of each rest.
    double movingS = 0;
    double modelMotionS = 0;
    // What broke, in two groups. wrong: the job ended somewhere the program does not (counters,
    // a vector run twice or never), the plan breaks a limit of the machine, or its estimate lies
    // below the time-optimal bound (a plan faster than the limits allow, or a wrong bound): never
    // acceptable. pace: the link did not keep the unit fed (starvation stops and the brake
    // violations they cause), the job took more than 2 % longer or shorter than the estimate, or
    // the estimate is more than 1.02 x the bound; a job that stopped with a named error (safe,
    // resumable).
    std::vector<std::string> wrong;
    std::vector<std::string> pace;
    bool ok() const { return wrong.empty() && pace.empty(); }
};

// Plans and runs a job and judges it.
JobOutcome runJob(const RandomJob &job);

} // namespace frezka::machine::test
