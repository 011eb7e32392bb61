// MachineCore on the in-process emulator (virtual clock): G38 probe moves.

#include "simchecks.h"
#include "simfixture.h"

#include "gcode/toolpath.h"

#include <gtest/gtest.h>

using namespace frezka;
using namespace frezka::driver;
using namespace frezka::driver::test;
using protocol::Variant;

namespace {

machine::UnitProgram probeProgram(gcode::ProbeKind kind, std::int32_t dz, bool moveAfter)
{
    using machine::UnitOp;
    machine::UnitProgram p;
    p.axisCount = 3;
    auto add = [&p](UnitOp op, std::int64_t value, std::array<std::int32_t, 4> d,
                    std::int32_t aux) {
        machine::UnitCommand c;
        c.op = op;
        c.value = value;
        c.d = d;
        c.aux = aux;
        c.sourceLine = static_cast<std::uint32_t>(p.commands.size() + 1);
        c.endSteps = p.commands.empty() ? p.startSteps : p.commands.back().endSteps;
        for (int a = 0; a < 4; ++a)
            c.endSteps[a] += d[a];
        p.commands.push_back(c);
    };
    add(UnitOp::Accel, 50, {}, 0);
    add(UnitOp::Speed, 2000, {}, 0);
    add(UnitOp::Probe, 0, {0, 0, dz, 0}, static_cast<std::int32_t>(kind));
    if (moveAfter)
        add(UnitOp::Line, 0, {100, 0, 0, 0}, 0);
    add(UnitOp::ProgramEnd, 0, {}, 0);
    return p;
}

} // namespace

TEST(MachineCore, ProbeStopsAtContact)
{
    Sim sim;
    sim.config.eeprom.polarityHigh = 0x80; // IN15 contact reads 1 in the emulator
    sim.core.setConfig(sim.config);
    // The probe touches when Z reaches -1000 steps.
    sim.port.unit().setSwitches({{15, 2, -1000, -1}});
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.run(probeProgram(gcode::ProbeKind::TowardErrorIfNoContact, -3000, false),
                              sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 120)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front()) << sim.lastLog();
    EXPECT_TRUE(sim.core.state().probeTripped);
    const auto z = sim.core.state().probeSteps[2];
    EXPECT_LE(z, -1000);
    EXPECT_GT(z, -3000);
    EXPECT_EQ(sim.port.unit().position()[2], z);
}

TEST(MachineCore, ProbeWithoutContactIsAnErrorForG38_2)
{
    Sim sim;
    sim.config.eeprom.polarityHigh = 0x80;
    sim.core.setConfig(sim.config);
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.run(probeProgram(gcode::ProbeKind::TowardErrorIfNoContact, -500, true),
                              sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 120)) << sim.lastLog();
    EXPECT_FALSE(sim.finished.front());
    EXPECT_EQ(sim.core.state().mode, MachineMode::Alarm);
    ASSERT_FALSE(sim.errors.empty());
    EXPECT_NE(sim.errors.back().message.find("without the probe tripping"), std::string::npos);
    // G38.3: no contact is fine and the program goes on from the planned end point.
    Sim sim3;
    sim3.config.eeprom.polarityHigh = 0x80;
    sim3.core.setConfig(sim3.config);
    ASSERT_TRUE(sim3.connect());
    const auto p = probeProgram(gcode::ProbeKind::Toward, -500, true);
    ASSERT_FALSE(sim3.core.run(p, sim3.runner.now()));
    ASSERT_TRUE(sim3.runner.runUntil([&] { return !sim3.finished.empty(); }, 120))
        << sim3.lastLog();
    EXPECT_TRUE(sim3.finished.front()) << sim3.lastLog();
    expectAt(sim3, endOf(p));
}

TEST(MachineCore, ProbeTrippedWithMotionAfterEndsTheJob)
{
    Sim sim;
    sim.config.eeprom.polarityHigh = 0x80;
    sim.core.setConfig(sim.config);
    sim.port.unit().setSwitches({{15, 2, -1000, -1}});
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(
        sim.core.run(probeProgram(gcode::ProbeKind::Toward, -3000, true), sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 120)) << sim.lastLog();
    EXPECT_FALSE(sim.finished.front());
    ASSERT_FALSE(sim.errors.empty());
    EXPECT_NE(sim.errors.back().message.find("plan it again"), std::string::npos);
    EXPECT_EQ(sim.port.unit().position()[0], 0) << "nothing after the probe ran";
}
