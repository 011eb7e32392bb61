// RemainingTime (issue 16 item 8): the time left counts down through a long move and through a
// dwell, where the driver's own estimate (elapsed time scaled by the commands run) counts up;
// on the in-process emulator and a virtual clock, from what the driver shows.
#include "session/plannedspeed.h"
#include "session/remainingtime.h"
#include "session/runworkflow.h"
#include "session/simlink.h"

#include "gcode/interpreter.h"
#include "machine/planner.h"

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

TEST(RemainingTime, CountsDownThroughALineAndStopsAtItsEnd)
{
    // Lines 1 and 2 plan 10 s each, line 3 nothing, line 4 a 5 s dwell.
    RemainingTime r({0.f, 10.f, 20.f, 20.f, 25.f}, 25.0);
    EXPECT_DOUBLE_EQ(r.at(0, 100), 25.0);
    EXPECT_DOUBLE_EQ(r.at(1, 100), 25.0);
    EXPECT_DOUBLE_EQ(r.at(1, 104), 21.0);
    EXPECT_DOUBLE_EQ(r.at(1, 130), 15.0) << "a slow line waits at its end, never counts up";
    EXPECT_DOUBLE_EQ(r.at(2, 130), 15.0);
    EXPECT_DOUBLE_EQ(r.at(4, 140), 5.0);
    EXPECT_DOUBLE_EQ(r.at(4, 143), 2.0);
    EXPECT_DOUBLE_EQ(r.at(4, 150, false), 2.0) << "held: the time on the line does not count";
    EXPECT_DOUBLE_EQ(r.at(4, 151), 1.0);
    EXPECT_DOUBLE_EQ(RemainingTime().at(3, 1), -1.0);
}

// A 20 s dwell between two cuts: the driver shows the dwell's line while it waits (not the next
// line, which has not been sent), and through the dwell the figure falls with the clock, while
// the driver's own estimate rises.
TEST(RemainingTime, CountsDownThroughADwellOnTheEmulator)
{
    auto config = machine::defaultMachineConfig(protocol::Variant::Gve64);
    config.motion.runBeforeHoming = true;
    const gcode::Result g = gcode::interpretText(
        "G21 G90\nG1 Z-2 F600\nG1 X40 F1200\nG4 P20\nG1 Y40 F1200\nG0 Z0\nM2\n", {});
    ASSERT_TRUE(g.ok());
    machine::PlanResult p = machine::plan(g.toolpath, config);
    ASSERT_TRUE(p.ok());
    RemainingTime remaining(plannedLineTimes(p.program, p.stats.speedModeVk, p.stats.estimatedS),
                            p.stats.estimatedS);
    SimLink link(config, driver::unitOptionsFor(config), driver::WireOptions{},
                 driver::CoreOptions{});
    RunWorkflow workflow(link);
    workflow.setProfile(config);
    workflow.setProgram(std::make_shared<machine::UnitProgram>(p.program), {},
                        QStringLiteral("dwell.nc"));
    workflow.start(RunWorkflow::connectionFor(config), false);
    std::vector<double> atDwell, driverAtDwell;
    double last = 1e9;
    while (!workflow.hasEnded() && link.now() < 600) {
        link.runFor(0.5);
        const auto &s = link.state();
        if (!s.jobActive)
            continue;
        const double left = remaining.at(s.sourceLine, link.now());
        EXPECT_LE(left, last + 1e-9) << "at line " << s.sourceLine << ", " << link.now() << " s";
        last = left;
        if (s.sourceLine == 4) {
            atDwell.push_back(left);
            driverAtDwell.push_back(s.etaS);
        }
    }
    ASSERT_TRUE(workflow.hasEnded());
    ASSERT_GE(atDwell.size(), 30u) << "the driver shows the dwell's line while it waits";
    EXPECT_NEAR(atDwell.front() - atDwell.back(), 0.5 * double(atDwell.size() - 1), 1.0);
    EXPECT_GT(driverAtDwell.back(), driverAtDwell.front()) << "the driver's own estimate rises";
}

} // namespace
} // namespace frezka::session
