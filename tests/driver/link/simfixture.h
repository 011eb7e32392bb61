#pragma once
// Test fixture: a MachineCore connected to the in-process emulator on a virtual clock.

#include "driver/link/emulatorport.h"
#include "driver/link/machinecore.h"
#include "driver/link/simrunner.h"
#include "machine/machineconfig.h"

#include <memory>
#include <string>
#include <vector>

namespace frezka::driver::test {

struct Sim
{
    // unitFromProfile: the unit as the built-in emulator makes it (switches and EEPROM from the
    // profile); otherwise a unit with the factory EEPROM and no switches. firmware: the unit's
    // '?' string ("" = the variant's).
    explicit Sim(protocol::Variant variant = protocol::Variant::Gve64, WireOptions wire = {},
                 CoreOptions options = {}, bool unitFromProfile = false, std::string firmware = {})
        : config(machine::defaultMachineConfig(variant))
        , port(unitFor(config, unitFromProfile, firmware), wire)
        , core(config, options)
        , runner(core, port)
    {
        core.onLog = [this](const std::string &line) {
            if (!errors.empty() && ++afterError > 20)
                return; // keep what led to the first error
            // Keep the interesting lines: routine polls would push everything else out.
            static const char *kRoutine[] = {"> !0P4", "> !0PF", "> !0F", "> !0I1", "> !0I2"};
            for (const char *r : kRoutine) {
                if (line == r) {
                    skipNext = true;
                    return;
                }
            }
            if (skipNext && line.rfind("< ", 0) == 0) {
                skipNext = false;
                return;
            }
            skipNext = false;
            log.push_back(line);
            if (log.size() > 400)
                log.erase(log.begin(), log.begin() + 200);
        };
        core.onError = [this](const MachineError &e) { errors.push_back(e); };
        core.onJobFinished = [this](bool ok) { finished.push_back(ok); };
    }
    static emulator::UnitOptions unitFor(const machine::MachineConfig &config, bool fromProfile,
                                         std::string firmware)
    {
        emulator::UnitOptions u = fromProfile
                                      ? unitOptionsFor(config)
                                      : emulator::UnitOptions{.variant = config.unit.variant};
        u.firmware = std::move(firmware);
        return u;
    }
    bool connect(double limitS = 30)
    {
        runner.open();
        return runner.runUntil([this] { return core.state().mode != MachineMode::Connecting; },
                               limitS) &&
               core.state().mode == MachineMode::Idle;
    }
    bool until(MachineMode mode, double limitS = 60)
    {
        return runner.runUntil([&] { return core.state().mode == mode; }, limitS);
    }
    std::string lastLog(int n = 30) const
    {
        std::string s = std::string("mode ") + machineModeName(core.state().mode) + ", acked " +
                        std::to_string(core.state().commandsAcked) + "\n";
        for (const MachineError &e : errors)
            s += "error: " + e.message + " [" + e.command + "] -> '" + e.reply + "'\n";
        for (std::size_t i = log.size() > static_cast<std::size_t>(n) ? log.size() - n : 0;
             i < log.size(); ++i)
            s += log[i] + "\n";
        return s;
    }

    machine::MachineConfig config;
    EmulatorPort port;
    MachineCore core;
    SimRunner runner;
    std::vector<std::string> log;
    bool skipNext = false;
    int afterError = 0;
    std::vector<MachineError> errors;
    std::vector<bool> finished;
};

// Builds a unit program command by command; each command's endSteps follow from its delta.
struct ProgramBuilder
{
    explicit ProgramBuilder(int axisCount)
    {
        program.axisCount = axisCount;
        at = program.startSteps;
    }
    void add(machine::UnitOp op, std::int64_t value, std::array<std::int32_t, 4> d = {},
             std::uint32_t line = 0)
    {
        machine::UnitCommand c;
        c.op = op;
        c.value = value;
        c.d = d;
        for (int a = 0; a < 4; ++a)
            at[a] += d[a];
        c.endSteps = at;
        c.sourceLine = line;
        program.commands.push_back(c);
    }
    machine::UnitProgram program;
    machine::Steps4 at{};
};

// A dense program: `n` short continuous vectors tracing a zig-zag, preceded by speed settings.
inline machine::UnitProgram denseProgram(int n, int axisCount = 3, int speed = 20000,
                                         int brake = 20000, int stepLen = 60)
{
    using machine::UnitOp;
    ProgramBuilder b(axisCount);
    auto add = [&b](UnitOp op, std::int64_t value, std::array<std::int32_t, 4> d = {},
                    std::uint32_t line = 0) { b.add(op, value, d, line); };
    add(UnitOp::Accel, 200);
    add(UnitOp::Speed, speed);
    add(UnitOp::Brake, brake);
    for (int i = 0; i < n; ++i) {
        const int dy = (i / 7) % 2 ? -stepLen / 3 : stepLen / 3;
        add(UnitOp::Vector, 0, {stepLen, dy, (i % 5) - 2, 0}, static_cast<std::uint32_t>(10 + i));
    }
    add(UnitOp::ProgramEnd, 0);
    return b.program;
}

// A slow job (long vectors) so that there is time to pause it.
inline machine::UnitProgram slowProgram(int n)
{
    auto p = denseProgram(n, 3, 4000, 4000, 400);
    // Start below Z = 0 (the default profile's Z runs -120..0) so that the tool can be lifted.
    std::vector<machine::UnitCommand> commands = p.commands.toVector();
    for (auto &c : commands) {
        if (c.op == machine::UnitOp::Vector)
            c.d[2] = -1;
    }
    machine::Steps4 at = p.startSteps;
    for (auto &c : commands) {
        for (int a = 0; a < 4; ++a)
            at[a] += c.d[a];
        c.endSteps = at;
    }
    p.commands = commands;
    return p;
}

} // namespace frezka::driver::test
