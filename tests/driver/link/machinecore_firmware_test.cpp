// MachineCore on the in-process emulator (virtual clock): the unit's EEPROM against the profile,
// older firmware and what it gates, the GVE114's fast baud range.

#include "simfixture.h"

#include <gtest/gtest.h>

using namespace frezka;
using namespace frezka::driver;
using namespace frezka::driver::test;
using protocol::Variant;

TEST(MachineCore, BuiltInEmulatorHoldsTheProfilesEeprom)
{
    for (Variant v : {Variant::Gve64, Variant::Gve114}) {
        Sim sim(v, {}, {}, true);
        ASSERT_TRUE(sim.connect());
        EXPECT_TRUE(sim.core.state().eepromDifferences.empty())
            << sim.core.state().eepromDifferences.front().text();
    }
}

TEST(MachineCore, EepromComparedOnConnectWrittenOnlyWhenAsked)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    const auto differences = sim.core.state().eepromDifferences;
    ASSERT_FALSE(differences.empty()) << "the emulator's defaults differ from the profile";
    const auto before = sim.port.unit().eepromByte(0x01);
    sim.runner.runFor(1.0);
    EXPECT_EQ(sim.port.unit().eepromByte(0x01), before) << "connecting never writes";
    ASSERT_FALSE(sim.core.writeEeprom(sim.runner.now()));
    sim.runner.runFor(2.0);
    EXPECT_TRUE(sim.core.state().eepromDifferences.empty())
        << sim.core.state().eepromDifferences.front().text();
    EXPECT_TRUE(sim.errors.empty()) << sim.errors.front().message;
}

// An older GVE64 firmware (v17: no VK/VL/XM/N<axis>): with a profile that says so, connecting
// sends nothing the unit lacks, a plan in VN runs (its VN is not sent: the unit knows no modes),
// a plan in VK and the XM override are refused with the reason, and homing zeroes all counters
// with N. With a profile that promises v19 the connect ends in an Alarm that names the fix.
TEST(MachineCore, OlderFirmwareGatesFeatures)
{
    const std::string firmware = "IP64MPG v17 1.2.2009";
    Sim sim(Variant::Gve64, {}, {}, false, firmware);
    sim.config.unit.firmwareVersion = 17;
    sim.core.setConfig(sim.config);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    EXPECT_TRUE(sim.errors.empty()) << sim.lastLog();
    EXPECT_EQ(sim.core.state().firmwareVersion, 17);
    EXPECT_FALSE(sim.core.state().features.vlVkXmNa);
    EXPECT_TRUE(sim.core.state().features.mpg);

    auto program = denseProgram(50);
    machine::UnitCommand mode;
    mode.op = machine::UnitOp::SpeedModeVk;
    program.commands.insert(program.commands.begin(), mode);
    auto refused = sim.core.run(program, sim.runner.now());
    ASSERT_TRUE(refused);
    EXPECT_NE(refused->message.find("VK"), std::string::npos) << refused->message;
    mode.op = machine::UnitOp::SpeedModeVn;
    program.commands.set(0, mode);
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 60)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front()) << sim.lastLog();
    EXPECT_EQ(sim.port.unit().position()[0], program.commands.back().endSteps[0]);
    EXPECT_TRUE(sim.errors.empty()) << sim.lastLog();

    auto xm = sim.core.setOverride(120, sim.runner.now());
    ASSERT_TRUE(xm);
    EXPECT_NE(xm->message.find("v19"), std::string::npos) << xm->message;
}

