// The trapezoid model of docs/gve-protocol.md §4.2 and the speed commands of §4 / §4.1.

#include "emulator_test_util.h"

#include "driver/emulator/wire.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace frezka::emulator;
using namespace frezka::emulator::test;

namespace {

// A unit with round numbers: A = 10 000 pulses/s^2, V = 10 000 pulses/s, T = 1 ms.
Unit fastUnit(Variant v = Variant::Gve64, bool trace = false)
{
    UnitOptions o = optionsFor(v);
    o.trace = trace;
    Unit unit(o);
    if (unit.variantInfo().hasMpg)
        ask(unit, "!0Y-\r");
    EXPECT_EQ(ask(unit, "!0A10\r!0V10000\r!0T1\r"), "0\r0\r0\r");
    return unit;
}

double peak(const Unit &unit, int axis = 0)
{
    return unit.stats().motion.peakAxisSpeedPulsesPerS[axis];
}

// Path speed recorded when the X counter first reached `x`.
double speedAtX(const Unit &unit, std::int64_t x)
{
    for (const TracePoint &p : unit.trace()) {
        if (p.position[0] == x)
            return p.pathSpeedPulsesPerS;
    }
    return -1;
}

} // namespace

TEST(Motion, TrapezoidTimesAndPositions)
{
    Unit unit = fastUnit();
    // 30 000 steps: 1 s up to 10 000 (5 000 steps), 2 s cruise, 1 s down.
    ASSERT_EQ(ask(unit, "!0L30000,-15000,0\r"), "0\r");
    unit.advance(1.0);
    EXPECT_EQ(unit.position()[0], 5000);
    EXPECT_EQ(unit.position()[1], -2500);
    EXPECT_NEAR(unit.pathSpeed(), 10000, 1e-6);
    EXPECT_TRUE(unit.isMoving());
    EXPECT_EQ(ask(unit, "!0P\r"), "0,5000,-2500\r");
    EXPECT_EQ(ask(unit, "!0SR6\r"), "0,40\r"); // RUN
    unit.advance(2.0);
    EXPECT_EQ(unit.position()[0], 25000);
    runUntilIdle(unit);
    EXPECT_NEAR(unit.now(), 4.0, 1e-9);
    EXPECT_EQ(ask(unit, "!0P\r"), "0,30000,-15000\r");
    EXPECT_EQ(unit.stats().motion.vectorsExecuted, 1);
    EXPECT_NEAR(peak(unit, 1), 5000, 1e-6);
    EXPECT_NEAR(unit.stats().motion.movingTimeS, 4.0, 1e-9);
}

TEST(Motion, TriangleWhenTooShortToCruise)
{
    Unit unit = fastUnit();
    ask(unit, "!0L2500,0,0\r"); // peak sqrt(A * 2500) = 5000 pulses/s, 0.5 s each way
    runUntilIdle(unit);
    EXPECT_NEAR(unit.now(), 1.0, 1e-9);
    EXPECT_NEAR(peak(unit), 5000, 1e-6);
}

TEST(Motion, ContinuousVectorsPassAtBrakeSpeed)
{
    Unit unit = fastUnit(Variant::Gve64, true);
    ask(unit, "!0B2000\r");
    for (int i = 0; i < 4; ++i)
        ASSERT_EQ(ask(unit, "!0C20000,0,0\r"), "0\r");
    runUntilIdle(unit);
    EXPECT_NEAR(speedAtX(unit, 20000), 2000, 1e-6);
    EXPECT_NEAR(speedAtX(unit, 40000), 2000, 1e-6);
    EXPECT_NEAR(speedAtX(unit, 60000), 2000, 1e-6);
    EXPECT_NEAR(speedAtX(unit, 80000), 0, 1e-6);
    // 2.82 s for each end vector, 2.64 s for each middle one (ramps 0.8 s / 1 s, cruise rest).
    EXPECT_NEAR(unit.now(), 2 * 2.82 + 2 * 2.64, 1e-9);
    const MotionStats s = unit.stats().motion;
    EXPECT_EQ(s.vectorsExecuted, 4);
    EXPECT_EQ(s.brakeViolations, 0);
    EXPECT_EQ(s.starvationStops, 0);
}

