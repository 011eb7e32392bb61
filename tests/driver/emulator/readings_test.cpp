// One test per reading of readings.h: the adopted readings of docs/gve-protocol.md and the
// emulator's own choices. Each checks the behaviour through the unit, so a reading that is
// changed in readings.h but not followed (or followed elsewhere) fails here.

#include "emulator_test_util.h"

#include "driver/emulator/readings.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace frezka::emulator;
using namespace frezka::emulator::test;
namespace r = frezka::emulator::readings;

namespace {

char codeDigit(int code, bool inta = false)
{
    return "0123456789ABCDEF"[code | (inta ? 8 : 0)];
}

} // namespace

// §2
TEST(Readings, LineFeedAfterCr)
{
    Unit unit = readyUnit();
    unit.receive("!0Q\r\n");
    EXPECT_EQ(unit.takeTransmit(), "0,25020304\r");
    EXPECT_EQ(unit.stats().discardedBytes, r::kIgnoreLfAfterCr ? 0 : 1);
}

// §2: decimal motion numbers, hex bytes.
TEST(Readings, NumberBases)
{
    static_assert(r::kMotionNumberBase == 10 && r::kByteNumberBase == 16);
    Unit unit = readyUnit();
    EXPECT_EQ(ask(unit, "!0V1A\r"), "4\r");   // not hex
    EXPECT_EQ(ask(unit, "!0O0,1A\r"), "0\r"); // hex
    EXPECT_EQ(unit.outputs(), 0x1A);
    EXPECT_EQ(ask(unit, "!0SW0,FF\r!0SR0\r"), "0\r0,FF\r");
}

// §2.1
TEST(Readings, BadChecksum)
{
    Unit unit = readyUnit();
    ask(unit, "!0%+\r");
    const std::string before = ask(unit, withChecksum("!0@"));
    const std::string reply = ask(unit, "!0V100,00\r");
    EXPECT_EQ(reply[0], codeDigit(r::kBadChecksumCode));
    const std::string after = ask(unit, withChecksum("!0@"));
    EXPECT_EQ(before == after, !r::kBadChecksumAdvancesIndex);
}

// §2.2
TEST(Readings, PacketPartialFailureReply)
{
    EXPECT_EQ(r::packetReply(1, 6).code, 1);
    EXPECT_EQ(r::packetReply(1, 6).values, "6");
    Unit unit = readyUnit(Variant::Gve84);
    ask(unit, "!0V10\r");
    for (int i = 0; i < 58; ++i)
        ask(unit, "!0C1,0,0\r");
    std::string packet = "!0*S\r";
    for (int i = 0; i < 10; ++i)
        packet += "!0C1,0,0\r";
    EXPECT_EQ(ask(unit, packet + "!0*E10\r"), "1,6\r"); // six fitted, the seventh did not
}

// §4: VL in pulses/s.
TEST(Readings, VelocityLimitUnit)
{
    Unit unit = readyUnit();
    ask(unit, "!0A100\r!0V2000\r!0VL2500,2500,2500\r!0XM200\r!0L100000,0,0\r");
    runUntilIdle(unit);
    EXPECT_NEAR(unit.stats().motion.peakAxisSpeedPulsesPerS[0],
                2500 * r::kVelocityLimitUnitPulsesPerS, 1e-6);
}

// §4: VN after reset.
TEST(Readings, ResetSpeedMode)
{
    Unit unit = readyUnit();
    ask(unit, "!0A100\r!0L30000,40000,0\r");
    runUntilIdle(unit);
    const double y = unit.stats().motion.peakAxisSpeedPulsesPerS[1];
    EXPECT_NEAR(y, r::kResetModeIsVk ? 800 : 1000, 1e-6);
}

