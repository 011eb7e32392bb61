#include "gcode/interpreter.h"
#include "gcode/trace.h"

#include <gtest/gtest.h>

using namespace frezka::gcode;

namespace {

Result run(const std::string &text)
{
    return interpretText(text);
}

} // namespace

TEST(Interpreter, StraightMovesAndArcInMachineCoordinates)
{
    const Result r = run("G10 L2 P1 X10\nG0 X1 Y2\nG1 Z-1 F100\nG2 X3 Y2 I1 J0\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const Toolpath &tp = r.toolpath;
    ASSERT_EQ(tp.size(), 4u); // rapid, feed, arc, M2 event
    EXPECT_EQ(tp.kind(0), MotionKind::Rapid);
    EXPECT_EQ(tp.end(0), (Point4{11, 2, 0, 0}));
    EXPECT_EQ(tp.kind(2), MotionKind::Arc);
    EXPECT_EQ(tp.arc(2).centre, (Point4{12, 2, -1, 0}));
    EXPECT_EQ(tp.arc(2).turns, -1);
    EXPECT_EQ(tp.line(2), 4u);
    EXPECT_DOUBLE_EQ(tp.feedMmPerMin(1), 100);
}

TEST(Interpreter, FirstErrorStopsWithLineAndColumn)
{
    const Result r = run("G0 X1\nG1 X2 F10 G41\nG0 X3\nM2\n");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].code, ErrorCode::UnsupportedGCode);
    EXPECT_EQ(r.errors[0].line, 2u);
    EXPECT_EQ(r.errors[0].column, 11u);
}

TEST(Interpreter, InchesAreConvertedToMillimetres)
{
    const Result r = run("G20 G0 X1 Y-0.5\nG1 X2 F10\nM30\n");
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.toolpath.end(0), (Point4{25.4, -12.7, 0, 0}));
    EXPECT_DOUBLE_EQ(r.toolpath.feedMmPerMin(1), 254);
}
