// Run from a line (issue 16 item 2): the interpreter's modal state where the line begins (units,
// plane, distance mode, work offset, tool, spindle, coolant, feed, position; the position, feed
// and spindle also against LinuxCNC's rs274 run up to that line), the job (the line's state, the
// safe approach, then the program's rest, ending where the whole program ends, also on the
// unit's counters as planned), and the lines that are refused with the line to choose instead.
#include "runfromline_program.h"

#include "session/programplanner.h"
#include "session/runfromline.h"

#include "../gcode/rs274.h"

#include "gcode/interpreter.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

using gcode::EventKind;
using gcode::MotionKind;
using gcode::Point4;

InterpretOutcome interpret(const char *text, std::uint32_t startLine)
{
    InterpretRequest r;
    r.text = text;
    r.fileName = QStringLiteral("job.nc");
    r.startLine = startLine;
    return interpretProgram(r);
}

machine::MachineConfig gve64()
{
    return machine::defaultMachineConfig(protocol::Variant::Gve64);
}

FromLineOutcome fromLine(const char *text, std::uint32_t line, const Point4 &fromMm = {})
{
    const InterpretOutcome whole = interpret(text, line);
    EXPECT_TRUE(whole.errors.empty());
    return runFromLine(*whole.toolpath, whole.mark, gve64(), fromMm, QStringLiteral("job.nc"));
}

TEST(RunFromLine, ModalStateAtTheLine)
{
    const InterpretOutcome r = interpret(test::kRunFromLineProgram, test::kRunFromLine);
    ASSERT_TRUE(r.errors.empty());
    ASSERT_TRUE(r.mark.ok());
    const gcode::LineState &s = r.mark.state;
    EXPECT_EQ(r.mark.line, 18u);
    EXPECT_TRUE(s.metric);
    EXPECT_EQ(s.plane, 170);
    EXPECT_FALSE(s.absolute);         // G91 on line 14
    EXPECT_EQ(s.coordinateSystem, 1); // G55
    EXPECT_EQ(s.workOffsetMm, (std::array<double, 4>{40, 30, -60, 0}));
    EXPECT_EQ(s.tool, 2);
    EXPECT_EQ(s.toolLengthMm, 0.0);
    EXPECT_EQ(s.speedRpm, 12000.0);
    EXPECT_EQ(s.spindle, 1);
    EXPECT_TRUE(s.flood);
    EXPECT_FALSE(s.mist);
    EXPECT_EQ(s.feedMmPerMin, 800.0);
    EXPECT_EQ(s.motion, 10);
    EXPECT_EQ(s.programMm, (Point4{45, 5, -2, 0}));
    EXPECT_EQ(s.machineMm, (Point4{85, 35, -62, 0}));
    // The entries before the mark are the lines before 18.
    ASSERT_LT(r.mark.entry, r.toolpath->size());
    EXPECT_EQ(r.toolpath->line(r.mark.entry), 18u);
    EXPECT_EQ(r.toolpath->line(r.mark.entry - 1), 17u);
}

