#pragma once
// The soft-limit policy: when the configured travel (axes.*.softMinMm .. softMaxMm) applies
// and what it does to a manual move. Pure functions, one place for the whole program; the
// driver's jog, the GUI's jog buttons (for the refusal's words) and the planner (runs, console
// lines) all ask here. docs/machine-profile.md, "Soft limits and homing", states the policy:
//
//   - An axis's counter is a machine position only once the axis is homed: the unit counts from
//     0 at power-on, wherever the axis stands. Before that the soft limits are off for jogging
//     (the operator sees "not homed: limits off"): a jog may go either way, at most the axis's
//     homing speed toward the switch (homing.towardMmPerS), a continuous one at most one
//     homing travel (homing.travelMm) far.
//   - From the moment the axis is homed its limits apply. A jog step that would end beyond one
//     is refused, the axis stays where it is (a step promises its distance); a continuous jog
//     runs to the limit and stops there (clipped). An axis standing outside its limits may only
//     move back toward them.
//   - Programs (a run, a console line) are always planned within the limits (withinSoftLimits,
//     used by machine::plan); a run before homing asks for homing first
//     (motion.runBeforeHoming), because before homing those limits refer to nothing.

#include "machine/machineconfig.h"

#include <cstdint>

namespace frezka::machine {

// Whether `mm` lies within the axis's soft limits (a relative tolerance of 1e-9 for rounding).
bool withinSoftLimits(const AxisConfig &axis, double mm);

// The fastest jog of an axis not homed yet, mm/min: its homing speed toward the switch.
double unhomedJogMmPerMin(const AxisConfig &axis);

enum class JogVerdict : std::uint8_t {
    Move,        // targetSteps / deltaSteps / speedMmPerMin say what to send
    BeyondLimit, // homed: the step would end outside the limits (targetMm says where)
    AtLimit,     // homed: nothing left to move in that direction
    NoMove,      // a step of less than one step
};

struct JogMove
{
    JogVerdict verdict = JogVerdict::NoMove;
    std::int64_t targetSteps = 0; // the counter value the move ends at
    std::int64_t deltaSteps = 0;  // the L component of the axis
    double targetMm = 0;          // where it would end (also when refused)
    double speedMmPerMin = 0;     // requested, capped by the axis (and before homing)
    bool limitsOn = false;        // the axis is homed: the soft limits applied
    bool clipped = false;         // a continuous jog ends at the limit
    friend bool operator==(const JogMove &, const JogMove &) = default;
};

// A jog step of `distanceMm` (A: degrees) from the counter `fromSteps`.
JogMove jogStep(const MachineConfig &config, int axis, std::int64_t fromSteps, double distanceMm,
                double speedMmPerMin, bool homed);
// A continuous jog in `direction` (+1 / -1) from `fromSteps`: where it may run to.
JogMove jogContinuous(const MachineConfig &config, int axis, std::int64_t fromSteps, int direction,
                      double speedMmPerMin, bool homed);

} // namespace frezka::machine
