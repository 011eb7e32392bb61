// EEPROM-driven behaviour of the emulated unit (issue 20 item 3), the MPG handwheel, the
// interrupt masks of the unit's own moves and homing from an input: each test writes the
// setting through the driver, switches the MPG on through the driver, turns the simulated
// wheel and asserts the unit's counters, stops and status.
#include "eeprombehaviour.h"

#include <gtest/gtest.h>

namespace frezka::driver::test {
namespace {

using machine::MpgMode;

// 0x06 (manuals 12.2): the wheel moves the axis only with the MPG enabled in the EEPROM.
TEST(EepromMpg, TheWheelMovesOnlyWhenTheEepromEnablesTheMpg)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_TRUE(writeThroughDriver(sim, [](auto &c) { c.eeprom.mpg = MpgMode::Off; }));
    ASSERT_TRUE(mpgOn(sim));
    emulator::Unit &unit = sim.port.unit();
    EXPECT_FALSE(unit.turnWheel(10));
    sim.runner.runFor(1.0);
    EXPECT_EQ(unit.position()[0], 0);
    ASSERT_FALSE(sim.core.setMpg(false, sim.runner.now()));
    sim.runner.runFor(0.5);
    ASSERT_TRUE(writeThroughDriver(sim, [](auto &c) { c.eeprom.mpg = MpgMode::On; }));
    ASSERT_TRUE(mpgOn(sim));
    unit.setWheelMultiplier(10);
    EXPECT_TRUE(unit.turnWheel(10)); // 10 x 0.1 mm at 200 steps/mm
    sim.runner.runFor(2.0);
    EXPECT_EQ(unit.position()[0], 200);
    unit.setWheelAxis(1);
    unit.setWheelMultiplier(1);
    EXPECT_TRUE(unit.turnWheel(-7)); // 7 x 0.01 mm
    sim.runner.runFor(2.0);
    EXPECT_EQ(unit.position()[1], -14);
}

// 0x44 and 0x40 (manuals 12.6): the wheel's moves run at the MPG top speed.
TEST(EepromMpg, TheWheelRunsAtTheMpgTopSpeed)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_TRUE(writeThroughDriver(sim, [](auto &c) {
        c.eeprom.mpgMaxSpeedMmPerS = 5;
        c.eeprom.mpgDelayMs = 2000; // longer than the move
    }));
    ASSERT_TRUE(mpgOn(sim));
    emulator::Unit &unit = sim.port.unit();
    unit.setWheelMultiplier(100);
    ASSERT_TRUE(unit.turnWheel(2)); // 2 mm
    sim.runner.runFor(3.0);
    EXPECT_EQ(unit.position()[0], 400);
    EXPECT_NEAR(unit.stats().motion.peakAxisSpeedPulsesPerS[0], 5 * 200, 1e-6);
}

// 0x48 (manuals 12.7): when the wheel stops, the unit brakes after the delay even if steps
// remain.
TEST(EepromMpg, AfterTheMpgDelayTheUnitBrakesAndDropsTheRest)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_TRUE(writeThroughDriver(sim, [](auto &c) { c.eeprom.mpgDelayMs = 100; }));
    ASSERT_TRUE(mpgOn(sim));
    emulator::Unit &unit = sim.port.unit();
    unit.setWheelMultiplier(100);
    ASSERT_TRUE(unit.turnWheel(50)); // 50 mm at 20 mm/s: 2.5 s of travel
    sim.runner.runFor(4.0);
    EXPECT_GT(unit.position()[0], 0);
    EXPECT_LT(unit.position()[0], 5 * 200) << "braked 0.1 s after the last detent";
    EXPECT_EQ(unit.queueLength(), 0u);
    EXPECT_TRUE(unit.turnWheel(1)) << "the wheel works again";
}

// 0x06 = 02 (manuals 12.2, 12.4): with limits the wheel stops at the lower limit.
TEST(EepromMpg, WithLimitsTheWheelStaysWithinThem)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_TRUE(writeThroughDriver(sim, [](auto &c) { c.eeprom.mpg = MpgMode::OnWithLimits; }));
    ASSERT_TRUE(mpgOn(sim));
    emulator::Unit &unit = sim.port.unit();
    unit.setWheelMultiplier(10);
    ASSERT_TRUE(unit.turnWheel(3));
    ASSERT_TRUE(unit.turnWheel(-10)); // 0.3 mm up, then 1 mm down: stops at 0 (lower limit X)
    sim.runner.runFor(3.0);
    EXPECT_EQ(unit.position()[0], 0);
}