// G92, G20, G18, G43 with a tool length, M7 and G64 P, each as the interpreter holds it.
TEST(RunFromLine, OffsetsUnitsPlaneToolLengthAndPathMode)
{
    const InterpretOutcome g92 = interpret("G21 G90 F100\nG0 X10\nG92 X0\nG1 X5\nG1 X6\nM2\n", 5);
    ASSERT_TRUE(g92.mark.ok());
    EXPECT_EQ(g92.mark.state.g92Mm, (std::array<double, 4>{10, 0, 0, 0}));
    EXPECT_EQ(g92.mark.state.programMm.x, 5.0);
    EXPECT_EQ(g92.mark.state.machineMm.x, 15.0);

    gcode::Options options;
    options.toolLengthMm[3] = 12.5;
    options.startLine = 6;
    const gcode::Result r = gcode::interpretText(
        "G20 G90 G18 G64 P0.001\nT3 M6\nG43 H3\nM7 S8000 M3\nG1 X1 Z0 F10\nG1 X2\nM2\n", options);
    ASSERT_TRUE(r.ok());
    ASSERT_TRUE(r.mark.ok());
    const gcode::LineState &s = r.mark.state;
    EXPECT_FALSE(s.metric);
    EXPECT_EQ(s.plane, 180);
    EXPECT_EQ(s.tool, 3);
    EXPECT_EQ(s.toolLengthMm, 12.5);
    EXPECT_TRUE(s.mist);
    EXPECT_FALSE(s.flood);
    EXPECT_EQ(s.speedRpm, 8000.0);
    EXPECT_NEAR(s.feedMmPerMin, 254.0, 1e-9); // F10 in/min
    EXPECT_EQ(s.pathMode, 2);
    EXPECT_NEAR(s.pathToleranceMm, 0.0254, 1e-12);
    EXPECT_NEAR(s.machineMm.x, 25.4, 1e-9);
    EXPECT_NEAR(s.machineMm.z, 12.5, 1e-9); // Z0 with the tool's length
    FromLine from;
    from.line = 6;
    from.state = s;
    const QString summary = fromLineSummary(from);
    for (const char *text :
         {"tool 3 (length 12.500 mm)", "S8000 M3", "M7", "F10", "G54 G90 G20 G18"})
        EXPECT_TRUE(summary.contains(QLatin1String(text))) << text << " " << summary.toStdString();
}

// rs274 run on the lines before 18 holds the same position, feed and spindle at their end.
TEST(RunFromLine, StateMatchesRs274)
{
    if (gcode::test::rs274Path().empty())
        GTEST_SKIP() << "rs274 (linuxcnc-uspace) not installed";
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("prefix.ngc"));
    const QByteArray all(test::kRunFromLineProgram);
    QByteArray prefix = all.left(int(all.indexOf("G1 Y10\n")));
    prefix += "M2\n";
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(prefix);
    f.close();
    const gcode::test::Rs274Run rs = gcode::test::runRs274(path.toStdString());
    ASSERT_TRUE(rs.available);
    ASSERT_TRUE(rs.error.empty()) << rs.error;
    ASSERT_FALSE(rs.moves.empty());
    const gcode::test::CanonMove &last = rs.moves.back();
    const InterpretOutcome r = interpret(test::kRunFromLineProgram, test::kRunFromLine);
    const gcode::LineState &s = r.mark.state;
    EXPECT_NEAR(last.end.x, s.machineMm.x, 1e-4);
    EXPECT_NEAR(last.end.y, s.machineMm.y, 1e-4);
    EXPECT_NEAR(last.end.z, s.machineMm.z, 1e-4);
    EXPECT_NEAR(last.feedMmPerMin, s.feedMmPerMin, 1e-6);
    EXPECT_NEAR(last.spindleRpm, s.speedRpm * s.spindle, 1e-6);
    EXPECT_EQ(last.unitMm, 1.0);
}

