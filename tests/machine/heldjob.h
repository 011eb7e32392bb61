#pragma once
// A random job (randomjob.h) planned and streamed through the driver to the in-process emulator
// with every line the driver put on the wire kept: the tests of the unit held by H inside a job
// (leadin_hold_test.cpp, dry_hold_test.cpp) read the wire and the emulated unit.

#include "driver/link/emulatorport.h"
#include "driver/link/machinecore.h"
#include "driver/link/simrunner.h"
#include "gcode/interpreter.h"
#include "machine/planner.h"
#include "randomjob.h"

#include <string>
#include <string_view>
#include <vector>

namespace frezka::machine::test {

// A random job's program planned and streamed through the driver to the in-process emulator,
// every line the driver put on the wire kept.
struct HeldJob
{
    explicit HeldJob(const RandomJob &j, bool hold, bool stopEnabled = false)
        : job(j)
        , port(unitOptions(j, stopEnabled), j.wire)
        , core(config(j, stopEnabled), options(j, hold))
        , runner(core, port)
    {
        port.tamper = [this](std::string_view bytes) {
            pending += bytes;
            for (std::size_t cr; (cr = pending.find('\r')) != std::string::npos;) {
                std::string line = pending.substr(0, cr);
                pending.erase(0, cr + 1);
                if (line.size() > 3 && line[line.size() - 3] == ',')
                    line.resize(line.size() - 3); // the checksum
                wire.push_back(line);
                wireAt.push_back(port.now());
                queuedAt.push_back(port.unit().queueLength());
            }
            return std::string(bytes);
        };
        core.onJobFinished = [this](bool ok) { finished.push_back(ok); };
        plan = machine::plan(gcode::interpretText(j.program).toolpath, core.config());
    }
    static machine::MachineConfig config(const RandomJob &j, bool stopEnabled)
    {
        machine::MachineConfig c = j.config;
        if (stopEnabled) {
            c.eeprom.interruptEnable |= 0x80; // IN7 = STOP
            c.eeprom.polarity |= 0x80;        // active high: pressed reads 1 in the emulator
        }
        return c;
    }
    static emulator::UnitOptions unitOptions(const RandomJob &j, bool stopEnabled)
    {
        emulator::UnitOptions o = driver::unitOptionsFor(config(j, stopEnabled));
        o.trace = true; // as the property test's runs (randomjob.cpp): speeds by time
        return o;
    }
    static driver::CoreOptions options(const RandomJob &j, bool hold)
    {
        driver::CoreOptions o;
        o.packets = j.config.link.packets;
        o.returnToPathAutomatically = true;
        o.leadInHold = hold;
        return o;
    }
    // atOverride: the job's drawn feed override set before the run, as the property test does.
    bool connectAndRun(bool atOverride = false)
    {
        runner.open();
        runner.runUntil([&] { return core.state().mode != driver::MachineMode::Connecting; }, 300);
        if (core.state().mode != driver::MachineMode::Idle || !plan.ok())
            return false;
        if (atOverride && job.overridePercent != 100) {
            if (core.setOverride(job.overridePercent, runner.now()))
                return false;
            runner.runUntil([&] { return core.state().overridePercent == job.overridePercent; },
                            10);
        }
        return !core.run(plan.program, runner.now());
    }
    std::size_t find(std::string_view prefix, std::size_t from = 0) const
    {
        for (std::size_t i = from; i < wire.size(); ++i) {
            if (wire[i].starts_with(prefix))
                return i;
        }
        return wire.size();
    }

    RandomJob job;
    driver::EmulatorPort port;
    driver::MachineCore core;
    driver::SimRunner runner;
    machine::PlanResult plan;
    std::string pending;
    std::vector<std::string> wire;
    std::vector<double> wireAt;        // when each line was put on the wire (the port's clock)
    std::vector<std::size_t> queuedAt; // the vectors the unit held then
    std::vector<bool> finished;
};

} // namespace frezka::machine::test