TEST(Motion, BrakeViolationWhenAVectorIsTooShortToBrake)
{
    Unit unit = fastUnit();
    ask(unit, "!0B10000\r");
    ask(unit, "!0C10000,0,0\r"); // leaves at 10 000 pulses/s into...
    ask(unit, "!0C100,0,0\r");   // ...100 steps that must end at 0: needs 5 000
    runUntilIdle(unit);
    const MotionStats s = unit.stats().motion;
    EXPECT_EQ(s.brakeViolations, 1);
    EXPECT_NEAR(s.worstBrakeExcessPulsesPerS, std::sqrt(1e8 - 2 * 1e4 * 100), 1e-6);
    EXPECT_EQ(unit.position()[0], 10100);
}

TEST(Motion, StarvationStops)
{
    // The next C arrives before braking must begin: no stop.
    {
        Unit unit = fastUnit();
        ask(unit, "!0B1000\r!0C5000,0,0\r");
        unit.advance(0.3);
        ask(unit, "!0C5000,0,0\r");
        runUntilIdle(unit);
        EXPECT_EQ(unit.stats().motion.starvationStops, 0);
    }
    // It arrives while the vector already brakes to zero: the unit stops, then goes on.
    {
        Unit unit = fastUnit();
        ask(unit, "!0B1000\r!0C5000,0,0\r");
        unit.advance(1.0); // braking began at 0.707 s
        ask(unit, "!0C5000,0,0\r");
        runUntilIdle(unit);
        EXPECT_EQ(unit.stats().motion.starvationStops, 1);
        EXPECT_EQ(unit.position()[0], 10000);
    }
    // It arrives after the stop.
    {
        Unit unit = fastUnit();
        ask(unit, "!0C5000,0,0\r");
        runUntilIdle(unit);
        ask(unit, "!0C5000,0,0\r");
        runUntilIdle(unit);
        EXPECT_EQ(unit.stats().motion.starvationStops, 1);
    }
    // A stand-alone L between streams ends one: a new stream is not a starvation stop.
    {
        Unit unit = fastUnit();
        ask(unit, "!0C5000,0,0\r");
        runUntilIdle(unit);
        EXPECT_EQ(ask(unit, "!0L0,0,0\r"), "0\r");
        ask(unit, "!0C5000,0,0\r");
        runUntilIdle(unit);
        EXPECT_EQ(unit.stats().motion.starvationStops, 0);
    }
}

// §4: L is accepted only when the queue is empty, so L0,0,0 polls for "all done".
TEST(Motion, LineIsRefusedWhileTheQueueRuns)
{
    Unit unit = fastUnit();
    ask(unit, "!0C10000,0,0\r");
    int refusals = 0;
    while (ask(unit, "!0L0,0,0\r") == "1\r") {
        ++refusals;
        unit.advance(0.1);
    }
    EXPECT_GE(refusals, 19); // 1 s up to 10 000 pulses/s, 1 s down: done at 2 s
    EXPECT_LE(refusals, 20);
    EXPECT_EQ(unit.position()[0], 10000);
    EXPECT_EQ(ask(unit, "!0L20000,0,0\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0L1,0,0\r"), "1\r"); // not while another L runs
    EXPECT_EQ(ask(unit, "!0C1,0,0\r"), "0\r"); // a C may queue behind it...
    runUntilIdle(unit);
    EXPECT_EQ(unit.position()[0], 30001); // ...and the L still ends at zero speed
}

TEST(Motion, ShortThresholdSelectsTheCruiseSpeed)
{
    auto run = [](const char *threshold) {
        Unit unit = fastUnit();
        ask(unit, "!0A100\r!0B3000\r");
        ask(unit, threshold);
        ask(unit, "!0L1000,0,0\r");
        runUntilIdle(unit);
        return peak(unit);
    };
    EXPECT_NEAR(run("!0$2000\r"), 3000, 1e-6);  // short: only up to B
    EXPECT_NEAR(run("!0$1000\r"), 10000, 1e-6); // long (>= $): up to V
}

