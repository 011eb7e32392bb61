// Cutter radius compensation (gcode/cuttercomp.h, gcode/interp_comp*.cpp): the geometry on small
// programs whose compensated path is known by hand. The comparison with LinuxCNC's rs274 is in the
// corpus (good/cutter_comp_*.nc, bad/comp_*.nc) and the LinuxCNC examples (linuxcnc_test.cpp).
#include "gcode/cuttercomp.h"
#include "gcode/interpreter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace frezka::gcode;

namespace {

Result runWithTool(const std::string &text, double diameterMm)
{
    ToolTable table;
    ToolEntry e;
    e.tool = 1;
    e.diameterMm = diameterMm;
    table.tools.push_back(e);
    Options options;
    options.toolTable = table;
    return interpretText(text, options);
}

void expectNear(const Point4 &p, double x, double y, double z = 0)
{
    EXPECT_NEAR(p.x, x, 1e-9);
    EXPECT_NEAR(p.y, y, 1e-9);
    EXPECT_NEAR(p.z, z, 1e-9);
}

} // namespace

TEST(CutterComp, FindTurnGivesTheSignedSweep)
{
    constexpr double pi = std::numbers::pi;
    EXPECT_NEAR(findTurn(1, 0, 0, 0, 1, 0, 1), pi / 2, 1e-12);
    EXPECT_NEAR(findTurn(1, 0, 0, 0, -1, 0, 1), -3 * pi / 2, 1e-12);
    EXPECT_NEAR(findTurn(1, 0, 0, 0, 2, 1, 0), 4 * pi, 1e-12); // a full circle, twice
    EXPECT_EQ(findTurn(1, 0, 0, 0, 0, 0, 1), 0.0);
}

// Outside a square, tool on the left going clockwise: every side one radius out, every corner
// an arc around the programmed corner; the exit move after G40 goes to the programmed point.
TEST(CutterComp, OutsideCornersAreRoundedAroundTheProgrammedCorner)
{
    const Result r = runWithTool("G21 G90 F100\nG0 X10 Y-10\nG41 D1 G1 X0 Y0\nG1 Y20\n"
                                 "G1 X20\nG1 Y0\nG1 X0\nG40 G1 X-10 Y-10\nM2\n",
                                 4);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const Toolpath &tp = r.toolpath;
    ASSERT_EQ(tp.size(), 12u); // rapid, entry, 4 x (corner arc, side), exit, M2
    // Entry: one radius to the left of the line from the start to (0, 0).
    expectNear(tp.end(1), -std::sqrt(2.0), -std::sqrt(2.0));
    EXPECT_EQ(tp.kind(2), MotionKind::Arc); // around (0, 0) onto the first side's offset
    expectNear(tp.end(2), -2, 0);
    expectNear(tp.end(3), -2, 20);
    ASSERT_EQ(tp.kind(4), MotionKind::Arc);
    expectNear(tp.end(4), 0, 22);
    expectNear(tp.arc(4).centre, 0, 20);
    EXPECT_EQ(tp.arc(4).turns, -1); // clockwise around the corner
    expectNear(tp.end(5), 20, 22);
    expectNear(tp.end(6), 22, 20);
    expectNear(tp.end(7), 22, 0);
    expectNear(tp.end(9), 0, -2);
    EXPECT_EQ(tp.kind(10), MotionKind::Feed); // the exit move, from where the tool is
    expectNear(tp.end(10), -10, -10);
    EXPECT_EQ(tp.kind(11), MotionKind::Event); // M2
}

// Inside a pocket corner the move ends where the two offset lines meet (no arc), and a Z-only
// move made in the corner stays there.
TEST(CutterComp, InsideCornerEndsWhereTheOffsetsMeet)
{
    const Result r = runWithTool("G21 G90 F100\nG0 X5 Y-10\nG41 D1 G1 X5 Y0\nG1 X20\n"
                                 "G1 Z-1\nG1 Y20\nG40 G1 X10 Y10\nM2\n",
                                 4);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const Toolpath &tp = r.toolpath;
    // rapid, entry, corner arc, X side, Z down, Y side, exit
    ASSERT_GE(tp.size(), 7u);
    expectNear(tp.end(3), 18, 2);     // the X side ends two radii short of the wall
    expectNear(tp.end(4), 18, 2, -1); // the Z move in the corner
    EXPECT_EQ(tp.kind(5), MotionKind::Feed);
    expectNear(tp.end(5), 18, 20, -1);
}

// Without the compensation's queue the X side would run to X18 Y2 only once the next move is
// known: a program ending (M2) in the middle leaves the last move as the offset put it.
TEST(CutterComp, ProgramEndFlushesTheLastMove)
{
    const Result r = runWithTool("G21 G90 F100\nG0 X0 Y-10\nG42 D1 G1 X0 Y0\nG1 X20\nM2\n", 4);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    expectNear(r.toolpath.last(), 20, -2); // right of the +X move
}

