// The rests of a job (issue 12, docs/planner.md §7, driver/link/poller.h): while the job waits for
// the unit to stand it reads F alone, back to back, so that it sees the stop one F exchange after
// it; then the path guard's position read, the commands that travel alone and the first packet,
// which the unit runs at its *E; the estimate charges exactly that. Property seeds 27 (GVE64 at
// 19 200 Bd and 10.5 ms, 67 rests of one-vector chains), 4 (GVE84 at 38 400 Bd and 9.6 ms, 120
// rests, 16 chains held at their start) and 20 (GVE114 at 115 200 Bd and 14.6 ms, packets off, 174
// rests), clean links: until issue 12's eleventh session the job learnt of each stop from its polls
// (position, F and the inputs, back to back where they took longer than 50 ms), at a phase of that
// cycle that repeats with repeating chains, and ran 11.6 %, 5.1 % and 5.7 % over its estimate.

#include "heldjob.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <cstdio>

using namespace frezka;
using namespace frezka::machine::test;

namespace {

void restsCostWhatTheEstimateCharges(unsigned seed)
{
    HeldJob held(drawJob(seed, 300), true);
    ASSERT_EQ(held.job.wire.byteErrorRate, 0.0);
    ASSERT_EQ(held.job.overridePercent, 100);
    ASSERT_TRUE(held.connectAndRun());
    ASSERT_TRUE(held.runner.runUntil([&] { return !held.finished.empty(); }, 3000));
    EXPECT_TRUE(held.finished.front());
    const emulator::Unit &unit = held.port.unit();
    EXPECT_EQ(unit.position(), held.plan.program.commands.back().endSteps); // every vector once
    EXPECT_EQ(unit.stats().motion.brakeViolations, 0);
    EXPECT_EQ(unit.stats().motion.starvationStops, machine::plannedRestarts(held.plan.program));
    const driver::JobReport &rep = held.core.jobReport();
    const double jobS = rep.endS - rep.startS;
    const double estimateS = held.plan.stats.estimatedS;
    EXPECT_LE(std::abs(jobS - estimateS), 0.02 * estimateS)
        << "job " << jobS << " s, estimate " << estimateS << " s";
    // On the wire, at each rest (the lines the driver wrote while the unit stood): at most one F
    // (the one that sees the stop), one position read after it, then the commands that start the
    // next chain; no second position read, no F after the position read, and the inputs only
    // where they were not read for twice their interval (poller.h: they go where the model has the
    // unit run on, else at the start of a wait once that long; a chain shorter than their read
    // then rests with them).
    const double inputsGapS = 2 * 4 * driver::CoreOptions{}.inputsPollIntervalS;
    double lastInputsS = -1e9;
    int rests = 0, polled = 0;
    for (std::size_t i = 0; i < held.wire.size() && held.wireAt[i] < rep.endS; ++i) {
        const double inputsBeforeS = lastInputsS;
        if (held.wire[i].starts_with("!0I1"))
            lastInputsS = held.wireAt[i];
        if (held.movingAt[i] || held.wireAt[i] < rep.startS)
            continue;
        std::size_t end = i;
        int flags = 0, positions = 0, inputs = 0, flagsAfterPosition = 0;
        for (; end < held.wire.size() && !held.movingAt[end] && held.wireAt[end] < rep.endS;
             ++end) {
            const std::string &line = held.wire[end];
            if (!line.starts_with("!0F") && !line.starts_with("!0P") && !line.starts_with("!0I"))
                break; // the next chain's commands (or a spindle's, before a wait of its own)
            flags += line == "!0F" ? 1 : 0;
            flagsAfterPosition += line == "!0F" && positions > 0 ? 1 : 0;
            positions += line.starts_with("!0P") ? 1 : 0;
            if (line.starts_with("!0I1"))
                inputs += held.wireAt[end] - inputsBeforeS < inputsGapS - 0.1 ? 1 : 0;
        }
        ++rests;
        if (flags > 1 || positions > 1 || inputs > 0 || flagsAfterPosition > 0) {
            ++polled;
            std::string lines;
            for (std::size_t k = i; k < end; ++k)
                lines += held.wire[k] + " ";
            ADD_FAILURE() << "a rest at " << held.wireAt[i] << " s polled: " << lines
                          << "(the inputs read before at " << inputsBeforeS << " s)";
        }
        for (end = i; end < held.wire.size() && !held.movingAt[end]; ++end)
            lastInputsS = held.wire[end].starts_with("!0I1") ? held.wireAt[end] : lastInputsS;
        i = end;
    }
    EXPECT_GE(rests, machine::plannedRestarts(held.plan.program));
    EXPECT_EQ(polled, 0);
}

} // namespace

TEST(RestWait, Seed27OneVectorChainsRestWithinTheEstimate)
{
    restsCostWhatTheEstimateCharges(27);
}

TEST(RestWait, Seed4HeldChainsRestWithinTheEstimate)
{
    restsCostWhatTheEstimateCharges(4);
}

TEST(RestWait, Seed20WithoutPacketsRestsWithinTheEstimate)
{
    restsCostWhatTheEstimateCharges(20);
}
