// A program that never ends (issue 17 item 4): an o-word loop or a recursion without an exit is
// stopped at Options::maxMoves toolpath entries or Options::maxBlocks executed lines, the error
// standing on the line of the loop (or the recursive call) that never ends and naming the line
// the program had reached; Options::cancel stops any interpretation within 4 096 lines.

#include "gcode/interpreter.h"

#include <gtest/gtest.h>

using namespace frezka::gcode;

namespace {

Options bounded(std::uint64_t lines, std::uint64_t moves, bool check = true)
{
    Options options;
    options.maxBlocks = lines;
    options.maxMoves = moves;
    options.collectAllErrors = check; // the program check's mode (GUI and frezka-cli)
    return options;
}

// The one error of a result, or a failure naming what came instead.
::testing::AssertionResult oneError(const Result &r, ErrorCode code, std::uint32_t line,
                                    std::uint32_t column = 1)
{
    if (r.errors.size() != 1)
        return ::testing::AssertionFailure() << r.errors.size() << " errors";
    const Error &e = r.errors[0];
    if (e.code != code || e.line != line || e.column != column)
        return ::testing::AssertionFailure() << errorName(e.code) << " at " << e.line << ":"
                                             << e.column << ": " << englishMessage(e);
    return ::testing::AssertionSuccess();
}

} // namespace

TEST(EndlessProgram, WhileLoopThatMovesIsStoppedAtItsLineWithinTheBound)
{
    const Result r = interpretText("G21 G90 F100\n"
                                   "  o1 while [1]\n"
                                   "G1 X1\n"
                                   "G1 X0\n"
                                   "o1 endwhile\n"
                                   "M2\n",
                                   bounded(100'000'000, 1000));
    ASSERT_TRUE(oneError(r, ErrorCode::LoopMovesNeverEnd, 2, 3));
    const std::string message = englishMessage(r.errors[0]);
    EXPECT_EQ(
        message.rfind("o1 while has not ended after 1000 moves (it was stopped at line 3)", 0), 0u)
        << message;
    EXPECT_EQ(r.toolpath.size(), 1001u); // stopped at the first entry beyond the bound
    EXPECT_TRUE(r.warnings.empty());     // no "file ends without M2" after a stop
    EXPECT_FALSE(r.ended);
}

TEST(EndlessProgram, MotionlessLoopIsStoppedAtTheLinesExecuted)
{
    const Result r = interpretText("#1 = 0\n"
                                   "o<spin> while [#1 ge 0]\n"
                                   "#1 = [#1 + 1]\n"
                                   "o<spin> endwhile\n"
                                   "M2\n",
                                   bounded(1000, 100'000'000));
    ASSERT_TRUE(oneError(r, ErrorCode::LoopNeverEnds, 2));
    const std::string message = englishMessage(r.errors[0]);
    EXPECT_EQ(message.rfind("o<spin> while has not ended after 1000 lines executed", 0), 0u)
        << message;
    EXPECT_TRUE(r.toolpath.empty());
}

TEST(EndlessProgram, FirstErrorModeStopsTheSameWay)
{
    const Result r =
        interpretText("o1 do\nG0 X1\nG0 X2\no1 while [1]\nM2\n", bounded(100'000'000, 500, false));
    ASSERT_TRUE(oneError(r, ErrorCode::LoopMovesNeverEnd, 1)); // the do line
}

TEST(EndlessProgram, TheLoopThatKeepsTurningIsNamedNotTheFiniteOneInsideIt)
{
    // An endless outer loop around a finite inner one: the outer loop is named.
    const Result outer = interpretText("o1 while [1]\n"
                                       "o2 repeat [3]\n"
                                       "G0 X1\n"
                                       "o2 endrepeat\n"
                                       "o1 endwhile\n"
                                       "M2\n",
                                       bounded(100'000'000, 1000));
    ASSERT_TRUE(oneError(outer, ErrorCode::LoopMovesNeverEnd, 1));
    // A finite outer loop around an endless inner one: the inner loop is named.
    const Result inner = interpretText("o1 repeat [2]\n"
                                       "G0 Z1\n"
                                       "o2 while [1]\n"
                                       "G0 X1\n"
                                       "o2 endwhile\n"
                                       "o1 endrepeat\n"
                                       "M2\n",
                                       bounded(100'000'000, 1000));
    ASSERT_TRUE(oneError(inner, ErrorCode::LoopMovesNeverEnd, 3));
}

TEST(EndlessProgram, RecursionThatMovesNamesTheRecursiveCall)
{
    // Each call makes two more down to depth 40 (within the 100 nested calls): 2^40 moves.
    const Result r = interpretText("o<tree> sub\n"
                                   "G1 X[#1] F100\n"
                                   "o10 if [#1 lt 40]\n"
                                   "o<tree> call [#1 + 1]\n"
                                   "o<tree> call [#1 + 1]\n"
                                   "o10 endif\n"
                                   "o<tree> endsub\n"
                                   "o<tree> call [0]\n"
                                   "M2\n",
                                   bounded(100'000'000, 1000));
    ASSERT_TRUE(oneError(r, ErrorCode::LoopMovesNeverEnd, 4));
    EXPECT_NE(englishMessage(r.errors[0]).find("o<tree> call has not ended"), std::string::npos);
}

TEST(EndlessProgram, ALongProgramWithoutLoopsIsStoppedAtTheLineReached)
{
    std::string text;
    for (int i = 0; i < 50; ++i)
        text += "G0 X" + std::to_string(i) + "\n";
    text += "M2\n";
    ASSERT_TRUE(
        oneError(interpretText(text, bounded(100'000'000, 20)), ErrorCode::TooManyMoves, 21));
    ASSERT_TRUE(
        oneError(interpretText(text, bounded(30, 100'000'000)), ErrorCode::TooManyBlocks, 31));
    // Within both bounds it is a program like any other.
    EXPECT_TRUE(interpretText(text, bounded(51, 51)).ok());
}

TEST(EndlessProgram, DefaultsLeaveAFiveMillionLineProgramWellInside)
{
    const Options defaults;
    EXPECT_GE(defaults.maxMoves, 2 * 5'000'000u);
    EXPECT_GE(defaults.maxBlocks, 10 * 5'000'000u);
    // ... and the entries of a program stopped there stay well under 800 MB.
    Toolpath path;
    for (int i = 0; i < 1000; ++i)
        path.appendFeed({double(i), 0, 0, 0}, 100, std::uint32_t(i + 1));
    EXPECT_LT(double(path.memoryBytes()) / double(path.size()) * double(defaults.maxMoves), 600e6);
}

TEST(EndlessProgram, CancelStopsAnyProgramWithinFourThousandLines)
{
    std::atomic_bool cancel{true};
    Options options = bounded(100'000'000, 100'000'000);
    options.cancel = &cancel;
    const Result r = interpretText("o1 while [1]\nG1 X1 F100\nG1 X0\no1 endwhile\nM2\n", options);
    EXPECT_TRUE(r.cancelled);
    EXPECT_TRUE(r.errors.empty());
    EXPECT_TRUE(r.warnings.empty());
    EXPECT_LE(r.toolpath.size(), 4096u);
}
