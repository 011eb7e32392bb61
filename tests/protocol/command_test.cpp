// Encoding of every command, byte-exact against the manuals' examples, and validation against
// the variant table.

#include "protocol/command.h"

#include <gtest/gtest.h>

#include <vector>

using namespace frezka::protocol;

TEST(CommandEncode, ManualChecksumExamples)
{
    EXPECT_EQ(encode(cmd::accel(100), true), "!0A100,4F\r");
    EXPECT_EQ(encode(cmd::checksumOff(), true), "!0%-,CF\r");
    EXPECT_EQ(encode(cmd::checksumOn(), false), "!0%+\r");
    EXPECT_EQ(encode(cmd::packetStart(), true), "!0*S,FA\r");
    EXPECT_EQ(encode(cmd::vector(697, 30, 0), true), "!0C697,30,0,51\r");
    EXPECT_EQ(encode(cmd::packetEnd(10), true), "!0*E10,4D\r");
}

// The GVE64 manual's packet (§13.3.3), line by line.
TEST(CommandEncode, ManualPacketExample)
{
    const std::vector<Command> vectors{cmd::vector(697, 30, 0),  cmd::vector(692, 92, 0),
                                       cmd::vector(682, 151, 0), cmd::vector(665, 209, 0),
                                       cmd::vector(645, 268, 0), cmd::vector(619, 322, 0),
                                       cmd::vector(589, 375, 0), cmd::vector(553, 425, 0),
                                       cmd::vector(515, 471, 0), cmd::vector(471, 515, 0)};
    const std::string expected = "!0*S,FA\r"
                                 "!0C697,30,0,51\r"
                                 "!0C692,92,0,54\r"
                                 "!0C682,151,0,7F\r"
                                 "!0C665,209,0,84\r"
                                 "!0C645,268,0,87\r"
                                 "!0C619,322,0,7F\r"
                                 "!0C589,375,0,8D\r"
                                 "!0C553,425,0,80\r"
                                 "!0C515,471,0,7F\r"
                                 "!0C471,515,0,7F\r"
                                 "!0*E10,4D\r";
    EXPECT_EQ(encodePacket(vectors, true), expected);
    EXPECT_FALSE(validatePacket(vectors, Variant::Gve64));
    EXPECT_EQ(encodePacket(std::vector{cmd::brake(500), cmd::vector(1, 2, 3)}, false),
              "!0*S\r!0B500\r!0C1,2,3\r!0*E2\r");
}

TEST(CommandEncode, ManualPlainExamples)
{
    EXPECT_EQ(encode(cmd::line(1000, 0, 0), false), "!0L1000,0,0\r");
    EXPECT_EQ(encode(cmd::line(1000, 1000, 20, 500), false), "!0L1000,1000,20,500\r");
    EXPECT_EQ(encode(cmd::vector(100, 20, 0), false), "!0C100,20,0\r");
    EXPECT_EQ(encode(cmd::positionXYZ(), false), "!0PF\r");
    EXPECT_EQ(encode(cmd::speed(1000), false), "!0V1000\r");
    EXPECT_EQ(encode(cmd::statusWrite(8, 0xF1), false), "!0SW8,F1\r");
    EXPECT_EQ(encode(cmd::statusRead(2), false), "!0SR2\r");
    EXPECT_EQ(encode(cmd::home(Axis::Y, -20000, 1000, 2000, 500), false),
              "!0WY,-20000,1000,2000,500\r");
    EXPECT_EQ(encode(cmd::velocityLimit(25000, 25000, 30000, 10000), false),
              "!0VL25000,25000,30000,10000\r");
    EXPECT_EQ(encode(cmd::output(0xFB), false), "!0O0,FB\r");
    EXPECT_EQ(encode(cmd::output(0xFF), false), "!0O0,FF\r");
    EXPECT_EQ(encode(cmd::spindle(300), false), "!7V300\r");
    EXPECT_EQ(encode(cmd::setCounter(Axis::X, 0), false), "!0NX0\r");
    EXPECT_EQ(encode(cmd::setCounter(Axis::X, 100), false), "!0NX100\r");
    EXPECT_EQ(encode(cmd::multiplier(200), false), "!0XM200\r");
    EXPECT_EQ(encode(cmd::pause(5), false), "!0T5\r");
    EXPECT_EQ(encode(cmd::shortThreshold(512), false), "!0$512\r");
    EXPECT_EQ(encode(cmd::accel(50), false), "!0A50\r");
    EXPECT_EQ(encode(cmd::eepromWriteFloat(0x30, 400.0), false), "!0EFW30,400.0\r");
    EXPECT_EQ(encode(cmd::eepromWriteFloat(0x60, 0.1), false), "!0EFW60,0.1\r");
    EXPECT_EQ(encode(cmd::eepromWriteUint(0x48, 200), false), "!0EUW48,200\r");
    EXPECT_EQ(encode(cmd::eepromReadByte(0x0D), false), "!0ER0D\r");
    EXPECT_EQ(encode(cmd::eepromWriteByte(0x05, 0xAC), false), "!0EW05,AC\r");
}

