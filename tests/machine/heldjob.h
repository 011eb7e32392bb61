#pragma once
// A random job (randomjob.h) planned and streamed through the driver to the in-process emulator
// with every line the driver put on the wire kept: the tests of the unit held by H inside a job
// (leadin_hold_test.cpp, dry_hold_test.cpp) read the wire and the emulated unit. A test may damage
// one chosen packet line instead of the job's random byte errors (PacketDamage): where the damage
// falls then does not depend on the bytes the driver sends before it (polls, waits).

#include "driver/link/emulatorport.h"
#include "driver/link/machinecore.h"
#include "driver/link/simrunner.h"
#include "gcode/interpreter.h"
#include "machine/planner.h"
#include "randomjob.h"

#include <cmath>
#include <cstdint>
#include <cstdio>
#include <string>
#include <string_view>
#include <vector>

namespace frezka::machine::test {

// One line of one packet damaged on its way to the unit: the `line`-th command (from 1) of the
// `packet`-th packet (from 1) the driver puts on the wire gets one digit changed by one, so its
// checksum no longer matches and the unit refuses it and the rest of the packet (code 4, the
// commands before it accepted). 0: nothing damaged.
struct PacketDamage
{
    int packet = 0;
    int line = 0;
};

// A random job's program planned and streamed through the driver to the in-process emulator,
// every line the driver put on the wire kept.
struct HeldJob
{
    explicit HeldJob(const RandomJob &j, bool hold, bool stopEnabled = false,
                     PacketDamage damage = {})
        : job(withDamage(j, damage))
        , port(unitOptions(job, stopEnabled), job.wire)
        , core(config(job, stopEnabled), options(job, hold))
        , runner(core, port)
        , damage(damage)
    {
        port.tamper = [this](std::string_view in) {
            const std::string bytes = damaged(in);
            pending += bytes;
            for (std::size_t cr; (cr = pending.find('\r')) != std::string::npos;) {
                std::string line = pending.substr(0, cr);
                pending.erase(0, cr + 1);
                if (line.size() > 3 && line[line.size() - 3] == ',')
                    line.resize(line.size() - 3); // the checksum
                wire.push_back(line);
                wireAt.push_back(port.now());
                queuedAt.push_back(port.unit().queueLength());
                movingAt.push_back(port.unit().isMoving());
            }
            return bytes;
        };
        core.onJobFinished = [this](bool ok) { finished.push_back(ok); };
        plan = machine::plan(gcode::interpretText(j.program).toolpath, core.config());
    }
    // A chosen damaged line replaces the random byte errors: the link is clean apart from it.
    static RandomJob withDamage(RandomJob j, PacketDamage damage)
    {
        if (damage.packet > 0) {
            j.wire.byteErrorRate = 0;
            j.wire.replyLossRate = 0;
        }
        return j;
    }
    // The bytes with PacketDamage applied: lines are followed as they pass (a write may hold
    // part of a line); in the chosen line the first digit after the command letter changes.
    std::string damaged(std::string_view in)
    {
        std::string out(in);
        for (char &c : out) {
            if (c == '\r') {
                if (outLine.starts_with("!0*S"))
                    inPacket = true, packetLine = 0;
                else if (outLine.starts_with("!0*E"))
                    inPacket = false, ++packetsSent;
                else if (inPacket)
                    ++packetLine;
                outLine.clear();
                lineDamaged = false;
                continue;
            }
            const bool target = damage.packet > 0 && inPacket && packetsSent + 1 == damage.packet &&
                                packetLine + 1 == damage.line && !outLine.starts_with("!0*");
            if (target && !lineDamaged && outLine.size() >= 3 && c >= '0' && c <= '9') {
                outLine += c; // the line as written, so that it is still followed
                c = c == '9' ? '8' : static_cast<char>(c + 1);
                lineDamaged = true;
                ++damagedLines;
                continue;
            }
            outLine += c;
        }
        return out;
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
    PacketDamage damage;
    std::string outLine;   // the line being written (PacketDamage)
    bool inPacket = false; // between a packet's *S and its *E
    int packetsSent = 0;   // packets ended (*E) so far
    int packetLine = 0;    // command lines of the current packet so far
    bool lineDamaged = false;
    int damagedLines = 0;
    std::string pending;
    std::vector<std::string> wire;
    std::vector<double> wireAt;        // when each line was put on the wire (the port's clock)
    std::vector<std::size_t> queuedAt; // the vectors the unit held then
    std::vector<bool> movingAt;        // whether it moved then
    std::vector<bool> finished;
};

// tests/bench/link/overfeed.sh's raster: `rows` rows of 1 000 segments of 0.1 mm over a wavy
// surface (Z varying), at `feed` mm/min (12 000: three times the GVE64's axes).
inline std::string overfeedRaster(int feed, int rows = 12)
{
    std::string s = "G21 G90 G17 G94 G64\nG0 X30 Y30\nG1 Z-5 F300\nF" + std::to_string(feed) + "\n";
    char line[96];
    for (int row = 0; row < rows; ++row) {
        const double y = 30 + row * 0.5;
        for (int j = 0; j < 1000; ++j) {
            const int t = row % 2 == 0 ? j : 1000 - j;
            const double x = 30 + 0.1 * t;
            const double z = -5 + 0.3 * std::sin(x * 0.7) * std::cos(y * 0.3);
            std::snprintf(line, sizeof line, "G1 X%.4f Y%.4f Z%.4f\n", x, y, z);
            s += line;
        }
    }
    return s + "G0 Z-1\nM2\n";
}

// The commands the unit runs as vectors (C and L): its vectorsExecuted when none is lost or run
// twice.
inline std::int64_t motionCommands(const UnitCommands &cmds)
{
    std::int64_t vectors = 0;
    for (std::size_t i = 0; i < cmds.size(); ++i)
        vectors += cmds.op(i) == UnitOp::Vector || cmds.op(i) == UnitOp::Line;
    return vectors;
}

} // namespace frezka::machine::test
