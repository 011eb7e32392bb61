// MdiSession: the console keeps its modes between lines (G91, G20, F, the coordinate system),
// follows the machine when it moved elsewhere, and hands G10 / G92 back to the offsets.
#include "session/mdisession.h"

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

Axes4 endOf(const MdiSession::Outcome &o)
{
    const gcode::Point4 p = o.toolpath.last();
    return {p.x, p.y, p.z, p.a};
}

// The machine follows the console exactly (as after an executed line).
struct Console
{
    MdiSession mdi;
    Axes4 machine{};
    OffsetState offsets;
    MdiSession::Outcome line(const char *text)
    {
        MdiSession::Outcome o = mdi.interpret(text, machine, offsets);
        EXPECT_TRUE(o.ok()) << text << ": " << (o.ok() ? "" : o.errors.front().detail);
        machine = endOf(o);
        if (o.offsetsChanged)
            offsets = o.offsets;
        return o;
    }
};

TEST(MdiSession, IncrementalModeLastsBetweenLines)
{
    Console c;
    c.line("G91");
    c.line("G1 X1 F100");
    const auto o = c.line("G1 X1");
    EXPECT_DOUBLE_EQ(c.machine[0], 2.0);
    EXPECT_DOUBLE_EQ(o.toolpath.origin().x, 1.0);
    EXPECT_FALSE(c.mdi.modal().absolute);
}

TEST(MdiSession, InchesLastBetweenLines)
{
    Console c;
    c.line("G20");
    c.line("G1 X1 F10");
    EXPECT_DOUBLE_EQ(c.machine[0], 25.4);
    EXPECT_FALSE(c.mdi.modal().metric);
}

TEST(MdiSession, FeedAndMotionModeCarryOver)
{
    Console c;
    c.line("G1 X5 F250");
    const auto o = c.line("X10"); // G1 and F250 from the line before
    ASSERT_EQ(o.toolpath.size(), 1u);
    EXPECT_EQ(o.toolpath.kind(0), gcode::MotionKind::Feed);
    EXPECT_DOUBLE_EQ(o.toolpath.feedMmPerMin(0), 250.0);
    EXPECT_DOUBLE_EQ(c.mdi.modal().feed, 250.0);
    EXPECT_DOUBLE_EQ(c.mdi.modal().motion, 1.0);
    EXPECT_EQ(c.mdi.modal().text(), QStringLiteral("G1 G17 G21 G90 G94 G54 F250 S0"));
}

TEST(MdiSession, FollowsTheMachineAfterAJogAndKeepsItsModes)
{
    Console c;
    c.line("G20"); // F on the line of a G20 would be read in mm first, as in LinuxCNC
    c.line("G91 G1 X1 F10");
    c.machine = {100, -20, -5, 0}; // jogged elsewhere between lines
    const auto o = c.line("X1");
    EXPECT_DOUBLE_EQ(o.toolpath.origin().x, 100.0);
    EXPECT_NEAR(c.machine[0], 125.4, 1e-9);
    EXPECT_NEAR(c.machine[1], -20.0, 1e-9);
    EXPECT_EQ(o.toolpath.kind(0), gcode::MotionKind::Feed);
    EXPECT_DOUBLE_EQ(o.toolpath.feedMmPerMin(0), 254.0);
}

TEST(MdiSession, UsesOffsetsChangedElsewhere)
{
    Console c;
    c.line("G0 X1");
    c.offsets.systems[1] = {50, 0, 0, 0};
    c.offsets.active = 1; // the operator chose G55 on the DRO
    c.line("G0 X0");
    EXPECT_DOUBLE_EQ(c.machine[0], 50.0);
    EXPECT_EQ(c.mdi.modal().coordSystem, 1);
}

TEST(MdiSession, G10AndG92ReachTheOffsets)
{
    Console c;
    c.machine = {10, 20, -5, 0};
    auto o = c.line("G10 L2 P7 X1 Y2 Z3");
    EXPECT_TRUE(o.offsetsChanged);
    EXPECT_EQ(c.offsets.systems[6], (Axes4{1, 2, 3, 0}));
    o = c.line("G92 X0");
    EXPECT_TRUE(o.offsetsChanged);
    EXPECT_DOUBLE_EQ(c.offsets.g92[0], 10.0);
    o = c.line("G59.1");
    EXPECT_EQ(c.offsets.active, 6);
    o = c.line("G0 X0");
    EXPECT_FALSE(o.offsetsChanged);
    EXPECT_DOUBLE_EQ(c.machine[0], 11.0); // G59.1 X1 + G92 X10
}

TEST(MdiSession, ErrorsAreReportedAndM2StartsAfresh)
{
    Console c;
    c.line("G91 G1 F100");
    const auto bad = c.mdi.interpret("G1 X1 Q5", c.machine, c.offsets);
    EXPECT_FALSE(bad.ok());
    c.line("M2");
    c.line("G1 X3 F100");
    EXPECT_DOUBLE_EQ(c.machine[0], 3.0); // absolute again after M2
}

// Issue 15: G5.1 runs from the console; a G5.2 curve cannot span console lines, so it is
// refused at once (and the next line is not taken for one of its control points).
TEST(MdiSession, SplinesOnOneLineOnly)
{
    Console c;
    const auto o = c.line("G5.1 X10 Y0 I5 J10 F100");
    EXPECT_GT(o.toolpath.size(), 20u);
    EXPECT_DOUBLE_EQ(c.machine[0], 10.0);
    const auto nurbs = c.mdi.interpret("G5.2 X20 Y5 P1", c.machine, c.offsets);
    ASSERT_FALSE(nurbs.ok());
    EXPECT_EQ(nurbs.errors.front().code, gcode::ErrorCode::NurbsNotEnded);
    c.line("G1 X12");
    EXPECT_DOUBLE_EQ(c.machine[0], 12.0);
}

} // namespace
} // namespace frezka::session
