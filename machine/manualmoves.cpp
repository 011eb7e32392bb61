// Manual moves as pure functions. See manualmoves.h.

#include "machine/manualmoves.h"

#include "machine/pathcheck.h"
#include "machine/steps.h"

#include <algorithm>

namespace frezka::machine {

namespace {

const AxisConfig &axisOf(const MachineConfig &config, int axis)
{
    return config.axes[static_cast<std::size_t>(axis)];
}

// Z up to travelZ, across, Z down; moves of no steps left out.
LineMoves upAcrossDown(const Steps4 &from, const Steps4 &to, std::int64_t travelZ, int axes)
{
    LineMoves moves;
    auto add = [&moves](Steps4 d) {
        if (std::any_of(d.begin(), d.end(), [](std::int64_t v) { return v != 0; }))
            moves.push_back(d);
    };
    add({0, 0, travelZ - from[2], 0});
    add({to[0] - from[0], to[1] - from[1], 0, axes == 4 ? to[3] - from[3] : 0});
    add({0, 0, to[2] - travelZ, 0});
    return moves;
}

} // namespace

double slowestAxisPulseRate(const MachineConfig &config, int axes, double mmPerMin)
{
    double rate = config.unit.maxPulseRate;
    for (int a = 0; a < axes; ++a) {
        const AxisConfig &ax = axisOf(config, a);
        rate = std::min(rate, pulseRateOf(ax.maxSpeedMmPerMin, ax.stepsPerMm));
        if (mmPerMin > 0)
            rate = std::min(rate, pulseRateOf(mmPerMin, ax.stepsPerMm));
    }
    return rate;
}

std::int64_t toolLiftSteps(const MachineConfig &config, std::int64_t zSteps)
{
    const AxisConfig &z = axisOf(config, 2);
    const std::int64_t top = stepsOf(z.softMaxMm, z.stepsPerMm);
    return std::min(stepsOf(config.motion.toolLiftMm, z.stepsPerMm),
                    std::max<std::int64_t>(0, top - zSteps));
}

Steps4 liftedJogMove(const MachineConfig &config, int axis, std::int64_t atSteps, double distanceMm)
{
    const AxisConfig &ax = axisOf(config, axis);
    const std::int64_t target =
        std::clamp(atSteps + stepsOf(distanceMm, ax.stepsPerMm),
                   stepsOf(ax.softMinMm, ax.stepsPerMm), stepsOf(ax.softMaxMm, ax.stepsPerMm));
    Steps4 d{};
    d[static_cast<std::size_t>(axis)] = target - atSteps;
    return d;
}

LineMoves backToLiftPoint(const Steps4 &from, const Steps4 &liftPoint, int axes)
{
    return upAcrossDown(from, liftPoint, std::max(from[2], liftPoint[2]), axes);
}

std::int64_t travelHeightSteps(const MachineConfig &config, std::int64_t fromZ, std::int64_t toZ)
{
    const AxisConfig &z = axisOf(config, 2);
    const std::int64_t top = stepsOf(z.softMaxMm, z.stepsPerMm);
    const std::int64_t high = std::max(fromZ, toZ);
    return std::max(
        high, std::min(top, high + stepsOf(std::max(0.0, config.motion.toolLiftMm), z.stepsPerMm)));
}

LineMoves returnToPathMoves(const MachineConfig &config, const Steps4 &from, const Steps4 &target,
                            int axes)
{
    return upAcrossDown(from, target, travelHeightSteps(config, from[2], target[2]), axes);
}

ProbeArming probeArming(const EepromConfig &eeprom, gcode::ProbeKind kind)
{
    using gcode::ProbeKind;
    const bool toward = kind == ProbeKind::TowardErrorIfNoContact || kind == ProbeKind::Toward;
    const std::uint8_t contactHigh = eeprom.polarityHigh & 0x80; // IN15 level that means contact
    ProbeArming arming;
    arming.mustTrip =
        kind == ProbeKind::TowardErrorIfNoContact || kind == ProbeKind::AwayErrorIfNoLoss;
    arming.interruptEnableHigh = static_cast<std::uint8_t>(eeprom.interruptEnableHigh | 0x80);
    arming.polarityHigh = static_cast<std::uint8_t>((eeprom.polarityHigh & 0x7F) |
                                                    (toward ? contactHigh : (contactHigh ^ 0x80)));
    return arming;
}

bool probeAlreadyTripped(const ProbeArming &arming, std::uint8_t inputs2)
{
    return (inputs2 & 0x80) == (arming.polarityHigh & 0x80);
}

ProbeOutcome probeOutcome(const UnitProgram &program, std::size_t index, const Steps4 &stoppedAt,
                          bool tripped, bool mustTrip)
{
    if (!tripped && mustTrip)
        return ProbeOutcome::NotTripped;
    if (sameSteps(stoppedAt, program.commands[index].endSteps, program.axisCount))
        return ProbeOutcome::AtEnd;
    const bool motionFollows = std::any_of(
        program.commands.begin() + static_cast<std::ptrdiff_t>(index) + 1, program.commands.end(),
        [](const UnitCommand &u) {
            return u.op == UnitOp::Vector || u.op == UnitOp::Line || u.op == UnitOp::Probe;
        });
    return motionFollows ? ProbeOutcome::StoppedShortMotion : ProbeOutcome::StoppedShort;
}

} // namespace frezka::machine