// The tool-lift sequence of §7 exactly as the manual prints it.
TEST(CommandEncode, ManualToolLiftSequence)
{
    const std::vector<Command> seq{cmd::halt(),
                                   cmd::positionXY(),
                                   cmd::statusRead(4),
                                   cmd::statusRead(5),
                                   cmd::statusRead(6),
                                   cmd::statusWrite(0, 0x1A),
                                   cmd::statusWrite(1, 0x3F),
                                   cmd::keep(),
                                   cmd::line(0, 0, -1000),
                                   cmd::line(0, 0, 1000),
                                   cmd::restore(),
                                   cmd::speed(500),
                                   cmd::exchangeAll(),
                                   cmd::statusWrite(0, 0xA2),
                                   cmd::statusWrite(1, 0x78),
                                   cmd::go()};
    std::string all;
    for (const Command &c : seq)
        all += encodeBody(c) + " ";
    EXPECT_EQ(all, "!0H !0P !0SR4 !0SR5 !0SR6 !0SW0,1A !0SW1,3F !0K !0L0,0,-1000 !0L0,0,1000 "
                   "!0R !0V500 !0XA !0SW0,A2 !0SW1,78 !0G ");
    for (const Command &c : seq)
        EXPECT_FALSE(validate(c, Variant::Gve64)) << encodeBody(c);
}

TEST(CommandEncode, EveryMnemonic)
{
    EXPECT_EQ(encodeBody(cmd::version()), "!0?");
    EXPECT_EQ(encodeBody(cmd::version(7)), "!7?");
    EXPECT_EQ(encodeBody(cmd::identify()), "!0Q");
    EXPECT_EQ(encodeBody(cmd::brake(35000)), "!0B35000");
    EXPECT_EQ(encodeBody(cmd::speedModeVk()), "!0VK");
    EXPECT_EQ(encodeBody(cmd::speedModeVn()), "!0VN");
    EXPECT_EQ(encodeBody(cmd::exchangeUp()), "!0XU");
    EXPECT_EQ(encodeBody(cmd::exchangeDown()), "!0XD");
    EXPECT_EQ(encodeBody(cmd::positionXYZA()), "!0P4");
    EXPECT_EQ(encodeBody(cmd::zeroAll()), "!0N");
    EXPECT_EQ(encodeBody(cmd::mpgReporting()), "!0Y+");
    EXPECT_EQ(encodeBody(cmd::mpgSilent()), "!0Y&");
    EXPECT_EQ(encodeBody(cmd::mpgOff()), "!0Y-");
    EXPECT_EQ(encodeBody(cmd::deleteQueue()), "!0D");
    EXPECT_EQ(encodeBody(cmd::eepromReadFloat(0x30)), "!0EFR30");
    EXPECT_EQ(encodeBody(cmd::eepromReadUint(0x48)), "!0EUR48");
    EXPECT_EQ(encodeBody(cmd::input1()), "!0I1");
    EXPECT_EQ(encodeBody(cmd::input2()), "!0I2");
    EXPECT_EQ(encodeBody(cmd::flag()), "!0F");
    EXPECT_EQ(encodeBody(cmd::index()), "!0@");
    EXPECT_EQ(encodeBody(cmd::repeat()), "!0>");
    EXPECT_EQ(encodeBody(cmd::jump()), "!0J");
    EXPECT_EQ(encodeBody(cmd::index(7)), "!7@");
}

TEST(CommandValidate, ComponentsPerVariant)
{
    EXPECT_EQ(validate(cmd::vector(1, 2, 3, 4), Variant::Gve84).error, CommandError::AxisCount);
    EXPECT_FALSE(validate(cmd::vector(1, 2, 3, 4), Variant::Gve64));
    EXPECT_FALSE(validate(cmd::vector(1, 2, 3), Variant::Gve64)); // A may be left out
    EXPECT_FALSE(validate(cmd::line(1, 2, 3), Variant::Gve84));
    EXPECT_EQ(validate(cmd::line(2147483648LL, 0, 0), Variant::Gve64).error,
              CommandError::OutOfRange);
    EXPECT_EQ(validate(cmd::line(-2147483648LL, 0, 0), Variant::Gve64).error,
              CommandError::OutOfRange);
    EXPECT_FALSE(validate(cmd::line(-2147483647LL, 0, 0), Variant::Gve64));
    Command twoComponents = cmd::vector(1, 2, 3);
    twoComponents.argCount = 2;
    EXPECT_EQ(validate(twoComponents, Variant::Gve64).error, CommandError::AxisCount);
}

