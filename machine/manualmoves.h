#pragma once
// Manual moves: the arithmetic of the moves the driver makes outside a planned job (docs/
// architecture.md, "Where each kind of change goes"). Pure functions of the profile and the
// unit's counters, in steps and pulses/s as the unit's commands take them; the driver sequences
// them with the unit (K, R, L, V, the waits for the machine to stand) and owns every refusal.
//
//   - The tool lift (driver/link/toollift.cpp): Z up by motion.toolLiftMm within Z's upper soft
//     limit, hand moves of the lifted tool clipped to the limits, and the way back to the lift
//     point (Z up to the higher end, across, Z down), each move from rest to rest.
//   - The return to the planned path (driver/link/returntopath.cpp): Z up by the lift height
//     above both ends (within the limit), across, down to the last verified point.
//   - The G38 probe move (driver/link/probemove.cpp): how the probe input (IN15) is armed for
//     contact or its loss, and what the counters where the move stopped mean for the job.
//
// Jogging's soft-limit policy is machine/softlimits.h; steps and pulse rates round as
// machine/steps.h says.

#include "gcode/toolpath.h"
#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace frezka::machine {

// Relative L moves (steps), each from rest to rest, in the order they run.
using LineMoves = std::vector<Steps4>;

// ---- speeds (V, pulses/s) ----

// The slowest of the first `axes` axes' maximum feeds, and when mmPerMin > 0 of that feed on each
// of them, in pulses/s; at most the unit's maximum pulse rate. Not rounded.
double slowestAxisPulseRate(const MachineConfig &config, int axes, double mmPerMin = 0);

// ---- the tool lift ----

// How far Z goes up from the counter zSteps for a tool lift: motion.toolLiftMm (> 0), never
// beyond Z's upper soft limit; 0 when Z stands at or above it.
std::int64_t toolLiftSteps(const MachineConfig &config, std::int64_t zSteps);

// A hand move of the lifted tool: `axis` by distanceMm from the counter atSteps, clipped to its
// soft limits (a step is shortened at a limit, not refused). All zero at the limit.
Steps4 liftedJogMove(const MachineConfig &config, int axis, std::int64_t atSteps,
                     double distanceMm);

// From `from` back to the lift point `liftPoint`: Z up to the higher of the two, across (X, Y
// and, with four axes, A), Z down. Moves of no steps are left out.
LineMoves backToLiftPoint(const Steps4 &from, const Steps4 &liftPoint, int axes);

// ---- the return to the planned path ----

// The Z counter to travel at between two points: motion.toolLiftMm above the higher of fromZ
// and toZ, never beyond Z's upper soft limit, and never below the higher one.
std::int64_t travelHeightSteps(const MachineConfig &config, std::int64_t fromZ, std::int64_t toZ);

// From `from` to the path's point `target`: Z up to travelHeightSteps, across (X, Y and, with
// four axes, A), Z down. Moves of no steps are left out.
LineMoves returnToPathMoves(const MachineConfig &config, const Steps4 &from, const Steps4 &target,
                            int axes);

// ---- the G38 probe move ----

struct ProbeArming
{
    bool mustTrip = false;              // G38.2 / G38.4: the job fails when the input never changes
    std::uint8_t interruptEnableHigh{}; // ST1: the profile's IN14/IN15 enables with IN15's on
    std::uint8_t polarityHigh{};        // ST3: IN15's active level is contact (G38.2/.3) or its
                                        // loss (G38.4/.5); IN14's as the profile has it
    friend bool operator==(const ProbeArming &, const ProbeArming &) = default;
};

// How the probe input is armed for a probe move of `kind`, from the profile's EEPROM polarity
// (polarityHigh bit 7: the IN15 level that means contact).
ProbeArming probeArming(const EepromConfig &eeprom, gcode::ProbeKind kind);

// Whether IN15 (bit 7 of the unit's I2 reading) already stands where the armed move waits for:
// the move must not start.
bool probeAlreadyTripped(const ProbeArming &arming, std::uint8_t inputs2);

enum class ProbeOutcome : std::uint8_t {
    AtEnd,              // at the programmed end: the job runs on as planned
    StoppedShort,       // short of it, nothing moves after it: the path guard goes off, runs on
    StoppedShortMotion, // short of it with motion after it: the job ends (plan it again)
    NotTripped,         // a G38.2 / G38.4 whose input never changed: the job fails
};

// What the probe move of program command `index` did, standing at `stoppedAt` with the input
// tripped or not.
ProbeOutcome probeOutcome(const UnitProgram &program, std::size_t index, const Steps4 &stoppedAt,
                          bool tripped, bool mustTrip);

} // namespace frezka::machine
