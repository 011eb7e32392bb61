// Reply decoding: the manuals' reply table and checksummed replies, value shapes, garbage.

#include "protocol/reply.h"

#include <gtest/gtest.h>

#include <random>

using namespace frezka::protocol;

namespace {
Reply ok(std::vector<std::string> values = {})
{
    return Reply{ReplyCode::Ok, false, std::move(values)};
}
} // namespace

// §2: !0L1000,0,0 -> 0; !0PF -> 0,-1000,2000,50; !0C100,20,0 -> 1; !0V1000 -> 8;
// !0SW8,F1 -> 5; !0SR2 -> 0,2B.
TEST(ReplyDecode, ManualReplyTable)
{
    EXPECT_EQ(decodeReply("0", ChecksumMode::Off).reply, ok());
    const auto pf = decodeReply("0,-1000,2000,50", ChecksumMode::Off);
    ASSERT_TRUE(pf.reply);
    EXPECT_EQ(pf.reply->decimals(), (std::vector<std::int64_t>{-1000, 2000, 50}));
    EXPECT_FALSE(checkReplyShape(cmd::positionXYZ(), *pf.reply, "0,-1000,2000,50"));
    const auto full = decodeReply("1", ChecksumMode::Off);
    EXPECT_EQ(full.reply->code, ReplyCode::QueueFull);
    EXPECT_FALSE(full.reply->inta);
    const auto inta = decodeReply("8", ChecksumMode::Off);
    EXPECT_EQ(inta.reply->code, ReplyCode::Ok);
    EXPECT_TRUE(inta.reply->inta);
    EXPECT_EQ(decodeReply("5", ChecksumMode::Off).reply->code, ReplyCode::OutOfRange);
    const auto sr2 = decodeReply("0,2B", ChecksumMode::Off);
    EXPECT_EQ(sr2.reply->hexValue(), 0x2B);
    EXPECT_FALSE(checkReplyShape(cmd::statusRead(2), *sr2.reply, "0,2B"));
}

TEST(ReplyDecode, EveryStatusDigit)
{
    for (int d = 0; d < 16; ++d) {
        const std::string line(1, "0123456789ABCDEF"[d]);
        const auto r = decodeReply(line, ChecksumMode::Off);
        ASSERT_TRUE(r.reply) << line;
        EXPECT_EQ(static_cast<int>(r.reply->code), d & 7);
        EXPECT_EQ(r.reply->inta, d >= 8);
        EXPECT_EQ(encodeReply(*r.reply, false), line + "\r");
    }
}

TEST(ReplyDecode, ChecksummedManualReplies)
{
    // %+ -> 0,5C ; packet -> 0,10,E9.
    const auto on = decodeReply("0,5C", ChecksumMode::On);
    EXPECT_EQ(on.reply, ok());
    EXPECT_TRUE(on.checksummed);
    const auto packet = decodeReply("0,10,E9", ChecksumMode::On);
    EXPECT_EQ(packet.reply, ok({"10"}));
    EXPECT_EQ(packet.reply->decimal(), 10);
    EXPECT_FALSE(checkReplyShape(cmd::packetEnd(10), *packet.reply, "0,10,E9"));
    EXPECT_EQ(encodeReply(ok({"10"}), true), "0,10,E9\r");
    EXPECT_EQ(encodeReply(ok(), true), "0,5C\r");
    // Without checksum mode the same text is two values.
    EXPECT_EQ(decodeReply("0,10,E9", ChecksumMode::Off).reply, ok({"10", "E9"}));
}

TEST(ReplyDecode, ChecksumErrors)
{
    EXPECT_EQ(decodeReply("0,10,E8", ChecksumMode::On).error->kind, DecodeErrorKind::BadChecksum);
    // "0,10": the last field looks like a checksum, and a wrong one.
    EXPECT_EQ(decodeReply("0,10", ChecksumMode::On).error->kind, DecodeErrorKind::BadChecksum);
    EXPECT_EQ(decodeReply("0,100", ChecksumMode::On).error->kind, DecodeErrorKind::MissingChecksum);
    EXPECT_EQ(decodeReply("0", ChecksumMode::On).error->kind, DecodeErrorKind::MissingChecksum);
    const auto bad = decodeReply("0,11,E9", ChecksumMode::On);
    ASSERT_TRUE(bad.error);
    EXPECT_EQ(bad.error->raw, "0,11,E9");
    // Auto: strips a valid checksum, leaves anything else alone.
    const auto a1 = decodeReply("0,10,E9", ChecksumMode::Auto);
    EXPECT_EQ(a1.reply, ok({"10"}));
    EXPECT_TRUE(a1.checksummed);
    const auto a2 = decodeReply("0", ChecksumMode::Auto);
    EXPECT_EQ(a2.reply, ok());
    EXPECT_FALSE(a2.checksummed);
    EXPECT_EQ(decodeReply("0,2B", ChecksumMode::Auto).reply, ok({"2B"}));
}

