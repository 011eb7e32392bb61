// LinuxCNC dialect the interpreter suite exercises: EXISTS of numbered parameters, computed
// O numbers, coordinate-system rotation, top-level return. Each case checked against what
// `rs274 -g` gives for the same text (its values noted beside each).
#include "rs274.h"

#include "gcode/interpreter.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>

#include <cmath>
#include <fstream>

using namespace frezka::gcode;

namespace {

Result run(const std::string &text)
{
    return interpretText(text);
}

} // namespace

// rs274: EXISTS[#n] is 1 for any integer value n naming #1..#5601 (##1, #[1+1] too), 0 for the
// others, with no error; EXISTS[#<name>] is 1 when the name has a value.
TEST(Dialect, ExistsOfNumberedAndNamedParameters)
{
    const Result r = run("#<a>=1\n#1=2\n#2=99999\n"
                         "G0 X EXISTS[#1] Y EXISTS[#5602] Z EXISTS[#0] A EXISTS[#5601]\n"
                         "G0 X EXISTS[##2] Y EXISTS[#[1+1]] Z EXISTS[#<A>] A EXISTS[#<b>]\n"
                         "M2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(r.toolpath.end(0), (Point4{1, 0, 0, 1}));
    EXPECT_EQ(r.toolpath.end(1), (Point4{0, 1, 1, 0}));
    for (const char *bad :
         {"G0 X EXISTS[1]\nM2\n", "G0 X EXISTS[#1+1]\nM2\n", "G0 X EXISTS[#1.5]\nM2\n"}) {
        const Result e = run(bad);
        EXPECT_FALSE(e.ok()) << bad;
    }
}

// rs274: the O number of a call may be any integer value; a computed O word inside a block
// being skipped is not evaluated (its parameters need not exist yet).
TEST(Dialect, ComputedSubroutineNumbers)
{
    const Result r = run("o2 sub\nG0 X2\no2 endsub\n"
                         "o3 sub\n#<n> = 2\no#<n> call\no3 endsub\n"
                         "o[1+1] call\nG0 X0\no3 call\n#1=2\no#1 call\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    ASSERT_EQ(r.toolpath.size(), 5u); // X2, X0, X2, X2, M2
    EXPECT_EQ(r.toolpath.end(0).x, 2);
    EXPECT_EQ(r.toolpath.end(1).x, 0);
    EXPECT_EQ(r.toolpath.end(2).x, 2);
    EXPECT_EQ(r.toolpath.end(3).x, 2);
    const Result half = run("o2 sub\nG0 X2\no2 endsub\no[2.5] call\nM2\n");
    ASSERT_EQ(half.errors.size(), 1u);
    EXPECT_EQ(half.errors[0].code, ErrorCode::NonIntegerValue);
    EXPECT_EQ(half.errors[0].line, 4u);
    const Result undefined = run("o#<nope> call\nM2\n");
    ASSERT_EQ(undefined.errors.size(), 1u);
    EXPECT_EQ(undefined.errors[0].code, ErrorCode::NamedParameterUndefined);
}

// rs274: return and endsub end the running call whatever their O label (the suite's
// return-value returns with the label of the if it stands in), set #<_value> (0 for a plain
// return); outside a call they are an error.
TEST(Dialect, ReturnEndsTheRunningCallWhateverItsLabel)
{
    const Result r = run("o1 sub\no2 if [#1 GT 0]\no2 return [5]\no2 endif\no1 endsub [7]\n"
                         "o4 sub\no4 return\no4 endsub\n"
                         "o1 call [1]\nG0 X#<_value> Y#<_value_returned>\n"
                         "o1 call [0]\nG0 X#<_value>\no4 call\nG0 X#<_value> Y#<_value_returned>\n"
                         "M2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(r.toolpath.end(0), (Point4{5, 1, 0, 0}));
    EXPECT_EQ(r.toolpath.end(1), (Point4{7, 1, 0, 0}));
    EXPECT_EQ(r.toolpath.end(2), (Point4{0, 0, 0, 0}));
    // A definition ends at its own label's endsub only; an endsub of another label returns.
    const Result other = run("o1 sub\nG0 X1\no2 endsub\nG0 X5\no1 endsub\no1 call\nG0 X3\nM2\n");
    ASSERT_TRUE(other.ok()) << englishMessage(other.errors[0]);
    ASSERT_EQ(other.toolpath.size(), 3u); // X1, X3, M2
    EXPECT_EQ(other.toolpath.end(1).x, 3);
    const Result top = run("G0 X1\no2 return\nG0 X3\nM2\n");
    ASSERT_EQ(top.errors.size(), 1u);
    EXPECT_EQ(top.errors[0].code, ErrorCode::ReturnOutsideSub);
    EXPECT_EQ(top.errors[0].line, 2u);
}

// G10 L2 R turns the system's XY plane about its origin, with the G92 offset inside the turn
// (rs274ngc and its canon): straight moves, both arc forms, G91, G92, G10 L20 in the turned
// system, another system with its own angle, a canned cycle, polar words, G53 and G28 read back
// through the turn, and R0 again. Compared with rs274 move by move, feeds included.
TEST(Dialect, CoordinateRotationMatchesRs274)
{
    if (test::rs274Path().empty())
        GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const std::string file = dir.filePath("rotation.ngc").toStdString();
    std::ofstream(file) << "G21 G17 G90 G94 F600\nG10 L2 P1 X10 Y5 R30\nG0 X10 Y0 Z5\n"
                           "G1 X20 Y10\nG2 X30 Y0 I5 J-5\nG3 X20 Y-10 R10\nG91 G1 X5 Y5\nG90\n"
                           "G92 X0 Y0\nG1 X10 Y10\nG2 X20 Y0 I5 J-5 F300\nG92.1\n"
                           "G10 L20 P1 X0 Y0\nG1 X5 Y5\nG10 L2 P2 X-10 R-45\nG55 G0 X1 Y1\n"
                           "G81 R2 Z-1 X5 Y5\nG80\nG54 G1 X2 Y3\nG10 L2 P0 R90\nG1 X1 Y0\n"
                           "G0 @5 ^45\nG53 G0 X0 Y0\nG1 X3\nG28 X0\nG1 Y4\nG10 L2 P0 R0\n"
                           "G1 X1 Y1\nM2\n";
    EXPECT_TRUE(test::matchesRs274(file));
    const Result r = interpretFile(file);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    // G53 X0 Y0 under a 90 degree turn is the machine origin all the same.
    bool sawOrigin = false;
    for (std::size_t i = 0; i < r.toolpath.size(); ++i)
        sawOrigin =
            sawOrigin || (r.toolpath.line(i) == 23 && std::fabs(r.toolpath.end(i).x) < 1e-9 &&
                          std::fabs(r.toolpath.end(i).y) < 1e-9);
    EXPECT_TRUE(sawOrigin);
}

// Under a rotation, arcs outside G17 and cutter radius compensation are refused with the code
// that names them; R in G10 L20 is refused as rs274 refuses it.
TEST(Dialect, RotationRefusesWhatItCannotTurn)
{
    struct Case
    {
        const char *text;
        ErrorCode code;
        std::uint32_t line;
    };
    const Case cases[] = {
        {"G10 L2 P1 R10\nG18 G2 X1 Z0 I0.5 K0 F100\nM2\n", ErrorCode::UnsupportedRotation, 2},
        {"G10 L2 P1 R10\nG41.1 D2\nM2\n", ErrorCode::UnsupportedRotation, 2},
        {"G10 L20 P1 X0 R10\nM2\n", ErrorCode::WordNotUsed, 1},
    };
    for (const Case &c : cases) {
        const Result r = run(c.text);
        ASSERT_EQ(r.errors.size(), 1u) << c.text;
        EXPECT_EQ(r.errors[0].code, c.code) << c.text;
        EXPECT_EQ(r.errors[0].line, c.line) << c.text;
    }
    const Result angle = run("G10 L2 P2 R12.5\nG0 X#5250\nM2\n"); // #5210 + 20 x 2
    ASSERT_TRUE(angle.ok());
    EXPECT_EQ(angle.toolpath.end(0).x, 12.5);
    const Result plain = run("G10 L2 P1 R0\nG18 G2 X1 Z0 I0.5 K0 F100\nM2\n");
    EXPECT_TRUE(plain.ok());
}

// M70 saves the modal state, M72 restores it (units first, F to one decimal, S, the G modes
// that differ, spindle and coolant), M73 restores it when the subroutine ends by endsub or by a
// return inside an if, M71 forgets it. Feeds and spindle speeds compared with rs274.
TEST(Dialect, ModalStateSaveAndRestoreMatchesRs274)
{
    if (test::rs274Path().empty())
        GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
    QTemporaryDir dir;
    ASSERT_TRUE(dir.isValid());
    const std::string file = dir.filePath("m7x.ngc").toStdString();
    const char *program =
        "G21 G90 F200 S1000 M3\nG1 X1\nM70\nG20 G91 F5 S300 M4 M8\nG1 X1\n"
        "M72\nG1 X2\no<s> sub\nM73\nG20 G91 F7.25 S100 M5 M7\nG1 X1\n"
        "o<s> endsub\no<s> call\nG1 X3\no<r> sub\nM73\nF33 G91 S5\n"
        "o1 if [1]\no1 return\no1 endif\no<r> endsub\no<r> call\nG1 X4\nM71\nM2\n";
    std::ofstream(file) << program;
    EXPECT_TRUE(test::matchesRs274(file));
    const Result r = interpretFile(file);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    // After M72 the feed is 200 mm/min again and the spindle turns clockwise at 1000 rpm.
    std::size_t g1x2 = 0;
    while (g1x2 < r.toolpath.size() && r.toolpath.line(g1x2) != 7)
        ++g1x2;
    ASSERT_LT(g1x2, r.toolpath.size());
    EXPECT_DOUBLE_EQ(r.toolpath.feedMmPerMin(g1x2), 200);
    EXPECT_EQ(r.toolpath.end(g1x2).x, 2);
}

TEST(Dialect, ModalStateErrors)
{
    const Result unsaved = run("M70\nM71\nM72\nM2\n");
    ASSERT_EQ(unsaved.errors.size(), 1u);
    EXPECT_EQ(unsaved.errors[0].code, ErrorCode::ModalStateNotSaved);
    EXPECT_EQ(unsaved.errors[0].line, 3u);
    // A call level has its own saved state: the caller's M70 is not the subroutine's.
    const Result level = run("M70\no1 sub\nM72\no1 endsub\no1 call\nM2\n");
    ASSERT_EQ(level.errors.size(), 1u);
    EXPECT_EQ(level.errors[0].code, ErrorCode::ModalStateNotSaved);
    const Result shared = run("M70 G1 X1 F10\nM2\n");
    ASSERT_EQ(shared.errors.size(), 1u);
    EXPECT_EQ(shared.errors[0].code, ErrorCode::ModalStateNotAlone);
    EXPECT_EQ(shared.errors[0].column, 1u);
}
