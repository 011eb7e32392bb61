// frezka-cli run-line --rotary-a: the program planned and split for the two units. See
// rotaryline.h.

#include "rotaryline.h"

#include "cli.h"

#include "machine/planner.h"
#include "protocol/variant.h"

#include <QCoreApplication>

namespace frezka::cli {

namespace {

struct RotaryLineCli
{
    Q_DECLARE_TR_FUNCTIONS(RotaryLineCli)
};

std::optional<machine::MachineConfig> rotaryProfileFor(const ProgramOptions &options, int address,
                                                       const QString &profile, int machineAddress)
{
    auto config = loadProfile(profile.isEmpty() ? options.machine : profile);
    if (!config)
        return std::nullopt;
    if (config->unit.variant != protocol::Variant::Gve114) {
        err(RotaryLineCli::tr("frezka-cli run-line: the rotary unit must be a GVE114 (only it "
                              "shares its line with other units): give a GVE114 profile, "
                              "--rotary-a %1:PROFILE\n")
                .arg(address));
        return std::nullopt;
    }
    if (address == machineAddress) {
        err(RotaryLineCli::tr("frezka-cli run-line: the rotary unit's address %1 is the "
                              "machine's unit's (unit.address of --machine): each unit on the "
                              "line has its own address\n")
                .arg(address));
        return std::nullopt;
    }
    if (!config->axes[3].present) {
        err(RotaryLineCli::tr("frezka-cli run-line: the rotary unit's profile has no A axis "
                              "(axes.a.present is false): give a profile that sets the A "
                              "axis's scale, speeds and limits, --rotary-a %1:PROFILE\n")
                .arg(address));
        return std::nullopt;
    }
    config->unit.address = address;
    return config;
}

} // namespace

std::optional<RotaryLinePlan> planRotaryLine(const QString &file, const ProgramOptions &options,
                                             int rotaryAddress, const QString &rotaryProfile)
{
    auto machineConfig = loadProfile(options.machine);
    if (!machineConfig)
        return std::nullopt;
    auto rotary =
        rotaryProfileFor(options, rotaryAddress, rotaryProfile, machineConfig->unit.address);
    if (!rotary)
        return std::nullopt;
    const auto program = interpretFile(file, options);
    if (!program)
        return std::nullopt;
    machine::PlanOptions planOptions;
    planOptions.restAroundA = true;
    const machine::PlanResult plan = machine::plan(
        *program->toolpath, machine::withRotaryA(*machineConfig, *rotary), planOptions);
    for (const machine::PlanError &e : plan.warnings)
        err(planMessage(file, e, RotaryLineCli::tr("warning: ")));
    if (!plan.ok()) {
        for (const machine::PlanError &e : plan.errors)
            err(planMessage(file, e, QString()));
        return std::nullopt;
    }
    RotaryLinePlan out{*machineConfig, *rotary, machine::splitRotaryA(plan.program)};
    if (out.split.errorCode == machine::RotarySplit::Error::NotRestAroundA) {
        err(RotaryLineCli::tr("%1:%2: internal error: the program was planned without a rest "
                              "around each move that turns A; please report it with the program\n")
                .arg(file)
                .arg(out.split.errorLine));
        return std::nullopt;
    }
    if (!out.split.ok()) {
        err(RotaryLineCli::tr("%1:%2: a probe move that turns A cannot run with A on its own "
                              "unit (--rotary-a): probe without moving A\n")
                .arg(file)
                .arg(out.split.errorLine));
        return std::nullopt;
    }
    return out;
}

} // namespace frezka::cli
