// The soft-limit policy (machine/softlimits.h): limits off and the homing speed before homing,
// refused steps and clipped continuous jogs after it, moves back toward the range allowed.
#include "machine/softlimits.h"

#include <gtest/gtest.h>

#include <cmath>

namespace frezka::machine {
namespace {

MachineConfig gve64()
{
    return defaultMachineConfig(protocol::Variant::Gve64); // X 0..400, 200 steps/mm
}

TEST(SoftLimits, BeforeHomingNoLimitsAndTheHomingSpeed)
{
    const MachineConfig c = gve64();
    const JogMove m = jogStep(c, 0, 0, -5, 3000, false);
    EXPECT_EQ(m.verdict, JogVerdict::Move);
    EXPECT_EQ(m.deltaSteps, -1000);
    EXPECT_FALSE(m.limitsOn);
    EXPECT_DOUBLE_EQ(m.speedMmPerMin, c.axes[0].homing.towardMmPerS * 60);
    const JogMove run = jogContinuous(c, 0, 0, -1, 3000, false);
    EXPECT_EQ(run.verdict, JogVerdict::Move);
    EXPECT_EQ(run.deltaSteps, -std::llround(c.axes[0].homing.travelMm * 200));
    EXPECT_FALSE(run.clipped);
}

TEST(SoftLimits, AfterHomingStepsBeyondAreRefusedAndContinuousClipped)
{
    const MachineConfig c = gve64();
    EXPECT_EQ(jogStep(c, 0, 2000, -15, 3000, true).verdict, JogVerdict::BeyondLimit);
    EXPECT_DOUBLE_EQ(jogStep(c, 0, 2000, -15, 3000, true).targetMm, -5);
    EXPECT_EQ(jogStep(c, 0, 2000, -10, 3000, true).deltaSteps, -2000);
    const JogMove run = jogContinuous(c, 0, 2000, -1, 9000, true);
    EXPECT_EQ(run.verdict, JogVerdict::Move);
    EXPECT_EQ(run.deltaSteps, -2000);
    EXPECT_TRUE(run.clipped);
    EXPECT_DOUBLE_EQ(run.speedMmPerMin, c.axes[0].maxSpeedMmPerMin);
    EXPECT_EQ(jogContinuous(c, 0, 0, -1, 3000, true).verdict, JogVerdict::AtLimit);
    EXPECT_EQ(jogStep(c, 0, 0, 0.001, 3000, true).verdict, JogVerdict::NoMove);
}

TEST(SoftLimits, OutsideTheLimitsOnlyBackTowardThem)
{
    const MachineConfig c = gve64();
    EXPECT_EQ(jogStep(c, 0, -2000, 5, 3000, true).verdict, JogVerdict::Move);
    EXPECT_EQ(jogStep(c, 0, -2000, -1, 3000, true).verdict, JogVerdict::BeyondLimit);
    EXPECT_EQ(jogStep(c, 0, -2000, 500, 3000, true).verdict, JogVerdict::BeyondLimit);
    EXPECT_TRUE(withinSoftLimits(c.axes[0], 400));
    EXPECT_FALSE(withinSoftLimits(c.axes[0], 400.001));
}

} // namespace
} // namespace frezka::machine
