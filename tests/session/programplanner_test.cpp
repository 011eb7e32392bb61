// The program's check and plan shared by the GUI and frezka-cli run: work systems beyond G59
// and G92 apply, every G-code error is reported with its line, plan errors are worded.
#include "session/programplanner.h"

#include "gcode/interpreter.h"
#include "machine/machineconfig.h"

#include <gtest/gtest.h>

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

namespace frezka::session {
namespace {

InterpretOutcome interpret(const char *text, const OffsetState &offsets = {},
                           std::array<double, 4> start = {})
{
    InterpretRequest r;
    r.text = text;
    r.fileName = QStringLiteral("job.nc");
    r.offsets = offsets;
    r.startMm = start;
    return interpretProgram(r);
}

TEST(ProgramPlanner, NineSystemsAndG92Apply)
{
    OffsetState o;
    o.systems[7] = {100, 50, -10, 0}; // G59.2
    o.g92 = {1, 2, 3, 0};
    o.active = 7;
    const InterpretOutcome r = interpret("G21 G90\nG0 X0 Y0 Z0\nG54 G0 X0\nM2\n", o, {5, 5, 0, 0});
    ASSERT_TRUE(r.errors.empty());
    ASSERT_TRUE(r.toolpath);
    EXPECT_EQ(r.toolpath->origin(), (gcode::Point4{5, 5, 0, 0}));
    EXPECT_EQ(r.toolpath->end(0), (gcode::Point4{101, 52, -7, 0}));
    EXPECT_EQ(r.toolpath->end(1).x, 1.0); // G54 is zero, G92 stays
}

TEST(ProgramPlanner, EveryGcodeErrorWithItsLine)
{
    const InterpretOutcome r = interpret("G21\nG1 X10 Q\nG1 Y5 F100 K\nM2\n");
    ASSERT_EQ(r.errors.size(), 2u);
    EXPECT_EQ(r.errors[0].line, 2);
    EXPECT_EQ(r.errors[1].line, 3);
    EXPECT_TRUE(r.errors[0].text.startsWith(QStringLiteral("job.nc:2:")))
        << r.errors[0].text.toStdString();
}

// Issue 17 item 4: the profile's bounds reach the interpreter, the cancel flag stops it, and
// the profile's defaults are the interpreter's.
TEST(ProgramPlanner, TheProfilesBoundsAndTheCancelFlagReachTheInterpreter)
{
    InterpretRequest r;
    r.text = "#1 = 0\no2 do\n#1 = [#1 + 1]\no2 while [1]\nM2\n";
    r.fileName = QStringLiteral("spin.nc");
    r.limits.maxLinesExecuted = 3000;
    const InterpretOutcome bounded = interpretProgram(r);
    ASSERT_EQ(bounded.errors.size(), 1u);
    EXPECT_TRUE(bounded.errors[0].text.startsWith(
        QStringLiteral("spin.nc:2:1: o2 do has not ended after 3000 lines executed")))
        << bounded.errors[0].text.toStdString();
    EXPECT_FALSE(bounded.cancelled);

    std::atomic_bool cancel{true};
    r.text = "o2 do\nG1 X1 F100\nG1 X0\no2 while [1]\nM2\n";
    r.limits = {};
    r.cancel = &cancel;
    const InterpretOutcome cancelled = interpretProgram(r);
    EXPECT_TRUE(cancelled.cancelled);
    EXPECT_TRUE(cancelled.errors.empty());
    ASSERT_TRUE(cancelled.toolpath);
    EXPECT_LE(cancelled.toolpath->size(), 4096u); // stopped within 4 096 lines executed

    const gcode::Options interpreter;
    const machine::ProgramConfig profile;
    EXPECT_EQ(std::uint64_t(profile.maxLinesExecuted), interpreter.maxBlocks);
    EXPECT_EQ(std::uint64_t(profile.maxMoves), interpreter.maxMoves);
}

// Issue 15: o<name> call finds name.ngc in the program's folder and in the profile's
// program.subroutinePath folders (relative ones from the profile's folder); an error in the file
// names the file.
TEST(ProgramPlanner, SubroutineFilesFromTheProgramsFolderAndTheProfilesPath)
{
    QTemporaryDir dir;
    ASSERT_TRUE(QDir(dir.path()).mkpath(QStringLiteral("profiles/subs")));
    ASSERT_TRUE(QDir(dir.path()).mkpath(QStringLiteral("jobs")));
    const auto write = [&](const QString &name, const QByteArray &text) {
        QFile f(dir.filePath(name));
        ASSERT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(text);
    };
    write(QStringLiteral("profiles/subs/drill.ngc"), "o<drill> sub\nG0 X#1\no<drill> endsub\n");
    write(QStringLiteral("jobs/pocket.ngc"), "o<pocket> sub\nG0 Y#1\n#2=[1/0]\no<pocket> endsub\n");
    machine::MachineConfig config = machine::defaultMachineConfig(protocol::Variant::Gve64);
    config.program.subroutinePath = "subs:/nowhere";
    const std::string profile = dir.filePath(QStringLiteral("profiles/mill.json")).toStdString();
    InterpretRequest r;
    r.text = "o<drill> call [12]\nM2\n";
    r.fileName = QStringLiteral("job.nc");
    r.programDirectory = dir.filePath(QStringLiteral("jobs")).toStdString();
    r.subroutinePath = machine::subroutineFolders(config, profile);
    ASSERT_EQ(r.subroutinePath.size(), 2u);
    EXPECT_EQ(r.subroutinePath[0], dir.filePath(QStringLiteral("profiles/subs")).toStdString());
    InterpretOutcome out = interpretProgram(r);
    ASSERT_TRUE(out.errors.empty()) << out.errors[0].text.toStdString();
    EXPECT_EQ(out.toolpath->end(0).x, 12);
    r.text = "o<pocket> call [3]\nM2\n";
    out = interpretProgram(r);
    ASSERT_EQ(out.errors.size(), 1u);
    EXPECT_TRUE(out.errors[0].text.startsWith(dir.filePath(QStringLiteral("jobs/pocket.ngc:3:"))))
        << out.errors[0].text.toStdString();
    r.subroutinePath.clear();
    r.text = "o<drill> call [12]\nM2\n";
    EXPECT_EQ(interpretProgram(r).errors.size(), 1u) << "not found without the profile's path";
}

// Issue 15: splines are cut within the profile's chord tolerance (the one arcs are planned
// with); the defaults agree.
TEST(ProgramPlanner, SplinesAreChordedWithinTheRequestsTolerance)
{
    EXPECT_EQ(InterpretRequest{}.splineToleranceMm,
              machine::MachineConfig{}.motion.chordToleranceMm);
    InterpretRequest r;
    r.text = "G21 F100\nG5.1 X10 Y0 I5 J10\nM2\n";
    r.fileName = QStringLiteral("spline.nc");
    const InterpretOutcome fine = interpretProgram(r);
    r.splineToleranceMm = 0.5;
    const InterpretOutcome rough = interpretProgram(r);
    ASSERT_TRUE(fine.errors.empty() && rough.errors.empty());
    EXPECT_GT(fine.toolpath->size(), 20u);
    EXPECT_LT(rough.toolpath->size(), 10u);
}

TEST(ProgramPlanner, PlansOrWordsThePlanError)
{
    const auto config = machine::defaultMachineConfig(protocol::Variant::Gve64);
    const InterpretOutcome ok = interpret("G21 G90\nG1 X10 F600\nM2\n");
    const PlanOutcome plan = planProgram(*ok.toolpath, config, QStringLiteral("job.nc"));
    ASSERT_TRUE(plan.ok());
    EXPECT_FALSE(plan.program->commands.empty());
    EXPECT_GT(plan.stats.estimatedS, 0);
    const PlanOutcome slower = planProgram(*ok.toolpath, config, QStringLiteral("job.nc"), 0.5);
    ASSERT_TRUE(slower.ok());
    EXPECT_GT(slower.stats.estimatedS, plan.stats.estimatedS); // the feed override plans in

    const InterpretOutcome far = interpret("G21 G90\nG0 X5000\nM2\n");
    const PlanOutcome refused = planProgram(*far.toolpath, config, QStringLiteral("far.nc"));
    EXPECT_FALSE(refused.ok());
    ASSERT_FALSE(refused.errors.empty());
    EXPECT_EQ(refused.errors.front().line, 2);
    EXPECT_TRUE(refused.errors.front().text.startsWith(QStringLiteral("far.nc:2: the move leaves")))
        << refused.errors.front().text.toStdString();
}

} // namespace
} // namespace frezka::session
