// Floating-point rounding must never change what the unit does: advancing the clock by exactly
// nextEventIn() takes that event, and the switch from cruising to braking of a long vector
// arrives at its exit speed, not a hair above it.

#include "emulator_test_util.h"

#include <gtest/gtest.h>

#include <cmath>
#include <random>

using namespace frezka::emulator;
using namespace frezka::emulator::test;

namespace {

// Runs the clock event by event with advance(nextEventIn()), as a planner or a benchmark does,
// and counts the calls that did not take their event. Every motion event (pause end, segment
// end, vector end) adds a trace point, so a call that adds none stopped short.
int missedEvents(Unit &unit)
{
    int missed = 0;
    for (int i = 0; i < 100000 && unit.nextEventIn() < kNever; ++i) {
        const std::size_t before = unit.trace().size();
        unit.advance(unit.nextEventIn());
        missed += unit.trace().size() > before ? 0 : 1;
    }
    return missed;
}

} // namespace

TEST(Rounding, AdvancingByNextEventInAlwaysTakesTheEvent)
{
    // Late on the clock (hours of a long job) one ulp of `now` is about 2e-12 s, and
    // (now + dt) - now is dt rounded to it: half of the events would fall short.
    for (double start : {0.0, 0.7, 12345.678, 86400.0 * 3 + 0.1}) {
        UnitOptions o = optionsFor(Variant::Gve84);
        o.trace = true;
        Unit unit(o);
        unit.advance(start);
        ASSERT_EQ(ask(unit, "!0A37\r!0V23456\r!0B3173\r!0T3\r"), "0\r0\r0\r0\r");
        std::mt19937 rng(7);
        std::uniform_int_distribution<int> len(1, 20000);
        std::string batch;
        for (int i = 0; i < 60; ++i)
            batch += "!0C" + std::to_string(len(rng)) + "," + std::to_string(len(rng) / 3) + ",0\r";
        std::string accepted;
        for (int i = 0; i < 60; ++i)
            accepted += "0\r";
        ASSERT_EQ(ask(unit, batch), accepted);
        EXPECT_EQ(missedEvents(unit), 0) << "clock started at " << start;
        EXPECT_EQ(unit.stats().motion.vectorsExecuted, 60);
        EXPECT_EQ(unit.stats().motion.brakeViolations, 0) << "clock started at " << start;
    }
}
