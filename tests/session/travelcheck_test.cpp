// checkTravel (issue 16 item 8): the first line that leaves the machine's travel on each side,
// how far, the farthest point, an arc's bulge, and whether another work zero would fit it.
#include "session/travelcheck.h"

#include "gcode/interpreter.h"

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

TravelFit fitOf(const char *text)
{
    const gcode::Result g = gcode::interpretText(text, {});
    EXPECT_TRUE(g.ok());
    return checkTravel(g.toolpath, machine::defaultMachineConfig(protocol::Variant::Gve64));
}

TEST(TravelCheck, InsideSaysNothing)
{
    EXPECT_TRUE(fitOf("G0 X10 Y10 Z-5\nG1 X390 F100\nM2\n").inside());
}

TEST(TravelCheck, NamesTheFirstLineAndTheFarthest)
{
    const TravelFit fit = fitOf("G0 X10 Y10\nG1 X600 F100\nG1 X650\nG1 X10\nM2\n");
    ASSERT_EQ(fit.excursions.size(), 1u);
    const TravelExcursion &e = fit.excursions.front();
    EXPECT_EQ(e.axis, 0);
    EXPECT_TRUE(e.aboveMax);
    EXPECT_EQ(e.firstLine, 2u);
    EXPECT_DOUBLE_EQ(e.firstBeyondMm, 200.0);
    EXPECT_EQ(e.farthestLine, 3u);
    EXPECT_DOUBLE_EQ(e.farthestBeyondMm, 250.0);
    EXPECT_DOUBLE_EQ(e.limitMm, 400.0);
    EXPECT_FALSE(fit.fitsElsewhere) << "650 mm of X on a 400 mm travel";
}

// The Z+5 safe height of a CAM program: it fits once the work zero is 5 mm (or more) lower.
TEST(TravelCheck, AStockRelativeProgramFitsElsewhere)
{
    const TravelFit fit = fitOf("G0 Z5\nG0 X0 Y0\nG1 Z-1 F100\nG1 X40\nG0 Z5\nM2\n");
    ASSERT_EQ(fit.excursions.size(), 1u);
    EXPECT_EQ(fit.excursions.front().axis, 2);
    EXPECT_EQ(fit.excursions.front().firstLine, 1u);
    EXPECT_TRUE(fit.fitsElsewhere);
    EXPECT_DOUBLE_EQ(fit.shiftMm[2], -5.0);
    EXPECT_DOUBLE_EQ(fit.shiftMm[0], 0.0);
}

// An arc whose end points are inside but whose bulge leaves the travel below X 0.
TEST(TravelCheck, FollowsAnArcsBulge)
{
    const TravelFit fit = fitOf("G0 X5 Y50\nG3 X5 Y10 I15 J-20 F100\nM2\n");
    ASSERT_EQ(fit.excursions.size(), 1u);
    EXPECT_EQ(fit.excursions.front().axis, 0);
    EXPECT_FALSE(fit.excursions.front().aboveMax);
    EXPECT_EQ(fit.excursions.front().firstLine, 2u);
    EXPECT_NEAR(fit.excursions.front().farthestBeyondMm, 5.0, 0.01);
}

} // namespace
} // namespace frezka::session
