// Unit side: received lines -> commands or the unit's reply code; round trips of every op.

#include "protocol/commandparser.h"

#include <gtest/gtest.h>

#include <random>

using namespace frezka::protocol;

namespace {

// One representative command of every op.
std::vector<Command> everyOp()
{
    return {cmd::version(),
            cmd::identify(),
            cmd::line(1000, -20, 0),
            cmd::line(1, 2, 3, -4),
            cmd::vector(697, 30, 0),
            cmd::vector(-1, 0, 5, 2147483647),
            cmd::pause(5),
            cmd::shortThreshold(512),
            cmd::accel(20),
            cmd::speed(1000),
            cmd::velocityLimit(25000, 25000, 30000),
            cmd::velocityLimit(25000, 25000, 30000, 10000),
            cmd::brake(35000),
            cmd::speedModeVk(),
            cmd::speedModeVn(),
            cmd::exchangeAll(),
            cmd::exchangeUp(),
            cmd::exchangeDown(),
            cmd::multiplier(200),
            cmd::positionXY(),
            cmd::positionXYZ(),
            cmd::positionXYZA(),
            cmd::zeroAll(),
            cmd::setCounter(Axis::Z, -100),
            cmd::home(Axis::Y, -20000, 1000, 2000, 500),
            cmd::mpgReporting(),
            cmd::mpgSilent(),
            cmd::mpgOff(),
            cmd::keep(),
            cmd::restore(),
            cmd::halt(),
            cmd::deleteQueue(),
            cmd::go(),
            cmd::eepromReadByte(0x0D),
            cmd::eepromWriteByte(0x05, 0xAC),
            cmd::eepromReadFloat(0x30),
            cmd::eepromReadUint(0x48),
            cmd::eepromWriteFloat(0x30, 400.25),
            cmd::eepromWriteUint(0x48, 200),
            cmd::output(0xFB),
            cmd::input1(),
            cmd::input2(),
            cmd::statusRead(6),
            cmd::statusWrite(0, 0x1A),
            cmd::flag(),
            cmd::index(),
            cmd::repeat(),
            cmd::jump(),
            cmd::checksumOn(),
            cmd::checksumOff(),
            cmd::packetStart(),
            cmd::packetEnd(10),
            cmd::spindle(300),
            cmd::index(7)};
}

ParsedCommand parseEncoded(const Command &c, bool checksums)
{
    std::string bytes = encode(c, checksums);
    bytes.pop_back(); // CR
    return parseCommand(bytes, checksums);
}

} // namespace

TEST(CommandParser, RoundTripEveryOp)
{
    std::vector<bool> seen(kOpCount, false);
    for (const Command &c : everyOp()) {
        seen[static_cast<int>(c.op)] = true;
        for (bool checksums : {false, true}) {
            const ParsedCommand p = parseEncoded(c, checksums);
            ASSERT_EQ(p.status, ParseStatus::Ok) << encodeBody(c) << " " << p.message;
            EXPECT_EQ(p.command, c) << encodeBody(c);
            EXPECT_EQ(p.address, c.address);
            EXPECT_EQ(unitCheck(p.command, Variant::Gve64), ReplyCode::Ok) << encodeBody(c);
        }
    }
    for (int i = 0; i < kOpCount; ++i)
        EXPECT_TRUE(seen[i]) << "op " << i << " not covered";
}

TEST(CommandParser, ManualExamples)
{
    const ParsedCommand sw = parseCommand("!0SW8,F1", false);
    ASSERT_EQ(sw.status, ParseStatus::Ok);
    EXPECT_EQ(sw.command, cmd::statusWrite(8, 0xF1));
    EXPECT_EQ(unitCheck(sw.command, Variant::Gve64), ReplyCode::OutOfRange); // -> 5
    const ParsedCommand a = parseCommand("!0A100,4F", true);
    ASSERT_EQ(a.status, ParseStatus::Ok);
    EXPECT_EQ(a.command, cmd::accel(100));
    EXPECT_EQ(parseCommand("!0%-,CF", true).command, cmd::checksumOff());
    EXPECT_EQ(parseCommand("!0*S,FA", true).command, cmd::packetStart());
    EXPECT_EQ(parseCommand("!0*E10,4D", true).command, cmd::packetEnd(10));
    EXPECT_EQ(parseCommand("!0C697,30,0,51", true).command, cmd::vector(697, 30, 0));
    EXPECT_EQ(parseCommand("!0WY,-20000,1000,2000,500", false).command,
              cmd::home(Axis::Y, -20000, 1000, 2000, 500));
    // GVE114 prints W without the comma after the axis.
    EXPECT_EQ(parseCommand("!0WY-20000,1000,2000,500", false).command,
              cmd::home(Axis::Y, -20000, 1000, 2000, 500));
    EXPECT_EQ(parseCommand("!7V300", false).command, cmd::spindle(300));
    EXPECT_EQ(parseCommand("!0V300", false).command, cmd::speed(300));
    EXPECT_EQ(parseCommand("!0NX100", false).command, cmd::setCounter(Axis::X, 100));
    EXPECT_EQ(parseCommand("!0N", false).command, cmd::zeroAll());
}

