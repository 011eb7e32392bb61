// The serial trace's format, its replay and the session's recorder ring (docs/serial-trace.md).

#include "driver/emulator/serialtrace.h"
#include "driver/emulator/tracereplay.h"
#include "driver/link/tracerecorder.h"

#include <gtest/gtest.h>

using namespace frezka;
using emulator::SerialTrace;
using emulator::TraceDirection;
using emulator::TraceEntry;
using emulator::TraceMessage;

namespace {

SerialTrace parsed(const std::string &text)
{
    SerialTrace t;
    TraceMessage error;
    EXPECT_TRUE(emulator::parseTrace(text, t, error)) << emulator::englishText(error);
    return t;
}

std::string parseError(const std::string &text)
{
    SerialTrace t;
    TraceMessage error;
    EXPECT_FALSE(emulator::parseTrace(text, t, error));
    return emulator::englishText(error);
}

const std::string kHead = std::string(emulator::kTraceMagic) + "\n# variant: gve64\n";

} // namespace

TEST(SerialTrace, EveryByteSurvivesTheFile)
{
    SerialTrace t;
    t.set("variant", "gve114");
    t.set("operation", "connect");
    std::string all;
    for (int b = 0; b < 256; ++b)
        all += static_cast<char>(b);
    t.entries = {{TraceDirection::ToUnit, 0, "!0?\r", 0},
                 {TraceDirection::ToPc, 1.234567, all, 0},
                 {TraceDirection::Event, 2.5, "mode Idle", 0}};
    const std::string text = emulator::formatTrace(t);
    const SerialTrace back = parsed(text);
    ASSERT_EQ(back.entries.size(), 3u);
    EXPECT_EQ(back.entries[1].bytes, all);
    EXPECT_EQ(back.entries[1].timeMs, 1.234567);
    EXPECT_EQ(back.entries[2].bytes, "mode Idle");
    EXPECT_EQ(back.value("variant"), "gve114");
    EXPECT_EQ(back.entries[0].fileLine + 1, back.entries[1].fileLine);
    EXPECT_EQ(emulator::formatTraceEntry(t.entries[0]), "      0.000000 > !0?\\r | 21 30 3F 0D");
    EXPECT_EQ(emulator::escapeTraceBytes("a|b\\\n"), "a\\x7Cb\\\\\\n");
}

TEST(SerialTrace, HandWrittenLinesNeedNoHexColumn)
{
    const SerialTrace t = parsed(kHead + "  5 > !0P\\r\n  7.5 < 0,1,2\\r\n");
    ASSERT_EQ(t.entries.size(), 2u);
    EXPECT_EQ(t.entries[1].bytes, "0,1,2\r");
    EXPECT_EQ(t.entries[1].fileLine, 4);
}

TEST(SerialTrace, BadLinesAreNamed)
{
    EXPECT_EQ(parseError("hello\n"),
              "line 1: not a Frezka serial trace (it must start with '# frezka-serial-trace 1')");
    EXPECT_NE(parseError(kHead + "1 > !0P\\r\n2 ? x\n").find("line 4: the direction"),
              std::string::npos);
    EXPECT_NE(parseError(kHead + "1 < 0\\r | 31 0D\n").find("line 3: the hex column"),
              std::string::npos);
    EXPECT_NE(parseError(kHead + "x < 0\\r\n").find("line 3: not an entry"), std::string::npos);
    EXPECT_NE(parseError(kHead + "1 < 0\\q\n").find("line 3: a bad escape"), std::string::npos);
}

TEST(TraceReplay, RepliesWhenTheRecordedCommandComesWithItsTiming)
{
    emulator::TraceReplay r(
        parsed(kHead + "0 > !0P\\r\n2.5 < 0,1,2\\r\n3 > !0F\\r\n4 < 0,40\\r\n"));
    r.advance(1.0);
    r.pcWrite("!0");
    EXPECT_EQ(r.nextEventIn(), std::numeric_limits<double>::infinity());
    r.pcWrite("P\r");
    EXPECT_DOUBLE_EQ(r.nextEventIn(), 0.0025);
    r.advance(0.002);
    EXPECT_EQ(r.pcRead(), "");
    r.advance(0.0005);
    EXPECT_EQ(r.pcRead(), "0,1,2\r");
    EXPECT_EQ(r.lastReplyLine(), 4);
    EXPECT_FALSE(r.finished());
    r.pcWrite("!0F\r");
    r.advance(0.001);
    EXPECT_EQ(r.pcRead(), "0,40\r");
    EXPECT_TRUE(r.finished());
    r.pcWrite("!0P\r"); // past the end of the record: counted, no error
    EXPECT_EQ(r.commandsAfterEnd(), 1);
    EXPECT_FALSE(r.divergence());
}

