// The path guard's geometry (machine/pathcheck.h): the planned position before a command, and
// a polled position on a segment within one step per axis, or off it.
#include "machine/pathcheck.h"

#include <gtest/gtest.h>

namespace frezka::machine {
namespace {

UnitCommand motion(UnitOp op, std::array<std::int32_t, 4> d, Steps4 end)
{
    UnitCommand c;
    c.op = op;
    c.d = d;
    c.endSteps = end;
    return c;
}

// From (100, 0, 0): X +1000, a speed, Y +500 (a line), a probe Z -200.
UnitProgram program()
{
    UnitProgram p;
    p.axisCount = 3;
    p.startSteps = {100, 0, 0, 0};
    p.commands = {motion(UnitOp::Vector, {1000, 0, 0, 0}, {1100, 0, 0, 0}),
                  UnitCommand{UnitOp::Speed, {}, 2000, 0, 0, {1100, 0, 0, 0}},
                  motion(UnitOp::Line, {0, 500, 0, 0}, {1100, 500, 0, 0}),
                  motion(UnitOp::Probe, {0, 0, -200, 0}, {1100, 500, -200, 0})};
    return p;
}

TEST(PathCheck, PlannedBeforeACommand)
{
    const UnitProgram p = program();
    EXPECT_EQ(plannedBefore(p, 0), (Steps4{100, 0, 0, 0}));
    EXPECT_EQ(plannedBefore(p, 1), (Steps4{1100, 0, 0, 0}));
    EXPECT_EQ(plannedBefore(p, 3), (Steps4{1100, 500, 0, 0}));
    EXPECT_EQ(plannedBefore(p, 4), (Steps4{1100, 500, -200, 0}));
    EXPECT_EQ(plannedBefore(p, 99), (Steps4{1100, 500, -200, 0}));
}

TEST(PathCheck, SameStepsOnTheProgramsAxes)
{
    EXPECT_TRUE(sameSteps({1, 2, 3, 4}, {1, 2, 3, 9}, 3));
    EXPECT_FALSE(sameSteps({1, 2, 3, 4}, {1, 2, 3, 9}, 4));
    EXPECT_FALSE(sameSteps({1, 2, 3, 4}, {1, 2, 2, 4}, 3));
}

TEST(PathCheck, APositionOnASegmentWithinAStep)
{
    const UnitProgram p = program();
    EXPECT_EQ(segmentHolding(p, 0, 4, {600, 0, 0, 0}), 0u);
    EXPECT_EQ(segmentHolding(p, 0, 4, {600, 1, -1, 0}), 0u); // a step off on Y and Z
    EXPECT_EQ(segmentHolding(p, 0, 4, {600, 2, 0, 0}), std::nullopt);
    EXPECT_EQ(segmentHolding(p, 0, 4, {1100, 250, 0, 0}), 2u); // the speed moves nothing
    EXPECT_EQ(segmentHolding(p, 0, 4, {1100, 500, -120, 0}), 3u);
    EXPECT_EQ(segmentHolding(p, 0, 4, {1201, 0, 0, 0}), std::nullopt); // beyond the end
    // Only the commands in the range count.
    EXPECT_EQ(segmentHolding(p, 1, 4, {1100, 0, 0, 0}), 2u); // the line's start
    EXPECT_EQ(segmentHolding(p, 0, 2, {1100, 250, 0, 0}), std::nullopt);
}

TEST(PathCheck, ADiagonalHoldsEachAxisWithinAStepOfTheLine)
{
    UnitProgram p;
    p.commands = {motion(UnitOp::Vector, {300, 100, 0, 0}, {300, 100, 0, 0})};
    EXPECT_EQ(segmentHolding(p, 0, 1, {150, 50, 0, 0}), 0u);
    EXPECT_EQ(segmentHolding(p, 0, 1, {151, 49, 0, 0}), 0u);
    EXPECT_EQ(segmentHolding(p, 0, 1, {150, 52, 0, 0}), std::nullopt);
}

} // namespace
} // namespace frezka::machine
