// The soft-limit policy. See softlimits.h.

#include "machine/softlimits.h"

#include "machine/steps.h"

#include <algorithm>
#include <cmath>

namespace frezka::machine {

bool withinSoftLimits(const AxisConfig &axis, double mm)
{
    const double tol = 1e-9 * std::max(1.0, std::abs(mm));
    return mm >= axis.softMinMm - tol && mm <= axis.softMaxMm + tol;
}

double unhomedJogMmPerMin(const AxisConfig &axis)
{
    return std::min(axis.homing.towardMmPerS * 60.0, axis.maxSpeedMmPerMin);
}

namespace {

JogMove start(const AxisConfig &a, std::int64_t fromSteps, double speedMmPerMin, bool homed)
{
    JogMove m;
    m.limitsOn = homed;
    m.speedMmPerMin = std::min(speedMmPerMin, homed ? a.maxSpeedMmPerMin : unhomedJogMmPerMin(a));
    m.targetSteps = fromSteps;
    return m;
}

void finish(JogMove &m, const AxisConfig &a, std::int64_t fromSteps)
{
    m.deltaSteps = m.targetSteps - fromSteps;
    m.targetMm = static_cast<double>(m.targetSteps) / a.stepsPerMm;
    if (m.verdict == JogVerdict::Move && m.deltaSteps == 0)
        m.verdict = JogVerdict::NoMove;
}

} // namespace

JogMove jogStep(const MachineConfig &config, int axis, std::int64_t fromSteps, double distanceMm,
                double speedMmPerMin, bool homed)
{
    const AxisConfig &a = config.axes[static_cast<std::size_t>(axis)];
    JogMove m = start(a, fromSteps, speedMmPerMin, homed);
    m.targetSteps = fromSteps + stepsOf(distanceMm, a.stepsPerMm);
    m.verdict = JogVerdict::Move;
    if (homed) {
        const std::int64_t lo = stepsOf(a.softMinMm, a.stepsPerMm);
        const std::int64_t hi = stepsOf(a.softMaxMm, a.stepsPerMm);
        const std::int64_t t = m.targetSteps;
        // Within the limits, or (from outside them) back toward them without passing the far one.
        const bool inside = t >= lo && t <= hi;
        const bool back = (fromSteps < lo && t > fromSteps && t <= hi) ||
                          (fromSteps > hi && t < fromSteps && t >= lo);
        if (!inside && !back)
            m.verdict = JogVerdict::BeyondLimit;
    }
    finish(m, a, fromSteps);
    if (m.verdict == JogVerdict::BeyondLimit)
        m.deltaSteps = 0;
    return m;
}

JogMove jogContinuous(const MachineConfig &config, int axis, std::int64_t fromSteps, int direction,
                      double speedMmPerMin, bool homed)
{
    const AxisConfig &a = config.axes[static_cast<std::size_t>(axis)];
    JogMove m = start(a, fromSteps, speedMmPerMin, homed);
    const int dir = direction < 0 ? -1 : 1;
    m.verdict = JogVerdict::Move;
    if (!homed) {
        m.targetSteps = fromSteps + dir * stepsOf(a.homing.travelMm, a.stepsPerMm);
    } else {
        const std::int64_t limit = stepsOf(dir > 0 ? a.softMaxMm : a.softMinMm, a.stepsPerMm);
        m.clipped = true;
        m.targetSteps = limit;
        if ((dir > 0 && fromSteps >= limit) || (dir < 0 && fromSteps <= limit))
            m.verdict = JogVerdict::AtLimit;
    }
    finish(m, a, fromSteps);
    if (m.verdict == JogVerdict::AtLimit)
        m.deltaSteps = 0;
    return m;
}

} // namespace frezka::machine
