// The emulator core alone: bytes in, time, bytes out.
#include "driver/grinder/controlleremulator.h"
#include "driver/grinder/imagecheck.h"
#include "driver/grinder/zposition.h"

#include <gtest/gtest.h>

using namespace frezka::grinder;

namespace {

std::string text(const Bytes &bytes)
{
    return std::string(bytes.begin(), bytes.end());
}

Bytes ascii(const std::string &s)
{
    return Bytes(s.begin(), s.end());
}

EmulatorConfig zConfig()
{
    EmulatorConfig c;
    c.mode = TransferMode::ZPosition;
    c.replyDelayUs = 0;
    return c;
}

} // namespace

TEST(GrinderEmulator, Konfig6Numbering)
{
    EXPECT_EQ(transferModeFromKonfig6(0, false), TransferMode::None);
    EXPECT_EQ(transferModeFromKonfig6(1, false), TransferMode::ZPosition);
    EXPECT_EQ(transferModeFromKonfig6(2, false), TransferMode::Programs);
    EXPECT_EQ(transferModeFromKonfig6(3, false), TransferMode::Table);
    EXPECT_FALSE(transferModeFromKonfig6(4, false));
    EXPECT_FALSE(transferModeFromKonfig6(0xFF, false)); // unprogrammed EEPROM byte
    EXPECT_EQ(transferModeFromKonfig6(1, true), TransferMode::Programs);
    EXPECT_FALSE(transferModeFromKonfig6(2, true));
}

TEST(GrinderEmulator, AnswersEnqAfterItsReplyDelay)
{
    EmulatorConfig c;
    c.replyDelayUs = 5000;
    ControllerEmulator emu(c);
    emu.feed(encodeFrame(Frame::control(Framing::K51, Code::Enq)));
    EXPECT_TRUE(emu.takeOutput().empty());
    emu.advance(4999);
    EXPECT_TRUE(emu.takeOutput().empty());
    emu.advance(1);
    EXPECT_EQ(emu.takeOutput(), (Bytes{0xAA, 0x06, 0x00, 0x00, 0xFF, 0x50}));
}

TEST(GrinderEmulator, ModeNoneNeverAnswers)
{
    EmulatorConfig c;
    c.mode = TransferMode::None;
    ControllerEmulator emu(c);
    emu.feed(encodeFrame(Frame::control(Framing::K51, Code::Enq)));
    emu.advance(10'000'000);
    EXPECT_TRUE(emu.takeOutput().empty());
}

TEST(GrinderEmulator, BadChecksumIsAnsweredWithNak)
{
    EmulatorConfig c;
    c.replyDelayUs = 0;
    ControllerEmulator emu(c);
    Bytes load = encodeFrame(Frame::withData(Framing::K51, Code::Load, {}, Bytes(100, 7)));
    load[50] ^= 1;
    emu.feed(load);
    EXPECT_EQ(emu.takeOutput(), encodeFrame(Frame::control(Framing::K51, Code::Nak)));
    EXPECT_EQ(emu.checksumErrors(), 1);
    EXPECT_EQ(emu.loadsStored(), 0);
    EXPECT_EQ(emu.prenos(), 0x00);
}

TEST(GrinderEmulator, ResendsOnNakUpToItsLimit)
{
    EmulatorConfig c;
    c.replyDelayUs = 0;
    c.maxResends = 2;
    ControllerEmulator emu(c);
    emu.feed(encodeFrame(Frame::control(Framing::K51, Code::Request)));
    const Bytes sav = emu.takeOutput();
    EXPECT_EQ(sav.size(), 4 + 16 + kK51ImageSize + 2);
    const Bytes nak = encodeFrame(Frame::control(Framing::K51, Code::Nak));
    emu.feed(nak);
    EXPECT_EQ(emu.takeOutput(), sav);
    emu.feed(nak);
    EXPECT_EQ(emu.takeOutput(), sav);
    emu.feed(nak); // third NAK: the controller gives up
    EXPECT_TRUE(emu.takeOutput().empty());
}

// The manual: FORM=1 works only with the selector in PGN.
TEST(GrinderEmulator, Form1AnswersOnlyWithTheSelectorInPgn)
{
    EmulatorConfig c = zConfig();
    c.selectorInPgn = false;
    ControllerEmulator emu(c);
    emu.feed(ascii("Z? "));
    emu.advance(1'000'000);
    EXPECT_EQ(text(emu.takeOutput()), "");
}

TEST(GrinderEmulator, Form1GrammarAndErrors)
{
    ControllerEmulator emu(zConfig());
    emu.feed(ascii("Z? "));
    EXPECT_EQ(text(emu.takeOutput()), "Z=-0001.234 ");
    emu.feed(ascii("Z! Q"));
    EXPECT_EQ(text(emu.takeOutput()), "E0 E1 "); // '!' then 'Q'
    emu.feed(ascii("GO 12,5 "));                 // comma accepted, leading zeros optional
    emu.advance(2'000'000);                      // 13.734 mm at 20 mm/s
    EXPECT_EQ(text(emu.takeOutput()), "Z=0012.500 ");
    EXPECT_EQ(emu.zPositionUm(), 12500);
    emu.feed(ascii("GO 1.2345 ")); // four decimals: bad
    EXPECT_EQ(text(emu.takeOutput()), "E0 ");
}

TEST(GrinderEmulator, Form2SendsPeriodicFrames)
{
    EmulatorConfig c = zConfig();
    c.zForm = 2;
    c.zPeriodUs = 100'000;
    ControllerEmulator emu(c);
    emu.feed(ascii("Z? ")); // one way: ignored
    emu.advance(250'000);
    const Bytes out = emu.takeOutput();
    ASSERT_EQ(out.size(), 3 * kZBinaryFrameSize); // at 0, 100 and 200 ms
    EXPECT_EQ(Bytes(out.begin(), out.begin() + 4), encodeZBinary(-1234));
}

TEST(GrinderEmulator, NoiseComesBeforeEveryReply)
{
    EmulatorConfig c;
    c.replyDelayUs = 0;
    c.noise = true;
    ControllerEmulator emu(c);
    emu.feed(encodeFrame(Frame::control(Framing::K51, Code::Enq)));
    Bytes expected = emulatorNoise();
    const Bytes ack = encodeFrame(Frame::control(Framing::K51, Code::Ack));
    expected.insert(expected.end(), ack.begin(), ack.end());
    EXPECT_EQ(emu.takeOutput(), expected);
}
