// Identification, reset state, replies and the command set of every variant.

#include "emulator_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace frezka::emulator;
using namespace frezka::emulator::test;
using frezka::protocol::allVariants;
using frezka::protocol::VariantInfo;

class EveryVariant : public ::testing::TestWithParam<Variant>
{
};

INSTANTIATE_TEST_SUITE_P(Unit, EveryVariant,
                         ::testing::Values(Variant::Gve84, Variant::Gve64, Variant::Gve64Phantom,
                                           Variant::Gve114),
                         [](const auto &info) {
                             std::string id(frezka::protocol::variantInfo(info.param).id);
                             std::erase(id, '-');
                             return id;
                         });

TEST_P(EveryVariant, IdentifiesItself)
{
    Unit unit(optionsFor(GetParam()));
    const VariantInfo &info = unit.variantInfo();
    EXPECT_EQ(ask(unit, "!0?\r"), "0," + std::string(info.firmware) + "\r");
    EXPECT_EQ(ask(unit, "!0Q\r"), "0," + std::string(info.defaultId) + "\r");
}

// docs/gve-protocol.md §3.
TEST_P(EveryVariant, ResetState)
{
    Unit unit(optionsFor(GetParam()));
    const VariantInfo &info = unit.variantInfo();
    for (int n = 0; n <= 5; ++n)
        EXPECT_EQ(ask(unit, "!0SR" + std::to_string(n) + "\r"), "0,00\r") << n;
    // GVE64/114 start in Y& (MPG on, silent): RUN=1 and vectors are refused until Y-.
    EXPECT_EQ(ask(unit, "!0SR6\r"), info.hasMpg ? "0,40\r" : "0,00\r");
    EXPECT_EQ(ask(unit, "!0L10,0,0\r"), info.hasMpg ? "7\r" : "0\r");
    EXPECT_EQ(ask(unit, "!0P\r"), "0,0,0\r"); // nothing has moved yet
    EXPECT_EQ(unit.outputs(), 0xFF);
    EXPECT_FALSE(unit.checksumsOn());
    EXPECT_EQ(ask(unit, "!0@\r"), "0,9\r"); // nine commands so far
}

TEST_P(EveryVariant, ResetSpeedsAndModes)
{
    Unit unit = readyUnit(GetParam());
    const VariantInfo &info = unit.variantInfo();
    // A20 V1000 VN: a long L of 1000 steps accelerates 25 steps (0.05 s), cruises at 1000
    // pulses/s, brakes 25 steps: 1.05 s. Diagonal in VN: the major axis sets the time.
    EXPECT_EQ(ask(unit, "!0L1000,1000,0\r"), "0\r");
    runUntilIdle(unit);
    EXPECT_NEAR(unit.now(), 1.05, 1e-9);
    EXPECT_NEAR(unit.stats().motion.peakAxisSpeedPulsesPerS[0], 1000, 1e-9);
    // B after reset: a short vector ($ above its length) cruises at min(V, B).
    ask(unit, "!0V" + std::to_string(info.defaultMaxPulseRate) + "\r");
    ask(unit, "!0A10000\r");
    ask(unit, "!0$2000000\r");
    EXPECT_EQ(ask(unit, "!0L1000000,0,0\r"), "0\r");
    runUntilIdle(unit);
    EXPECT_NEAR(unit.stats().motion.peakAxisSpeedPulsesPerS[0],
                std::min(info.resetBrakeSpeed, info.defaultMaxPulseRate), 1e-6);
}

TEST_P(EveryVariant, QueueCapacity)
{
    Unit unit = readyUnit(GetParam());
    ask(unit, "!0V10\r");
    int accepted = 0;
    while (ask(unit, "!0C100,20,0\r") == "0\r")
        ++accepted;
    EXPECT_EQ(accepted, unit.variantInfo().queueCapacity);
    EXPECT_EQ(ask(unit, "!0C100,20,0\r"), "1\r");
    EXPECT_EQ(ask(unit, "!0F\r"), "0,60\r"); // RUN + queue full
}

TEST_P(EveryVariant, AxisCountRules)
{
    Unit unit = readyUnit(GetParam());
    const bool four = unit.variantInfo().axisCount == 4;
    EXPECT_EQ(ask(unit, "!0L1,2\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0C1,2,3,4\r"), four ? "0\r" : "4\r");
    EXPECT_EQ(ask(unit, "!0C1,2,3,4,5\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0P4\r"), four ? "0,0,0,0,0\r" : "3\r");
    EXPECT_EQ(ask(unit, "!0VL1000,1000\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0VL1000,1000,1000,1000\r"), four ? "0\r" : "4\r");
    EXPECT_EQ(ask(unit, "!0NA5\r"), four ? "7\r" : "4\r"); // RUN=1: the C above is queued
}

