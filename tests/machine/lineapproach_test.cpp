// The approach of a run from a line (machine/lineapproach.h): the safe height from the program's
// own clearance, the tool lift above the start, the Z travel and where Z stands; the moves up,
// across and down at the feed, none that would not move.
#include "machine/lineapproach.h"

#include <gtest/gtest.h>

namespace frezka::machine {
namespace {

using gcode::Point4;

gcode::Toolpath program(std::initializer_list<double> zs)
{
    gcode::Toolpath t;
    double x = 0;
    for (double z : zs)
        t.appendFeed({x += 1, 0, z, 0}, 300, 1);
    return t;
}

TEST(LineApproach, SafeHeightIsTheProgramsClearanceOrTheLiftAboveTheStart)
{
    MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    c.motion.toolLiftMm = 5;
    c.axis(Axis::Z).softMaxMm = 0;
    const Point4 deep{10, 10, -60, 0};
    EXPECT_EQ(approachSafeZ(c, program({-50, -60, -55}), {0, 0, -100, 0}, deep), -50.0);
    // The program never rises above the start: the tool lift above it.
    EXPECT_EQ(approachSafeZ(c, program({-60, -62}), {0, 0, -100, 0}, deep), -55.0);
    // Never above the Z travel, never down from where Z stands.
    EXPECT_EQ(approachSafeZ(c, program({-60, -62}), {0, 0, -100, 0}, {0, 0, -2, 0}), 0.0);
    EXPECT_EQ(approachSafeZ(c, program({-50}), {0, 0, -20, 0}, deep), -20.0);
}

TEST(LineApproach, UpAcrossThenDownAtTheFeed)
{
    const auto moves = lineApproach({0, 0, -70, 0}, {85, 35, -62, 10}, -55);
    ASSERT_EQ(moves.size(), 3u);
    EXPECT_EQ(moves[0], (ApproachMove{{0, 0, -55, 0}, false}));
    EXPECT_EQ(moves[1], (ApproachMove{{85, 35, -55, 10}, false}));
    EXPECT_EQ(moves[2], (ApproachMove{{85, 35, -62, 10}, true}));
}

TEST(LineApproach, MovesThatWouldNotMoveAreLeftOut)
{
    // Z already above the safe height: across at that height, then down.
    auto moves = lineApproach({0, 0, 0, 0}, {85, 35, -62, 0}, -55);
    ASSERT_EQ(moves.size(), 2u);
    EXPECT_EQ(moves[0], (ApproachMove{{85, 35, 0, 0}, false}));
    EXPECT_EQ(moves[1], (ApproachMove{{85, 35, -62, 0}, true}));
    // Already at the start: nothing.
    EXPECT_TRUE(lineApproach({5, 5, -55, 0}, {5, 5, -55, 0}, -55).empty());
    // A start at the safe height: up and across only.
    moves = lineApproach({0, 0, -60, 0}, {5, 5, -55, 0}, -55);
    ASSERT_EQ(moves.size(), 2u);
    EXPECT_FALSE(moves[1].feed);
}

} // namespace
} // namespace frezka::machine