TEST(Motion, PauseBetweenStandAloneMoves)
{
    Unit unit = fastUnit();
    ask(unit, "!0T20\r!0L2500,0,0\r");
    runUntilIdle(unit);
    const double firstEnd = unit.now();
    ask(unit, "!0L2500,0,0\r");
    runUntilIdle(unit);
    EXPECT_NEAR(unit.now() - firstEnd, 1.0 + 0.020, 1e-9);
    unit.advance(1.0);
    ask(unit, "!0L2500,0,0\r"); // the pause has long passed
    const double start = unit.now();
    runUntilIdle(unit);
    EXPECT_NEAR(unit.now() - start, 1.0, 1e-9);
}

TEST(Motion, VelocityCorrectionModes)
{
    Unit vn = fastUnit();
    ask(vn, "!0V1000\r!0VN\r!0L3000,4000,0\r");
    runUntilIdle(vn);
    EXPECT_NEAR(peak(vn, 1), 1000, 1e-6); // the major axis runs at V
    EXPECT_NEAR(peak(vn, 0), 750, 1e-6);
    Unit vk = fastUnit();
    ask(vk, "!0V1000\r!0VK\r!0L3000,4000,0\r");
    runUntilIdle(vk);
    EXPECT_NEAR(peak(vk, 1), 800, 1e-6); // the path (Euclidean) runs at V
    EXPECT_NEAR(peak(vk, 0), 600, 1e-6);
}

TEST(Motion, ExchangeCommandsChangeQueuedSpeeds)
{
    auto run = [](const std::string &commands, Variant v = Variant::Gve64) {
        Unit unit = fastUnit(v);
        ask(unit, "!0V1600\r!0B1600\r");
        for (int i = 0; i < 3; ++i)
            ask(unit, "!0C20000,0,0\r");
        EXPECT_EQ(ask(unit, commands).find_first_not_of("0\r"), std::string::npos) << commands;
        runUntilIdle(unit);
        return peak(unit);
    };
    EXPECT_NEAR(run("!0XU\r"), 1700, 1e-6);
    EXPECT_NEAR(run("!0XD\r!0XD\r"), 1600.0 * 15 / 16 * 15 / 16, 1e-6);
    EXPECT_NEAR(run("!0V800\r!0XA\r"), 800, 1e-6);
    EXPECT_NEAR(run("!0XM200\r"), 3200, 1e-6);
    EXPECT_NEAR(run("!0VL2500,2500,2500\r!0XM200\r"), 2500, 1e-6);
    EXPECT_NEAR(run("!0VL1000,1000,1000\r!0XM200\r"), 1600, 1e-6); // VL never cuts below V
    EXPECT_NEAR(run("!0XM50\r"), 800, 1e-6);
}

TEST(Motion, ExchangeAllAlsoSetsAccelerationOnGve64Only)
{
    auto run = [](Variant v) {
        Unit unit = fastUnit(v);
        ask(unit, "!0C20000,0,0\r");
        ask(unit, "!0A20\r!0XA\r");
        runUntilIdle(unit);
        return unit.now();
    };
    // 20 000 steps at V = 10 000: with A = 10 000: 1 + 1.5 + 1 s; with A = 20 000: 0.5 + 1.75 +
    // 0.5.
    EXPECT_NEAR(run(Variant::Gve84), 3.0, 1e-9);
    EXPECT_NEAR(run(Variant::Gve64), 2.5, 1e-9);
}

TEST(Motion, SpeedRangeFollowsTheUnitsPulseRate)
{
    UnitOptions o = optionsFor(Variant::Gve84);
    o.maxPulseRate = 15000;
    Unit unit(o);
    EXPECT_EQ(ask(unit, "!0V15000\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0V15001\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0B15001\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0XM400\r!0A1000\r!0L1000000,0,0\r"), "0\r0\r0\r");
    runUntilIdle(unit);
    EXPECT_NEAR(peak(unit), 15000, 1e-6); // XM cannot exceed the interpolator
}