// Homing on v17: one axis alone is refused (its counter cannot be set by itself); all axes with
// home position 0 end with N, every counter 0.
TEST(MachineCore, OlderFirmwareHomesWithN)
{
    Sim sim(Variant::Gve64, {}, {}, true, "IP64MPG v17 1.2.2009");
    sim.config.unit.firmwareVersion = 17;
    for (auto &ax : sim.config.axes)
        ax.homing.homePositionMm = 0;
    sim.config.axes[3].present = false; // the profile homes X, Y and Z; N also zeroes A
    sim.core.setConfig(sim.config);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    auto one = sim.core.home(sim.runner.now(), 0x1);
    ASSERT_TRUE(one);
    EXPECT_NE(one->message.find("N<axis>"), std::string::npos) << one->message;
    const auto homing = sim.core.home(sim.runner.now());
    ASSERT_FALSE(homing) << homing->message;
    ASSERT_TRUE(sim.runner.runUntil(
        [&] { return sim.core.state().mode == MachineMode::Idle && sim.core.state().homed; }, 120))
        << sim.lastLog();
    EXPECT_TRUE(sim.errors.empty()) << sim.lastLog();
    for (int a = 0; a < sim.core.state().axisCount; ++a)
        EXPECT_EQ(sim.port.unit().position()[a], 0) << "axis " << a;
    bool sawN = false;
    for (const std::string &line : sim.log)
        sawN = sawN || line.rfind("> !0N,", 0) == 0 || line == "> !0N";
    EXPECT_TRUE(sawN) << sim.lastLog(60);
}

TEST(MachineCore, FirmwareOlderThanTheProfileIsAnAlarm)
{
    Sim sim(Variant::Gve64, {}, {}, false, "IP64MPG v17 1.2.2009"); // the profile says v19
    sim.connect();
    ASSERT_TRUE(sim.until(MachineMode::Alarm)) << sim.lastLog();
    ASSERT_FALSE(sim.errors.empty());
    EXPECT_NE(sim.errors.front().message.find("unit.firmwareVersion to 17"), std::string::npos)
        << sim.errors.front().message;
    for (const std::string &line : sim.log)
        EXPECT_EQ(line.find("unknown command"), std::string::npos) << line;
}

// Before IP64MPG v10 a GVE64 has no W (manual §14.1): homing is refused with the reason and
// nothing reaches the wire; the unit's counters stay where they were.
TEST(MachineCore, FirmwareBeforeV10RefusesHomingToASwitch)
{
    Sim sim(Variant::Gve64, {}, {}, false, "IP64 v9 1.2.2008");
    sim.config.unit.firmwareVersion = 9;
    sim.config.eeprom.mpg = machine::MpgMode::Off;
    sim.config.eeprom.sync = false;
    sim.core.setConfig(sim.config);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    EXPECT_TRUE(sim.errors.empty()) << sim.lastLog();
    EXPECT_FALSE(sim.core.state().features.switchHoming);
    const auto refused = sim.core.home(sim.runner.now());
    ASSERT_TRUE(refused);
    EXPECT_NE(refused->message.find("has no W"), std::string::npos) << refused->message;
    sim.runner.runFor(1.0);
    for (const std::string &line : sim.log)
        EXPECT_EQ(line.rfind("> !0W", 0), std::string::npos) << line;
    EXPECT_FALSE(sim.core.state().homed);
}

// A GVE114 profile at 921 600 Bd needs the unit's EEPROM 0x0D = 01: connecting to a unit set
// for the low range names the byte among the differences, and writing (asked) sets it.
TEST(MachineCore, Gve114FastBaudRangeIsCheckedAndWrittenWhenAsked)
{
    Sim sim(Variant::Gve114);
    sim.config.link.baud = 921600;
    sim.core.setConfig(sim.config);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    EXPECT_EQ(sim.port.unit().eepromByte(0x0D), 0xFF);
    bool named = false;
    for (const EepromDifference &d : sim.core.state().eepromDifferences)
        named = named || d.text().find("baud range") != std::string::npos;
    EXPECT_TRUE(named) << sim.lastLog();
    ASSERT_FALSE(sim.core.writeEeprom(sim.runner.now()));
    sim.runner.runFor(2.0);
    EXPECT_EQ(sim.port.unit().eepromByte(0x0D), 0x01);
    EXPECT_TRUE(sim.errors.empty()) << sim.errors.front().message;
}
