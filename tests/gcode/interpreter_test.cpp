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
    const Result r = run("G0 X1\nG1 X2 F10 G95\nG0 X3\nM2\n");
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

TEST(Interpreter, CheckModeCollectsEveryError)
{
    Options options;
    options.collectAllErrors = true;
    const Result r = interpretText("G21 F100\nG1 X1 Q2\nG0 X1\nG2 X5 Y0 R1\nG0 G95 X1\n", options);
    ASSERT_EQ(r.errors.size(), 3u); // three bad blocks (the missing end is a warning)
    EXPECT_EQ(r.errors[0].code, ErrorCode::WordNotUsed);
    EXPECT_EQ(r.errors[1].code, ErrorCode::ArcRadiusTooSmall);
    EXPECT_EQ(r.errors[2].code, ErrorCode::UnsupportedGCode);
    EXPECT_EQ(r.errors[2].line, 5u);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].code, ErrorCode::ImpliedProgramEnd);
}

TEST(Interpreter, EndlessLoopEndsAtItsLine)
{
    Options options;
    options.maxBlocks = 1000;
    const Result r = interpretText("o1 while [1]\nG0 X1\no1 endwhile\nM2\n", options);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].code, ErrorCode::LoopNeverEnds); // more in endless_test.cpp
    EXPECT_EQ(r.errors[0].line, 1u);
}

TEST(Interpreter, SystemParametersFollowTheState)
{
    const Result r = interpretText("G10 L2 P2 X5 Y6\nG55 G0 X1 Y2\n"
                                   "G0 X#5220 Y#5241\n"       // 2 and G55 X offset 5
                                   "G0 X[#5420 + 1] Y#<_y>\n" // current program position
                                   "G20\nG0 X#5241\n"         // offsets read in inches
                                   "M2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(r.toolpath.end(1), (Point4{2 + 5, 5 + 6, 0, 0}));
    EXPECT_EQ(r.toolpath.end(2), (Point4{3 + 5, 5 + 6, 0, 0}));
    EXPECT_NEAR(r.toolpath.end(3).x, 5 + 5.0, 1e-12); // 5 mm offset = 5/25.4 in, back to mm
}

TEST(Interpreter, NamedParametersAreLocalToSubroutinesUnlessGlobal)
{
    const Result r = interpretText("#<a> = 1\n#<_g> = 2\no<s> sub\n#<_g> = [#<_g> + 1]\n"
                                   "G0 X#<a>\no<s> endsub\no<s> call\nM2\n");
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].code, ErrorCode::NamedParameterUndefined);
    EXPECT_EQ(r.errors[0].line, 5u);
    EXPECT_EQ(r.errors[0].column, 5u);
}

TEST(Interpreter, BlockDeleteIsAnOption)
{
    const std::string text = "/G0 X5\nG0 Y1\nM2\n";
    EXPECT_EQ(interpretText(text).toolpath.end(0).x, 5); // LinuxCNC's default: switch off
    Options options;
    options.blockDelete = true;
    const Result r = interpretText(text, options);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.toolpath.end(0), (Point4{0, 1, 0, 0}));
}

TEST(Interpreter, InverseTimeFeedBecomesMillimetresPerMinute)
{
    const Result r = interpretText("G93 G1 X10 F2\nG94 F100\nM2\n");
    ASSERT_TRUE(r.ok());
    EXPECT_DOUBLE_EQ(r.toolpath.feedMmPerMin(0), 20); // 10 mm in 1/2 minute
}

TEST(Interpreter, PathModeEventCarriesToleranceInMillimetres)
{
    const Result r = interpretText("G20 G64 P0.01 Q0.001\nM2\n");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.toolpath.kind(0), MotionKind::Event);
    const Event &e = r.toolpath.event(0);
    EXPECT_EQ(e.kind, EventKind::PathMode);
    EXPECT_EQ(e.value, 2);
    EXPECT_NEAR(e.p, 0.254, 1e-12);
    EXPECT_NEAR(e.q, 0.0254, 1e-12);
}

