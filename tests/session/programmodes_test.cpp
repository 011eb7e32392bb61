// ModalScanner (issue 16 item 1): the program's active codes line by line, as the status panel
// shows them: LinuxCNC's defaults at the start, each group as the lines change it, the tool of
// T then M6, the spindle and coolant, reading on as the line grows and again from the top.
#include "session/programmodes.h"

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

std::shared_ptr<const ProgramText> textOf(const char *text)
{
    return std::make_shared<ProgramText>(QByteArray(text));
}

TEST(ProgramModes, StartsWithLinuxCncsDefaults)
{
    EXPECT_EQ(startModes(0).gText(),
              QStringLiteral("G80 G17 G40 G21 G90 G94 G54 G49 G99 G64 G91.1"));
    EXPECT_EQ(startModes(6).gText(),
              QStringLiteral("G80 G17 G40 G21 G90 G94 G59.1 G49 G99 G64 G91.1"));
    EXPECT_EQ(startModes(0).mText(), QStringLiteral("M5 M9"));
}

TEST(ProgramModes, FollowsTheLinesAndReadsAgainFromTheTop)
{
    ModalScanner scanner(textOf("G20 G91 (a comment G18)\n"
                                "T3 M6 ; tool three\n"
                                "M3 S1000 M8\n"
                                "G1 X1 F10\n"
                                "G18 G2 X2 Z0 I1 K0\n"
                                "M7\n"
                                "G55 M9 M5\n"
                                "T4\n"),
                         0);
    EXPECT_EQ(scanner.at(1).gText(),
              QStringLiteral("G80 G17 G40 G20 G91 G94 G54 G49 G99 G64 G91.1"));
    EXPECT_EQ(scanner.at(2).tool, 3);
    EXPECT_EQ(scanner.at(3).mText(), QStringLiteral("M3 M8"));
    EXPECT_TRUE(scanner.at(4).gText().startsWith(QLatin1String("G1 G17")));
    EXPECT_TRUE(scanner.at(5).gText().startsWith(QLatin1String("G2 G18")));
    EXPECT_EQ(scanner.at(6).mText(), QStringLiteral("M3 M7 M8"));
    const ProgramModes end = scanner.at(8);
    EXPECT_EQ(end.mText(), QStringLiteral("M5 M9"));
    EXPECT_EQ(end.g[gcode::kGCoordSystem], 550);
    EXPECT_EQ(end.tool, 3) << "T4 selects; only M6 puts it in the spindle";
    // Back to an earlier line: read again from the top.
    EXPECT_EQ(scanner.at(2).mText(), QStringLiteral("M5 M9"));
    EXPECT_EQ(scanner.at(0), startModes(0));
}

} // namespace
} // namespace frezka::session