TEST_P(EveryVariant, VariantOnlyCommands)
{
    Unit unit(optionsFor(GetParam()));
    const VariantInfo &info = unit.variantInfo();
    EXPECT_EQ(ask(unit, "!0Y-\r"), info.hasMpg ? "0,Y-\r" : "3\r");
    EXPECT_EQ(ask(unit, "!0EFR30\r"), info.hasEepromFloat ? "0,100\r" : "3\r");
    EXPECT_EQ(ask(unit, "!0I2\r"), info.variant == Variant::Gve84 ? "3\r" : "0,00\r");
    EXPECT_EQ(ask(unit, "!7?\r"),
              info.hasSpindleAddress7 ? "0," + std::string(info.firmware) + "\r" : "");
}

TEST(Unit, ManualReplyTable)
{
    // docs/gve-protocol.md §2 examples.
    Unit unit = readyUnit(Variant::Gve64);
    EXPECT_EQ(ask(unit, "!0L1000,0,0\r"), "0\r");
    runUntilIdle(unit);
    EXPECT_EQ(ask(unit, "!0NX-1000\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0NY2000\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0NZ50\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0PF\r"), "0,-1000,2000,50\r");
    EXPECT_EQ(ask(unit, "!0SW8,F1\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0SW2,2B\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0SR2\r"), "0,2B\r");
    ask(unit, "!0V10\r");
    while (ask(unit, "!0C1,0,0\r") == "0\r") {
    }
    EXPECT_EQ(ask(unit, "!0C100,20,0\r"), "1\r");
    unit.advance(0.05); // under way (after the 10 ms pause that follows the L)
    EXPECT_EQ(ask(unit, "!0H\r"), "");
    runUntilIdle(unit);
    EXPECT_EQ(unit.takeTransmit(), "8\r");
    EXPECT_EQ(ask(unit, "!0V1000\r"), "8\r"); // OK, INTA=1
    EXPECT_EQ(ask(unit, "!0SW8,F1\r"), "D\r");
}

TEST(Unit, UnknownCommandsSyntaxAndRange)
{
    Unit unit = readyUnit(Variant::Gve64);
    EXPECT_EQ(ask(unit, "!0ZZ\r"), "3\r");
    EXPECT_EQ(ask(unit, "!0\r"), "3\r");
    EXPECT_EQ(ask(unit, "!0Vabc\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0V\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0V9\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0V50001\r"), "5\r"); // above the unit's 50 000 pulses/s
    EXPECT_EQ(ask(unit, "!0V50000\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0V99999999999999999999999999\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0V1,2\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0L2147483648,0,0\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0L-2147483648,0,0\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0L1,x,0\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0L1,,0\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0T0\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0T25\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0T24\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0$0\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0$4294967295\r"), "0\r"); // GVE64 range
    EXPECT_EQ(ask(unit, "!0A0\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0B5\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0XQ\r"), "3\r");
    EXPECT_EQ(ask(unit, "!0XM0\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0O1,FF\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0O0,1FF\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0O0,G\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0SR7\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0SRx\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0HX\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0Y*\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0NQ5\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0I3\r"), "3\r");
}

TEST(Unit, Gve84ShortThresholdRange)
{
    Unit unit = readyUnit(Variant::Gve84);
    EXPECT_EQ(ask(unit, "!0$2147483647\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0$2147483648\r"), "5\r");
}

TEST(Unit, OutputsAndSpindle)
{
    Unit unit = readyUnit(Variant::Gve64);
    EXPECT_EQ(ask(unit, "!0O0,FB\r"), "0\r"); // coolant on (OUT1, active low)
    EXPECT_EQ(unit.outputs(), 0xFB);
    EXPECT_EQ(ask(unit, "!7V300\r"), "0\r");
    EXPECT_EQ(unit.spindlePermille(), 300);
    EXPECT_EQ(unit.outputs(), 0xFA); // OUT0 switched on with the spindle
    EXPECT_EQ(ask(unit, "!7V0\r"), "0\r");
    EXPECT_EQ(unit.outputs(), 0xFB);
    EXPECT_EQ(ask(unit, "!7V1001\r"), "5\r");
    EXPECT_EQ(ask(unit, "!7L1,0,0\r"), "3\r"); // address 7 is not the interpolator
    EXPECT_EQ(ask(unit, "!7VL1,2,3\r"), "3\r");
    EXPECT_EQ(ask(unit, "!0V500\r"), "0\r"); // !0V500 is not !7V500
    EXPECT_EQ(unit.spindlePermille(), 0);
    EXPECT_EQ(ask(unit, "!0O0,FF\r"), "0\r");
    EXPECT_EQ(unit.outputs(), 0xFF);
}