// The manuals' ranges (docs/emulator.md "Parameter ranges"): A and XM have no documented bound
// (any positive 32-bit number), T is 1..24, $ reaches 2^32 - 1 only on the GVE64, V/B/VL stop
// at the unit's pulse rate.
TEST(Motion, ParameterRangesFollowTheManuals)
{
    for (Variant v : {Variant::Gve84, Variant::Gve64, Variant::Gve64Phantom, Variant::Gve114}) {
        Unit unit = readyUnit(v);
        const bool gve64 = v == Variant::Gve64 || v == Variant::Gve64Phantom;
        const bool gve84 = v == Variant::Gve84;
        const std::string rate = std::to_string(unit.variantInfo().defaultMaxPulseRate);
        EXPECT_EQ(ask(unit, "!0A1\r!0A100001\r!0A2147483647\r"), "0\r0\r0\r");
        EXPECT_EQ(ask(unit, "!0A0\r!0A2147483648\r"), "5\r5\r");
        EXPECT_EQ(ask(unit, "!0XM1\r!0XM1001\r!0XM2147483647\r"), "0\r0\r0\r");
        EXPECT_EQ(ask(unit, "!0XM0\r!0XM2147483648\r"), "5\r5\r");
        EXPECT_EQ(ask(unit, "!0T1\r!0T24\r!0T0\r!0T25\r"), "0\r0\r5\r5\r");
        EXPECT_EQ(ask(unit, "!0$1\r!0$2147483647\r!0$0\r"), "0\r0\r5\r");
        EXPECT_EQ(ask(unit, "!0$4294967295\r"), gve64 ? "0\r" : "5\r");
        EXPECT_EQ(ask(unit, "!0$4294967296\r"), "5\r");
        EXPECT_EQ(ask(unit, "!0V10\r!0B10\r!0V" + rate + "\r!0B" + rate + "\r"), "0\r0\r0\r0\r");
        EXPECT_EQ(ask(unit, "!0V9\r!0B9\r"), "5\r5\r");
        const std::string vl = gve84 ? "," : ",10,";
        EXPECT_EQ(ask(unit, "!0VL" + rate + ",10" + vl + rate + "\r"), "0\r");
        EXPECT_EQ(ask(unit, "!0VL9,10,10\r"), "5\r");
    }
}

// Counters are exact integers at every vector end: the sum of the steps sent.
TEST(Motion, ManyVectorsEndExactly)
{
    Unit unit = fastUnit(Variant::Gve114);
    ask(unit, "!0V50000\r!0A500\r!0B3000\r!0$20\r");
    SplitMix64 rng(3);
    std::array<std::int64_t, 4> sum{};
    int sent = 0;
    while (sent < 20000) {
        std::array<std::int64_t, 4> d{};
        std::string cmd = "!0C";
        for (int i = 0; i < 4; ++i) {
            d[i] = static_cast<std::int64_t>(rng.next() % 401) - 200;
            cmd += (i ? "," : "") + std::to_string(d[i]);
        }
        const std::string r = ask(unit, cmd + "\r");
        if (r == "0\r") {
            for (int i = 0; i < 4; ++i)
                sum[i] += d[i];
            ++sent;
        } else {
            ASSERT_EQ(r, "1\r");
            unit.advance(unit.nextEventIn());
        }
    }
    runUntilIdle(unit);
    EXPECT_EQ(unit.position(), sum);
    EXPECT_EQ(unit.stats().motion.vectorsExecuted, 20000);
    EXPECT_EQ(unit.stats().motion.starvationStops, 0);
}

TEST(Motion, TraceRecordsTimePositionAndSpeed)
{
    Unit unit = fastUnit(Variant::Gve64, true);
    ask(unit, "!0L30000,0,0\r");
    runUntilIdle(unit);
    const auto &trace = unit.trace();
    ASSERT_GE(trace.size(), 4u);
    for (std::size_t i = 1; i < trace.size(); ++i) {
        EXPECT_GE(trace[i].timeS, trace[i - 1].timeS);
        EXPECT_GE(trace[i].position[0], trace[i - 1].position[0]);
    }
    EXPECT_EQ(trace.back().position[0], 30000);
    EXPECT_NEAR(trace.back().timeS, 4.0, 1e-9);
    EXPECT_EQ(trace.back().pathSpeedPulsesPerS, 0);
    unit.clearTrace();
    EXPECT_TRUE(unit.trace().empty());
}
