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

// A long vector that cruises and then brakes to B for the C queued behind it (planner fuzz,
// seed 9: 5348 steps). Wherever the clock stands and however the caller chops time (exactly to
// each event, 1 ns past it, or in arbitrary slices), it arrives at B: no brake violation, and
// no excess at all beyond rounding.
TEST(Rounding, CruiseToBrakeOfALongVectorArrivesAtItsExitSpeed)
{
    std::mt19937 rng(9);
    std::uniform_real_distribution<double> unit01(0, 1);
    for (int trial = 0; trial < 300; ++trial) {
        const int chopping = trial % 3; // 0: to each event, 1: 1 ns past it, 2: random slices
        const double start = trial < 150 ? 1000 * unit01(rng) : 3e5 * unit01(rng);
        const int accel = 5 + static_cast<int>(995 * unit01(rng));           // A, thousands
        const int speed = 2000 + static_cast<int>(46000 * unit01(rng));      // V, pulses/s
        const int brake = 10 + static_cast<int>((speed - 10) * unit01(rng)); // B
        // Long enough for the last vector to brake from V to a stop: only rounding can fail.
        const double brakeSteps = double(speed) * speed / (2000.0 * accel);
        const int length =
            static_cast<int>(brakeSteps) + 3000 + static_cast<int>(200000 * unit01(rng));
        const int side = static_cast<int>(length * unit01(rng));
        UnitOptions o = optionsFor(Variant::Gve64);
        o.trace = true;
        Unit u(o);
        u.advance(start);
        const std::string setup =
            "!0A" + std::to_string(accel) + "\r!0V" + std::to_string(speed) + "\r!0B" +
            std::to_string(brake) + "\r!0C" + std::to_string(length) + "," + std::to_string(side) +
            ",0\r!0C5348,17,0\r!0C" + std::to_string(length) + ",-" + std::to_string(side) + ",3\r";
        ASSERT_EQ(ask(u, "!0Y-\r" + setup), "0,Y-\r0\r0\r0\r0\r0\r0\r");
        for (int i = 0; i < 100000 && u.nextEventIn() < kNever; ++i) {
            const double next = u.nextEventIn();
            if (chopping == 0)
                u.advance(next);
            else if (chopping == 1)
                u.advance(next + 1e-9);
            else
                u.advance(unit01(rng) < 0.5 ? next : next * unit01(rng)); // partial steps
        }
        const MotionStats m = u.stats().motion;
        ASSERT_EQ(m.vectorsExecuted, 3) << "trial " << trial;
        EXPECT_EQ(m.brakeViolations, 0)
            << "trial " << trial << " A" << accel << " V" << speed << " B" << brake << " C"
            << length << "," << side << " from " << start << ": " << m.worstBrakeExcessPulsesPerS;
        // The speed at each vertex, from the trace: B up to rounding (1e-6 pulses/s here).
        int vertices = 0;
        for (const TracePoint &t : u.trace()) {
            if (t.position[0] != length && t.position[0] != length + 5348)
                continue;
            ++vertices;
            EXPECT_LE(t.pathSpeedPulsesPerS, brake + 1e-6) << "trial " << trial;
        }
        EXPECT_GE(vertices, 2) << "trial " << trial;
        const auto pos = u.position();
        EXPECT_EQ(pos[0], 2 * length + 5348) << "trial " << trial;
        EXPECT_EQ(pos[1], 17) << "trial " << trial;
    }
}
