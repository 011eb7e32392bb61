// The unit halted where it would run dry in the middle of a chain (driver/link/leadinhold.h,
// JobPace::dryAhead), read on the wire and on the emulated unit: property seed 132 (GVE64,
// 19 200 Bd) with one chosen packet line damaged on an otherwise clean link (heldjob.h,
// PacketDamage): the unit accepts the packet's lines before it, starts on those, and the next
// packets, cut to half of what it holds, shrink until it runs dry. Without the halt it runs dry at
// a speed its last vector cannot brake from (a brake violation on the unit); each test runs the
// same job without the hold too and sees that. Until issue 12's eleventh session these cases took
// their damage from the random byte errors of seeds 90, 14 and 132 (1 in 1 000): every byte the
// driver sent differently (a poll, a wait) moved where the damage fell, and the cases stopped
// showing the halt.

#include "heldjob.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cstddef>
#include <string>

using namespace frezka;
using namespace frezka::machine::test;

namespace {

void haltsBeforeRunningDryAtSpeed(unsigned seed, PacketDamage damage)
{
    HeldJob held(drawJob(seed, 300), true, false, damage);
    ASSERT_TRUE(held.connectAndRun(true));
    ASSERT_TRUE(held.runner.runUntil([&] { return !held.finished.empty(); }, 3000));
    EXPECT_TRUE(held.finished.front());
    EXPECT_EQ(held.damagedLines, 1);
    EXPECT_EQ(held.port.wireStats().corrupted, 0); // no other damage on the link
    const emulator::Unit &unit = held.port.unit();
    EXPECT_EQ(unit.stats().motion.brakeViolations, 0);
    EXPECT_EQ(unit.position(), held.plan.program.commands.back().endSteps); // every vector once
    EXPECT_GE(held.core.jobReport().dryHolds, 1);
    // On the wire: an H sent while the unit still held vectors of the chain (a chain's start
    // is held with its queue empty), then (the lead-in hold from where it stood) the interrupt
    // causes read and G, and between the two only the chain's own commands.
    int halted = 0;
    for (std::size_t h = held.find("!0H"); h < held.wire.size(); h = held.find("!0H", h + 1)) {
        if (held.queuedAt[h] == 0)
            continue; // a chain's start, held with nothing queued
        ++halted;
        const std::size_t g = held.find("!0G", h);
        ASSERT_LT(g, held.wire.size());
        const bool gve84 = held.job.config.unit.variant == protocol::Variant::Gve84;
        EXPECT_EQ(held.wire[g - 1], gve84 ? "!0SR4" : "!0SR5")
            << "before the G: " << held.wire[g - 2] << " " << held.wire[g - 1];
        for (std::size_t i = h + 1; i < g; ++i)
            EXPECT_FALSE(held.wire[i].starts_with("!0L") || held.wire[i].starts_with("!0H"))
                << held.wire[i] << ": between the H and its G only the chain's own commands";
    }
    EXPECT_GE(halted, 1);

    // The same job and damage without the hold: the unit runs dry at speed.
    HeldJob free(drawJob(seed, 300), false, false, damage);
    ASSERT_TRUE(free.connectAndRun(true));
    ASSERT_TRUE(free.runner.runUntil([&] { return !free.finished.empty(); }, 3000));
    EXPECT_EQ(free.damagedLines, 1);
    EXPECT_EQ(free.core.jobReport().dryHolds, 0);
    EXPECT_GT(free.port.unit().stats().motion.brakeViolations, 0);
}

} // namespace

// The 6th and the 14th packet of the job, each damaged at its 18th line: the unit starts on the
// 17 lines it took and holds little while the rest comes in shrinking packets.
TEST(DryHold, Seed132SixthPacketDamagedAfter17LinesEndsInAHaltOnTheRamp)
{
    haltsBeforeRunningDryAtSpeed(132, {6, 18});
}

TEST(DryHold, Seed132FourteenthPacketDamagedAfter17LinesEndsInAHaltOnTheRamp)
{
    haltsBeforeRunningDryAtSpeed(132, {14, 18});
}
