// MachineState's logical inputs and outputs (issue 13 item 3): the ports decoded once, in the
// driver, as the window's lamps and buttons show them.
#include "driver/link/machinestate.h"

#include <gtest/gtest.h>

namespace frezka::driver {
namespace {

TEST(MachineStateIo, InputsByNumber)
{
    MachineState s;
    s.inputs1 = 0x09; // IN0, IN3
    s.inputs2 = 0xBF; // bit6 IN14 low, bit7 IN15 high; the other bits are no inputs
    EXPECT_EQ(s.inputLevels(), 0x8009);
    machine::MachineConfig c = machine::defaultMachineConfig(protocol::Variant::Gve64);
    c.eeprom.polarity = 0x08;     // IN3 active high, the rest active low
    c.eeprom.polarityHigh = 0x00; // IN14, IN15 active low
    EXPECT_FALSE(s.inputActive(c, 0));
    EXPECT_TRUE(s.inputActive(c, 1));
    EXPECT_TRUE(s.inputActive(c, 3));
    EXPECT_TRUE(s.inputActive(c, 14));
    EXPECT_FALSE(s.inputActive(c, 15));
}

TEST(MachineStateIo, OutputsByNumberAndFunction)
{
    MachineState s;
    EXPECT_EQ(s.outputsOn(), 0);                         // port 0 all high: all off
    s.outputs = static_cast<std::uint8_t>(~0x02 & 0xFF); // bit1 low: OUT3
    EXPECT_EQ(s.outputsOn(), 0x08);
    s.outputs = static_cast<std::uint8_t>(~0x0C & 0xFF); // bit2 OUT1, bit3 OUT2
    EXPECT_EQ(s.outputsOn(), 0x06);
    s.spindleOn = true; // !7V: OUT0 on in the unit as well
    EXPECT_EQ(s.outputsOn(), 0x07);
    // The default GVE64 profile: OUT1 coolant, OUT2 air blow, OUT3 brake.
    const machine::MachineConfig c = machine::defaultMachineConfig(protocol::Variant::Gve64);
    EXPECT_TRUE(s.outputOn(c, machine::OutputFunction::Coolant));
    EXPECT_TRUE(s.outputOn(c, machine::OutputFunction::AirBlow));
    EXPECT_FALSE(s.outputOn(c, machine::OutputFunction::Brake));
    EXPECT_FALSE(s.outputOn(c, machine::OutputFunction::Laser)); // no output carries it
}

// What the window's lamps and the jog panel read, one input, output or axis at a time.
TEST(MachineStateIo, InputsOutputsAndHomedAxesOneByOne)
{
    MachineState s;
    s.inputs1 = 0x09; // IN0, IN3
    s.inputs2 = 0x80; // IN15
    for (int n = 0; n < 16; ++n)
        EXPECT_EQ(s.inputHigh(n), n == 0 || n == 3 || n == 15) << "IN" << n;
    EXPECT_FALSE(s.inputHigh(-1));
    EXPECT_FALSE(s.inputHigh(16));
    s.outputs = static_cast<std::uint8_t>(~0x0A & 0xFF); // bit1 OUT3, bit3 OUT2
    for (int n = 0; n < 4; ++n)
        EXPECT_EQ(s.outputIsOn(n), n == 2 || n == 3) << "OUT" << n;
    EXPECT_FALSE(s.outputIsOn(4));
    s.homedAxes = 0b0101; // X and Z
    EXPECT_TRUE(s.axisHomed(0));
    EXPECT_FALSE(s.axisHomed(1));
    EXPECT_TRUE(s.axisHomed(2));
    EXPECT_FALSE(s.axisHomed(3));
    EXPECT_FALSE(s.axisHomed(4));
}

} // namespace
} // namespace frezka::driver