// 0x60 (GVE114 manual 12.9): the step multiplier scales the detent.
TEST(EepromMpg, TheStepMultiplierScalesTheDetentOnTheGve114)
{
    Sim sim(protocol::Variant::Gve114);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_TRUE(writeThroughDriver(sim, [](auto &c) { c.eeprom.mpgStepMultiplier = 0.1; }));
    ASSERT_TRUE(mpgOn(sim));
    emulator::Unit &unit = sim.port.unit();
    ASSERT_TRUE(unit.turnWheel(10)); // 10 x 0.001 mm at 400 steps/mm
    sim.runner.runFor(2.0);
    EXPECT_EQ(unit.position()[0], 4);
}

// 0x08 and 0x0A (manuals 12.3/12.4): the inputs that stop the unit's own moves, and at which
// level, are the EEPROM's; ST0..ST3 (set by the PC, here none) are not.
TEST(EepromMpg, TheEepromInterruptMasksStopTheWheelsMove)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_TRUE(writeThroughDriver(sim, [](auto &c) {
        c.eeprom.interruptEnable = 0x40; // IN6
        c.eeprom.polarity = 0x40;        // active at level 1
    }));
    ASSERT_EQ(sim.port.unit().status(0), 0x00) << "the PC's mask was set on connect";
    ASSERT_TRUE(mpgOn(sim));
    emulator::Unit &unit = sim.port.unit();
    unit.setWheelMultiplier(100);
    ASSERT_TRUE(unit.turnWheel(4)); // 4 mm at 20 mm/s
    sim.runner.runFor(0.1);
    unit.setInput(6, true);
    sim.runner.runFor(3.0);
    EXPECT_LT(unit.position()[0], 800) << "stopped by IN6";
    EXPECT_EQ(unit.status(4), 0x40) << "ST4: IN6 fired";
    EXPECT_TRUE(unit.status(6) & 0x80) << "INTA";
    EXPECT_FALSE(unit.turnWheel(1)) << "the wheel waits for G or D";
}

// 0x09 and 0x0B (manuals 12.3/12.4): IN14/IN15 in bits 6/7, their cause in ST5.
TEST(EepromMpg, TheHighInterruptMasksStopTheWheelsMoveByTheProbe)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_TRUE(writeThroughDriver(sim, [](auto &c) {
        c.eeprom.interruptEnableHigh = 0x80; // IN15
        c.eeprom.polarityHigh = 0x80;        // active at level 1
    }));
    ASSERT_TRUE(mpgOn(sim));
    emulator::Unit &unit = sim.port.unit();
    unit.setWheelAxis(2);
    unit.setWheelMultiplier(100);
    ASSERT_TRUE(unit.turnWheel(-4)); // Z 4 mm down
    sim.runner.runFor(0.1);
    unit.setProbe(true);
    sim.runner.runFor(3.0);
    EXPECT_GT(unit.position()[2], -800) << "stopped by the probe";
    EXPECT_EQ(unit.status(5), 0x80) << "ST5: IN15 fired";
}

// 0x07 (GVE64 manual 12.3): an input held for 1 s starts homing of the wheel's axis.
TEST(EepromMpg, AnInputHeldForASecondHomesTheWheelsAxis)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    emulator::Unit &unit = sim.port.unit();
    ASSERT_FALSE(sim.core.jogStep(0, 5, 600, sim.runner.now())); // X to +1000 steps
    ASSERT_TRUE(sim.until(MachineMode::Idle, 30)) << sim.lastLog();
    ASSERT_EQ(unit.position()[0], 1000);
    unit.setSwitches({{0, 0, 200, -1}}); // home X pressed at and below +200
    ASSERT_TRUE(writeThroughDriver(sim, [](auto &c) {
        c.eeprom.homingInput = 5;
        c.eeprom.interruptEnable = 0x20;
        c.eeprom.polarity = 0x20;
    }));
    ASSERT_TRUE(mpgOn(sim)); // Y&, as the driver parks a machine with a homing input
    unit.setInput(5, true);
    sim.runner.runFor(0.9);
    EXPECT_EQ(unit.position()[0], 1000) << "not before 1 s";
    sim.runner.runFor(10.0);
    EXPECT_EQ(unit.position()[0], 0) << "homed: the counter is the lower limit";
    EXPECT_TRUE(unit.status(6) & 0x40) << "the MPG is still on";
    sim.runner.runFor(3.0);
    EXPECT_EQ(unit.position()[0], 0) << "once per press";
}

} // namespace
} // namespace frezka::driver::test
