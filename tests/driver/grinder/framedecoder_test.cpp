#include "driver/grinder/framedecoder.h"

#include <gtest/gtest.h>

using namespace frezka::grinder;

namespace {

std::vector<DecodeEvent> decodeByteByByte(Framing framing, const Bytes &wire)
{
    FrameDecoder decoder(framing);
    std::vector<DecodeEvent> events;
    for (std::uint8_t byte : wire)
        decoder.feed(&byte, 1, events);
    return events;
}

Bytes programData(std::size_t size)
{
    Bytes data(size);
    for (std::size_t i = 0; i < size; ++i)
        data[i] = (i % 0x800 == 0) ? 0xAA : std::uint8_t(i * 13 + 5); // inner AA bytes
    return data;
}

} // namespace

TEST(GrinderDecoder, RoundTripsEveryCodeOneByteAtATime)
{
    const Header header = headerFromText("TEST");
    for (Code code :
         {Code::Enq, Code::Ack, Code::Nak, Code::Request, Code::RequestHardChrome, Code::Load,
          Code::LoadTable, Code::LoadHardChrome, Code::Save, Code::SaveHardChrome}) {
        const Frame frame =
            Frame::withData(Framing::K51, code, header,
                            isControlCode(Framing::K51, code) ? Bytes{} : programData(300));
        const auto events = decodeByteByByte(Framing::K51, encodeFrame(frame));
        ASSERT_EQ(events.size(), 1u) << codeName(Framing::K51, std::uint8_t(code));
        EXPECT_EQ(events[0].kind, DecodeEvent::Kind::Frame);
        EXPECT_EQ(events[0].frame, frame);
    }
    for (Code code : {Code::Enq, Code::Ack, Code::Nak, Code::AncLoad, Code::AncSave}) {
        const Frame frame =
            Frame::withData(Framing::Anc, code, {},
                            isControlCode(Framing::Anc, code) ? Bytes{} : programData(0x5506));
        const auto events = decodeByteByByte(Framing::Anc, encodeFrame(frame));
        ASSERT_EQ(events.size(), 1u);
        EXPECT_EQ(events[0].frame, frame);
    }
}

TEST(GrinderDecoder, SkipsNoiseBetweenFramesAndReportsIt)
{
    // Noise holding AA bytes followed by codes and lengths that do not fit.
    const Bytes noise = {0x00, 0x13, 0xAA, 0x99, 0xFF, 0xAA, 0x06, 0x00, 0x05, 0xAA, 0xAA};
    const Frame ack = Frame::control(Framing::K51, Code::Ack);
    const Frame sav =
        Frame::withData(Framing::K51, Code::Save, headerFromText("X"), programData(0x5507));
    Bytes wire = noise;
    const Bytes ackWire = encodeFrame(ack);
    wire.insert(wire.end(), ackWire.begin(), ackWire.end());
    wire.insert(wire.end(), noise.begin(), noise.end());
    const Bytes savWire = encodeFrame(sav);
    wire.insert(wire.end(), savWire.begin(), savWire.end());

    const auto events = decodeByteByByte(Framing::K51, wire);
    ASSERT_EQ(events.size(), 4u);
    EXPECT_EQ(events[0].kind, DecodeEvent::Kind::Noise);
    EXPECT_EQ(events[0].noise, noise);
    EXPECT_EQ(events[1].frame, ack);
    EXPECT_EQ(events[2].noise, noise);
    EXPECT_EQ(events[3].kind, DecodeEvent::Kind::Frame);
    EXPECT_EQ(events[3].frame, sav);
}

TEST(GrinderDecoder, ReportsChecksumFailureAndContinues)
{
    const Frame load =
        Frame::withData(Framing::K51, Code::Load, headerFromText("A"), programData(100));
    Bytes wire = encodeFrame(load);
    wire[30] ^= 0x01;
    const Bytes ack = encodeFrame(Frame::control(Framing::K51, Code::Ack));
    wire.insert(wire.end(), ack.begin(), ack.end());

    FrameDecoder decoder(Framing::K51);
    std::vector<DecodeEvent> events;
    decoder.feed(wire, events);
    ASSERT_EQ(events.size(), 2u);
    EXPECT_EQ(events[0].kind, DecodeEvent::Kind::ChecksumError);
    EXPECT_NE(events[0].receivedSum, events[0].expectedSum);
    EXPECT_EQ(events[0].frame.code, Code::Load);
    EXPECT_EQ(events[1].kind, DecodeEvent::Kind::Frame);
    EXPECT_EQ(events[1].frame.code, Code::Ack);
}

TEST(GrinderDecoder, ProgressAndReset)
{
    const Bytes wire = encodeFrame(Frame::withData(Framing::Anc, Code::AncSave, {}, Bytes(1000)));
    FrameDecoder decoder(Framing::Anc);
    std::vector<DecodeEvent> events;
    decoder.feed(wire.data(), 3, events);
    EXPECT_EQ(decoder.pendingTotal(), 0u); // length not known yet
    decoder.feed(wire.data() + 3, 500, events);
    EXPECT_EQ(decoder.pendingBytes(), 503u);
    EXPECT_EQ(decoder.pendingTotal(), 1005u);
    EXPECT_TRUE(events.empty());
    decoder.reset(events);
    ASSERT_EQ(events.size(), 1u);
    EXPECT_EQ(events[0].noise.size(), 503u); // nothing goes unaccounted
    EXPECT_EQ(decoder.pendingBytes(), 0u);
}

TEST(GrinderDecoder, AncCodesAreNoiseToK51)
{
    const Bytes anc = encodeFrame(Frame::control(Framing::Anc, Code::Enq)); // 5 bytes
    const auto events = decodeByteByByte(Framing::K51, anc);
    // A K51 decoder sees AA 05 00 00 51 and waits for the second checksum byte.
    EXPECT_TRUE(events.empty());
    const auto ancLoad = decodeByteByByte(
        Framing::K51, encodeFrame(Frame::withData(Framing::Anc, Code::AncLoad, {}, Bytes{1})));
    ASSERT_EQ(ancLoad.size(), 0u); // still scanning; nothing accepted as a frame
}