TEST(Unit, OnlyTheAddressedUnitAnswers)
{
    UnitOptions o = optionsFor(Variant::Gve114);
    o.address = 2;
    Unit unit(o);
    EXPECT_EQ(ask(unit, "!0?\r"), "");
    EXPECT_EQ(ask(unit, "!3Q\r"), "");
    EXPECT_EQ(ask(unit, "!2Q\r"), "0,16091801\r");
    EXPECT_EQ(ask(unit, "!7?\r"), "0,IP114/500 x16 16.9.2018\r");
    EXPECT_EQ(ask(unit, "!2@\r"), "0,2\r"); // only its own commands count
    Unit gve84(optionsFor(Variant::Gve84));
    EXPECT_EQ(ask(gve84, "!7V300\r"), ""); // no spindle address on the GVE84
}

TEST(Unit, JumpResetsAfterTwoSeconds)
{
    Unit unit = readyUnit(Variant::Gve64);
    ask(unit, "!0L100,0,0\r");
    runUntilIdle(unit);
    ask(unit, "!0%+\r");
    EXPECT_EQ(ask(unit, withChecksum("!0J")), "0,5C\r"); // answered before the reset
    EXPECT_EQ(ask(unit, "!0?\r"), "");                   // deaf while it restarts
    unit.advance(1.999);
    EXPECT_EQ(ask(unit, "!0?\r"), "");
    unit.advance(0.002);
    EXPECT_EQ(ask(unit, "!0P\r"), "0,0,0\r"); // counters zero, checksums off
    EXPECT_EQ(ask(unit, "!0@\r"), "0,1\r");
    EXPECT_EQ(ask(unit, "!0L1,0,0\r"), "7\r"); // Y& again
    EXPECT_GT(unit.stats().discardedBytes, 0);
}

TEST(Unit, MpgRefusesVectorsUntilYMinus)
{
    Unit unit(optionsFor(Variant::Gve114));
    EXPECT_EQ(ask(unit, "!0C1,0,0\r"), "7\r");
    EXPECT_EQ(ask(unit, "!0L1,0,0\r"), "7\r");
    EXPECT_EQ(ask(unit, "!0N\r"), "7\r");
    EXPECT_EQ(ask(unit, "!0WX,-100,1000,10,100\r"), "7\r");
    EXPECT_EQ(ask(unit, "!0Y+\r"), "0,Y+\r");
    EXPECT_EQ(ask(unit, "!0SR6\r"), "0,40\r");
    EXPECT_EQ(ask(unit, "!0C1,0,0\r"), "7\r");
    EXPECT_EQ(ask(unit, "!0Y-\r"), "0,Y-\r");
    EXPECT_EQ(ask(unit, "!0SR6\r"), "0,00\r");
    EXPECT_EQ(ask(unit, "!0V10\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0C100,0,0\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0Y&\r"), "7,Y&\r"); // not while vectors run
    EXPECT_EQ(unit.takeTransmit(), "");
    EXPECT_EQ(unit.stats().motion.vectorsExecuted, 0);
}

// An older GVE64 firmware (§1): below v19 no VL/VK/VN/XM/N<axis>, below v10 no MPG and no
// EEPROM float/uint32 commands; the '?' reply is the given string.
TEST(OlderFirmware, AnswersUnknownToWhatItLacks)
{
    UnitOptions o = optionsFor(Variant::Gve64);
    o.firmware = "IP64MPG v17 1.2.2009";
    Unit v17(o);
    EXPECT_EQ(ask(v17, "!0?\r"), "0,IP64MPG v17 1.2.2009\r");
    EXPECT_EQ(ask(v17, "!0Y-\r"), "0,Y-\r");
    for (const char *c : {"!0VK\r", "!0VN\r", "!0VL1000,1000,1000\r", "!0XM120\r", "!0NX0\r"})
        EXPECT_EQ(ask(v17, c), "3\r") << c;
    EXPECT_EQ(ask(v17, "!0N\r"), "0\r");
    EXPECT_EQ(ask(v17, "!0XA\r"), "0\r");
    EXPECT_EQ(ask(v17, "!0EFR30\r").front(), '0');

    o.firmware = "IP64 v9 1.2.2008";
    Unit v9(o);
    EXPECT_EQ(ask(v9, "!0Y-\r"), "3\r");
    EXPECT_EQ(ask(v9, "!0EFR30\r"), "3\r");
    EXPECT_EQ(ask(v9, "!0ER30\r").front(), '0');
    // Without an MPG the reset state does not hold RUN: vectors are taken at once.
    EXPECT_EQ(ask(v9, "!0C100,0,0\r"), "0\r");
}
