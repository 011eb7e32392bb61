#pragma once
// Steps from millimetres: the one function and the one rounding rule (docs/planner.md §2); and
// the unit's speeds (pulses/s) from feeds, with their two rounding rules.
//
// Every absolute position is rounded on its own, to the nearest step, halves away from zero
// (std::llround); a relative vector is always the difference of two rounded absolutes. So after
// any number of moves the unit's counter equals stepsOf(final mm) exactly: rounding never drifts.

#include "gcode/toolpath.h"
#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <algorithm>
#include <cmath>
#include <cstdint>

namespace frezka::machine {

// Largest magnitude of a unit position counter or vector component (signed 32 bit).
inline constexpr std::int64_t kMaxCounter = 2147483647;

// Absolute step count of a position in mm (A: degrees) at stepsPerMm.
inline std::int64_t stepsOf(double mm, double stepsPerMm)
{
    return std::llround(mm * stepsPerMm);
}

// Absolute steps of a machine position for every axis (absent axes: their value still rounds,
// the planner refuses motion on them).
inline Steps4 stepsOf(const gcode::Point4 &p, const MachineConfig &config)
{
    return {stepsOf(p.x, config.axes[0].stepsPerMm), stepsOf(p.y, config.axes[1].stepsPerMm),
            stepsOf(p.z, config.axes[2].stepsPerMm), stepsOf(p.a, config.axes[3].stepsPerMm)};
}

// ---- speeds: the unit's V (and W, XV ...) in pulses (steps) per second ----

// The slowest V the unit takes, pulses/s.
inline constexpr std::int64_t kMinPulseRate = 10;

// The pulse rate of an axis at mmPerMin (A: degrees/min), pulses/s. Not rounded.
inline double pulseRateOf(double mmPerMin, double stepsPerMm)
{
    return mmPerMin / 60.0 * stepsPerMm;
}

// A speed for the unit from a pulse rate: the nearest whole rate (halves away from zero), at
// least kMinPulseRate, at most maxPulseRate. For a speed asked for (a jog, homing, the way back).
inline std::int64_t speedPulses(double pulsesPerS, std::int64_t maxPulseRate)
{
    return std::clamp<std::int64_t>(std::llround(pulsesPerS), kMinPulseRate, maxPulseRate);
}

// A speed for the unit that must not exceed the rate (an axis's maximum): rounded down, at least
// kMinPulseRate, at most maxPulseRate.
inline std::int64_t speedPulsesAtMost(double pulsesPerS, std::int64_t maxPulseRate)
{
    return std::clamp<std::int64_t>(static_cast<std::int64_t>(std::floor(pulsesPerS)),
                                    kMinPulseRate, maxPulseRate);
}

} // namespace frezka::machine
