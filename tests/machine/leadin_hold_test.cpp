// The unit held at a chain's start until the wire can feed it (driver/link/leadinhold.h), read
// on the wire and on the emulated unit: property seed 235 (a GVE114 at 19 200 Bd), whose chain
// begins with a slow vector, then an A and a V, then vectors faster than packets of two or three
// could bring them. Without the hold the unit ran dry and stopped dead twice (brake violations).

#include "heldjob.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

using namespace frezka;
using namespace frezka::machine::test;

TEST(LeadInHold, AChainTheWireCannotFeedFromRestStartsWhenItsLeadInIsQueued)
{
    HeldJob held(drawJob(235, 300), true);
    ASSERT_TRUE(held.connectAndRun());
    ASSERT_TRUE(held.runner.runUntil([&] { return !held.finished.empty(); }, 600));
    EXPECT_TRUE(held.finished.front());
    const auto &stats = held.port.unit().stats().motion;
    EXPECT_EQ(stats.brakeViolations, 0);
    EXPECT_EQ(held.core.jobReport().leadInHolds, 1);
    EXPECT_EQ(held.port.unit().position(), held.plan.program.commands.back().endSteps);
    // On the wire: H with the unit at rest, the lead-in queued (its A and V too), the interrupt
    // causes read, then G; nothing moved before G.
    const std::size_t h = held.find("!0H");
    ASSERT_LT(h, held.wire.size());
    const std::size_t g = held.find("!0G", h);
    ASSERT_LT(g, held.wire.size());
    EXPECT_EQ(held.wire[g - 2], "!0SR4");
    EXPECT_EQ(held.wire[g - 1], "!0SR5");
    long vectors = 0, speeds = 0;
    for (std::size_t i = h; i < g; ++i) {
        vectors += held.wire[i].starts_with("!0C") ? 1 : 0;
        speeds += held.wire[i].starts_with("!0V") || held.wire[i].starts_with("!0A") ? 1 : 0;
    }
    EXPECT_GT(vectors, 100); // the packets while held are full ones
    EXPECT_GE(speeds, 2);

    // The same job without the hold: the unit runs dry in that chain and stops dead.
    HeldJob free(drawJob(235, 300), false);
    ASSERT_TRUE(free.connectAndRun());
    ASSERT_TRUE(free.runner.runUntil([&] { return !free.finished.empty(); }, 600));
    EXPECT_EQ(free.find("!0H"), free.wire.size());
    EXPECT_GT(free.port.unit().stats().motion.brakeViolations, 0);
}

// The STOP button pressed while the unit is held at the chain's start: G would clear the cause
// and start the chain; the job is held for the operator instead, and the unit has not moved.
TEST(LeadInHold, AnInputThatFiresWhileHeldHoldsTheJobInsteadOfStartingIt)
{
    HeldJob held(drawJob(235, 300), true, true);
    ASSERT_TRUE(held.connectAndRun());
    ASSERT_TRUE(held.runner.runUntil(
        [&] { return held.core.jobReport().leadInHolds > 0 && held.core.state().inta; }, 600));
    const auto at = held.port.unit().position();
    held.port.unit().setStopButton(true);
    ASSERT_TRUE(held.runner.runUntil(
        [&] { return held.core.state().mode == driver::MachineMode::Paused; }, 30));
    held.runner.runFor(1.0);
    EXPECT_EQ(held.core.state().hold, driver::HoldReason::Interrupt);
    EXPECT_NE(held.core.state().holdText.find("IN7"), std::string::npos)
        << held.core.state().holdText;
    EXPECT_EQ(held.find("!0G", held.find("!0H")), held.wire.size());
    EXPECT_EQ(held.port.unit().position(), at);
    // Released and resumed by the operator, the job runs to its end exactly.
    held.port.unit().setStopButton(false);
    ASSERT_FALSE(held.core.resume(held.runner.now()));
    ASSERT_TRUE(held.runner.runUntil([&] { return !held.finished.empty(); }, 600));
    EXPECT_TRUE(held.finished.front());
    EXPECT_EQ(held.port.unit().position(), held.plan.program.commands.back().endSteps);
    EXPECT_EQ(held.port.unit().stats().motion.brakeViolations, 0);
}