TEST(Interpreter, ArcsKeepTheirCentreCompactly)
{
    const Result r = interpretText("G0 X10 Y0 Z3 A7\nG18 G2 X0 Z13 I-10 K0 F100\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const ArcInfo arc = r.toolpath.arc(1);
    EXPECT_EQ(arc.plane, Plane::XZ);
    EXPECT_EQ(arc.turns, -1);
    EXPECT_EQ(arc.centre, (Point4{0, 0, 3, 7})); // normal coordinate and A from the start
}

TEST(Errors, EveryCodeHasNameTextAndHint)
{
    for (int c = 100; c < 600; ++c) {
        const auto code = static_cast<ErrorCode>(c);
        const std::string name = errorName(code);
        if (name == "Unknown")
            continue;
        ErrorCode back{};
        EXPECT_TRUE(errorCodeFromName(name, &back));
        EXPECT_EQ(back, code);
        EXPECT_GT(std::string(errorHint(code)).size(), 5u) << name;
    }
    const Error e{ErrorCode::UnknownGCode, 12, 7, "G12.3", {}};
    EXPECT_EQ(englishMessage(e),
              "Unknown G code G12.3. Check the number; see the list of supported codes.");
    EXPECT_EQ(formatError(QStringLiteral("a.nc"), e).toStdString(),
              "a.nc:12:7: Unknown G code G12.3. Check the number; see the list of supported "
              "codes.");
}

TEST(Trace, JsonLinesUseFourDecimalsAndTheDocumentedKeys)
{
    const Result r = interpretText("G0 X1.23456 Y-0.00004\nG3 X0 Y1.23456 I-1.23456 F60\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(jsonLines(r.toolpath, false),
              "{\"line\":1,\"type\":\"rapid\",\"x\":1.2346,\"y\":0.0000,\"z\":0.0000,"
              "\"a\":0.0000,\"f\":0.0000}\n"
              "{\"line\":2,\"type\":\"arc\",\"x\":0.0000,\"y\":1.2346,\"z\":0.0000,"
              "\"a\":0.0000,\"f\":60.0000,\"cx\":0.0000,\"cy\":0.0000,\"cz\":0.0000,"
              "\"plane\":\"XY\",\"turns\":1}\n");
}

TEST(Interpreter, StartsFromTheGivenMachineStateOptions)
{
    Options options;
    options.workOffsetsMm[1] = {100, 200, -50, 0}; // G55
    options.coordinateSystem = 1;
    options.startMm = {1, 2, 3, 0};
    const Result r = interpretText("G0 X0\nG54 G0 X0\nM2\n", options);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.toolpath.origin(), (Point4{1, 2, 3, 0}));
    EXPECT_EQ(r.toolpath.end(0), (Point4{100, 2, 3, 0}));
    EXPECT_EQ(r.toolpath.end(1), (Point4{0, 2, 3, 0}));
}

// LinuxCNC executes F before G20/G21 and its canon keeps the physical feed across a units change
// (rs274: SET_FEED_RATE(6.0000) in mm, then USE_LENGTH_UNITS(INCHES)); the user is warned at the
// units change, with both readings, when a feed move then runs on the old F.
TEST(Interpreter, FeedKeepsItsRateAcrossAUnitsChangeWithAWarning)
{
    const Result r = run("G21\nF6\nG20\nG1 X1\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_DOUBLE_EQ(r.toolpath.feedMmPerMin(0), 6); // not 6 in/min = 152.4 mm/min
    ASSERT_EQ(r.warnings.size(), 1u);
    const Error &w = r.warnings[0];
    EXPECT_EQ(w.code, ErrorCode::FeedUnitsChanged);
    EXPECT_EQ(severity(w.code), Severity::Warning);
    EXPECT_EQ(w.line, 3u);
    EXPECT_EQ(w.column, 1u);
    EXPECT_EQ(englishMessage(w),
              "F6 was read in mm/min (line 2) before this change of units: the feed moves after "
              "it run at 6 mm/min (0.2362 in/min), as in LinuxCNC, not at 6 in/min (152.4 "
              "mm/min). LinuxCNC reads F before G20/G21, also on the same line; if 6 in/min was "
              "meant, give F again after the change of units.");
}

TEST(Interpreter, FeedOnTheLineOfAUnitsChangeIsReadInTheOldUnits)
{
    const Result r = run("G1 X1 G20 F6\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_DOUBLE_EQ(r.toolpath.feedMmPerMin(0), 6);
    EXPECT_EQ(r.toolpath.end(0).x, 25.4);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].line, 1u);
    EXPECT_EQ(r.warnings[0].column, 7u); // the G20
    // #<_feed> reads the F as programmed, as in rs274.
    const Result p = run("G21 F6\nG20\nG1 X#<_feed>\nM2\n");
    ASSERT_TRUE(p.ok());
    EXPECT_DOUBLE_EQ(p.toolpath.end(0).x, 6 * 25.4);
}

