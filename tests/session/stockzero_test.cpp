// Where a stock-relative program would sit and the work zero that puts it there (issue 16 item
// 7): the program's own extent leaves out the position it starts from; each anchor of the stock
// gives the offset that puts that point of the extent at the machine's position.
#include "session/stockzero.h"

#include "gcode/interpreter.h"

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

const char *const kCam = "G21 G90\nG0 Z5\nG0 X-10 Y-5\nG1 Z-1 F300\nG1 X10 Y5\nG0 Z5\nM2\n";

TravelFit fitAt(const gcode::Point4 &start, const OffsetState &offsets = {})
{
    gcode::Options options;
    options.startMm = start;
    options.workOffsetsMm = offsets.systems;
    options.coordinateSystem = offsets.active;
    const gcode::Result g = gcode::interpretText(kCam, options);
    EXPECT_TRUE(g.ok());
    return checkTravel(g.toolpath, machine::defaultMachineConfig(protocol::Variant::Gve64));
}

// The first G0 Z5 leaves X/Y where the machine stands: that is not the program's extent.
TEST(StockZero, TheProgramsExtentLeavesOutWhereItStarts)
{
    const TravelFit fit = fitAt({50, 40, -30, 0});
    ASSERT_TRUE(fit.moves);
    EXPECT_DOUBLE_EQ(fit.minMm[0], -10.0);
    EXPECT_DOUBLE_EQ(fit.maxMm[0], 10.0);
    EXPECT_DOUBLE_EQ(fit.minMm[1], -5.0);
    EXPECT_DOUBLE_EQ(fit.maxMm[2], 5.0);
    EXPECT_DOUBLE_EQ(fit.minMm[2], -1.0);
    EXPECT_FALSE(fit.inside());
}

TEST(StockZero, EachAnchorPutsItsPointOfTheExtentHere)
{
    const TravelFit fit = fitAt({50, 40, -30, 0});
    const Axes4 here{50, 40, -30, 0};
    const OffsetState none;
    const auto offset = [&](StockAnchor a) { return stockZeroOffset(fit, none, here, a); };
    EXPECT_EQ(offset(StockAnchor::ProgramZero), (Axes4{50, 40, -30, 0}));
    EXPECT_EQ(offset(StockAnchor::FrontLeft), (Axes4{60, 45, -30, 0}));
    EXPECT_EQ(offset(StockAnchor::FrontRight), (Axes4{40, 45, -30, 0}));
    EXPECT_EQ(offset(StockAnchor::BackLeft), (Axes4{60, 35, -30, 0}));
    EXPECT_EQ(offset(StockAnchor::BackRight), (Axes4{40, 35, -30, 0}));
    EXPECT_EQ(offset(StockAnchor::Centre), (Axes4{50, 40, -30, 0}));
    const Placement p = placeProgram(fit, none, offset(StockAnchor::FrontLeft),
                                     machine::defaultMachineConfig(protocol::Variant::Gve64));
    EXPECT_TRUE(p.inside);
    EXPECT_DOUBLE_EQ(p.minMm[0], 50.0);
    EXPECT_DOUBLE_EQ(p.maxMm[0], 70.0);
    EXPECT_DOUBLE_EQ(p.maxMm[2], -25.0);
}

// Read at another offset (G55 active): the anchor is of the program's own coordinates, so the
// new offset is the same as from none.
TEST(StockZero, TheOffsetItWasReadWithDoesNotCount)
{
    OffsetState offsets;
    offsets.active = 1;
    offsets.systems[1] = {100, 100, -50, 0};
    const TravelFit fit = fitAt({50, 40, -30, 0}, offsets);
    EXPECT_DOUBLE_EQ(fit.minMm[0], 90.0);
    EXPECT_EQ(stockZeroOffset(fit, offsets, {50, 40, -30, 0}, StockAnchor::FrontLeft),
              (Axes4{60, 45, -30, 0}));
}

} // namespace
} // namespace frezka::session
