// Lines, checksums (§2.1), packets (§2.2), watchdog, link recovery (§8) and bad input.

#include "emulator_test_util.h"

#include "driver/emulator/wire.h"

#include <gtest/gtest.h>

#include <regex>

using namespace frezka::emulator;
using namespace frezka::emulator::test;

namespace {

const char *const kManualPacket[] = {"!0C697,30,0,51\r",  "!0C692,92,0,54\r",  "!0C682,151,0,7F\r",
                                     "!0C665,209,0,84\r", "!0C645,268,0,87\r", "!0C619,322,0,7F\r",
                                     "!0C589,375,0,8D\r", "!0C553,425,0,80\r", "!0C515,471,0,7F\r",
                                     "!0C471,515,0,7F\r"};

} // namespace

TEST(Framing, ManualChecksumExamples)
{
    Unit unit = readyUnit(Variant::Gve64);
    EXPECT_EQ(withChecksum("!0A100"), "!0A100,4F\r");
    EXPECT_EQ(ask(unit, "!0%+\r"), "0,5C\r"); // its reply already carries one
    EXPECT_EQ(ask(unit, "!0A100,4F\r"), "0,5C\r");
    EXPECT_EQ(ask(unit, withChecksum("!0@")).substr(0, 2), "0,");
    EXPECT_EQ(ask(unit, "!0%-,CF\r"), "0\r"); // reply plain again
    EXPECT_EQ(ask(unit, "!0A100\r"), "0\r");
}

TEST(Framing, ManualPacketExample)
{
    Unit unit = readyUnit(Variant::Gve64);
    ask(unit, "!0%+\r");
    EXPECT_EQ(ask(unit, "!0*S,FA\r"), "");
    for (const char *line : kManualPacket)
        EXPECT_EQ(ask(unit, line), "") << line;
    EXPECT_EQ(ask(unit, "!0*E10,4D\r"), "0,10,E9\r");
    EXPECT_EQ(unit.queueLength(), 10u);
    runUntilIdle(unit);
    EXPECT_EQ(unit.position(), (std::array<std::int64_t, 4>{6128, 2858, 0, 0}));
}

TEST(Framing, BadChecksumIsCode4AndDoesNotAdvanceTheIndex)
{
    Unit unit = readyUnit(Variant::Gve64);
    ask(unit, "!0%+\r");
    const std::string before = ask(unit, withChecksum("!0@"));
    EXPECT_EQ(ask(unit, "!0A100,4E\r"), "4,60\r");
    EXPECT_EQ(ask(unit, "!0A100\r"), "4,60\r");     // no checksum at all
    EXPECT_EQ(ask(unit, "!0A100,4\r"), "4,60\r");   // one digit
    EXPECT_EQ(ask(unit, "!0A100,4FF\r"), "4,60\r"); // three digits
    EXPECT_EQ(ask(unit, withChecksum("!0@")), before);
    EXPECT_EQ(ask(unit, "!0L5,0,0,8A\r").substr(0, 1), "4"); // wrong sum: never executed
    EXPECT_EQ(unit.queueLength(), 0u);
    EXPECT_EQ(unit.stats().checksumErrors, 5);
    EXPECT_EQ(ask(unit, "!0a100,6f\r"), "3,5F\r"); // lower-case hex accepted; 'a' unknown
}

TEST(Framing, PacketPartialFailure)
{
    Unit unit = readyUnit(Variant::Gve84); // 64 vectors
    ask(unit, "!0V10\r");
    for (int i = 0; i < 58; ++i)
        ASSERT_EQ(ask(unit, "!0C10,0,0\r"), "0\r");
    const std::string index0 = ask(unit, "!0@\r");
    ask(unit, "!0*S\r");
    ask(unit, "!0B500\r");
    for (int i = 0; i < 9; ++i)
        ask(unit, "!0C10,0,0\r");
    // 58 + B + 6 C fill the queue; the seventh C hits a full queue: seven commands accepted.
    EXPECT_EQ(ask(unit, "!0*E10\r"), "1,7\r");
    EXPECT_EQ(unit.queueLength(), 64u);
    EXPECT_EQ(ask(unit, "!0@\r"), "0," + std::to_string(std::stoi(index0.substr(2)) + 12) + "\r");
}