TEST(TraceReplay, AnotherCommandNamesTheLineExpectedAndGot)
{
    emulator::TraceReplay r(
        parsed(kHead + "0 > !0P\\r\n1 < 0,1,2\\r\n2 = mode Idle\n3 > !0F\\r\n"));
    r.pcWrite("!0P\r");
    r.advance(0.001);
    r.pcRead();
    r.pcWrite("!0I1\r");
    ASSERT_TRUE(r.divergence());
    EXPECT_EQ(r.divergence().line, 6);
    EXPECT_EQ(emulator::englishText(r.divergence()),
              "trace line 6: expected '!0F\\r', got '!0I1\\r' (the last unit line given was trace "
              "line 4)");
    r.advance(1);
    EXPECT_EQ(r.pcRead(), ""); // silent after a divergence
}

TEST(TraceReplay, ACommandBeforeTheRecordedReplyIsADivergence)
{
    emulator::TraceReplay r(parsed(kHead + "0 > !0H\\r\n900 < 8\\r\n901 > !0P\\r\n"));
    r.pcWrite("!0H\r");
    r.advance(0.5);
    r.pcWrite("!0P\r"); // the driver gave up on H too early
    ASSERT_TRUE(r.divergence());
    EXPECT_EQ(r.divergence().line, 4);
}

// A record made on the wall clock: the driver's polls come where its own clock puts them.
TEST(TraceReplay, FreePollsMayComeElsewhereOtherCommandsMayNot)
{
    const std::string text = kHead + "0 > !0P4,01\\r\n1 < 0,5,0,0,0,AA\\r\n"
                                     "2 > !0F,C3\\r\n3 < 0,40,E8\\r\n"
                                     "4 > !0L10,0,0,6C\\r\n5 < 0,5C\\r\n"
                                     "6 > !0P4,01\\r\n7 < 0,15,0,0,0,AB\\r\n";
    {
        emulator::TraceReplay strict(parsed(text));
        strict.pcWrite("!0L10,0,0,6C\r"); // the driver did not poll first
        EXPECT_TRUE(strict.divergence());
    }
    emulator::TraceReplay r(parsed(text), true);
    r.pcWrite("!0L10,0,0,6C\r"); // the polls before it are passed over
    r.advance(0.001);
    EXPECT_EQ(r.pcRead(), "0,5C\r");
    r.pcWrite("!0F,C3\r"); // a poll the record has not here: answered as last recorded
    r.advance(0.001);
    EXPECT_EQ(r.pcRead(), "0,40,E8\r");
    EXPECT_EQ(r.pollsAnsweredFree(), 1);
    EXPECT_TRUE(r.finished()); // the last poll of the record need not come
    r.pcWrite("!0P4,01\r");
    r.advance(0.001);
    EXPECT_EQ(r.pcRead(), "0,15,0,0,0,AB\r");
    EXPECT_TRUE(r.finished());
    r.pcWrite("!0D\r"); // after the end: not an error
    r.pcWrite("!0L1,0,0,00\r");
    EXPECT_FALSE(r.divergence());
    emulator::TraceReplay other(parsed(text), true);
    other.pcWrite("!0L11,0,0,6D\r"); // another move is never free
    ASSERT_TRUE(other.divergence());
    EXPECT_EQ(other.divergence().line, 7);
    EXPECT_TRUE(emulator::TraceReplay::isRoutinePoll("!0PF,13\r"));
    EXPECT_FALSE(emulator::TraceReplay::isRoutinePoll("!0P4X\r"));
    EXPECT_FALSE(emulator::TraceReplay::isRoutinePoll("!7F\r"));
}

TEST(TraceRecorder, CutsLinesAtCrAndKeepsTheNewestWithinItsLimit)
{
    driver::TraceRecorder rec;
    rec.setProgramVersion("Frezka test");
    rec.begin({{"variant", "gve64"}}, 10.0);
    rec.record(TraceDirection::ToUnit, "!0P\r!0", 10.001);
    rec.record(TraceDirection::ToUnit, "F\r", 10.002);
    rec.record(TraceDirection::ToPc, "0,1", 10.003);
    rec.note("mode Idle", 10.004);
    SerialTrace t = rec.snapshot();
    ASSERT_EQ(t.entries.size(), 4u);
    EXPECT_EQ(t.entries[0].bytes, "!0P\r");
    EXPECT_NEAR(t.entries[1].timeMs, 2.0, 1e-6);
    EXPECT_EQ(t.entries[3].bytes, "0,1"); // the open line comes last
    EXPECT_EQ(t.value("frezka"), "Frezka test");
    rec.setLimitBytes(100); // about three short lines
    for (int i = 0; i < 50; ++i)
        rec.record(TraceDirection::ToUnit, "!0C" + std::to_string(i) + ",0,0\r", 11.0 + i);
    t = rec.snapshot();
    ASSERT_FALSE(t.entries.empty());
    EXPECT_LT(t.entries.size(), 5u);
    EXPECT_EQ(t.entries.back().bytes.substr(0, 6), "0,1"); // still open
    EXPECT_EQ(t.entries[t.entries.size() - 2].bytes, "!0C49,0,0\r");
    EXPECT_NE(t.value("dropped"), "");
    rec.setLimitBytes(0);
    rec.record(TraceDirection::ToUnit, "!0P\r", 70);
    EXPECT_FALSE(rec.enabled());
}
