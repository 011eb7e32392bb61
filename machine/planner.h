#pragma once
// The planner: a pure function of (toolpath, machine config, options) to a UnitProgram.
//
// It chords arcs, converts positions to steps (machine/steps.h), checks every point against the
// soft limits before anything runs, splits the path into continuous chains at the
// synchronisation points that must stop the motion, caps the speed at every vertex (velocity
// jump per axis, junction deviation, short-segment curvature, feeds and axis limits), runs a
// backward and a forward pass over each chain in the unit's own integer units, and emits the
// unit commands (docs/gve-protocol.md §4) with their source lines. docs/planner.md explains the
// algorithm.

#include "gcode/toolpath.h"
#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <cstdint>
#include <string>
#include <vector>

namespace frezka::machine {

// How vertex speeds are chosen. Full is the product; the others are the benchmark's baselines.
enum class PlanStrategy : std::uint8_t {
    Full,         // every limit, whole-program passes
    ExactStop,    // naive: stop at every vertex
    GrblJunction, // grbl-style: junction deviation only, passes over a short lookahead window
};

struct PlanOptions
{
    PlanStrategy strategy = PlanStrategy::Full;
    int grblLookahead = 16;          // GrblJunction: blocks in the planner buffer (grbl: 16)
    bool grblKeepsAllLimits = false; // GrblJunction: the full plan's caps, grbl's lookahead
    std::int64_t shortThreshold = 1; // $: vectors shorter than this run "short" (§4)
    double brakeMarginSteps = 0.25;  // distance kept in reserve when braking, steps (>= 0)
    double accelTolerance = 0.3;     // keep the last A while within this fraction below the cap
    double accelWindowSteps = 12;    // A: smallest cap of the neighbours within this distance
    double accelKeepS = 0.05;        // ... but only on vectors shorter than this at their V, s
    double feedOverride = 1.0;       // multiplies programmed feeds (not rapids), 0.01..10
    // Every vector lasts at least the time its bytes take on the serial line (link.baud), times
    // wireMargin for packet framing and polls, plus its share of a packet's round trip
    // (link.latencyMs, a packet of half the unit's queue): where the motion would be
    // faster than the link can feed it, the unit's queue would run dry mid-chain and stop the
    // machine without braking (docs/planner.md §4, "The link's pace").
    bool wireLimited = true;
    double wireMargin = 1.05;
    // A vector's V is kept from the one before while the cruise time this loses stays below
    // speedChangeCost x what a V command costs the link (its bytes and a round trip): V cannot
    // travel in a packet (docs/planner.md §4). 0: every vector at its own cap.
    double speedChangeCost = 1.0;
    // Every toolpath entry that moves A is a chain of its own, from rest to rest (a WaitIdle
    // before and after it; an arc that turns A: each chord), the block boundaries where a
    // rotary table on its own unit is synchronised with the machine (machine/rotarysplit.h).
    bool restAroundA = false;
};

enum class PlanErrorCode : std::uint8_t {
    SoftLimit,       // a point outside the configured travel
    AbsentAxis,      // motion on an axis the machine does not have
    CounterOverflow, // a position beyond the unit's 32-bit counters
    NoFeed,          // a feed move with feed 0
    SpindleTooFast,  // S above spindle.maxRpm
    Unsupported,     // something the unit cannot do (M4 reverse spindle, ...)
    FeedCapped,      // warning: a feed above what the axes allow; it runs at their maximum
};

struct PlanError
{
    PlanErrorCode code = PlanErrorCode::SoftLimit;
    std::uint32_t line = 0; // 1-based source line, 0 = none
    std::string message;    // English: what, where, what to do
    friend bool operator==(const PlanError &, const PlanError &) = default;
};

struct PlanStats
{
    std::size_t vectors = 0;        // C commands
    std::size_t chains = 0;         // runs of C vectors that start and end at rest
    double estimatedS = 0;          // job time under the unit's motion model (§4.2)
    double boundS = 0;              // time-optimal bound for the same path and limits
    double waitS = 0;               // dwells and spin-up waits (PC side), in both figures
    double linkWaitS = 0;           // the link's part of each rest (status poll, position check,
                                    // commands outside packets), in both figures
    double maxVertexJumpMmPerS = 0; // largest per-axis speed step at a vertex, mm/s
    double maxJumpRatio = 0;        // largest (speed step / axis limit) at a vertex
    std::size_t jumpOverLimit = 0;  // vertices whose speed step exceeds an axis limit
    double maxCurveAccelRatio = 0;  // largest axis acceleration through a turn / limit
    std::size_t curveAccelOverLimit = 0; // vertices turning faster than the axes accelerate
    std::size_t brakeViolations = 0;     // vectors the model cannot brake in time (must be 0)
    bool speedModeVk = false;            // VK (path speeds) or VN (major-axis speeds)
    // How often the planner planned its moves (the link's pace plans a run again with the B, V
    // and A commands of its last plan, docs/planner.md §4): each move counted once per plan of
    // its run (movePlans / vectors: the plans a move took), and the most plans of one run.
    std::size_t movePlans = 0;
    int mostPlans = 0;
    friend bool operator==(const PlanStats &, const PlanStats &) = default;
};

struct PlanResult
{
    UnitProgram program;
    PlanStats stats;
    std::vector<PlanError> errors;   // non-empty: the program must not run
    std::vector<PlanError> warnings; // the program runs, the user should know
    bool ok() const { return errors.empty(); }
};

// Plans a whole toolpath. Config must be valid (validateMachineConfig). Never throws.
PlanResult plan(const gcode::Toolpath &toolpath, const MachineConfig &config,
                const PlanOptions &options = {});

} // namespace frezka::machine
