// EEPROM-driven behaviour of the emulated unit (issue 20 item 3), outputs and axes: each test
// writes the setting through the driver and asserts what the unit does (relays, analog output,
// motors, line speed), which differs from what it did with the byte before.
#include "eeprombehaviour.h"

#include <gtest/gtest.h>

namespace frezka::driver::test {
namespace {

using machine::OutputFunction;
constexpr std::uint8_t kOut3 = 0x02; // port 0 bit of OUT3 (§10), active low

bool relayOn(Sim &sim, std::uint8_t bit)
{
    return !(sim.port.unit().relays() & bit);
}

// 0x01..0x03 = 09 (manuals 11.2): the output signals an accepted interrupt by itself.
TEST(EepromBehaviour, AnOutputSetToInterruptSignalFollowsInta)
{
    Sim sim;
    sim.config.eeprom.interruptEnable = 0x80; // STOP on IN7 stops motion (ST0 on connect)
    sim.config.eeprom.polarity = 0x80;        // pressed reads 1
    sim.core.setConfig(sim.config);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_TRUE(writeThroughDriver(
        sim, [](machine::MachineConfig &c) { c.outputs.out[2] = OutputFunction::Interrupt; }));
    EXPECT_EQ(sim.port.unit().eepromByte(0x03), 0x09);
    EXPECT_FALSE(relayOn(sim, kOut3));
    sim.port.unit().setStopButton(true);
    sim.runner.runFor(0.2);
    EXPECT_TRUE(sim.port.unit().status(6) & 0x80) << "INTA";
    EXPECT_TRUE(relayOn(sim, kOut3)) << "OUT3 signals the interrupt";
}

// GVE84 0x01 (manual 000): the relay switches the spindle only as function 00.
TEST(EepromBehaviour, TheGve84RelaySwitchesTheSpindleOnlyAsItsFunction)
{
    Sim sim(protocol::Variant::Gve84);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_FALSE(sim.core.sendRaw("!0O0,FE", sim.runner.now()));
    sim.runner.runFor(0.5);
    EXPECT_TRUE(sim.port.unit().spindleTurning()) << "function 00: the spindle";
    ASSERT_FALSE(sim.core.sendRaw("!0O0,FF", sim.runner.now()));
    ASSERT_TRUE(writeThroughDriver(
        sim, [](machine::MachineConfig &c) { c.outputs.out[0] = OutputFunction::Coolant; }));
    EXPECT_EQ(sim.port.unit().eepromByte(0x01), 0x02);
    ASSERT_FALSE(sim.core.sendRaw("!0O0,FE", sim.runner.now()));
    sim.runner.runFor(0.5);
    EXPECT_FALSE(sim.port.unit().spindleTurning()) << "the relay now switches the coolant";
    EXPECT_FALSE(sim.port.unit().relays() & 0x01) << "the relay itself is on";
}

// 0x03 = 08 and 0xFD (manuals 11.1, 11.2): the brake output is released by the unit the
// delay after power-on, whatever O0 says.
TEST(EepromBehaviour, TheBrakeOutputIsReleasedTheDelayAfterPowerOn)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_TRUE(writeThroughDriver(sim, [](machine::MachineConfig &c) {
        c.outputs.out[2] = OutputFunction::Brake;
        c.eeprom.brakeReleaseDelayS = 2.0;
    }));
    EXPECT_EQ(sim.port.unit().eepromByte(0xFD), 20);
    sim.port.unit().powerCycle();
    sim.port.unit().advance(1.9);
    EXPECT_FALSE(relayOn(sim, kOut3)) << "still braked 1.9 s after power-on";
    sim.port.unit().advance(0.2);
    EXPECT_TRUE(relayOn(sim, kOut3)) << "released 2 s after power-on";
    EXPECT_EQ(sim.port.unit().outputs(), 0xFF) << "without any O0 from the PC";
}

// 0x04 (manuals 10.2, 11.3): the breakout-board signal on the ANA jumper is the inverted level.
TEST(EepromBehaviour, PwmModeChangesTheAnalogOutput)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_FALSE(sim.core.setSpindleRpm(0.3 * sim.config.spindle.maxRpm, sim.runner.now()));
    sim.runner.runFor(0.5);
    const int permille = sim.port.unit().spindlePermille();
    ASSERT_GT(permille, 100);
    ASSERT_LT(permille, 450);
    EXPECT_NEAR(sim.port.unit().analogOutput(), permille / 100.0, 1e-9) << "0-10 V";
    ASSERT_TRUE(
        writeThroughDriver(sim, [](machine::MachineConfig &c) { c.eeprom.pwmBreakout = true; }));
    EXPECT_EQ(sim.port.unit().eepromByte(0x04), 0x01);
    EXPECT_NEAR(sim.port.unit().analogOutput(), 10.0 - permille / 100.0, 1e-9);
}

