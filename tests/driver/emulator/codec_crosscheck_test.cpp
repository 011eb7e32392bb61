// The codec (protocol/, written from the PC's side) against the emulator (written from the
// unit's side): every command the codec builds for a variant is accepted by the emulated unit,
// and every reply the unit gives decodes and fits the command it answers. Two independent
// readings of docs/gve-protocol.md that must agree.

#include "emulator_test_util.h"

#include "protocol/command.h"
#include "protocol/reply.h"

#include <gtest/gtest.h>

#include <vector>

using namespace frezka::emulator;
using namespace frezka::emulator::test;
namespace p = frezka::protocol;

namespace {

// One command of each kind with valid arguments, in an order that a unit can follow (no vector
// while the MPG is on, G after H, R after K).
std::vector<p::Command> corpus()
{
    using namespace p::cmd;
    return {version(),
            identify(),
            mpgOff(),
            pause(5),
            shortThreshold(100),
            accel(50),
            speed(2000),
            brake(500),
            speedModeVk(),
            speedModeVn(),
            velocityLimit(9000, 9000, 9000),
            multiplier(100),
            line(100, -50, 3),
            vector(10, 20, 30),
            vector(10, 20, 30, 4),
            line(0, 0, 0),
            exchangeAll(),
            exchangeUp(),
            exchangeDown(),
            positionXY(),
            positionXYZ(),
            positionXYZA(),
            halt(),
            go(),
            halt(),
            keep(),
            restore(),
            deleteQueue(),
            zeroAll(),
            setCounter(p::Axis::Y, -1234),
            eepromReadByte(0x05),
            eepromWriteByte(0x05, 0xFD), // X's DIR kept: the W below seeks X's switch
            eepromReadFloat(0x30),
            eepromWriteFloat(0x30, 400.5),
            eepromReadUint(0x48),
            eepromWriteUint(0x48, 200),
            output(0xFB),
            input1(),
            input2(),
            statusWrite(0, 0x1A),
            statusRead(0),
            statusRead(6),
            flag(),
            index(),
            repeat(),
            spindle(300),
            eepromReadByte(0x05, 7),
            index(7),
            home(p::Axis::X, -5000, 2000, 500, 500),
            mpgSilent(),
            mpgReporting(),
            mpgOff()};
}

void runCorpus(Variant variant, bool checksums)
{
    UnitOptions o = optionsFor(variant);
    o.switches = {{0, 0, -3000, -1}};
    Unit unit(o);
    if (checksums) {
        ASSERT_EQ(ask(unit, p::encode(p::cmd::checksumOn(), false)), "0,5C\r");
    }
    int sent = 0;
    for (const p::Command &c : corpus()) {
        if (p::validate(c, variant))
            continue; // the codec refuses it for this variant: nothing to send
        const std::string bytes = p::encode(c, checksums);
        unit.receive(bytes);
        runUntilIdle(unit, 60); // H and W answer later
        const std::string out = unit.takeTransmit();
        ASSERT_FALSE(out.empty()) << bytes;
        ASSERT_EQ(out.back(), '\r') << bytes;
        const auto result = p::decodeReply(std::string_view(out).substr(0, out.size() - 1),
                                           checksums ? p::ChecksumMode::On : p::ChecksumMode::Off);
        ASSERT_TRUE(result.reply) << bytes << " -> " << out << ": " << result.error->message;
        const p::Reply &r = *result.reply;
        EXPECT_NE(r.code, p::ReplyCode::UnknownCommand) << bytes;
        EXPECT_NE(r.code, p::ReplyCode::Syntax) << bytes;
        EXPECT_NE(r.code, p::ReplyCode::OutOfRange) << bytes;
        EXPECT_NE(r.code, p::ReplyCode::Watchdog) << bytes;
        if (c.op != p::Op::Repeat) {
            const auto shape = p::checkReplyShape(c, r, out);
            EXPECT_FALSE(shape) << bytes << " -> " << out << ": " << shape->message;
        }
        ++sent;
    }
    EXPECT_GT(sent, 30);
    // A packet the codec builds.
    std::vector<p::Command> packet;
    for (int i = 0; i < 10; ++i)
        packet.push_back(i % 3 ? p::cmd::vector(100, i, 0) : p::cmd::brake(1000 + i));
    ASSERT_FALSE(p::validatePacket(packet, variant));
    if (unit.variantInfo().hasMpg)
        ask(unit, p::encode(p::cmd::mpgOff(), checksums));
    const std::string out = ask(unit, p::encodePacket(packet, checksums));
    const auto result = p::decodeReply(std::string_view(out).substr(0, out.size() - 1),
                                       checksums ? p::ChecksumMode::On : p::ChecksumMode::Off);
    ASSERT_TRUE(result.reply) << out;
    EXPECT_EQ(result.reply->values, std::vector<std::string>{"10"});
    EXPECT_FALSE(p::checkReplyShape(p::cmd::packetEnd(10), *result.reply, out));
}

} // namespace

TEST(CodecCrossCheck, EveryVariantPlain)
{
    for (Variant v : {Variant::Gve84, Variant::Gve64, Variant::Gve64Phantom, Variant::Gve114})
        runCorpus(v, false);
}

TEST(CodecCrossCheck, EveryVariantWithChecksums)
{
    for (Variant v : {Variant::Gve84, Variant::Gve64, Variant::Gve64Phantom, Variant::Gve114})
        runCorpus(v, true);
}
