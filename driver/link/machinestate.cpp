// The English names of the modes and activities, the outputs as accepted, the logical inputs and
// outputs (machinestate.h).

#include "machinestate.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <tuple>

namespace frezka::driver {

const char *machineModeName(MachineMode mode)
{
    switch (mode) {
    case MachineMode::Disconnected:
        return "Disconnected";
    case MachineMode::Connecting:
        return "Connecting";
    case MachineMode::Idle:
        return "Idle";
    case MachineMode::Homing:
        return "Homing";
    case MachineMode::Jogging:
        return "Jogging";
    case MachineMode::Running:
        return "Running";
    case MachineMode::Stopping:
        return "Stopping";
    case MachineMode::Paused:
        return "Paused";
    case MachineMode::ToolLifted:
        return "Tool lifted";
    case MachineMode::Alarm:
        return "Alarm";
    case MachineMode::LinkLost:
        return "Link lost";
    }
    return "?";
}

int spindlePermilleAt(int askedPermille, int overridePercent)
{
    if (askedPermille <= 0)
        return 0;
    const long scaled = std::lround(askedPermille * overridePercent / 100.0);
    return static_cast<int>(std::clamp(scaled, 1L, 1000L));
}

bool noteOutputsAccepted(MachineState &state, const protocol::Command &c,
                         const machine::MachineConfig &config)
{
    using protocol::Op;
    const auto now = [&] {
        return std::make_tuple(state.outputs, state.spindlePermille, state.spindleOn,
                               state.overrideSentPercent);
    };
    const auto was = now();
    const auto changed = [&] { return was != now(); };
    if (c.op == Op::Multiplier)
        state.overrideSentPercent = static_cast<int>(c.args[0]);
    if (c.op == Op::SpindleSpeed && c.address == 7) {
        state.spindlePermille = static_cast<int>(c.args[0]);
        state.spindleRpm = config.spindle.maxRpm * static_cast<double>(c.args[0]) / 1000.0;
        state.outputs =
            static_cast<std::uint8_t>(c.args[0] > 0 ? state.outputs & 0xFE : state.outputs | 0x01);
        state.spindleOn = c.args[0] > 0;
        return changed();
    }
    if (c.op != Op::Output)
        return false;
    state.outputs = static_cast<std::uint8_t>(c.args[0]);
    if (!protocol::variantInfo(config.unit.variant).hasSpindleAddress7) {
        const std::uint8_t relay = machine::outputBit(config, machine::OutputFunction::Spindle);
        state.spindleOn = relay != 0 && !(state.outputs & relay);
        if (!state.spindleOn) {
            state.spindlePermille = 0;
            state.spindleRpm = 0;
        }
    } else {
        // OUT0 switches the spindle's power; its speed stays the last !7V.
        state.spindleOn = state.spindlePermille > 0 && !(state.outputs & 0x01);
    }
    return changed();
}

namespace {
// A value as the unit shows it: a byte in two hex digits, a number without trailing zeros.
std::string valueText(machine::EepromKind kind, double value)
{
    if (kind != machine::EepromKind::Byte)
        return numberText(value);
    char hex[8];
    std::snprintf(hex, sizeof hex, "%02X", static_cast<unsigned>(std::lround(value)) & 0xFFu);
    return hex;
}
} // namespace

std::string EepromDifference::text() const
{
    return entry.what + ": unit " + valueText(entry.kind, unitValue) + ", profile " +
           valueText(entry.kind, entry.value);
}

std::uint16_t MachineState::inputLevels() const
{
    return static_cast<std::uint16_t>(inputs1 | ((inputs2 & 0xC0) << 8));
}

bool MachineState::inputActive(const machine::MachineConfig &config, int n) const
{
    const bool level = ((inputLevels() >> n) & 1) != 0;
    const unsigned polarity = config.eeprom.polarity | (config.eeprom.polarityHigh << 8);
    return level == (((polarity >> n) & 1) != 0);
}

std::uint8_t MachineState::outputsOn() const
{
    const auto on = static_cast<std::uint8_t>(~outputs);
    return static_cast<std::uint8_t>((on & 0x01) | ((on & 0x04) ? 0x02 : 0) |
                                     ((on & 0x08) ? 0x04 : 0) | ((on & 0x02) ? 0x08 : 0) |
                                     (spindleOn ? 0x01 : 0));
}

bool MachineState::outputOn(const machine::MachineConfig &config,
                            machine::OutputFunction function) const
{
    const std::uint8_t bit = machine::outputBit(config, function);
    return bit != 0 && (outputs & bit) == 0;
}

const char *machineActivityName(MachineActivity activity)
{
    switch (activity) {
    case MachineActivity::None:
        return "None";
    case MachineActivity::Connecting:
        return "Connecting";
    case MachineActivity::Homing:
        return "Homing";
    case MachineActivity::Jogging:
        return "Jogging";
    case MachineActivity::Job:
        return "Job";
    case MachineActivity::CheckingProgress:
        return "Checking progress";
    case MachineActivity::Probing:
        return "Probing";
    case MachineActivity::PathFault:
        return "Path fault";
    case MachineActivity::ReturnToPath:
        return "Return to path";
    case MachineActivity::ToolLift:
        return "Tool lift";
    }
    return "?";
}

} // namespace frezka::driver