// 0x05 DIR (manuals 11.5): a reversed axis' motor runs against its counter, so the switches
// on the machine are met on the other side.
TEST(EepromBehaviour, ReversedDirMovesTheMotorAgainstTheCounter)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    // A limit switch on IN6, pressed while the X motor stands at or beyond +300 steps.
    sim.port.unit().setSwitches({{6, 0, 300, +1}});
    ASSERT_FALSE(sim.core.jogStep(0, 2, 600, sim.runner.now())); // +400 steps
    ASSERT_TRUE(sim.until(MachineMode::Idle, 30)) << sim.lastLog();
    EXPECT_EQ(sim.port.unit().motorPosition()[0], 400);
    EXPECT_TRUE(sim.port.unit().input(6));
    ASSERT_TRUE(writeThroughDriver(
        sim, [](machine::MachineConfig &c) { c.axes[0].invertDirection = true; }));
    EXPECT_EQ(sim.port.unit().eepromByte(0x05), 0xFE);
    ASSERT_FALSE(sim.core.jogStep(0, 2, 600, sim.runner.now())); // the counter to +800
    ASSERT_TRUE(sim.until(MachineMode::Idle, 30)) << sim.lastLog();
    EXPECT_EQ(sim.port.unit().position()[0], 800);
    EXPECT_EQ(sim.port.unit().motorPosition()[0], -800);
    EXPECT_FALSE(sim.port.unit().input(6)) << "the motor went the other way";
}

// 0x0C (manuals 11.4): A slaved to X runs with X.
TEST(EepromBehaviour, ASlavedToXFollowsX)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_TRUE(writeThroughDriver(sim, [](machine::MachineConfig &c) { c.eeprom.aSlavedTo = 1; }));
    EXPECT_EQ(sim.port.unit().eepromByte(0x0C), 0x01);
    ASSERT_FALSE(sim.core.jogStep(0, 2, 600, sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Idle, 30)) << sim.lastLog();
    EXPECT_EQ(sim.port.unit().position()[0], 400);
    EXPECT_EQ(sim.port.unit().position()[3], 400) << "P4 reports A with X";
    EXPECT_EQ(sim.port.unit().motorPosition()[3], 400);
}

// 0x0D (GVE114 manual 10.1): the baud range is read with the COM SPEED switch at power-on.
TEST(EepromBehaviour, TheBaudRangeChangesTheLineSpeedAtPowerOn)
{
    WireOptions wire;
    wire.baud = 38400;
    Sim sim(protocol::Variant::Gve114, wire);
    sim.config.link.baud = 38400;
    sim.core.setConfig(sim.config);
    emulator::UnitOptions unit{.variant = protocol::Variant::Gve114};
    unit.baudSwitch = 1; // OFF ON: 38 400 Bd (FF), 460 800 Bd (01)
    sim.port.unit() = emulator::Unit(unit);
    ASSERT_EQ(sim.port.unit().lineBaud(), 38400);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_TRUE(writeThroughDriver(sim, [](machine::MachineConfig &c) { c.link.baud = 460800; }));
    EXPECT_EQ(sim.port.unit().eepromByte(0x0D), 0x01);
    EXPECT_EQ(sim.port.unit().lineBaud(), 38400) << "the switch is read at power-on only";
    sim.port.unit().powerCycle();
    EXPECT_EQ(sim.port.unit().lineBaud(), 460800);
    ASSERT_TRUE(sim.until(MachineMode::LinkLost, 30)) << "the PC at 38 400 Bd hears nothing\n"
                                                      << sim.lastLog();
}

} // namespace
} // namespace frezka::driver::test