TEST(ReplyDecode, PacketPartialFailure)
{
    // Adopted reading §2.2: 1,6 = six accepted, the seventh hit a full queue.
    const std::string line = encodeReply(Reply{ReplyCode::QueueFull, false, {"6"}}, true);
    ASSERT_EQ(line.back(), '\r');
    const auto r = decodeReply(std::string_view(line).substr(0, line.size() - 1), ChecksumMode::On);
    ASSERT_TRUE(r.reply);
    EXPECT_EQ(r.reply->code, ReplyCode::QueueFull);
    EXPECT_EQ(r.reply->decimal(), 6);
    EXPECT_FALSE(checkReplyShape(cmd::packetEnd(10), *r.reply, line));
}

TEST(ReplyDecode, Malformed)
{
    EXPECT_EQ(decodeReply("", ChecksumMode::Off).error->kind, DecodeErrorKind::Empty);
    EXPECT_EQ(decodeReply("G", ChecksumMode::Off).error->kind, DecodeErrorKind::BadStatus);
    EXPECT_EQ(decodeReply("01", ChecksumMode::Off).error->kind, DecodeErrorKind::BadStatus);
    EXPECT_EQ(decodeReply("0,", ChecksumMode::Off).error->kind, DecodeErrorKind::BadValues);
    EXPECT_EQ(decodeReply("0,1,,2", ChecksumMode::Off).error->kind, DecodeErrorKind::BadValues);
    EXPECT_EQ(decodeReply(std::string("0\x01", 2), ChecksumMode::Off).error->kind,
              DecodeErrorKind::BadCharacter);
    EXPECT_EQ(decodeReply("0\xff", ChecksumMode::Off).error->kind, DecodeErrorKind::BadCharacter);
}

TEST(ReplyShape, ValuesFitTheCommand)
{
    auto shape = [](const Command &c, const std::string &line) {
        const auto r = decodeReply(line, ChecksumMode::Off);
        EXPECT_TRUE(r.reply) << line;
        return checkReplyShape(c, *r.reply, line);
    };
    EXPECT_FALSE(shape(cmd::positionXY(), "0,1,2"));
    EXPECT_TRUE(shape(cmd::positionXY(), "0,1,2,3"));
    EXPECT_TRUE(shape(cmd::positionXYZ(), "0,1,2"));
    EXPECT_TRUE(shape(cmd::positionXYZ(), "0,1,x,3"));
    EXPECT_FALSE(shape(cmd::positionXYZA(), "0,1,2,3,-4"));
    EXPECT_FALSE(shape(cmd::version(), "0,IP64MPG v19 10.9.2010"));
    EXPECT_TRUE(shape(cmd::version(), "0"));
    EXPECT_FALSE(shape(cmd::identify(), "0,25020304"));
    EXPECT_TRUE(shape(cmd::identify(), "0,2502030"));
    EXPECT_FALSE(shape(cmd::flag(), "0,C0"));
    EXPECT_TRUE(shape(cmd::flag(), "0,C"));
    EXPECT_TRUE(shape(cmd::flag(), "0,GG"));
    EXPECT_FALSE(shape(cmd::input2(), "0,80"));
    EXPECT_FALSE(shape(cmd::eepromReadByte(5), "0,FF"));
    EXPECT_FALSE(shape(cmd::eepromReadFloat(0x30), "0,400.5"));
    EXPECT_TRUE(shape(cmd::eepromReadFloat(0x30), "0,abc"));
    EXPECT_FALSE(shape(cmd::eepromReadUint(0x48), "0,200"));
    EXPECT_TRUE(shape(cmd::eepromReadUint(0x48), "0,-1"));
    EXPECT_FALSE(shape(cmd::index(), "0,255"));
    EXPECT_TRUE(shape(cmd::index(), "0,256"));
    EXPECT_FALSE(shape(cmd::vector(1, 2, 3), "0"));
    EXPECT_FALSE(shape(cmd::vector(1, 2, 3), "9"));
    EXPECT_TRUE(shape(cmd::vector(1, 2, 3), "0,5"));
    EXPECT_TRUE(shape(cmd::positionXYZ(), "7,1,2,3")); // error replies carry no values
    EXPECT_FALSE(shape(cmd::positionXYZ(), "7"));
    EXPECT_FALSE(shape(cmd::mpgOff(), "0"));
    EXPECT_FALSE(shape(cmd::mpgOff(), "0,Y-"));
    EXPECT_FALSE(shape(cmd::repeat(), "0,1,2,3"));
    const auto err = shape(cmd::positionXYZ(), "0,1,2");
    ASSERT_TRUE(err);
    EXPECT_NE(err->message.find("!0PF"), std::string::npos);
    EXPECT_EQ(err->raw, "0,1,2");
}