// §4: component counts.
TEST(Readings, VectorComponentCounts)
{
    for (Variant v : {Variant::Gve84, Variant::Gve114}) {
        Unit unit = readyUnit(v);
        const int axes = unit.variantInfo().axisCount;
        for (int n = 1; n <= 5; ++n) {
            std::string cmd = "!0C";
            for (int i = 0; i < n; ++i)
                cmd += (i ? ",1" : "1");
            EXPECT_EQ(ask(unit, cmd + "\r")[0], codeDigit(r::vectorComponentCountCode(n, axes)))
                << cmd;
        }
    }
    EXPECT_EQ(r::vectorComponentCountCode(3, 4), 0); // A left out = 0
    EXPECT_EQ(r::vectorComponentCountCode(2, 4), 4);
    EXPECT_EQ(r::vectorComponentCountCode(4, 3), 4);
}

// §6
TEST(Readings, HomingNotFound)
{
    Unit unit = readyUnit();
    ask(unit, "!0WX,-100,1000,10,100\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.takeTransmit()[0], codeDigit(r::kHomingNotFoundCode));
}

// §8
TEST(Readings, WhatAdvancesTheIndex)
{
    EXPECT_FALSE(r::advancesIndex("@"));
    EXPECT_FALSE(r::advancesIndex(">"));
    EXPECT_TRUE(r::advancesIndex("ZZ"));
    Unit unit = readyUnit(); // Y-: 1
    ask(unit, "!0ZZ\r!0V5\r!0@\r!0>\r!0*S\r!0*E0\r");
    EXPECT_EQ(ask(unit, "!0@\r"), "0,5\r");
}

// §12
TEST(Readings, EepromValuesAsDecimalText)
{
    EXPECT_EQ(r::formatEepromFloat(400.0f), "400");
    EXPECT_EQ(r::formatEepromFloat(0.1f), "0.1");
    Unit unit = readyUnit();
    EXPECT_EQ(ask(unit, "!0EFW30,0.1\r!0EFR30\r"), "0\r0," + r::formatEepromFloat(0.1f) + "\r");
}

// §13
TEST(Readings, MpgSendsNoReports)
{
    Unit unit(optionsFor(Variant::Gve64));
    EXPECT_EQ(ask(unit, "!0Y+\r"), "0,Y+\r");
    unit.advance(10);
    EXPECT_EQ(unit.takeTransmit().empty(), !r::kMpgSendsReports);
}

// Emulator choices.
TEST(Readings, WatchdogTime)
{
    Unit unit = readyUnit();
    unit.receive("!0Q");
    EXPECT_DOUBLE_EQ(unit.nextEventIn(), r::kWatchdogSeconds);
    unit.advance(r::kWatchdogSeconds);
    EXPECT_EQ(unit.takeTransmit(), "2\r");
}

TEST(Readings, MaxLineLength)
{
    Unit unit = readyUnit();
    const std::string fits = "!0V" + std::string(r::kMaxLineLength - 2, '1') + "\r";
    EXPECT_EQ(ask(unit, fits), "5\r"); // a number, out of range
    const std::string tooLong = "!0V" + std::string(r::kMaxLineLength - 1, '1') + "\r";
    EXPECT_EQ(ask(unit, tooLong), "4\r");
}

TEST(Readings, ResetTimeAndPause)
{
    Unit unit = readyUnit(Variant::Gve84);
    ask(unit, "!0J\r");
    unit.advance(r::kResetSeconds * 0.999);
    EXPECT_EQ(ask(unit, "!0Q\r"), "");
    unit.advance(r::kResetSeconds * 0.002);
    EXPECT_EQ(ask(unit, "!0Q\r"), "0,27011001\r");
    ask(unit, "!0A1000\r!0L1000,0,0\r");
    runUntilIdle(unit);
    const double end = unit.now();
    ask(unit, "!0L1000,0,0\r");
    runUntilIdle(unit);
    // A = 1e6 pulses/s^2, V = 1000: 1 ms and 0.5 steps each ramp, 999 steps at full speed.
    const double move = 2 * 1000 / 1e6 + (1000 - 1000.0 * 1000 / 1e6) / 1000;
    EXPECT_NEAR(unit.now() - end, r::kResetPauseMs / 1000.0 + move, 1e-9);
}

TEST(Readings, MpgReplyAndRefusal)
{
    Unit unit(optionsFor(Variant::Gve64));
    const auto reply = r::mpgReply(0, "Y&");
    EXPECT_EQ(ask(unit, "!0Y&\r"),
              std::string(1, codeDigit(reply.code)) + "," + reply.values + "\r");
    EXPECT_EQ(ask(unit, "!0C1,0,0\r")[0], codeDigit(r::kMpgRefusalCode));
}

TEST(Readings, KeepRestoreCodes)
{
    Unit unit = readyUnit();
    EXPECT_EQ(ask(unit, "!0R\r")[0], codeDigit(r::kKeepRestoreMisuseCode));
    EXPECT_EQ(ask(unit, "!0K\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0K\r")[0], codeDigit(r::kKeepRestoreMisuseCode));
    EXPECT_EQ(ask(unit, "!0C1,0,0\r")[0], codeDigit(r::kContinuousWhileKeptCode));
    EXPECT_EQ(ask(unit, "!0R\r"), "0\r");
}

TEST(Readings, GoWithNothingLeft)
{
    Unit unit = readyUnit();
    ask(unit, "!0H\r");
    EXPECT_EQ(ask(unit, "!0G\r")[0], codeDigit(r::kGoNothingLeftCode));
}

TEST(Readings, ForeignCommandInPacket)
{
    Unit unit = readyUnit();
    EXPECT_EQ(ask(unit, "!0*S\r!0A10\r!0*E1\r"),
              std::string(1, codeDigit(r::kForeignCommandInPacketCode)) + ",0\r");
}

TEST(Readings, ShortnessAndCruise)
{
    EXPECT_EQ(r::shortnessMeasure({3, -7, 2, 0}), 7);
    EXPECT_EQ(r::cruiseSpeed(true, 1000, 300), 300);
    EXPECT_EQ(r::cruiseSpeed(false, 1000, 300), 1000);
    EXPECT_EQ(r::multipliedSpeed(1000, 200, 1500), 1500);
    EXPECT_EQ(r::multipliedSpeed(1000, 200, 500), 1000);
    EXPECT_EQ(r::multipliedSpeed(1000, 50, 500), 500);
    Unit unit = readyUnit();
    ask(unit, "!0A100\r!0B300\r!0$8\r!0L0,-7,3\r"); // major 7 < 8: short -> min(V, B)
    runUntilIdle(unit);
    EXPECT_LE(unit.stats().motion.peakAxisSpeedPulsesPerS[1], r::cruiseSpeed(true, 1000, 300));
}

TEST(Readings, InputPolarity)
{
    EXPECT_TRUE(r::inputActive(false, false)); // active low, reads 0
    EXPECT_TRUE(r::inputActive(true, true));
    EXPECT_FALSE(r::inputActive(true, false));
}

TEST(Readings, ZeroVectorDoneAtOnce)
{
    Unit unit = readyUnit();
    ask(unit, "!0L100,0,0\r");
    runUntilIdle(unit);
    EXPECT_EQ(ask(unit, "!0L0,0,0\r!0N\r"), r::kZeroVectorDoneAtOnce ? "0\r0\r" : "0\r7\r");
}

TEST(Readings, ReceiveBufferWhileWaitingForHalt)
{
    Unit unit = readyUnit();
    ask(unit, "!0L100000,0,0\r");
    unit.advance(0.5);
    ask(unit, "!0H\r");
    std::string flood;
    while (flood.size() < r::kReceiveBufferBytes + 500)
        flood += "!0Q\r";
    unit.receive(flood);
    runUntilIdle(unit);
    const std::string out = unit.takeTransmit();
    const auto replies = std::count(out.begin(), out.end(), '\r');
    EXPECT_EQ(replies, 1 + static_cast<long>(r::kReceiveBufferBytes / 4));
    EXPECT_EQ(unit.stats().discardedBytes,
              static_cast<std::int64_t>(flood.size() - r::kReceiveBufferBytes));
}

TEST(Readings, SharedIndexOfAddresses)
{
    Unit unit(optionsFor(Variant::Gve64));
    ask(unit, "!7V100\r!0V100\r");
    EXPECT_EQ(ask(unit, "!0@\r"), r::kIndexSharedByAddresses ? "0,2\r" : "0,1\r");
}
