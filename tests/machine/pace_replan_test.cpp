// The link's pace planned again only while it helps (issue 17, docs/planner.md §4 "How often a
// run is planned"): a re-plan whose own B, V and A commands fit what it was paced for is kept.
// The spiral of bench_gui_load (one chain of short G1 moves) used to be planned 6 times, the
// first plan and all 5 re-plans, as its B commands near the centre went back and forth; the plan
// it keeps must still keep the unit fed on the emulated link, at the estimate.
#include "randomjob.h"
#include "spiralprogram.h"

#include "gcode/interpreter.h"
#include "machine/planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

using namespace frezka;
using namespace frezka::machine;

namespace {

using test::spiral; // spiralprogram.h

std::string list(const std::vector<std::string> &items)
{
    std::string out;
    for (const std::string &f : items)
        out += "\n  - " + f;
    return out;
}

test::RandomJob spiralJob(long lines)
{
    test::RandomJob job;
    job.config = defaultMachineConfig(protocol::Variant::Gve64);
    job.wire.baud = job.config.link.baud;
    job.wire.latencyS = job.config.link.latencyMs / 1000.0;
    job.program = spiral(lines);
    job.summary = "the spiral, " + std::to_string(lines) + " lines, GVE64 as shipped";
    return job;
}

} // namespace

TEST(PaceReplan, TheSpiralIsPlannedThreeTimesNotSix)
{
    const test::RandomJob job = spiralJob(30000);
    const gcode::Result g = gcode::interpretText(job.program);
    ASSERT_TRUE(g.ok());
    const PlanResult r = plan(g.toolpath, job.config);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.stats.chains, 1u);
    EXPECT_EQ(r.stats.vectors, 29997u);
    // The first plan assumes no B, V or A commands: it is always planned again once.
    EXPECT_EQ(r.stats.mostPlans, 3);
    EXPECT_EQ(r.stats.movePlans, 3 * r.stats.vectors);
    EXPECT_EQ(r.stats.brakeViolations, 0u);
}

TEST(PaceReplan, WithoutTheLinksPaceTheRunIsPlannedOnce)
{
    const gcode::Result g = gcode::interpretText(spiral(2000));
    PlanOptions options;
    options.wireLimited = false;
    const PlanResult r = plan(g.toolpath, defaultMachineConfig(protocol::Variant::Gve64), options);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.stats.mostPlans, 1);
    EXPECT_EQ(r.stats.movePlans, r.stats.vectors);
}

// The plan kept after fewer re-plans, streamed through the driver to the emulator on a virtual
// clock at the shipped link: every vector once, the counters at the program's end, the unit never
// ran dry, no brake violation, the job within 2 % of the estimate.
TEST(PaceReplan, TheSpiralsPlanKeepsTheUnitFedOnTheLink)
{
    const test::JobOutcome o = test::runJob(spiralJob(30000));
    ASSERT_TRUE(o.planned);
    EXPECT_EQ(o.stats.mostPlans, 3);
    EXPECT_TRUE(o.wrong.empty()) << list(o.wrong);
    EXPECT_TRUE(o.pace.empty()) << list(o.pace);
    EXPECT_EQ(o.vectorsExecuted, o.vectorsPlanned);
    EXPECT_EQ(o.vectorsPlanned, 29997);
    EXPECT_EQ(o.starvationStops, 0);
    EXPECT_EQ(o.brakeViolations, 0);
    EXPECT_TRUE(o.exact);
    EXPECT_NEAR(o.jobS, o.stats.estimatedS, 0.02 * o.stats.estimatedS);
}