// Along an arc the tool follows the arc one radius larger (outside) or smaller (inside).
TEST(CutterComp, ArcsAreOffsetByTheRadius)
{
    const Result r = runWithTool("G21 G90 F100\nG0 X-20 Y0\nG41 D1 G1 X-10 Y0\nG1 X0\n"
                                 "G3 X20 Y0 I10 J0\nG40 G1 X30 Y10\nM2\n",
                                 2);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const Toolpath &tp = r.toolpath;
    // Left of a counter-clockwise arc: inside, radius 9 around (10, 0).
    std::size_t arc = 0;
    for (std::size_t i = 0; i < tp.size(); ++i) {
        if (tp.kind(i) == MotionKind::Arc && tp.line(i) == 5)
            arc = i;
    }
    ASSERT_NE(arc, 0u);
    expectNear(tp.arc(arc).centre, 10, 0);
    expectNear(tp.start(arc), 1, 0);
    expectNear(tp.end(arc), 19, 0);
    EXPECT_EQ(tp.arc(arc).turns, 1);
}

// The errors name the line and the word, as rs274 does for the same programs (bad/comp_*.nc).
TEST(CutterComp, RefusesWhatLinuxCncRefuses)
{
    struct Case
    {
        const char *text;
        ErrorCode code;
        std::uint32_t line, column;
    };
    const Case cases[] = {
        {"G21 F100\nG41 D1 G1 X1\nM2\n", ErrorCode::CompEntryTooShort, 2, 8},
        {"G21 F100\nG41 D1 G1 X10\nG41 G1 Y10\nM2\n", ErrorCode::CompAlreadyOn, 3, 1},
        {"G21 F100\nG19 G42 D1 G1 Y10\nM2\n", ErrorCode::CompPlane, 2, 5},
        {"G21 F100\nG41 D1 G1 X10\nG18 G1 X20\nM2\n", ErrorCode::CompNotAllowed, 3, 1},
        {"G21 F100\nG41 D1 G1 X10\nG38.2 Z-5\nM2\n", ErrorCode::CompNotAllowed, 3, 1},
        {"G21 F100\nG41 D1 G1 X10\nG81 X20 R1 Z-1\nM2\n", ErrorCode::CompNotAllowed, 3, 1},
        {"G21 F100\nG41 D1 G1 X10\nG28\nM2\n", ErrorCode::CompNotAllowed, 3, 1},
        {"G21 F100\nG41 D1 G1 X10\nG92 X0\nM2\n", ErrorCode::CompNotAllowed, 3, 1},
        {"G21 F100\nG41 D1 G1 X10\nG53 G1 X20\nM2\n", ErrorCode::CompNotAllowed, 3, 1},
        {"G21 F100\nG41 D1 G1 X10\nG64 P0.1\nM2\n", ErrorCode::CompNotAllowed, 3, 1},
        {"G21 F100\nG41 D1 G1 X10\nT1 M6\nM2\n", ErrorCode::CompNotAllowed, 3, 4},
        {"G21 F100\nG0 Y-20\nG41 D1 G1 X0 Y0\nG1 X20\nG3 X24 Y0 I2 J0\nM2\n",
         ErrorCode::CompToolTooBig, 5, 1},
        {"G21 F100\nG41 D1 G1 X10\nG40\nG3 X20 R5\nM2\n", ErrorCode::CompArcAfterExit, 4, 1},
        {"G21 F100\nG42.1 G1 X10\nM2\n", ErrorCode::CompMissingD, 2, 1},
        {"G21 F100\nG1 X10 D1\nM2\n", ErrorCode::WordNotUsed, 2, 8},
    };
    for (const Case &c : cases) {
        const Result r = runWithTool(c.text, 4);
        ASSERT_FALSE(r.ok()) << c.text;
        EXPECT_EQ(errorName(r.errors[0].code), std::string(errorName(c.code)))
            << c.text << englishMessage(r.errors[0]);
        EXPECT_EQ(r.errors[0].line, c.line) << c.text;
        EXPECT_EQ(r.errors[0].column, c.column) << c.text;
    }
}

// A slot narrower than the tool: the move back along it would have to run backwards.
TEST(CutterComp, ANarrowSlotGouges)
{
    const Result r = runWithTool("G21 F100\nG0 X-20 Y0\nG41 D1 G1 X0 Y0\nG1 X30\nG1 Y3\n"
                                 "G1 X0\nM2\n",
                                 10);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].code, ErrorCode::CompGouge);
    EXPECT_EQ(r.errors[0].line, 6u);
    EXPECT_NE(englishMessage(r.errors[0]).find("5.0000"), std::string::npos); // the radius
}

// G41.1/G42.1 take the diameter from D; a negative one compensates on the other side.
TEST(CutterComp, DiameterFromTheBlockAndNegativeDiameter)
{
    const Result left = interpretText("G21 F100\nG0 X0 Y-10\nG41.1 D4 G1 X0 Y0\nG1 X20\nM2\n");
    ASSERT_TRUE(left.ok()) << englishMessage(left.errors[0]);
    expectNear(left.toolpath.last(), 20, 2);
    const Result right = interpretText("G21 F100\nG0 X0 Y-10\nG41.1 D-4 G1 X0 Y0\nG1 X20\nM2\n");
    ASSERT_TRUE(right.ok()) << englishMessage(right.errors[0]);
    expectNear(right.toolpath.last(), 20, -2);
}
