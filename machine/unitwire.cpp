#include "machine/unitwire.h"

#include "machine/steps.h"

#include <algorithm>
#include <cmath>

namespace frezka::machine {

namespace {

protocol::Command vectorCommand(bool line, const std::array<std::int32_t, 4> &d, int axisCount)
{
    if (axisCount >= 4 && d[3] != 0)
        return line ? protocol::cmd::line(d[0], d[1], d[2], d[3])
                    : protocol::cmd::vector(d[0], d[1], d[2], d[3]);
    return line ? protocol::cmd::line(d[0], d[1], d[2]) : protocol::cmd::vector(d[0], d[1], d[2]);
}

const char *probeName(std::int32_t kind)
{
    static const char *names[] = {"G38.2", "G38.3", "G38.4", "G38.5"};
    return kind >= 0 && kind < 4 ? names[kind] : "G38.?";
}

} // namespace

std::optional<protocol::Command> wireCommand(const UnitCommand &c, int axisCount)
{
    switch (c.op) {
    case UnitOp::Line:
        return vectorCommand(true, c.d, axisCount);
    case UnitOp::Vector:
        return vectorCommand(false, c.d, axisCount);
    case UnitOp::Brake:
        return protocol::cmd::brake(c.value);
    case UnitOp::Speed:
        return protocol::cmd::speed(c.value);
    case UnitOp::Accel:
        return protocol::cmd::accel(c.value);
    case UnitOp::Pause:
        return protocol::cmd::pause(c.value);
    case UnitOp::ShortThreshold:
        return protocol::cmd::shortThreshold(c.value);
    case UnitOp::SpeedModeVk:
        return protocol::cmd::speedModeVk();
    case UnitOp::SpeedModeVn:
        return protocol::cmd::speedModeVn();
    case UnitOp::Output:
        return protocol::cmd::output(static_cast<int>(c.value));
    case UnitOp::Spindle:
        return protocol::cmd::spindle(c.value);
    case UnitOp::WaitIdle:
    case UnitOp::Dwell:
    case UnitOp::OperatorStop:
    case UnitOp::Probe:
    case UnitOp::ProgramEnd:
        break;
    }
    return std::nullopt;
}

std::string commandText(const UnitCommand &c, int axisCount)
{
    if (const auto wire = wireCommand(c, axisCount))
        return protocol::encodeBody(*wire);
    switch (c.op) {
    case UnitOp::WaitIdle:
        return "# wait-idle";
    case UnitOp::Dwell:
        return "# dwell " + std::to_string(c.value) + " ms";
    case UnitOp::OperatorStop:
        switch (static_cast<StopReason>(c.value)) {
        case StopReason::Pause:
            return "# operator-stop M0";
        case StopReason::OptionalPause:
            return "# operator-stop M1";
        case StopReason::ToolChange:
            return "# operator-stop M6 T" + std::to_string(c.aux);
        }
        return "# operator-stop";
    case UnitOp::Probe:
        return std::string("# probe ") + probeName(c.aux) + " " +
               protocol::encodeBody(vectorCommand(true, c.d, axisCount));
    case UnitOp::ProgramEnd:
        return "# program-end";
    default:
        break;
    }
    return "# ?";
}

std::array<std::int64_t, 4> axisSpeedLimits(const MachineConfig &config)
{
    std::array<std::int64_t, 4> limits{};
    const auto rate = static_cast<std::int64_t>(config.unit.maxPulseRate);
    for (std::size_t i = 0; i < limits.size(); ++i) {
        const AxisConfig &a = config.axes[i];
        limits[i] = a.present
                        ? speedPulsesAtMost(pulseRateOf(a.maxSpeedMmPerMin, a.stepsPerMm), rate)
                        : rate;
    }
    return limits;
}

} // namespace frezka::machine