namespace {

// Seed 235 with the spindle started first (M3 before the program) and left on: what the
// operator's pause, abort and a lost link do to the spindle while the unit is held at the
// chain's start.
RandomJob spindleJob()
{
    RandomJob j = drawJob(235, 300);
    j.program = "M3 S12000\n" + j.program;
    // Its M5 before the held chain removed: the spindle turns while the unit is held there.
    for (std::size_t at; (at = j.program.find("\nM5\n")) != std::string::npos;)
        j.program.replace(at, 4, "\n");
    return j;
}

// Runs until the unit is held at a chain's start with the spindle turning; the unit's counters
// then.
bool untilHeld(HeldJob &held, std::array<std::int64_t, 4> &at)
{
    if (!held.connectAndRun() ||
        !held.runner.runUntil(
            [&] { return held.core.jobReport().leadInHolds > 0 && held.core.state().inta; }, 600))
        return false;
    at = held.port.unit().position();
    return held.port.unit().spindlePermille() > 0;
}

std::size_t count(const HeldJob &held, std::string_view prefix, std::size_t from)
{
    return static_cast<std::size_t>(
        std::count_if(held.wire.begin() + static_cast<std::ptrdiff_t>(from), held.wire.end(),
                      [&](const std::string &l) { return l.starts_with(prefix); }));
}

} // namespace

// Pause (spindle off) while held: the chain does not start, the spindle stops on the wire and
// on the unit, nothing moves; Resume turns it on again and the job ends exactly.
TEST(LeadInHold, PauseWhileHeldStopsTheSpindleAndStartsNothing)
{
    HeldJob held(spindleJob(), true);
    std::array<std::int64_t, 4> at{};
    ASSERT_TRUE(untilHeld(held, at));
    const std::size_t h = held.find("!0H");
    ASSERT_FALSE(held.core.pause(held.runner.now(), true));
    ASSERT_TRUE(held.runner.runUntil(
        [&] { return held.core.state().mode == driver::MachineMode::Paused; }, 30));
    held.runner.runFor(2.0);
    EXPECT_EQ(held.port.unit().position(), at);
    EXPECT_EQ(held.port.unit().spindlePermille(), 0);
    EXPECT_GE(count(held, "!7V0", h), 1u);
    EXPECT_EQ(count(held, "!0G", h), 0u);
    ASSERT_FALSE(held.core.resume(held.runner.now()));
    ASSERT_TRUE(held.runner.runUntil([&] { return !held.finished.empty(); }, 600));
    EXPECT_TRUE(held.finished.front());
    EXPECT_EQ(held.port.unit().position(), held.plan.program.commands.back().endSteps);
    EXPECT_EQ(held.port.unit().stats().motion.brakeViolations, 0);
    // On again before the chain goes on, the G the lead-in hold's own (after SR4 and SR5).
    EXPECT_GE(count(held, "!7V500", h), 1u);
    const std::size_t g = held.find("!0G", h);
    ASSERT_LT(g, held.wire.size());
    EXPECT_LT(held.find("!7V500", h), g);
    EXPECT_EQ(held.wire[g - 2], "!0SR4");
    EXPECT_EQ(held.wire[g - 1], "!0SR5");
}

// Abort while held: the queue is cleared, the chain never starts, the spindle is off, the job
// ends as aborted with the unit where it stood.
TEST(LeadInHold, AbortWhileHeldClearsTheQueueAndStopsTheSpindle)
{
    HeldJob held(spindleJob(), true);
    std::array<std::int64_t, 4> at{};
    ASSERT_TRUE(untilHeld(held, at));
    const std::size_t h = held.find("!0H");
    ASSERT_FALSE(held.core.abort(held.runner.now()));
    ASSERT_TRUE(held.runner.runUntil(
        [&] { return held.core.state().mode == driver::MachineMode::Idle; }, 30));
    held.runner.runFor(2.0);
    ASSERT_FALSE(held.finished.empty());
    EXPECT_FALSE(held.finished.front());
    EXPECT_EQ(held.port.unit().position(), at);
    EXPECT_EQ(held.port.unit().spindlePermille(), 0);
    EXPECT_GE(count(held, "!7V0", h), 1u);
    EXPECT_GE(count(held, "!0D", h), 1u);
    EXPECT_EQ(count(held, "!0G", h), 0u);
    EXPECT_EQ(held.port.unit().queueLength(), 0u);
}

// The link lost while held: the unit stays held (nothing runs without G); plugged in again, the
// job waits for the operator, never starting by itself; resumed, it ends exactly.
TEST(LeadInHold, ALinkLostWhileHeldNeverStartsTheChainByItself)
{
    HeldJob held(spindleJob(), true);
    std::array<std::int64_t, 4> at{};
    ASSERT_TRUE(untilHeld(held, at));
    held.runner.unplug("converter unplugged");
    EXPECT_EQ(held.core.state().mode, driver::MachineMode::LinkLost);
    held.runner.runFor(3.0);
    EXPECT_EQ(held.port.unit().position(), at);
    const std::size_t back = held.wire.size();
    held.runner.open();
    ASSERT_TRUE(held.runner.runUntil(
        [&] { return held.core.state().mode == driver::MachineMode::Paused; }, 120));
    held.runner.runFor(3.0);
    EXPECT_EQ(held.port.unit().position(), at);
    EXPECT_EQ(count(held, "!0G", back), 0u);
    bool resumed = false;
    ASSERT_TRUE(held.runner.runUntil(
        [&] { return resumed || (resumed = !held.core.resume(held.runner.now()).has_value()); },
        60));
    ASSERT_TRUE(held.runner.runUntil([&] { return !held.finished.empty(); }, 600));
    EXPECT_TRUE(held.finished.back());
    EXPECT_EQ(held.port.unit().position(), held.plan.program.commands.back().endSteps);
}

