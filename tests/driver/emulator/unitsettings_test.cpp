// The EEPROM readings of driver/emulator/unitsettings.h (issue 20 item 3), each pinned to the
// manual's example or table it follows (docs/emulator.md, "EEPROM-driven behaviour").
#include "driver/emulator/unit.h"
#include "driver/emulator/unitsettings.h"

#include <gtest/gtest.h>

namespace frezka::emulator {
namespace {

using protocol::Variant;

// GVE114 manual 11.5: 0xAC = "X,Y falling edge, Z,A rising, X reversed, Y normal, Z reversed,
// A normal".
TEST(UnitSettings, StepDirOfTheGve114ManualsExample)
{
    Eeprom e(Variant::Gve114);
    e.setByte(0x05, 0xAC);
    const UnitSettings s = decodeSettings(e, Variant::Gve114, 50000);
    EXPECT_EQ(s.stepRisingEdge, (std::array<bool, 4>{false, false, true, true}));
    EXPECT_EQ(s.dirReversed, (std::array<bool, 4>{true, false, true, false}));
}

// GVE64 manual 11.5: bits 0-3 DIR X..A, bit 4 STEP (set = falling edge); default FF.
TEST(UnitSettings, StepDirOfTheGve64)
{
    Eeprom e(Variant::Gve64);
    EXPECT_EQ(decodeSettings(e, Variant::Gve64, 50000).dirReversed,
              (std::array<bool, 4>{false, false, false, false}));
    e.setByte(0x05, 0xEB); // bit 2 (Z) and bit 4 (STEP) cleared
    const UnitSettings s = decodeSettings(e, Variant::Gve64, 50000);
    EXPECT_EQ(s.dirReversed, (std::array<bool, 4>{false, false, true, false}));
    EXPECT_TRUE(s.stepRisingEdge[0]);
}

// GVE114 manual 10.1: the two tables of the COM SPEED switch.
TEST(UnitSettings, BaudRangeTables)
{
    EXPECT_EQ(switchBaud(0, false), 19200);
    EXPECT_EQ(switchBaud(1, false), 38400);
    EXPECT_EQ(switchBaud(2, false), 57600);
    EXPECT_EQ(switchBaud(3, false), 115200);
    EXPECT_EQ(switchBaud(0, true), 921600);
    EXPECT_EQ(switchBaud(1, true), 460800);
    EXPECT_EQ(switchBaud(2, true), 230400);
    EXPECT_EQ(switchBaud(3, true), 115200);
    EXPECT_EQ(switchPositionFor(460800), 1);
    EXPECT_EQ(switchPositionFor(12345), -1);
    Eeprom e(Variant::Gve114);
    e.setByte(0x0D, 0x01);
    EXPECT_TRUE(decodeSettings(e, Variant::Gve114, 50000).highBaudRange);
    EXPECT_FALSE(decodeSettings(e, Variant::Gve64, 50000).highBaudRange) << "GVE114 only";
}

// Manuals 10.2/11.3 with the adopted reading of the breakout signal (inverted level).
TEST(UnitSettings, AnalogOutput)
{
    EXPECT_DOUBLE_EQ(analogOutput(300, AnalogJumper::Analog, false), 3.0);
    EXPECT_DOUBLE_EQ(analogOutput(300, AnalogJumper::Pwm, false), 30.0);
    EXPECT_DOUBLE_EQ(analogOutput(300, AnalogJumper::Analog, true), 7.0);
    EXPECT_DOUBLE_EQ(analogOutput(300, AnalogJumper::Pwm, true), 70.0);
}

// Manuals 12.4-12.7: a parameter out of range disables the MPG.
TEST(UnitSettings, MpgParametersOutOfRangeDisableIt)
{
    Eeprom e(Variant::Gve64);
    e.setByte(0x06, 0x01);
    EXPECT_TRUE(decodeSettings(e, Variant::Gve64, 50000).mpg.enabled);
    e.setByte(0x06, 0x81);
    EXPECT_FALSE(decodeSettings(e, Variant::Gve64, 50000).mpg.enabled) << "81 is the GVE114's";
    e.setByte(0x06, 0x01);
    e.writeUint32(0x48, 0); // delay 1..2000 ms
    EXPECT_FALSE(decodeSettings(e, Variant::Gve64, 50000).mpg.enabled);
    e.writeUint32(0x48, 100);
    e.writeFloat(0x44, 300.0f); // 300 mm/s x 100 steps/mm > half of 50 000 pulses/s
    EXPECT_FALSE(decodeSettings(e, Variant::Gve64, 50000).mpg.enabled);
    e.writeFloat(0x44, 10.0f);
    e.writeFloat(0x34, 0.5f); // steps per mm 1..10 000
    EXPECT_FALSE(decodeSettings(e, Variant::Gve64, 50000).mpg.enabled);
}

// Manuals 11.1/11.2, 11.4, 12.2: output functions, the brake delay (at most 5 s), A slaving.
TEST(UnitSettings, OutputsBrakeDelayAndSlaving)
{
    Eeprom e(Variant::Gve64);
    e.setByte(0x02, 0x09);
    e.setByte(0xFD, 80);
    e.setByte(0x0C, 0x02);
    const UnitSettings s = decodeSettings(e, Variant::Gve64, 50000);
    EXPECT_EQ(s.outputFunction[1], OutputFunction::InterruptSignal);
    EXPECT_EQ(s.outputFunction[2], OutputFunction::Brake) << "factory OUT3";
    EXPECT_DOUBLE_EQ(s.brakeReleaseDelayS, 5.0);
    EXPECT_EQ(s.aSlavedTo, 1);
    e.setByte(0x0C, 0x04);
    EXPECT_EQ(decodeSettings(e, Variant::Gve64, 50000).aSlavedTo, -1);
}

// The machine is wired for the EEPROM the unit starts with: a DIR bit preset (the built-in
// emulator of a profile with an inverted axis) runs with the counter; changing it reverses.
TEST(UnitSettings, DirIsAgainstTheWiringOfTheStartingEeprom)
{
    UnitOptions o{.variant = Variant::Gve64};
    o.eepromPreset = {{0x05, EepromPreset::Kind::Byte, 0xFE}}; // X's DIR cleared
    Unit unit(o);
    unit.receive("!0Y-\r!0L100,0,0\r");
    while (unit.nextEventIn() < kNever)
        unit.advance(unit.nextEventIn());
    EXPECT_EQ(unit.position()[0], 100);
    EXPECT_EQ(unit.motorPosition()[0], 100);
    unit.receive("!0EW05,FF\r");
    EXPECT_EQ(unit.motorPosition()[0], -100);
}

} // namespace
} // namespace frezka::emulator