TEST(Framing, PacketRunsNothingWhenALineIsMissingOrBad)
{
    Unit unit = readyUnit(Variant::Gve64);
    ask(unit, "!0V10\r");
    ask(unit, "!0*S\r");
    ask(unit, "!0C10,0,0\r");
    ask(unit, "!0C10,0,0\r");
    EXPECT_EQ(ask(unit, "!0*E3\r"), "4,0\r"); // three announced, two arrived
    EXPECT_EQ(unit.queueLength(), 0u);
    ask(unit, "!0%+\r");
    ask(unit, withChecksum("!0*S"));
    ask(unit, withChecksum("!0C10,0,0"));
    ask(unit, "!0C10,0,0,00\r"); // bad checksum inside the packet
    ask(unit, withChecksum("!0C10,0,0"));
    EXPECT_EQ(ask(unit, withChecksum("!0*E3")), "4,1,BD\r");
    EXPECT_EQ(unit.queueLength(), 1u);
}

TEST(Framing, PacketAcceptsOnlyCAndB)
{
    Unit unit = readyUnit(Variant::Gve64);
    ask(unit, "!0*S\r");
    ask(unit, "!0B100\r");
    ask(unit, "!0C10,0,0\r");
    ask(unit, "!0V100\r");
    ask(unit, "!0C10,0,0\r");
    EXPECT_EQ(ask(unit, "!0*E4\r"), "4,2\r");
    EXPECT_EQ(ask(unit, "!0*E4\r"), "4\r"); // no packet open
    for (const char *badEnd : {"!0*Ex\r", "!0*E\xFF\r", "!0*E99999\r", "!0*E\r", "!0*E-1\r"}) {
        ask(unit, "!0*S\r!0C1,0,0\r");
        EXPECT_EQ(ask(unit, badEnd), "4,0\r") << badEnd; // count unreadable: nothing runs
    }
    // '@' inside an unfinished packet abandons it and is answered.
    ask(unit, "!0*S\r");
    ask(unit, "!0C10,0,0\r");
    EXPECT_EQ(ask(unit, "!0@\r").substr(0, 2), "0,");
    EXPECT_EQ(ask(unit, "!0*E1\r"), "4\r");
}

