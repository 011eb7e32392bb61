// The time-optimal bound (docs/planner.md §7) is a lower bound of what the unit can do: no plan,
// ours included, runs faster. Two profiles from the random jobs (tests/machine/randomjob.h) where
// it was not, each cut down to the stretch that showed it.
#include "gcode/interpreter.h"
#include "machine/planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

using namespace frezka;
using namespace frezka::machine;

namespace {

PlanResult planText(const std::string &program, const MachineConfig &c)
{
    const gcode::Result parsed = gcode::interpretText(program);
    EXPECT_TRUE(parsed.errors.empty());
    PlanResult r = plan(parsed.toolpath, c);
    for (const PlanError &e : r.errors)
        ADD_FAILURE() << e.message;
    return r;
}

void setAxis(AxisConfig &a, double stepsPerMm, double speedMmPerMin, double accel, double jump)
{
    a.stepsPerMm = stepsPerMm;
    a.maxSpeedMmPerMin = speedMmPerMin;
    a.accelMmPerS2 = accel;
    a.maxJumpMmPerS = jump;
    a.softMinMm = -200;
    a.softMaxMm = 400;
}

} // namespace

// VK with X at 752 steps/mm and Z at 59.6: a gentle slope in 14-step X vectors whose Z moves a
// step or none. The unit carries one speed scalar (VK: step length per second) across each
// vertex, so X's speed hardly changes there, though the vectors' directions in mm differ by 16°.
// A bound with one continuous speed in mm capped X's jump of 0.06 mm/s at every such vertex and
// lay 25 % above the plan the unit runs (property seed 127: 48.8 s against 37.3 s, the job 39.8 s).
TEST(Bound, IsTheUnitsOwnSpeedScalarWhateverTheAxisScales)
{
    MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    c.unit.maxPulseRate = 200000;
    c.motion.speedMode = SpeedModeChoice::Vk;
    setAxis(c.axes[0], 752.429, 7462, 61.17, 0.0587);
    setAxis(c.axes[1], 41.141, 20000, 111.5, 0.0543);
    setAxis(c.axes[2], 59.58, 20000, 1647.8, 2.4936);
    std::string program = "G21 G90 G17 G94 G64\nG0 X40 Y30 Z-15\nF8000\n";
    for (int k = 1; k <= 60; ++k) // Z rises 0.0154 mm (0.9 steps) per 0.0186 mm of X
        program += "G1 X" + std::to_string(40 + 0.0186 * k) + " Z" +
                   std::to_string(-15 + 0.0154 * k) + "\n";
    program += "M2\n";
    const PlanResult r = planText(program, c);
    ASSERT_TRUE(r.stats.speedModeVk);
    EXPECT_GE(r.stats.estimatedS, r.stats.boundS);
    EXPECT_LE(r.stats.estimatedS, 1.02 * r.stats.boundS);
}

// VN, vectors of four or five steps along X with a Z step now and then (property seed 72): the
// corners' geometric caps (here a junction deviation of 0) lie below the unit's smallest speed of
// 10 pulses/s while the jump limits allow passing at it, so every plan passes them at 10 pulses/s.
// A bound that crawled below that was no plan this unit can run, and lay above the estimate.
TEST(Bound, CornersBelowTheSmallestSpeedArePassedAtIt)
{
    MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    c.unit.maxPulseRate = 125000;
    c.motion.speedMode = SpeedModeChoice::Vn;
    setAxis(c.axes[0], 29.5, 20000, 42.1, 2.08);
    setAxis(c.axes[1], 49.6, 20000, 269, 8.46);
    setAxis(c.axes[2], 40.5, 20000, 24.7, 0.146);
    c.motion.junctionDeviationMm = 0; // every corner's geometric cap is 0
    std::string program = "G20 G90 G17 G94 G64\nG0 X2.1448 Y1.1881 Z-0.4795\nF1713\n";
    const double z[] = {-0.4798, -0.4802, -0.4805, -0.4808, -0.4810, -0.4811,
                        -0.4811, -0.4810, -0.4808, -0.4805, -0.4802};
    for (int k = 0; k < 11; ++k) // 0.0061 in (4-5 steps) of X, Z on a shallow wave
        program +=
            "G1 X" + std::to_string(2.1509 + 0.00614 * k) + " Z" + std::to_string(z[k]) + "\n";
    program += "M2\n";
    const PlanResult r = planText(program, c);
    ASSERT_FALSE(r.stats.speedModeVk);
    EXPECT_GE(r.stats.estimatedS, r.stats.boundS);
}