TEST(Interpreter, FeedRestatedAfterAUnitsChangeGivesNoWarning)
{
    const Result r = run("G21 F6\nG20\nF6\nG1 X1\nG21\nG20\nG1 X2\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_DOUBLE_EQ(r.toolpath.feedMmPerMin(0), 152.4);
    EXPECT_DOUBLE_EQ(r.toolpath.feedMmPerMin(1), 152.4);
    EXPECT_TRUE(r.warnings.empty());
    // Rapids alone need no feed: no warning either.
    EXPECT_TRUE(run("G21 F6\nG20\nG0 X1\nM2\n").warnings.empty());
}

// FlatCAM, jscut, UGS Designer write no M2: the end of the file ends the program, with a warning
// and the same ProgramEnd (spindle and coolant off) as M2. LinuxCNC refuses such files.
TEST(Interpreter, EndOfFileWithoutM2EndsTheProgramWithAWarning)
{
    for (const char *text : {"G21\nG0 X1\n", "G21\nG0 X1", "%\nG21\nG0 X1\n"}) {
        const Result r = run(text);
        ASSERT_TRUE(r.ok()) << text << ": " << englishMessage(r.errors[0]);
        EXPECT_FALSE(r.ended);
        ASSERT_EQ(r.warnings.size(), 1u) << text;
        EXPECT_EQ(r.warnings[0].code, ErrorCode::ImpliedProgramEnd);
        EXPECT_EQ(r.warnings[0].line, std::string(text).front() == '%' ? 3u : 2u);
        const Toolpath &tp = r.toolpath;
        ASSERT_EQ(tp.kind(tp.size() - 1), MotionKind::Event);
        EXPECT_EQ(tp.event(tp.size() - 1).kind, EventKind::ProgramEnd);
    }
    EXPECT_TRUE(run("G0 X1\nM2\n").warnings.empty());
    // Where a text never ends (the console's lines), the old errors stay.
    Options options;
    options.acceptMissingEnd = false;
    Result r = interpretText("G0 X1\n", options);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].code, ErrorCode::FileEndedWithoutEnd);
    EXPECT_TRUE(r.warnings.empty());
    r = interpretText("%\nG0 X1\n", options);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].code, ErrorCode::FileEndedWithoutPercent);
}