TEST(Framing, PacketOfAlreadyQueuedCommandsRunsOnce)
{
    Unit unit = readyUnit(Variant::Gve64);
    std::string packet = "!0*S\r";
    for (int i = 0; i < 5; ++i)
        packet += "!0C100,0,0\r";
    packet += "!0*E5\r";
    EXPECT_EQ(ask(unit, packet), "0,5\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.position()[0], 500);
}

TEST(Framing, Watchdog)
{
    Unit unit = readyUnit(Variant::Gve64);
    EXPECT_EQ(ask(unit, "!0A10"), "");
    EXPECT_NEAR(unit.nextEventIn(), 0.1, 1e-12);
    unit.advance(0.099);
    EXPECT_EQ(unit.takeTransmit(), "");
    unit.advance(0.002);
    EXPECT_EQ(unit.takeTransmit(), "2\r");
    EXPECT_EQ(ask(unit, "0\r"), "");        // the rest of the late command is not a command
    EXPECT_EQ(ask(unit, "!0@\r"), "0,1\r"); // only Y- counted
    EXPECT_EQ(unit.stats().watchdogs, 1);
    // A packet whose end never comes.
    ask(unit, "!0*S\r!0C1,0,0\r");
    unit.advance(0.2);
    EXPECT_EQ(unit.takeTransmit(), "2\r");
    EXPECT_EQ(unit.queueLength(), 0u);
    // Another unit's incomplete command is not ours to time out.
    ask(unit, "!3A10");
    unit.advance(1.0);
    EXPECT_EQ(unit.takeTransmit(), "");
}

TEST(Framing, IndexAndRepeat)
{
    Unit unit = readyUnit(Variant::Gve64); // Y- was command 1
    EXPECT_EQ(ask(unit, "!0V1000\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0@\r"), "0,2\r");
    EXPECT_EQ(ask(unit, "!0@\r"), "0,2\r"); // '@' does not count itself
    EXPECT_EQ(ask(unit, "!0PF\r"), "0,0,0,0\r");
    EXPECT_EQ(ask(unit, "!0>\r"), "0,0,0,0\r");
    EXPECT_EQ(ask(unit, "!0>\r"), "0,0,0,0\r");
    EXPECT_EQ(ask(unit, "!0C10,0,0\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0>\r"), "0\r"); // repeated, not executed again
    EXPECT_EQ(unit.queueLength(), 1u);
    EXPECT_EQ(ask(unit, "!0@\r"), "0,4\r");
    EXPECT_EQ(ask(unit, "!0ZZ\r"), "3\r");
    EXPECT_EQ(ask(unit, "!0@\r"), "0,5\r"); // failing commands count too
    for (int i = 0; i < 300; ++i)
        ask(unit, "!0V1000\r");
    EXPECT_EQ(ask(unit, "!0@\r"), "0," + std::to_string((5 + 300) % 256) + "\r");
}

TEST(Framing, LineFeedAfterCrIgnoredAndGarbageDiscarded)
{
    Unit unit = readyUnit(Variant::Gve64);
    EXPECT_EQ(ask(unit, "!0Q\r\n!0Q\r\n"), "0,25020304\r0,25020304\r");
    EXPECT_EQ(unit.stats().discardedBytes, 0);
    EXPECT_EQ(ask(unit, "hello\r!0Q\r"), "0,25020304\r");
    EXPECT_EQ(unit.stats().discardedBytes, 6);
    EXPECT_EQ(ask(unit, "!0V10!0Q\r"), "0,25020304\r"); // a new '!' cuts off the old line
    EXPECT_EQ(ask(unit, "!\r!x?\r"), "");
}

TEST(Framing, OverlongLineIsCode4WithoutIndex)
{
    Unit unit = readyUnit(Variant::Gve64);
    const std::string before = ask(unit, "!0@\r");
    EXPECT_EQ(ask(unit, "!0C" + std::string(500, '1') + "\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0@\r"), before);
    EXPECT_EQ(ask(unit, "!0Q\r"), "0,25020304\r");
}

// Random bytes never crash the unit, and everything it sends is a well-formed reply.
TEST(Framing, FuzzedInputGetsWellFormedReplies)
{
    const std::regex reply("[0-9A-F](,[^\r,]*)*\r");
    for (Variant v : {Variant::Gve84, Variant::Gve64, Variant::Gve114}) {
        Unit unit = readyUnit(v);
        SplitMix64 rng(42);
        const std::string alphabet = "!0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ,.-+*$%&?@>\r\n\x01\xFF";
        std::string all;
        for (int round = 0; round < 3000; ++round) {
            std::string chunk;
            for (int i = 0, n = int(rng.next() % 12); i < n; ++i)
                chunk += alphabet[rng.next() % alphabet.size()];
            if (rng.next() % 3 == 0)
                chunk = "!0" + chunk + "\r";
            unit.receive(chunk);
            unit.advance(double(rng.next() % 1000) / 1e4);
            all += unit.takeTransmit();
        }
        runUntilIdle(unit, 1e4);
        all += unit.takeTransmit();
        std::size_t pos = 0;
        while (pos < all.size()) {
            const auto cr = all.find('\r', pos);
            ASSERT_NE(cr, std::string::npos);
            const std::string line = all.substr(pos, cr + 1 - pos);
            EXPECT_TRUE(std::regex_match(line, reply)) << line;
            pos = cr + 1;
        }
        EXPECT_GT(unit.stats().commands, 500);
    }
}