TEST(CommandValidate, FeaturesPerVariant)
{
    EXPECT_EQ(validate(cmd::mpgOff(), Variant::Gve84).error, CommandError::NotOnVariant);
    EXPECT_FALSE(validate(cmd::mpgOff(), Variant::Gve64));
    EXPECT_EQ(validate(cmd::positionXYZA(), Variant::Gve84).error, CommandError::NotOnVariant);
    EXPECT_EQ(validate(cmd::input2(), Variant::Gve84).error, CommandError::NotOnVariant);
    EXPECT_EQ(validate(cmd::spindle(300), Variant::Gve84).error, CommandError::NotOnVariant);
    EXPECT_FALSE(validate(cmd::spindle(300), Variant::Gve114));
    EXPECT_EQ(validate(cmd::eepromReadFloat(0x30), Variant::Gve84).error,
              CommandError::NotOnVariant);
    EXPECT_EQ(validate(cmd::setCounter(Axis::A, 0), Variant::Gve84).error,
              CommandError::NotOnVariant);
    EXPECT_EQ(validate(cmd::home(Axis::A, 100, 1000, 100, 500), Variant::Gve84).error,
              CommandError::NotOnVariant);
    Command lineOn7 = cmd::line(1, 2, 3);
    lineOn7.address = 7;
    EXPECT_EQ(validate(lineOn7, Variant::Gve64).error, CommandError::BadAddress);
    EXPECT_FALSE(validate(cmd::version(7), Variant::Gve64));
    Command speedOn0 = cmd::spindle(5);
    speedOn0.address = 0;
    EXPECT_EQ(validate(speedOn0, Variant::Gve64).error, CommandError::BadAddress);
    Command second = cmd::flag();
    second.address = 2;
    EXPECT_FALSE(validate(second, Variant::Gve114)); // several GVE114 units on one line
    EXPECT_EQ(validate(second, Variant::Gve64).error, CommandError::BadAddress);
}

TEST(CommandValidate, Ranges)
{
    EXPECT_EQ(validate(cmd::pause(0), Variant::Gve64).error, CommandError::OutOfRange);
    EXPECT_EQ(validate(cmd::pause(25), Variant::Gve64).error, CommandError::OutOfRange);
    EXPECT_FALSE(validate(cmd::pause(24), Variant::Gve64));
    EXPECT_EQ(validate(cmd::speed(9), Variant::Gve64).error, CommandError::OutOfRange);
    EXPECT_FALSE(validate(cmd::speed(125000), Variant::Gve64));
    EXPECT_EQ(validate(cmd::speed(125001), Variant::Gve64).error, CommandError::OutOfRange);
    EXPECT_EQ(validate(cmd::speed(60000), Variant::Gve64, 50000).error, CommandError::OutOfRange);
    EXPECT_FALSE(validate(cmd::speed(500000), Variant::Gve114));
    EXPECT_EQ(validate(cmd::brake(200001), Variant::Gve64Phantom).error, CommandError::OutOfRange);
    EXPECT_EQ(validate(cmd::statusWrite(8, 0xF1), Variant::Gve64).error, CommandError::OutOfRange);
    EXPECT_EQ(validate(cmd::statusRead(7), Variant::Gve64).error, CommandError::OutOfRange);
    EXPECT_EQ(validate(cmd::output(0x100), Variant::Gve64).error, CommandError::OutOfRange);
    EXPECT_EQ(validate(cmd::spindle(1001), Variant::Gve64).error, CommandError::OutOfRange);
    EXPECT_EQ(validate(cmd::eepromReadByte(0x100), Variant::Gve64).error, CommandError::OutOfRange);
    EXPECT_EQ(validate(cmd::home(Axis::Y, 0, 1000, 2000, 500), Variant::Gve64).error,
              CommandError::OutOfRange);
    EXPECT_FALSE(validate(cmd::home(Axis::Y, -20000, 1000, 2000, 500), Variant::Gve64));
    EXPECT_FALSE(validate(cmd::shortThreshold(4294967295LL), Variant::Gve64));
    EXPECT_EQ(validate(cmd::shortThreshold(4294967295LL), Variant::Gve84).error,
              CommandError::OutOfRange);
    EXPECT_EQ(validate(cmd::velocityLimit(5, 25000, 25000), Variant::Gve64).error,
              CommandError::OutOfRange);
    // The message names the command and the value.
    const CommandCheck check = validate(cmd::pause(25), Variant::Gve64);
    EXPECT_NE(check.message.find("!0T25"), std::string::npos);
    EXPECT_NE(check.message.find("25"), std::string::npos);
}

TEST(CommandValidate, Packets)
{
    EXPECT_EQ(
        validatePacket(std::vector{cmd::vector(1, 2, 3), cmd::line(1, 2, 3)}, Variant::Gve64).error,
        CommandError::NotInPacket);
    EXPECT_EQ(validatePacket(std::vector<Command>{}, Variant::Gve64).error,
              CommandError::EmptyPacket);
    EXPECT_EQ(validatePacket(std::vector{cmd::vector(1, 2, 3, 4)}, Variant::Gve84).error,
              CommandError::AxisCount);
    EXPECT_EQ(encodePacket(std::vector{cmd::speed(100)}, true), "");
}