// LinuxCNC ignores G80 beside another motion code: the safety line of Fanuc-style posts.
TEST(Interpreter, G80BesideG0ToG3IsIgnoredAsInLinuxCnc)
{
    const Result r = run("N1 G00 G17 G21 G40 G49 G80 G90\nG80 G0 X1\nG1 G80 X2 F100\n"
                         "G80 G2 X4 I1 J0\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(r.toolpath.kind(0), MotionKind::Rapid); // N1: G0 to where it stands, as rs274
    EXPECT_EQ(r.toolpath.end(1), (Point4{1, 0, 0, 0}));
    EXPECT_EQ(r.toolpath.kind(2), MotionKind::Feed);
    EXPECT_EQ(r.toolpath.kind(3), MotionKind::Arc);
    EXPECT_TRUE(r.warnings.empty());
    const Result c = run("G81 G80 X1 Z-1 R1 F100\nM2\n"); // beside a cycle: refused
    ASSERT_EQ(c.errors.size(), 1u);
    EXPECT_EQ(c.errors[0].code, ErrorCode::ModalGroupConflict);
}

// FreeCAD's grbl post writes K0 on G17 arcs: accepted with one note (rs274 refuses it); any
// other value is still an error.
TEST(Interpreter, ZeroOffsetOutOfThePlaneIsAcceptedWithANote)
{
    const Result r = run("G21 F100\nG17 G2 X2 Y0 I1 J0 K0\nG3 X0 Y0 I-1 J0 K0.000\n"
                         "G18 G2 X0 Z2 I0 K1 J0\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const Result plain = run("G21 F100\nG17 G2 X2 Y0 I1 J0\nG3 X0 Y0 I-1 J0\n"
                             "G18 G2 X0 Z2 I0 K1\nM2\n");
    EXPECT_EQ(r.toolpath, plain.toolpath);
    ASSERT_EQ(r.warnings.size(), 1u); // one note, the others counted
    EXPECT_EQ(r.warningsNotShown, 2u);
    EXPECT_EQ(r.warnings[0].code, ErrorCode::IgnoredArcWord);
    EXPECT_EQ(severity(r.warnings[0].code), Severity::Note);
    EXPECT_EQ(r.warnings[0].line, 2u);
    EXPECT_EQ(r.warnings[0].column, 20u);
    EXPECT_EQ(translatedMessage(r.warnings[0]).left(48),
              QStringLiteral("K0 has no effect on an arc in the XY plane and i"));
    const Result bad = run("G21 F100\nG2 X2 Y0 I1 J0 K0.01\nM2\n");
    ASSERT_EQ(bad.errors.size(), 1u);
    EXPECT_EQ(bad.errors[0].code, ErrorCode::ArcWrongPlaneWord);
}

// Mach3/UCCNC posts may write G4 P in milliseconds; Frezka reads seconds (as LinuxCNC) and says
// so when P looks like milliseconds.
TEST(Interpreter, DwellThatLooksLikeMillisecondsGivesAWarning)
{
    const Result r = run("G4 P4000\nG4 P2.5\nG4 P99\nG4 P150.5\nM2\n");
    ASSERT_TRUE(r.ok());
    EXPECT_DOUBLE_EQ(r.toolpath.event(0).value, 4000); // seconds, as LinuxCNC
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].code, ErrorCode::DwellLooksLikeMilliseconds);
    EXPECT_EQ(r.warnings[0].column, 4u);
    EXPECT_EQ(englishMessage(r.warnings[0]),
              "G4 P4000 dwells 4000 seconds (66.6667 min), as in LinuxCNC; if the post meant "
              "milliseconds (as Mach3 and UCCNC can), that is 4 s. Frezka reads P in seconds; "
              "write P4 if 4 s was meant.");
}

// After a line with an unsupported code (G96) the arcs that follow are checked from the point the
// program meant, not from where the skipped block left off: one error, not one per arc.
TEST(Interpreter, NoFollowOnErrorsAfterASkippedBlock)
{
    Options options;
    options.collectAllErrors = true;
    const char *text = "G21 G90 F100\nG0 X0 Y0\nG96 S100 G1 X10 Y0\nG2 X20 Y0 I5 J0\n"
                       "G3 X10 Y0 I-5 J0\nG1 X0\nM2\n";
    const Result r = interpretText(text, options);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].code, ErrorCode::UnsupportedGCode);
    EXPECT_EQ(r.errors[0].line, 3u);
    // An arc that fails still sets G2 and its end point: the next arc block (axis and centre
    // words only) is read as an arc from there.
    const Result a = interpretText("G21 F100\nG2 X10 Y0 I3 J0\nX20 Y0 I5 J0\nM2\n", options);
    ASSERT_EQ(a.errors.size(), 1u) << englishMessage(a.errors.back());
    EXPECT_EQ(a.errors[0].code, ErrorCode::ArcRadiusMismatch);
    ASSERT_EQ(a.toolpath.kind(0), MotionKind::Feed); // a straight stand-in for the bad arc
    EXPECT_EQ(a.toolpath.end(0), (Point4{10, 0, 0, 0}));
    ASSERT_EQ(a.toolpath.kind(1), MotionKind::Arc);
    EXPECT_EQ(a.toolpath.arc(1).centre, (Point4{15, 0, 0, 0}));
}

TEST(Interpreter, ErrorsComeInFileOrderOnceEach)
{
    Options options;
    options.collectAllErrors = true;
    const Result r = interpretText("F10\no<s> call\nG1 X1 Q2\no<s> call\nM2\n"
                                   "o<s> sub\nG91 G2 X5 Y0 R1\no<s> endsub\n",
                                   options);
    ASSERT_EQ(r.errors.size(), 2u);
    EXPECT_EQ(r.errors[0].line, 3u); // executed after line 7
    EXPECT_EQ(r.errors[0].code, ErrorCode::WordNotUsed);
    EXPECT_EQ(r.errors[1].line, 7u); // twice executed, once reported
    EXPECT_EQ(r.errors[1].code, ErrorCode::ArcRadiusTooSmall);
}