TEST(RunFromLine, StateThenApproachThenTheRest)
{
    const Point4 from{10, 10, -70, 0}; // down in the material (a broken tool)
    const InterpretOutcome whole = interpret(test::kRunFromLineProgram, test::kRunFromLine);
    const FromLineOutcome job =
        runFromLine(*whole.toolpath, whole.mark, gve64(), from, QStringLiteral("job.nc"));
    ASSERT_TRUE(job.ok()) << job.refusal.toStdString();
    const gcode::Toolpath &t = *job.toolpath;
    EXPECT_EQ(t.origin(), from);
    // Path mode, the spindle as at the line (the planner waits its spin-up), coolant.
    ASSERT_GE(t.size(), 6u);
    for (std::size_t i = 0; i < 3; ++i)
        ASSERT_EQ(t.kind(i), MotionKind::Event) << i;
    EXPECT_EQ(t.event(0).kind, EventKind::PathMode);
    EXPECT_EQ(t.event(1), (gcode::Event{EventKind::SpindleCw, 12000, 0, 0}));
    EXPECT_EQ(t.event(2).kind, EventKind::CoolantFlood);
    // Up to the program's own clearance (Z5 in G55: -55), across, down at the line's feed.
    EXPECT_EQ(job.from.safeZMm, -55.0);
    EXPECT_EQ(t.kind(3), MotionKind::Rapid);
    EXPECT_EQ(t.end(3), (Point4{10, 10, -55, 0}));
    EXPECT_EQ(t.kind(4), MotionKind::Rapid);
    EXPECT_EQ(t.end(4), (Point4{85, 35, -55, 0}));
    EXPECT_EQ(t.kind(5), MotionKind::Feed);
    EXPECT_EQ(t.end(5), (Point4{85, 35, -62, 0}));
    EXPECT_EQ(t.feedMmPerMin(5), 800.0);
    for (std::size_t i = 0; i < job.from.approachEntries; ++i)
        EXPECT_EQ(t.line(i), 18u);
    // Then every entry of the program from line 18 on, as it is.
    ASSERT_EQ(job.from.approachEntries, 6u);
    ASSERT_EQ(t.size() - 6, whole.toolpath->size() - whole.mark.entry);
    for (std::size_t i = 6; i < t.size(); ++i) {
        const std::size_t w = whole.mark.entry + i - 6;
        EXPECT_EQ(t.kind(i), whole.toolpath->kind(w));
        EXPECT_EQ(t.end(i), whole.toolpath->end(w));
        EXPECT_EQ(t.line(i), whole.toolpath->line(w));
    }
    EXPECT_EQ(t.last(), whole.toolpath->last());
    const QString summary = fromLineSummary(job.from);
    for (const char *text : {"Line 18", "tool 2", "S12000 M3", "M8", "F800", "G55 G91 G21 G17"})
        EXPECT_TRUE(summary.contains(QLatin1String(text))) << text << " " << summary.toStdString();
}

// Planned, the job ends on the same steps as the whole program and never cuts before the
// spindle: the spindle command and its spin-up wait come before the first motion.
TEST(RunFromLine, PlanEndsWhereTheWholeProgramEnds)
{
    const auto config = gve64();
    const InterpretOutcome whole = interpret(test::kRunFromLineProgram, test::kRunFromLine);
    const PlanOutcome wholePlan = planProgram(*whole.toolpath, config, QStringLiteral("job.nc"));
    ASSERT_TRUE(wholePlan.ok());
    const FromLineOutcome job =
        runFromLine(*whole.toolpath, whole.mark, config, {}, QStringLiteral("job.nc"));
    ASSERT_TRUE(job.ok());
    const PlanOutcome plan = planProgram(*job.toolpath, config, QStringLiteral("job.nc"));
    ASSERT_TRUE(plan.ok()) << (plan.errors.empty() ? "" : plan.errors[0].text.toStdString());
    EXPECT_EQ(plan.program->commands.back().endSteps, wholePlan.program->commands.back().endSteps);
    EXPECT_LT(plan.stats.estimatedS, wholePlan.stats.estimatedS);
    bool spindle = false, waited = false;
    for (const machine::UnitCommand &c : plan.program->commands) {
        if (c.op == machine::UnitOp::Spindle)
            spindle = true;
        if (c.op == machine::UnitOp::Dwell && spindle)
            waited = true;
        if (c.op == machine::UnitOp::Vector || c.op == machine::UnitOp::Line)
            break;
        EXPECT_NE(c.op, machine::UnitOp::OperatorStop); // the M6 before line 18 is not asked again
    }
    EXPECT_TRUE(spindle && waited);
}

// A canned cycle's later holes run from their own line: the cycle's modes and its initial
// level are the interpreter's, as when the whole program runs.
TEST(RunFromLine, CannedCycleLine)
{
    const char *text = "G21 G90 G17 F200\nG0 Z-10\nG98 G81 X10 Y10 Z-20 R-12\nX20\nX30\nG80\n"
                       "G0 Z-5\nM2\n";
    const InterpretOutcome whole = interpret(text, 5);
    const FromLineOutcome job =
        runFromLine(*whole.toolpath, whole.mark, gve64(), {0, 0, -5, 0}, QStringLiteral("c.nc"));
    ASSERT_TRUE(job.ok()) << job.refusal.toStdString();
    EXPECT_EQ(job.from.state.motion, 810);
    EXPECT_EQ(job.from.state.machineMm, (Point4{20, 10, -10, 0})); // back at the initial level
    EXPECT_EQ(job.toolpath->last(), whole.toolpath->last());
}

