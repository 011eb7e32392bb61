#include "driver/grinder/zposition.h"

#include <gtest/gtest.h>

using namespace frezka::grinder;

namespace {
std::vector<ZReply> read(const std::string &text)
{
    ZAsciiReader reader;
    std::vector<ZReply> replies;
    for (char c : text) {
        const auto byte = static_cast<std::uint8_t>(c);
        reader.feed(&byte, 1, replies);
    }
    return replies;
}
} // namespace

TEST(GrinderZPosition, FormatAndParseMillimetres)
{
    EXPECT_EQ(formatMillimetres(-1234), "-0001.234");
    EXPECT_EQ(formatMillimetres(12123), "0012.123");
    EXPECT_EQ(formatMillimetres(-789), "-0000.789");
    EXPECT_EQ(parseMillimetres("-0001,234"), -1234); // the manual's comma
    EXPECT_EQ(parseMillimetres("0012.123"), 12123);
    EXPECT_EQ(parseMillimetres("12.1"), 12100); // leading zeros optional
    EXPECT_EQ(parseMillimetres("+5"), 5000);
    EXPECT_FALSE(parseMillimetres("1.2345"));
    EXPECT_FALSE(parseMillimetres("1x"));
    EXPECT_FALSE(parseMillimetres("-"));
    EXPECT_FALSE(parseMillimetres("."));
}

TEST(GrinderZPosition, MessagesOfTheManual)
{
    EXPECT_EQ(zQueryMessage(), "Z? ");
    EXPECT_EQ(goMessage(12123), "GO 0012.123 ");
    EXPECT_EQ(positionMessage(-1234), "Z=-0001.234 ");
}

TEST(GrinderZPosition, ReaderSplitsRepliesAtSpaces)
{
    const auto replies = read("Z=-0001,234 E0 E1  Z=-0000.789 Z=abc ");
    ASSERT_EQ(replies.size(), 5u);
    EXPECT_EQ(replies[0].kind, ZReply::Kind::Position);
    EXPECT_EQ(replies[0].positionUm, -1234);
    EXPECT_EQ(replies[1].kind, ZReply::Kind::BadFirst);
    EXPECT_EQ(replies[2].kind, ZReply::Kind::BadMore);
    EXPECT_EQ(replies[3].positionUm, -789);
    EXPECT_EQ(replies[4].kind, ZReply::Kind::Unknown);
    EXPECT_EQ(replies[4].text, "Z=abc");
}

TEST(GrinderZPosition, BinaryFramesRoundTripAndResync)
{
    for (std::int64_t um : {0LL, 1LL, -1LL, 1234567LL, -8388608LL, 8388607LL}) {
        const Bytes frame = encodeZBinary(um);
        ASSERT_EQ(frame.size(), 4u);
        EXPECT_EQ(std::uint8_t(frame[0] + frame[1] + frame[2] + frame[3]), 0);
        ZBinaryDecoder decoder;
        std::vector<ZBinaryEvent> events;
        decoder.feed(frame.data(), frame.size(), events);
        ASSERT_EQ(events.size(), 1u);
        EXPECT_EQ(events[0].positionUm, um);
    }
    EXPECT_EQ(encodeZBinary(0x010203), (Bytes{0x03, 0x02, 0x01, 0xFA})); // low, middle, high

    Bytes wire = {0x17}; // one stray byte before the stream
    for (std::int64_t um : {1000LL, -2000LL}) {
        const Bytes frame = encodeZBinary(um);
        wire.insert(wire.end(), frame.begin(), frame.end());
    }
    ZBinaryDecoder decoder;
    std::vector<ZBinaryEvent> events;
    decoder.feed(wire.data(), wire.size(), events);
    ASSERT_EQ(events.size(), 3u);
    EXPECT_FALSE(events[0].position);
    EXPECT_EQ(events[0].skipped, 0x17);
    EXPECT_EQ(events[1].positionUm, 1000);
    EXPECT_EQ(events[2].positionUm, -2000);
}
