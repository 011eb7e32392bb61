// Several units on one line (Simulation with moreUnits, GVE114 manual §9.5): each unit answers
// only its own address, keeps its own counters, index and EEPROM; address 7 belongs to the one
// unit that has the spindle; a command for an address nobody has gets no reply; and the units
// share the wire's time.

#include "emulator_test_util.h"

#include "driver/emulator/simulation.h"

#include <gtest/gtest.h>

using namespace frezka::emulator;
using namespace frezka::emulator::test;

namespace {

SimulationOptions twoGve114()
{
    SimulationOptions o;
    o.unit.variant = Variant::Gve114;
    o.unit.address = 0;
    UnitOptions second = o.unit;
    second.address = 1;
    second.spindleAddress = false; // the spindle at 7 is unit 0's
    o.moreUnits.push_back(second);
    return o;
}

// Sends a command and reads the one line that comes back within a second ("" when none).
std::string talk(Simulation &sim, const std::string &command)
{
    sim.pcWrite(command);
    std::string line = sim.pcReadLine(1.0);
    return line.find('\r') == std::string::npos ? std::string() : line;
}

void runUntilStill(Simulation &sim)
{
    for (int i = 0; i < 100000 && (sim.unit(0).isMoving() || sim.unit(1).isMoving()); ++i)
        sim.advance(std::min(sim.nextEventIn(), 0.5));
}

} // namespace

TEST(SharedLine, EachUnitAnswersOnlyItsAddress)
{
    Simulation sim(twoGve114());
    ASSERT_EQ(sim.unitCount(), 2u);
    EXPECT_EQ(talk(sim, "!0Y-\r"), "0,Y-\r");
    EXPECT_EQ(talk(sim, "!1Y-\r"), "0,Y-\r");
    // Different moves on the two addresses: each unit runs its own, nothing of the other's.
    EXPECT_EQ(talk(sim, "!0L100,0,0\r"), "0\r");
    EXPECT_EQ(talk(sim, "!1L0,-250,30\r"), "0\r");
    runUntilStill(sim);
    EXPECT_EQ(sim.unit(0).position(), (std::array<std::int64_t, 4>{100, 0, 0, 0}));
    EXPECT_EQ(sim.unit(1).position(), (std::array<std::int64_t, 4>{0, -250, 30, 0}));
    EXPECT_EQ(talk(sim, "!1P4\r"), "0,0,-250,30,0\r");
    EXPECT_EQ(talk(sim, "!0P4\r"), "0,100,0,0,0\r");
    // Each unit counts only the commands to it: its own index (§8).
    EXPECT_EQ(talk(sim, "!0@\r"), "0,3\r");
    EXPECT_EQ(talk(sim, "!1@\r"), "0,3\r");
    EXPECT_EQ(sim.unit(0).stats().commands, 4);
    EXPECT_EQ(sim.unit(1).stats().commands, 4);
    // Checksums on one unit only: the other still talks plain.
    EXPECT_EQ(talk(sim, "!1%+\r"), "0,5C\r");
    EXPECT_TRUE(sim.unit(1).checksumsOn());
    EXPECT_FALSE(sim.unit(0).checksumsOn());
    // EEPROM per unit.
    EXPECT_EQ(talk(sim, withChecksum("!1EW05,AC")), "0,5C\r");
    EXPECT_EQ(sim.unit(1).eepromByte(0x05), 0xAC);
    EXPECT_NE(sim.unit(0).eepromByte(0x05), 0xAC);
}

TEST(SharedLine, NobodyAnswersAnAddressNobodyHas)
{
    Simulation sim(twoGve114());
    EXPECT_EQ(talk(sim, "!3?\r"), "");
    EXPECT_EQ(sim.unit(0).stats().commands, 0);
    EXPECT_EQ(sim.unit(1).stats().commands, 0);
    // A garbled address byte ('!' then 0x31 ^ 0x40 = 'q') is no command for anybody.
    EXPECT_EQ(talk(sim, "!qP4\r"), "");
    EXPECT_EQ(talk(sim, "!1?\r"), "0,IP114/500 x16 16.9.2018\r");
    EXPECT_EQ(sim.unit(0).stats().commands, 0);
}

TEST(SharedLine, TheSpindleAtSevenIsTheUnitThatHasIt)
{
    Simulation sim(twoGve114());
    EXPECT_EQ(talk(sim, "!7V500\r"), "0\r"); // one reply, not two
    EXPECT_EQ(sim.pcReadLine(0.5), "");
    EXPECT_EQ(sim.unit(0).spindlePermille(), 500);
    EXPECT_EQ(sim.unit(1).spindlePermille(), 0);
    EXPECT_EQ(sim.unit(1).stats().commands, 0);
}

TEST(SharedLine, UnitsShareTheWiresTime)
{
    // Both units answer at once (a unit answering out of turn is simulated by a second write):
    // the replies follow each other on the one line, the second after the first's bytes.
    SimulationOptions o = twoGve114();
    o.wire.baud = 19200;
    Simulation sim(o);
    const double byteTime = 10.0 / 19200;
    sim.pcWrite("!0?\r");
    sim.advance(4 * byteTime + 1e-9); // the command has arrived, the reply starts now
    sim.unitSideWrite("0\r");         // another unit talks at the same time
    const std::string reply = "0,IP114/500 x16 16.9.2018\r";
    sim.advance(static_cast<double>(reply.size()) * byteTime);
    EXPECT_EQ(sim.pcRead(), reply); // the foreign bytes queue behind the reply
    sim.advance(2 * byteTime);
    EXPECT_EQ(sim.pcRead(), "0\r");
}