void expectRefused(const char *text, std::uint32_t line, gcode::LineMarkRefusal why,
                   std::uint32_t refLine, const char *words)
{
    const InterpretOutcome whole = interpret(text, line);
    ASSERT_TRUE(whole.errors.empty());
    EXPECT_EQ(whole.mark.refusal, why);
    EXPECT_EQ(whole.mark.refLine, refLine);
    const FromLineOutcome job =
        runFromLine(*whole.toolpath, whole.mark, gve64(), {}, QStringLiteral("job.nc"));
    EXPECT_FALSE(job.ok());
    EXPECT_TRUE(
        job.refusal.startsWith(QStringLiteral("job.nc:%1: cannot run from this line").arg(line)))
        << job.refusal.toStdString();
    EXPECT_TRUE(job.refusal.contains(QLatin1String(words))) << job.refusal.toStdString();
}

TEST(RunFromLine, LinesThatDoNotRunOnceAreRefusedWithTheLineToChoose)
{
    using R = gcode::LineMarkRefusal;
    expectRefused("G21 G90 F100\n#1=0\no100 while [#1 LT 2]\nG1 X#1\n#1=[#1+1]\no100 endwhile\n"
                  "M2\n",
                  4, R::InLoop, 3, "Choose line 3");
    expectRefused("G21 G90 F100\nG0 X-10\nG42.1 D4 G1 X0 Y0\nG1 X20\nG1 Y20\nG40 G1 X30\nM2\n", 5,
                  R::InCutterComp, 3, "cutter radius compensation");
    expectRefused("G21 G90 F100\no101 repeat [2]\nG91 G1 X1\no101 endrepeat\nM2\n", 3, R::InLoop, 2,
                  "loop o101");
    expectRefused("o200 sub\nG1 X5\no200 endsub\nG21 G90 F100\no200 call\nM2\n", 2, R::InSubroutine,
                  1, "subroutine o200");
    expectRefused("G21 G90 F100\no300 call\nM2\no300 sub\nG1 X5\no300 endsub\n", 5, R::InCall, 2,
                  "Choose line 2");
    expectRefused("G21 G90 F100\no400 if [0]\nG1 X5\no400 endif\nG1 X1\nM2\n", 3, R::NotTaken, 2,
                  "never run");
    expectRefused("G21 F100\nG1 X1\nM2\nG1 X2\n", 4, R::NotReached, 3, "ends on line 3");
}

TEST(RunFromLine, LinesThatRunAtTheTopLevelAreTaken)
{
    // Inside an if taken, after a loop, after a subroutine's definition and call.
    const char *text = "o200 sub\nG1 X5\no200 endsub\nG21 G90 F100\no200 call\n"
                       "o100 if [1]\nG1 X7\no100 endif\n#1=0\no101 while [#1 LT 2]\n#1=[#1+1]\n"
                       "o101 endwhile\nG1 X9\nM2\n";
    for (std::uint32_t line : {7u, 13u}) {
        const FromLineOutcome job = fromLine(text, line, {});
        EXPECT_TRUE(job.ok()) << line << ": " << job.refusal.toStdString();
        EXPECT_EQ(job.from.line, line);
    }
    // A comment line starts at the next line that runs.
    const FromLineOutcome comment = fromLine("G21 G90 F100\nG1 X1\n(next)\nG1 X2\nM2\n", 3);
    ASSERT_TRUE(comment.ok());
    EXPECT_EQ(comment.from.line, 3u);
    EXPECT_EQ(comment.from.state.machineMm.x, 1.0);
}

TEST(RunFromLine, NoFeedInForceIsRefused)
{
    const FromLineOutcome job = fromLine("G21 G90\nG0 X1\nG0 X2\nM2\n", 3);
    EXPECT_FALSE(job.ok());
    EXPECT_TRUE(job.refusal.contains(QLatin1String("F word"))) << job.refusal.toStdString();
}

} // namespace
} // namespace frezka::session