TEST(ReplyDecoder, OneByteAtATime)
{
    ReplyDecoder d;
    const std::string stream = "0,10,E9\r0,5C\r\n1,6,";
    std::vector<ReplyResult> got;
    for (char c : stream) {
        d.feed(std::string_view(&c, 1));
        while (auto r = d.next(ChecksumMode::On))
            got.push_back(*r);
    }
    ASSERT_EQ(got.size(), 2u);
    EXPECT_EQ(got[0].reply, ok({"10"}));
    EXPECT_EQ(got[1].reply, ok());
    EXPECT_EQ(d.pending(), "1,6,");
    d.feed("BF\r"); // sum("1,6,") = 0x31 + 0x2C + 0x36 + 0x2C = 0xBF
    const auto last = d.next(ChecksumMode::On);
    ASSERT_TRUE(last && last->reply);
    EXPECT_EQ(last->reply->code, ReplyCode::QueueFull);
    EXPECT_EQ(last->reply->decimal(), 6);
}

TEST(ReplyDecoder, GarbageThenRecovery)
{
    ReplyDecoder d;
    d.feed(std::string("\x00\xff#~0,,zz\r", 10));
    const auto g = d.next(ChecksumMode::Off);
    ASSERT_TRUE(g && g->error);
    EXPECT_EQ(g->error->kind, DecodeErrorKind::BadCharacter);
    EXPECT_EQ(g->error->raw, std::string("\x00\xff#~0,,zz", 9));
    d.feed(std::string(1000, 'x')); // overlong: one error, bounded memory
    d.feed("yyy\r0,-5,6,7\r");
    const auto o = d.next(ChecksumMode::Off);
    ASSERT_TRUE(o && o->error);
    EXPECT_EQ(o->error->kind, DecodeErrorKind::Overlong);
    EXPECT_EQ(o->error->raw.size(), kMaxLineLength);
    const auto good = d.next(ChecksumMode::Off);
    ASSERT_TRUE(good && good->reply);
    EXPECT_EQ(good->reply->decimals(), (std::vector<std::int64_t>{-5, 6, 7}));
    EXPECT_FALSE(d.next(ChecksumMode::Off));
}

// Seeded random bytes in random splits: never a crash, every line is a reply or an error with
// its raw text, and a valid reply afterwards still decodes.
TEST(ReplyDecoder, RandomGarbageFuzz)
{
    std::mt19937 rng(1234);
    for (int round = 0; round < 200; ++round) {
        ReplyDecoder d;
        std::string bytes;
        const int n = static_cast<int>(rng() % 400);
        for (int i = 0; i < n; ++i)
            bytes += static_cast<char>(rng() % 7 == 0 ? '\r' : rng() % 256);
        bytes += "\r0,10,E9\r";
        std::size_t pos = 0;
        std::vector<ReplyResult> got;
        while (pos < bytes.size()) {
            const std::size_t len = std::min<std::size_t>(1 + rng() % 9, bytes.size() - pos);
            d.feed(std::string_view(bytes).substr(pos, len));
            pos += len;
            while (auto r = d.next(ChecksumMode::On)) {
                EXPECT_NE(r->reply.has_value(), r->error.has_value());
                got.push_back(*r);
            }
            EXPECT_LE(d.pending().size(), kMaxLineLength);
        }
        ASSERT_FALSE(got.empty());
        EXPECT_EQ(got.back().reply, ok({"10"}));
    }
}
