// programInfo (issue 16 item 7): the job split at its M6s with the planner's line times, the cut
// length of each tool, and the extent in the program's own and in machine coordinates.
#include "session/programinfo.h"

#include "gcode/interpreter.h"

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

const char *const kTools = "G21 G90\n"      // 1
                           "G1 X10 F600\n"  // 2: cut before the first M6 (the spindle's tool)
                           "T3 M6\n"        // 3
                           "G1 Y20\n"       // 4
                           "G0 Z-1\n"       // 5: a rapid: no cut length
                           "T5 M6\n"        // 6
                           "G1 X0 Y0 Z-2\n" // 7
                           "M2\n";          // 8

LoadedProgram loaded(const OffsetState &offsets)
{
    LoadedProgram p;
    p.text = std::make_shared<ProgramText>(QByteArray(kTools));
    gcode::Options options;
    options.workOffsetsMm = offsets.systems;
    options.coordinateSystem = offsets.active;
    gcode::Result g = gcode::interpretText(kTools, options);
    EXPECT_TRUE(g.ok());
    p.toolpath = std::make_shared<gcode::Toolpath>(std::move(g.toolpath));
    // Seconds at the end of each line (index = line), as the planner gives them.
    p.lineEndS = {0, 0, 2, 2, 6, 7, 7, 10, 10};
    p.estimatedS = 10;
    return p;
}

TEST(ProgramInfo, SplitsTheJobAtItsToolChanges)
{
    const ProgramInfo info = programInfo(loaded({}), {}, machine::MachineConfig{});
    EXPECT_EQ(info.lines, 8);
    ASSERT_EQ(info.tools.size(), 3u);
    EXPECT_EQ(info.tools[0], (ToolShare{-1, 1, 2, 10}));
    EXPECT_EQ(info.tools[1].tool, 3);
    EXPECT_EQ(info.tools[1].fromLine, 3u);
    EXPECT_DOUBLE_EQ(info.tools[1].seconds, 5);
    EXPECT_DOUBLE_EQ(info.tools[1].cutLengthMm, 20);
    EXPECT_EQ(info.tools[2].tool, 5);
    EXPECT_DOUBLE_EQ(info.tools[2].seconds, 3);
    EXPECT_NEAR(info.tools[2].cutLengthMm, std::hypot(10, 20, 1), 1e-9);
}

TEST(ProgramInfo, GivesTheExtentInProgramAndMachineCoordinates)
{
    OffsetState offsets;
    offsets.systems[0] = {100, 50, -20, 0};
    const ProgramInfo info = programInfo(loaded(offsets), offsets, machine::MachineConfig{});
    ASSERT_TRUE(info.moves);
    EXPECT_DOUBLE_EQ(info.workMinMm[0], 0);
    EXPECT_DOUBLE_EQ(info.workMaxMm[0], 10);
    EXPECT_DOUBLE_EQ(info.workMaxMm[1], 20);
    EXPECT_DOUBLE_EQ(info.workMinMm[2], -2);
    EXPECT_DOUBLE_EQ(info.machineMaxMm[0], 110);
    EXPECT_DOUBLE_EQ(info.machineMinMm[2], -22);
}

// Not planned: every time unknown, the rest still there.
TEST(ProgramInfo, WithoutAPlanTheTimesAreUnknown)
{
    LoadedProgram p = loaded({});
    p.lineEndS.clear();
    p.estimatedS = -1;
    const ProgramInfo info = programInfo(p, {}, machine::MachineConfig{});
    ASSERT_EQ(info.tools.size(), 3u);
    for (const ToolShare &t : info.tools)
        EXPECT_LT(t.seconds, 0);
    EXPECT_DOUBLE_EQ(info.tools[1].cutLengthMm, 20);
}

} // namespace
} // namespace frezka::session