namespace {

// Runs the job until the unit is held at a chain's start, pauses it there (stopping the spindle
// or not), resumes a second later and runs it to its end: it ends at its planned counters
// without a brake violation on the unit.
void pauseAndResumeWhileHeld(HeldJob &held, bool stopSpindle)
{
    ASSERT_TRUE(held.connectAndRun());
    ASSERT_TRUE(held.runner.runUntil(
        [&] { return held.core.jobReport().leadInHolds > 0 && held.core.state().inta; }, 600));
    ASSERT_FALSE(held.core.pause(held.runner.now(), stopSpindle));
    ASSERT_TRUE(held.runner.runUntil(
        [&] { return held.core.state().mode == driver::MachineMode::Paused; }, 30));
    held.runner.runFor(1.0);
    ASSERT_FALSE(held.core.resume(held.runner.now()));
    ASSERT_TRUE(held.runner.runUntil([&] { return !held.finished.empty(); }, 600));
    EXPECT_TRUE(held.finished.front());
    EXPECT_EQ(held.port.unit().position(), held.plan.program.commands.back().endSteps);
    EXPECT_EQ(held.port.unit().stats().motion.brakeViolations, 0);
}

} // namespace

// Paused and resumed while held, before the lead-in is queued: the resume's G must not start the
// chain with only its first vectors queued (the wire then cannot feed it, as without the hold);
// the job queues the lead-in first and its own G starts the chain (after SR4 and SR5).
TEST(LeadInHold, ResumeWhileHeldStillQueuesTheLeadInFirst)
{
    HeldJob held(drawJob(235, 300), true);
    ASSERT_NO_FATAL_FAILURE(pauseAndResumeWhileHeld(held, false));
    const std::size_t h = held.find("!0H");
    // One G after the hold, the lead-in's own: after the causes were read, with the lead-in
    // queued in full packets.
    const std::size_t g = held.find("!0G", h);
    ASSERT_LT(g, held.wire.size());
    EXPECT_EQ(count(held, "!0G", h), 1u);
    EXPECT_EQ(held.wire[g - 2], "!0SR4");
    EXPECT_EQ(held.wire[g - 1], "!0SR5");
    EXPECT_GT(count(held, "!0C", h) - count(held, "!0C", g), 100u);
}

namespace {

// Seed 235 with the spindle started first and its M5 kept: the held chain begins with the M5,
// then a two-step vector at V25 (where the plain seed has V37), an A and a V, then 156-step
// vectors that take 10 ms each, about what a lone C takes on the 19 200 Bd line. The lead-in's
// byte count let the unit go with only the slow vector queued; the job's packets, cut to half of
// what the unit held, shrank to single commands and the unit ran dry at speed.
RandomJob spindleOffJob()
{
    RandomJob j = drawJob(235, 300);
    j.program = "M3 S12000\n" + j.program;
    return j;
}

} // namespace

TEST(LeadInHold, TheHoldLastsUntilTheJobsOwnPacketsKeepTheChainFed)
{
    HeldJob held(spindleOffJob(), true);
    ASSERT_TRUE(held.connectAndRun());
    ASSERT_TRUE(held.runner.runUntil([&] { return !held.finished.empty(); }, 600));
    EXPECT_TRUE(held.finished.front());
    EXPECT_EQ(held.port.unit().position(), held.plan.program.commands.back().endSteps);
    EXPECT_EQ(held.port.unit().stats().motion.brakeViolations, 0);
    const std::size_t h = held.find("!0H");
    const std::size_t g = held.find("!0G", h);
    ASSERT_LT(g, held.wire.size());
    EXPECT_GT(count(held, "!0C", h) - count(held, "!0C", g), 100u);
}

// The same job paused and resumed while held: 4 brake violations when the resume's G started
// the chain.
TEST(LeadInHold, ThePausedAndResumedHoldKeepsTheChainFed)
{
    HeldJob held(spindleOffJob(), true);
    ASSERT_NO_FATAL_FAILURE(pauseAndResumeWhileHeld(held, true));
}
