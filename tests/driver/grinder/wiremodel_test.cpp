// The wire model (when bytes a port took have left the line) and the UART resampling that
// simulates a baud rate mismatch.
#include "driver/grinder/frame.h"
#include "driver/grinder/wiremodel.h"

#include <gtest/gtest.h>

using namespace frezka::grinder;

TEST(GrinderWire, BytesTakenAtOnceLeaveOneByteTimeApart)
{
    WireModel wire(9600); // 1041 us a byte
    wire.reset(0);
    wire.accepted(0, 21789); // a USB adapter takes the whole K51 message at once
    EXPECT_EQ(wire.endUs(), 21789 * 1041);
    EXPECT_EQ(wire.sentBy(0), 0);
    EXPECT_EQ(wire.sentBy(1041 * 960), 960); // one second later
    EXPECT_EQ(wire.sentBy(wire.endUs()), 21789);
}

TEST(GrinderWire, ChunksTakenLaterQueueBehindTheEarlierOnes)
{
    WireModel wire(4800); // 2083 us a byte
    wire.reset(0);
    wire.accepted(0, 100);
    wire.accepted(10'000, 100); // still on the wire: queued behind
    EXPECT_EQ(wire.endUs(), 200 * 2083);
    wire.accepted(10'000'000, 10); // the line was idle: starts now
    EXPECT_EQ(wire.endUs(), 10'000'000 + 10 * 2083);
    EXPECT_EQ(wire.acceptedBytes(), 210);
}

TEST(GrinderWire, TheSameRateReadsTheSameBytes)
{
    const Bytes enq = encodeFrame(Frame::control(Framing::K51, Code::Enq));
    EXPECT_EQ(resampleUart(enq, 9600, 9600), enq);
    Bytes all(256);
    for (int i = 0; i < 256; ++i)
        all[std::size_t(i)] = std::uint8_t(i);
    // 2 % apart is within what a UART tolerates.
    EXPECT_EQ(resampleUart(all, 9600, 9792), all);
}

TEST(GrinderWire, AMismatchGarblesEveryMessage)
{
    const Bytes enq = encodeFrame(Frame::control(Framing::K51, Code::Enq));
    const Bytes slow = resampleUart(enq, 9600, 4800); // the receiver is too slow
    const Bytes fast = resampleUart(enq, 4800, 9600); // the receiver is too fast
    EXPECT_NE(slow, enq);
    EXPECT_NE(fast, enq);
    EXPECT_LT(slow.size(), enq.size()); // it misses start bits
    EXPECT_GT(fast.size(), enq.size()); // it finds start bits inside bytes
}