TEST(CommandParser, Checksums)
{
    const ParsedCommand bad = parseCommand("!0A100,4E", true);
    EXPECT_EQ(bad.status, ParseStatus::Error);
    EXPECT_EQ(bad.code, ReplyCode::Syntax); // adopted reading §2.1
    EXPECT_TRUE(bad.checksumFailed);
    const ParsedCommand missing = parseCommand("!0A100", true);
    EXPECT_EQ(missing.status, ParseStatus::Error);
    EXPECT_TRUE(missing.checksumFailed);
    // A checksummed line while checksums are off is a syntax error (extra parameter).
    const ParsedCommand extra = parseCommand("!0A100,4F", false);
    EXPECT_EQ(extra.status, ParseStatus::Error);
    EXPECT_EQ(extra.code, ReplyCode::Syntax);
    EXPECT_FALSE(extra.checksumFailed);
}

TEST(CommandParser, ErrorsGetTheDocumentedCode)
{
    auto code = [](std::string_view line) { return parseCommand(line, false).code; };
    EXPECT_EQ(code("!0Z"), ReplyCode::UnknownCommand);
    EXPECT_EQ(code("!0"), ReplyCode::UnknownCommand);
    EXPECT_EQ(code("!0L1,2"), ReplyCode::Syntax); // fewer than three components
    EXPECT_EQ(code("!0L1,2,3,4,5"), ReplyCode::Syntax);
    EXPECT_EQ(code("!0Lx,2,3"), ReplyCode::Syntax);
    EXPECT_EQ(code("!0L1,,3"), ReplyCode::Syntax);
    EXPECT_EQ(code("!0L99999999999999999999,0,0"), ReplyCode::OutOfRange);
    EXPECT_EQ(code("!0V"), ReplyCode::Syntax);
    EXPECT_EQ(code("!0H1"), ReplyCode::Syntax);
    EXPECT_EQ(code("!0O0FB"), ReplyCode::Syntax);
    EXPECT_EQ(code("!0ERXYZ"), ReplyCode::Syntax);
    EXPECT_EQ(code("!0W,1,2,3,4"), ReplyCode::Syntax);
    EXPECT_EQ(code("!0EFW30,abc"), ReplyCode::Syntax);
    // A 4-component vector on the 3-axis GVE84 is code 4 (adopted reading §4).
    const ParsedCommand four = parseCommand("!0C1,2,3,4", false);
    ASSERT_EQ(four.status, ParseStatus::Ok);
    EXPECT_EQ(unitCheck(four.command, Variant::Gve84), ReplyCode::Syntax);
    EXPECT_EQ(unitCheck(four.command, Variant::Gve64), ReplyCode::Ok);
    EXPECT_EQ(unitCheck(parseCommand("!0Y-", false).command, Variant::Gve84),
              ReplyCode::UnknownCommand);
    EXPECT_EQ(unitCheck(parseCommand("!0T25", false).command, Variant::Gve84),
              ReplyCode::OutOfRange);
}

TEST(CommandParser, NotACommand)
{
    EXPECT_EQ(parseCommand("", false).status, ParseStatus::NotACommand);
    EXPECT_EQ(parseCommand("0,5C", false).status, ParseStatus::NotACommand);
    EXPECT_EQ(parseCommand("!8F", false).status, ParseStatus::NotACommand);
    EXPECT_EQ(parseCommand("!3F", false).address, 3); // addressed elsewhere: caller decides
}

TEST(CommandParser, RandomGarbageNeverCrashes)
{
    std::mt19937 rng(99);
    const std::string alphabet = "!0123456789ABCDEFGHIJKLMNOPQRSTUVWXYZ,-+$%*@>?&. \x01\xff";
    for (int i = 0; i < 20000; ++i) {
        std::string line = "!0";
        const int n = static_cast<int>(rng() % 24);
        for (int k = 0; k < n; ++k)
            line += alphabet[rng() % alphabet.size()];
        const ParsedCommand p = parseCommand(line, rng() % 2 == 0);
        if (p.status == ParseStatus::Ok) {
            // Whatever parsed must encode back to something that parses to the same command.
            const ParsedCommand again = parseEncoded(p.command, false);
            EXPECT_EQ(again.command, p.command) << line;
        } else {
            EXPECT_EQ(p.status, ParseStatus::Error);
            EXPECT_NE(p.code, ReplyCode::Ok);
        }
    }
}
