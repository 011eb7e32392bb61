#include "driver/grinder/frame.h"

#include <gtest/gtest.h>

using namespace frezka::grinder;

namespace {
Bytes k51Control(Code code)
{
    return encodeFrame(Frame::control(Framing::K51, code));
}
} // namespace

// Tab. 5 of the manual, byte for byte.
TEST(GrinderFrame, ManualExamples)
{
    EXPECT_EQ(k51Control(Code::Enq), (Bytes{0xAA, 0x05, 0x00, 0x00, 0xFF, 0x51}));
    EXPECT_EQ(k51Control(Code::Ack), (Bytes{0xAA, 0x06, 0x00, 0x00, 0xFF, 0x50}));
    EXPECT_EQ(k51Control(Code::Nak), (Bytes{0xAA, 0x07, 0x00, 0x00, 0xFF, 0x4F}));
    EXPECT_EQ(k51Control(Code::Request), (Bytes{0xAA, 0x20, 0x00, 0x00, 0xFF, 0x36}));
}

TEST(GrinderFrame, AncControlHasOneByteChecksum)
{
    const Bytes enq = encodeFrame(Frame::control(Framing::Anc, Code::Enq));
    EXPECT_EQ(enq, (Bytes{0xAA, 0x05, 0x00, 0x00, 0x51}));
}

TEST(GrinderFrame, K51DataMessageLayout)
{
    const Frame frame =
        Frame::withData(Framing::K51, Code::Load, headerFromText("PRG7"), Bytes{1, 2, 3});
    const Bytes wire = encodeFrame(frame);
    ASSERT_EQ(wire.size(), 4u + 16 + 3 + 2);
    EXPECT_EQ(wire[2], 0x00);
    EXPECT_EQ(wire[3], 19); // length counts header + data
    EXPECT_EQ(wire[4], 'P');
    EXPECT_EQ(wire[8], ' '); // header padded with spaces
    EXPECT_EQ(wire[20], 1);
    unsigned sum = 0;
    for (std::size_t i = 0; i + 2 < wire.size(); ++i)
        sum += wire[i];
    sum += (wire[wire.size() - 2] << 8) | wire.back();
    EXPECT_EQ(sum & 0xFFFF, 0u); // whole message sums to zero (16 bit)
}

TEST(GrinderFrame, AncDataMessageSumsToZero)
{
    Bytes data(0x5506);
    for (std::size_t i = 0; i < data.size(); ++i)
        data[i] = std::uint8_t(i * 7);
    const Bytes wire = encodeFrame(Frame::withData(Framing::Anc, Code::AncLoad, {}, data));
    ASSERT_EQ(wire.size(), 4u + 0x5506 + 1);
    EXPECT_EQ(wire[2], 0x55);
    EXPECT_EQ(wire[3], 0x06);
    std::uint8_t sum = 0;
    for (std::uint8_t byte : wire)
        sum = std::uint8_t(sum + byte);
    EXPECT_EQ(sum, 0);
}

TEST(GrinderFrame, InvalidFramesAreNotEncoded)
{
    Frame wrongFamily = Frame::control(Framing::Anc, Code::Request);
    EXPECT_EQ(validateFrame(wrongFamily), FrameError::UnknownCode);
    EXPECT_TRUE(encodeFrame(wrongFamily).empty());
    Frame controlWithData = Frame::control(Framing::K51, Code::Ack);
    controlWithData.data = {1};
    EXPECT_EQ(validateFrame(controlWithData), FrameError::DataInControl);
    Frame huge = Frame::withData(Framing::K51, Code::Load, {}, Bytes(0xFFFF - 15));
    EXPECT_EQ(validateFrame(huge), FrameError::PayloadTooLarge);
    huge.data.pop_back();
    EXPECT_EQ(validateFrame(huge), FrameError::None);
}

TEST(GrinderFrame, HeaderText)
{
    EXPECT_EQ(headerText(headerFromText("HRIDEL 42")), "HRIDEL 42");
    EXPECT_EQ(headerText(headerFromText("0123456789ABCDEFGH")), "0123456789ABCDEF");
    Header raw{};
    raw[0] = 'A';
    raw[1] = 0x01;
    EXPECT_EQ(headerText(raw), "A.");
    EXPECT_EQ(codeName(Framing::K51, 0x22), "DEJ2");
    EXPECT_EQ(codeName(Framing::Anc, 0x22), "0x22");
    EXPECT_EQ(hexDump(Bytes{0xAA, 0x05}), "AA 05");
}
