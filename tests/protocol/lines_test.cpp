#include "protocol/lines.h"

#include <gtest/gtest.h>

using namespace frezka::protocol;

TEST(LineAssembler, SplitsOnCrAndIgnoresLfAfterCr)
{
    LineAssembler a;
    a.feed("!0PF\r\n!0F\r");
    ASSERT_TRUE(a.hasLine());
    EXPECT_EQ(a.next(), (Line{"!0PF", false}));
    EXPECT_EQ(a.next(), (Line{"!0F", false}));
    EXPECT_FALSE(a.hasLine());
    // An LF not after CR is data; an empty line is still a line (the caller reports it).
    a.feed("a\nb\r\r");
    EXPECT_EQ(a.next().text, "a\nb");
    EXPECT_EQ(a.next().text, "");
    // LF after CR across feed() calls.
    a.feed("x\r");
    a.feed("\ny\r");
    EXPECT_EQ(a.next().text, "x");
    EXPECT_EQ(a.next().text, "y");
}

TEST(LineAssembler, OneByteAtATime)
{
    LineAssembler a;
    const std::string s = "!0C697,30,0,51\r\n!0*E10,4D\r";
    for (char c : s)
        a.feed(std::string_view(&c, 1));
    EXPECT_EQ(a.next().text, "!0C697,30,0,51");
    EXPECT_EQ(a.next().text, "!0*E10,4D");
    EXPECT_FALSE(a.hasLine());
}

TEST(LineAssembler, OverlongIsOneBoundedError)
{
    LineAssembler a;
    const std::string exact(kMaxLineLength, 'a');
    a.feed(exact + "\r");
    EXPECT_EQ(a.next(), (Line{exact, false}));
    for (int i = 0; i < 10000; ++i)
        a.feed("b");
    EXPECT_TRUE(a.hasLine()); // reported as soon as it is too long, not at its CR
    EXPECT_TRUE(a.pending().empty());
    const Line l = a.next();
    EXPECT_TRUE(l.overlong);
    EXPECT_EQ(l.text, std::string(kMaxLineLength, 'b'));
    a.feed("bbb\rok\r");
    EXPECT_EQ(a.next(), (Line{"ok", false}));
    EXPECT_FALSE(a.hasLine());
}

TEST(LineAssembler, Clear)
{
    LineAssembler a;
    a.feed("0\rpartial");
    a.clear();
    EXPECT_FALSE(a.hasLine());
    EXPECT_TRUE(a.pending().empty());
}
