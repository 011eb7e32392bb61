#include "machine/unitmodel.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace frezka::machine;

TEST(UnitModel, TriangleFromRestToRest)
{
    const VectorRun r = runVector(0, 1e9, 0, 1000, 100);
    EXPECT_NEAR(r.timeS, 2 * std::sqrt(100.0 / 1000), 1e-12);
    EXPECT_NEAR(r.peak, std::sqrt(100.0 * 1000), 1e-9);
    EXPECT_FALSE(r.violation);
    EXPECT_DOUBLE_EQ(r.exit, 0);
}

TEST(UnitModel, TrapezoidWithCruise)
{
    // 0 -> 100 in 0.1 s over 5 units, cruise 90 units at 100, brake to 50 over 3.75 units.
    const VectorRun r = runVector(0, 100, 50, 1000, 98.75);
    EXPECT_NEAR(r.timeS, 0.1 + 0.9 + 0.05, 1e-12);
    EXPECT_DOUBLE_EQ(r.exit, 50);
}

TEST(UnitModel, TooShortToBrakeIsAViolation)
{
    const VectorRun r = runVector(100, 100, 0, 1000, 4);
    EXPECT_TRUE(r.violation);
    EXPECT_NEAR(r.exit, std::sqrt(100.0 * 100 - 8000), 1e-9);
}

TEST(UnitModel, UnreachableExitArrivesSlower)
{
    const VectorRun r = runVector(0, 1000, 500, 1000, 2);
    EXPECT_FALSE(r.violation);
    EXPECT_NEAR(r.exit, std::sqrt(4000.0), 1e-9);
}

TEST(UnitModel, EnteringAboveCruiseSlowsDown)
{
    const VectorRun r = runVector(200, 100, 100, 1000, 100);
    // 200 -> 100 over 15 units in 0.1 s, then 85 units at 100.
    EXPECT_NEAR(r.timeS, 0.1 + 0.85, 1e-12);
    EXPECT_FALSE(r.violation);
}

TEST(UnitModel, ProgramChainsShortVectorsAndPauses)
{
    UnitProgram p;
    auto add = [&](UnitOp op, std::int64_t v, std::array<std::int32_t, 4> d = {}) {
        UnitCommand c;
        c.op = op;
        c.value = v;
        c.d = d;
        p.commands.push_back(c);
    };
    add(UnitOp::SpeedModeVn, 0);
    add(UnitOp::ShortThreshold, 50);
    add(UnitOp::Pause, 10);
    add(UnitOp::Accel, 1);
    add(UnitOp::Speed, 1000);
    add(UnitOp::Brake, 100);
    add(UnitOp::Vector, 0, {20, 5, 0, 0});  // short: cruises toward B = 100
    add(UnitOp::Vector, 0, {-10, 0, 0, 0}); // short, last: toward 100, brakes to 0
    add(UnitOp::WaitIdle, 0);
    add(UnitOp::Line, 0, {0, 200, 0, 0});
    const ModelResult m = runUnitModel(p);
    EXPECT_EQ(m.vectors, 3u);
    EXPECT_EQ(m.chains, 2u);
    EXPECT_EQ(m.brakeViolations, 0u);
    EXPECT_NEAR(m.waitS, 0.010, 1e-12); // T before the L, after the rest
    EXPECT_NEAR(m.vertexSpeeds[0], 100, 1e-9);
    EXPECT_LE(m.peakSpeed, 1000);
}
