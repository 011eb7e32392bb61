// checkProgram: whether a unit program can run on this unit from here. See programcheck.h.

#include "programcheck.h"

#include "driver/link/machinecore_internal.h"
#include "machine/unitwire.h"

#include <algorithm>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::refusal;
using machine::UnitOp;

std::optional<MachineError> checkProgram(machine::UnitProgram &program, const MachineState &state,
                                         const machine::MachineConfig &config, std::string *note)
{
    const VariantInfo &info = variantInfo(config.unit.variant);
    if (program.axisCount != 3 && program.axisCount != 4)
        return refusal(DriverCode::ProgramAxisCount, {std::to_string(program.axisCount)});
    if (program.axisCount > info.axisCount)
        return refusal(DriverCode::ProgramFourAxes, {std::string(info.displayName)});
    for (int a = 0; a < program.axisCount; ++a) {
        if (program.startSteps[a] != state.positionSteps[a])
            return refusal(DriverCode::ProgramStartsElsewhere,
                           {std::to_string(program.startSteps[a]), std::string(1, "XYZA"[a]),
                            std::to_string(state.positionSteps[a])});
    }
    auto &cmds = program.commands;
    if (!state.features.vlVkXmNa) {
        // Before v19 a GVE64 knows no speed modes: it always runs as VN (no direction
        // correction), and a plan in VK cannot run on it.
        const auto vk = std::find_if(cmds.begin(), cmds.end(), [](const machine::UnitCommand &c) {
            return c.op == UnitOp::SpeedModeVk;
        });
        if (vk != cmds.end())
            return refusal(DriverCode::ProgramNeedsVk,
                           {detail::lineArg(*vk), std::to_string(state.firmwareVersion)});
        const auto before = cmds.size();
        erase_if(cmds, [](const machine::UnitCommand &c) { return c.op == UnitOp::SpeedModeVn; });
        if (cmds.size() != before)
            *note = "VN not sent: firmware v" + std::to_string(state.firmwareVersion) +
                    " has no speed modes and always runs as VN";
    }
    for (const machine::UnitCommand &c : cmds) {
        if (c.op > UnitOp::Spindle)
            continue;
        Command wire = machine::wireCommand(c, program.axisCount).value_or(cmd::flag());
        if (c.op == UnitOp::Spindle && !info.hasSpindleAddress7)
            wire = cmd::output(c.value ? 0xFE : 0xFF); // GVE84: the relay
        if (auto bad = validate(wire, config.unit.variant, config.unit.maxPulseRate)) {
            auto e =
                refusal(DriverCode::InvalidCommand, {detail::lineArg(c)}, commandCheckMessage(bad));
            e.command = encodeBody(wire);
            return e;
        }
    }
    return std::nullopt;
}

} // namespace frezka::driver