TEST(Interpreter, ErrorsBeyondTheLimitAreCounted)
{
    Options options;
    options.collectAllErrors = true;
    options.maxErrors = 3;
    std::string text;
    for (int i = 0; i < 10; ++i)
        text += "G1 X1 Q2\n";
    text += "M2\n";
    const Result r = interpretText(text, options);
    EXPECT_EQ(r.errors.size(), 3u);
    EXPECT_EQ(r.errorsNotShown, 7u);
    EXPECT_EQ(r.errors[2].line, 3u);
}

// G41/G42 with a tool of diameter 0 (no table, or not measured) leave the path uncompensated:
// the user is told, with what to do; a lathe tool's nose radius is refused with advice that keeps
// the part safe.
TEST(Interpreter, CutterCompensationWithoutADiameterWarns)
{
    const Result r = run("G42 G1 X1 F10\nM2\n");
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].code, ErrorCode::CompZeroRadius);
    EXPECT_EQ(r.warnings[0].column, 1u);
    EXPECT_EQ(r.toolpath.end(0), (Point4{1, 0, 0, 0})); // not compensated
    const std::string m = englishMessage(r.warnings[0]);
    EXPECT_NE(m.find("Tool table"), std::string::npos) << m;

    Options options;
    ToolTable table;
    ToolEntry lathe;
    lathe.tool = 2;
    lathe.diameterMm = 0.8;
    lathe.orientation = 3;
    table.tools.push_back(lathe);
    options.toolTable = table;
    const Result l = interpretText("G18 G42 D2 G1 X1 F10\nM2\n", options);
    ASSERT_EQ(l.errors.size(), 1u);
    EXPECT_EQ(l.errors[0].code, ErrorCode::CutterCompensation);
    const std::string advice = englishMessage(l.errors[0]);
    EXPECT_NE(advice.find("post the program again from the CAM"), std::string::npos) << advice;
    EXPECT_EQ(advice.find("Remove it"), std::string::npos) << advice;
}

// #5599 (LinuxCNC's switch for DEBUG/PRINT output, set by its example offsets.ngc) may be
// written; the tool and position parameters stay read-only, as in LinuxCNC.
TEST(Interpreter, ParameterWritesAsLinuxCncAllows)
{
    const Result r = run("#5599 = 1\nG0 X#5599\nM2\n");
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(r.toolpath.end(0).x, 1);
    for (const char *text : {"#5400 = 1\nM2\n", "#5420 = 1\nM2\n"}) {
        const Result bad = run(text);
        ASSERT_EQ(bad.errors.size(), 1u) << text;
        EXPECT_EQ(bad.errors[0].code, ErrorCode::ReadOnlyParameter) << text;
    }
}

// Polar coordinates are refused where LinuxCNC refuses them, naming what is in the way.
TEST(Interpreter, PolarCoordinatesOnlyWhereLinuxCncTakesThem)
{
    struct Case
    {
        const char *text, *detail;
        std::uint32_t column;
    };
    const Case cases[] = {
        {"G18 G0 @1 ^30\nM2\n", "G18", 8}, {"G0 X1 @2\nM2\n", "X", 7},
        {"G53 G0 ^30\nM2\n", "G53", 8},    {"G0 @5\nM2\n", "X0 Y0", 4},
        {"G91 G0 ^10\nM2\n", "X0 Y0", 8},
    };
    for (const Case &c : cases) {
        const Result r = run(c.text);
        ASSERT_EQ(r.errors.size(), 1u) << c.text;
        EXPECT_EQ(r.errors[0].code, ErrorCode::PolarNotAllowed) << c.text;
        EXPECT_EQ(r.errors[0].detail, c.detail) << c.text;
        EXPECT_EQ(r.errors[0].column, c.column) << c.text;
    }
    const Result ok = run("G0 @2 ^90\nM2\n");
    ASSERT_TRUE(ok.ok());
    EXPECT_NEAR(ok.toolpath.end(0).x, 0, 1e-12);
    EXPECT_NEAR(ok.toolpath.end(0).y, 2, 1e-12);
}
