#include "machine/planner.h"

#include "machine/steps.h"
#include "plancheck.h"

#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

using namespace frezka;
using namespace frezka::machine;
using namespace frezka::machine::test;
using gcode::Point4;

namespace {

MachineConfig gve64()
{
    return defaultMachineConfig(protocol::Variant::Gve64);
}

// Limits that let one cap act alone: huge jumps, deviation and accelerations.
MachineConfig looseConfig()
{
    MachineConfig c = gve64();
    for (AxisConfig &a : c.axes) {
        a.maxJumpMmPerS = 1000;
        a.accelMmPerS2 = 100000;
        a.softMinMm = -1000;
        a.softMaxMm = 1000;
    }
    c.motion.junctionDeviationMm = 10;
    return c;
}

PlanResult planOk(const gcode::Toolpath &tp, const MachineConfig &c, PlanOptions o = {})
{
    PlanResult r = plan(tp, c, o);
    for (const PlanError &e : r.errors)
        ADD_FAILURE() << e.message;
    return r;
}

std::vector<UnitCommand> ops(const PlanResult &r, UnitOp op)
{
    std::vector<UnitCommand> out;
    for (const UnitCommand &c : r.program.commands) {
        if (c.op == op)
            out.push_back(c);
    }
    return out;
}

Steps4 finalSteps(const PlanResult &r)
{
    Steps4 pos = r.program.startSteps;
    for (const UnitCommand &c : r.program.commands) {
        if (c.op == UnitOp::Vector || c.op == UnitOp::Line) {
            for (int i = 0; i < 4; ++i)
                pos[i] += c.d[i];
        }
    }
    return pos;
}

void expectValid(const PlanResult &r)
{
    bool vk = r.stats.speedModeVk;
    const auto vs = replay(r.program, &vk);
    expectFeasible(vs, vk);
    EXPECT_EQ(r.stats.brakeViolations, 0u);
    EXPECT_EQ(r.stats.jumpOverLimit, 0u);
    EXPECT_EQ(r.stats.curveAccelOverLimit, 0u);
}

} // namespace

TEST(Steps, OneRoundingRuleHalvesAwayFromZero)
{
    EXPECT_EQ(stepsOf(0.0025, 200), 1);
    EXPECT_EQ(stepsOf(-0.0025, 200), -1);
    EXPECT_EQ(stepsOf(0.0024, 200), 0);
    EXPECT_EQ(stepsOf(123.456, 200), 24691);
}

TEST(Steps, NoDriftAfterManyMoves)
{
    gcode::Toolpath tp;
    tp.setOrigin({1, 1, -1, 0});
    Point4 p{1, 1, -1, 0};
    for (int i = 0; i < 5000; ++i) {
        p.x += 0.0137;
        p.y += (i % 7 == 0) ? -0.0031 : 0.0013;
        tp.appendFeed(p, 1200, static_cast<std::uint32_t>(i + 1));
    }
    const PlanResult r = planOk(tp, gve64());
    EXPECT_EQ(finalSteps(r), stepsOf(p, gve64()));
    replay(r.program); // endSteps of every command follow the vectors; no zero vectors
    expectValid(r);
}

TEST(Steps, SubStepSegmentsSendOnlyWholeSteps)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    for (int i = 1; i <= 100; ++i) // 0.001 mm = 0.2 steps each
        tp.appendFeed({10 + 0.001 * i, 10, -1, 0}, 600, static_cast<std::uint32_t>(i));
    const PlanResult r = planOk(tp, gve64());
    const auto vectors = ops(r, UnitOp::Vector);
    EXPECT_EQ(vectors.size(), 20u);
    for (const UnitCommand &c : vectors)
        EXPECT_EQ(c.d, (std::array<std::int32_t, 4>{1, 0, 0, 0}));
    EXPECT_EQ(finalSteps(r)[0], stepsOf(10.1, 200));
    EXPECT_EQ(r.stats.chains, 1u);
    expectValid(r);
}

TEST(Steps, ZeroLengthSegmentsSendNothingAndKeepTheChain)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendFeed({20, 10, -1, 0}, 1200, 1);
    tp.appendFeed({20, 10, -1, 0}, 1200, 2);      // zero length
    tp.appendFeed({20.0001, 10, -1, 0}, 1200, 3); // sub-step: rounds to the same step
    tp.appendFeed({30, 10, -1, 0}, 1200, 4);
    const PlanResult r = planOk(tp, gve64());
    const auto vectors = ops(r, UnitOp::Vector);
    ASSERT_EQ(vectors.size(), 2u);
    EXPECT_EQ(vectors[1].sourceLine, 4u);
    EXPECT_EQ(r.stats.chains, 1u);
    EXPECT_EQ(ops(r, UnitOp::WaitIdle).size(), 1u);
    const auto vs = replay(r.program);
    EXPECT_EQ(vs[0].b, vs[0].v); // straight on at full speed
    expectValid(r);
}

TEST(Corners, VelocityJumpLimitsASquareCorner)
{
    MachineConfig c = looseConfig();
    c.axes[0].maxJumpMmPerS = 2;
    c.axes[1].maxJumpMmPerS = 3;
    gcode::Toolpath tp;
    tp.setOrigin({0, 0, 0, 0});
    tp.appendFeed({50, 0, 0, 0}, 3000, 1);
    tp.appendFeed({50, 50, 0, 0}, 3000, 2);
    const PlanResult r = planOk(tp, c);
    const auto vs = replay(r.program);
    ASSERT_EQ(vs.size(), 2u);
    // X stops from B/200 mm/s to 0, Y starts from 0 to B/200: X's 2 mm/s limit decides.
    EXPECT_EQ(vs[0].b, 400);
    EXPECT_DOUBLE_EQ(r.stats.maxVertexJumpMmPerS, 2.0);
    EXPECT_DOUBLE_EQ(r.stats.maxJumpRatio, 1.0);
    expectValid(r);
}

TEST(Corners, JunctionDeviationLimitsACorner)
{
    MachineConfig c = looseConfig();
    c.motion.junctionDeviationMm = 0.01;
    c.axes[0].accelMmPerS2 = 400;
    c.axes[1].accelMmPerS2 = 400;
    gcode::Toolpath tp;
    tp.setOrigin({0, 0, 0, 0});
    tp.appendFeed({50, 0, 0, 0}, 3000, 1);
    tp.appendFeed({50, 50, 0, 0}, 3000, 2);
    const PlanResult r = planOk(tp, c);
    const auto vs = replay(r.program);
    // grbl's formula: the junction direction (-1, 1)/sqrt2 allows 400 * sqrt2 mm/s².
    const double aj = 400 * std::sqrt(2.0);
    const double s = std::sqrt(0.5);
    const double v = std::sqrt(aj * 0.01 * s / (1 - s));
    EXPECT_EQ(vs[0].b, static_cast<std::int64_t>(std::floor(v * 200)));
    expectValid(r);
}

TEST(Corners, ReversalStopsAtTheUnitsSmallestSpeed)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendFeed({30, 10, -1, 0}, 3000, 1);
    tp.appendFeed({10, 10, -1, 0}, 3000, 2);
    const PlanResult r = planOk(tp, gve64());
    const auto vs = replay(r.program);
    ASSERT_EQ(vs.size(), 2u);
    EXPECT_EQ(vs[0].b, 10);
    EXPECT_FALSE(vs[0].chainEnd); // the queue keeps running through the stop
    EXPECT_EQ(r.stats.chains, 2u);
    expectValid(r);
}

TEST(Corners, ReversalDrainsTheQueueWhenEvenTheSmallestSpeedJumpsTooFar)
{
    MachineConfig c = gve64();
    c.axes[0].maxJumpMmPerS = 0.05; // 10 pulses/s each way = 0.1 mm/s step at 200 steps/mm
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendFeed({30, 10, -1, 0}, 3000, 1);
    tp.appendFeed({10, 10, -1, 0}, 3000, 2);
    const PlanResult r = planOk(tp, c);
    const auto vs = replay(r.program);
    ASSERT_EQ(vs.size(), 2u);
    EXPECT_TRUE(vs[0].chainEnd);
    EXPECT_EQ(ops(r, UnitOp::WaitIdle).size(), 2u);
    expectValid(r);
}

TEST(Corners, TenTinySegmentsMakingAUTurnKeepCentripetalAcceleration)
{
    const MachineConfig c = gve64();
    gcode::Toolpath tp;
    tp.setOrigin({10, 20, -1, 0});
    tp.appendFeed({50, 20, -1, 0}, 3000, 1);
    // 10 chords of a half circle of radius 0.2 mm (each 0.0626 mm, 18° apart).
    const double r0 = 0.2;
    for (int k = 1; k <= 10; ++k) {
        const double phi = -std::numbers::pi / 2 + std::numbers::pi * k / 10;
        tp.appendFeed({50 + r0 * std::cos(phi), 20.2 + r0 * std::sin(phi), -1, 0}, 3000,
                      static_cast<std::uint32_t>(k + 1));
    }
    tp.appendFeed({10, 20.4, -1, 0}, 3000, 12);
    const PlanResult r = planOk(tp, c);
    const auto vs = replay(r.program);
    ASSERT_EQ(vs.size(), 12u);
    EXPECT_EQ(r.stats.chains, 1u); // 18° corners: no stop
    // Centripetal acceleration v²/r within the axes' 400 mm/s² (VK: B / 200 = mm/s) at the
    // vertices inside the turn (entering and leaving it, braking over one chord is allowed).
    for (std::size_t k = 1; k + 2 < vs.size(); ++k) {
        const double v = static_cast<double>(vs[k].b) / 200.0;
        EXPECT_LE(v * v / r0, 400 * std::sqrt(2.0) * 1.0001) << "vertex " << k;
    }
    expectValid(r);
    EXPECT_LE(r.stats.estimatedS, 1.02 * r.stats.boundS);
}

TEST(Corners, DenseChordedCircleRunsSmoothly)
{
    const MachineConfig c = gve64();
    gcode::Toolpath tp;
    tp.setOrigin({25, 20, -1, 0});
    gcode::ArcInfo arc;
    arc.centre = {20, 20, -1, 0};
    arc.turns = 3; // three full circles
    tp.appendArc({25, 20, -1, 0}, arc, 3000, 1);
    const PlanResult r = planOk(tp, c);
    const auto vs = replay(r.program);
    EXPECT_GT(vs.size(), 300u);
    EXPECT_EQ(r.stats.chains, 1u);
    EXPECT_EQ(ops(r, UnitOp::Speed).size(), 1u); // one path speed all around
    // Far from the start and end the vertex speed is steady: no stop-and-go.
    std::int64_t lo = vs[vs.size() / 3].b, hi = lo;
    for (std::size_t k = vs.size() / 3; k < 2 * vs.size() / 3; ++k) {
        lo = std::min(lo, vs[k].b);
        hi = std::max(hi, vs[k].b);
    }
    EXPECT_GE(lo, hi / 2);
    EXPECT_EQ(finalSteps(r), stepsOf(Point4{25, 20, -1, 0}, c));
    expectValid(r);
    EXPECT_LE(r.stats.estimatedS, 1.02 * r.stats.boundS);
}

TEST(Speeds, AxisSpeedLimitCapsTheFeed)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendFeed({60, 60, -1, 0}, 10000, 1);  // X and Y may each do 4000 mm/min
    tp.appendFeed({60, 60, -11, 0}, 10000, 2); // Z may do 2000 mm/min
    const PlanResult r = planOk(tp, gve64());
    const auto vs = replay(r.program);
    ASSERT_EQ(vs.size(), 2u);
    // VK: V is the path step rate. Diagonal: path 4000/60 * sqrt2 mm/s.
    EXPECT_EQ(vs[0].v, static_cast<std::int64_t>(std::floor(4000 / 60.0 * std::sqrt(2.0) * 200)));
    EXPECT_EQ(vs[1].v, static_cast<std::int64_t>(std::floor(2000 / 60.0 * 200 + 1e-6)));
    expectValid(r);
}

// The unit's speed scalar carries over numerically from vector to vector, so with unequal axis
// scales the same path speed is a different V on every chord of an arc. V cannot travel in a
// packet: a V per chord would be a round trip per chord on the link. The plan shares one V over
// stretches of short chords and holds each chord below its own cap with its B speeds
// (docs/planner.md §4): whatever V says, no chord runs faster than the feed, the path runs close
// to it, and the plan sends few V commands.
TEST(Speeds, PathSpeedStaysAtTheFeedWhateverTheAxisScales)
{
    for (SpeedModeChoice mode : {SpeedModeChoice::Auto, SpeedModeChoice::Vn}) {
        MachineConfig c = gve64();
        c.axes[0].stepsPerMm = 200;
        c.axes[1].stepsPerMm = 320;
        c.axes[2].stepsPerMm = 800;
        c.motion.speedMode = mode;
        gcode::Toolpath tp;
        tp.setOrigin({10, 10, -1, 0});
        tp.appendFeed({40, 50, -1, 0}, 1200, 1); // 20 mm/s
        tp.appendFeed({40, 50, -3, 0}, 1200, 2);
        gcode::ArcInfo arc;
        arc.centre = {40, 40, -3, 0};
        tp.appendArc({40, 50, -3, 0}, arc, 1200, 3);
        const PlanResult r = planOk(tp, c);
        // Auto takes VK (A does not move); V is then the step vector's length per second.
        EXPECT_EQ(r.stats.speedModeVk, mode == SpeedModeChoice::Auto);
        bool vk = !r.stats.speedModeVk;
        const auto vs = replay(r.program, &vk);
        EXPECT_EQ(vk, r.stats.speedModeVk);
        double entry = 0;
        std::size_t speedCommands = 0;
        for (const UnitCommand &u : r.program.commands)
            speedCommands += u.op == UnitOp::Speed ? 1 : 0;
        for (const Captured &v : vs) {
            const double dx = v.d[0] / 200.0, dy = v.d[1] / 320.0, dz = v.d[2] / 800.0;
            const double length = std::sqrt(dx * dx + dy * dy + dz * dz);
            const double units = speedUnitsLength(v.d, vk);
            const double exit = v.chainEnd ? 0 : static_cast<double>(v.b);
            const VectorRun run =
                runVector(entry, static_cast<double>(v.v), exit, v.a * 1000.0, units);
            const double fastest = std::max({entry, exit, run.peak}) * length / units; // mm/s
            EXPECT_LE(fastest, 20.0 * (1 + 1e-9));
            entry = exit;
        }
        expectValid(r);
        // Measured 3.9 % (VK) and 4.7 % (VN) above the bound: what sharing V costs here.
        EXPECT_LE(r.stats.estimatedS, 1.05 * r.stats.boundS);
        EXPECT_LE(speedCommands * 8, vs.size()) << speedCommands << " V for " << vs.size();
    }
}

TEST(Passes, BackwardAndForwardFitEveryVectorInIntegers)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    std::uint32_t line = 1;
    // Short colinear hops from rest: speeds limited by accelerating and braking within them.
    for (int i = 1; i <= 40; ++i)
        tp.appendFeed({10 + 0.02 * i, 10 + 0.01 * i, -1, 0}, 6000, line++);
    tp.appendFeed({30, 20, -1, 0}, 6000, line++); // straight on
    const PlanResult r = planOk(tp, gve64());
    const auto vs = replay(r.program);
    expectValid(r);
    // The first vertex is as fast as accelerating from rest over the first vector allows.
    // Usable distance: whole speed units less the 0.25-step braking margin.
    const double usable = std::floor(speedUnitsLength(vs[0].d, true)) - 0.25;
    const auto room = static_cast<std::int64_t>(2.0 * vs[0].a * 1000 * usable);
    EXPECT_LE(vs[0].b * vs[0].b, room);
    EXPECT_GT((vs[0].b + 1) * (vs[0].b + 1), room);
}

TEST(Passes, TheLastVectorBrakesToRest)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendFeed({10.05, 10, -1, 0}, 6000, 1);
    tp.appendFeed({10.1, 10.01, -1, 0}, 6000, 2);
    tp.appendFeed({10.15, 10.03, -1, 0}, 6000, 3);
    const PlanResult r = planOk(tp, gve64());
    expectValid(r);
    const ModelResult m = runUnitModel(r.program, r.stats.speedModeVk);
    EXPECT_EQ(m.brakeViolations, 0u);
    EXPECT_DOUBLE_EQ(m.vertexSpeeds.back(), 0.0);
}

TEST(Strategies, BaselinesPlanTheSamePath)
{
    gcode::Toolpath tp;
    tp.setOrigin({25, 20, -1, 0});
    gcode::ArcInfo arc;
    arc.centre = {20, 20, -1, 0};
    tp.appendArc({25, 20, -1, 0}, arc, 3000, 1);
    const PlanResult full = planOk(tp, gve64());
    PlanOptions naive;
    naive.strategy = PlanStrategy::ExactStop;
    const PlanResult stop = planOk(tp, gve64(), naive);
    PlanOptions grbl;
    grbl.strategy = PlanStrategy::GrblJunction;
    const PlanResult g = planOk(tp, gve64(), grbl);
    EXPECT_EQ(finalSteps(stop), finalSteps(full));
    EXPECT_EQ(finalSteps(g), finalSteps(full));
    EXPECT_TRUE(ops(stop, UnitOp::Vector).empty());
    EXPECT_EQ(ops(stop, UnitOp::Line).size(), ops(full, UnitOp::Vector).size());
    EXPECT_GT(stop.stats.estimatedS, 2 * full.stats.estimatedS);
    // The same path's bound; the link's part of its rests differs with how each sends the first
    // move (an L alone, a packet of C/B that the unit runs at its *E: docs/planner.md §7).
    EXPECT_DOUBLE_EQ(stop.stats.boundS - stop.stats.linkWaitS,
                     full.stats.boundS - full.stats.linkWaitS);
    // grbl's junction deviation (0.01 mm) on a 5 mm circle chorded to 0.002 mm: faster than the
    // axes can accelerate round it, which the full plan's curvature cap prevents.
    EXPECT_GT(g.stats.curveAccelOverLimit, 0u);
    EXPECT_EQ(full.stats.curveAccelOverLimit, 0u);
    expectFeasible(replay(g.program), g.stats.speedModeVk);
    EXPECT_EQ(g.stats.brakeViolations, 0u);
}

TEST(Accel, ShortVectorsKeepALowerAButALongMoveGetsItsOwn)
{
    gcode::Toolpath tp;
    tp.setOrigin({25, 20, -1, 0});
    gcode::ArcInfo arc;
    arc.centre = {20, 20, -1, 0};
    tp.appendArc({25, 20, -1, 0}, arc, 3000, 1); // chords in every direction
    tp.appendFeed({125, 120, -1, 0}, 3000, 2);   // a long diagonal
    const PlanResult r = planOk(tp, gve64());
    const auto vs = replay(r.program);
    std::size_t changes = 0;
    for (std::size_t k = 1; k + 1 < vs.size(); ++k)
        changes += vs[k].a != vs[k - 1].a ? 1 : 0;
    EXPECT_LE(changes, 4u); // the circle's chords share one A or two
    // The diagonal may accelerate at 400 mm/s² on both axes: 400·sqrt2 mm/s² of path.
    EXPECT_EQ(vs.back().a,
              static_cast<std::int64_t>(std::floor(400 * std::sqrt(2.0) * 200 / 1000)));
    for (const Captured &v : vs) { // no vector accelerates an axis beyond its limit
        const double len = std::sqrt(double(v.d[0]) * v.d[0] + double(v.d[1]) * v.d[1]);
        for (int i = 0; i < 2; ++i)
            EXPECT_LE(v.a * 1000.0 * std::abs(v.d[i]) / len / 200.0, 400.0 * 1.000001);
    }
    expectValid(r);
}

// A vector a step or two long takes the least acceleration of its neighbours (its direction
// jitters with the rounding), but not across a rest: after a rapid that Y's stiff acceleration
// bounds, a one-step X move from rest got a quarter of what X allows (property seed 45: 1 000
// pulses/s² where X takes 4 900; the plan 2.3 times its bound).
TEST(Accel, AShortMoveFromRestKeepsItsOwnAxisAcceleration)
{
    MachineConfig c = gve64();
    c.unit.maxPulseRate = 200000;
    c.axes[0].stepsPerMm = 12.417;
    c.axes[0].accelMmPerS2 = 394.8;
    c.axes[1].stepsPerMm = 618.592;
    c.axes[1].accelMmPerS2 = 118.95;
    c.axes[1].maxJumpMmPerS = 0; // the rapid ends at rest
    gcode::Toolpath tp;
    tp.setOrigin({0, 0, -1, 0});
    tp.appendRapid({100, 50, -40, 0}, 0, 1);
    tp.appendFeed({100 + 1 / 12.417, 50, -40, 0}, 4000, 2); // one X step
    const PlanResult r = planOk(tp, c);
    const auto vs = replay(r.program);
    ASSERT_EQ(vs.size(), 2u);
    EXPECT_EQ(vs.back().a, static_cast<std::int64_t>(std::floor(394.8 * 12.417 / 1000)));
    expectValid(r);
}

// Property seed 187, built by hand: A-axis moves of 364 steps with a one-step Z move between
// them, each corner a rest (Z's jump limit is below the unit's smallest speed). The quick
// vectors shared the least A across the rests, so after each rest the A axis started from
// standstill at the Z move's A 28, a 46th of its own (the plan 68 % over its bound). From rest a
// vector is all acceleration, and an A command sent while the unit stands costs no motion.
TEST(Accel, AStretchDoesNotShareTheAccelerationAcrossARest)
{
    MachineConfig c = defaultMachineConfig(protocol::Variant::Gve114);
    c.link.baud = 230400;
    c.link.latencyMs = 9.4;
    c.axes[2].stepsPerMm = 29.426;
    c.axes[2].accelMmPerS2 = 970.56;
    c.axes[2].maxJumpMmPerS = 0.157;
    c.axes[3].present = true;
    c.axes[3].stepsPerMm = 1914.593;
    c.axes[3].accelMmPerS2 = 667.76;
    c.axes[3].maxSpeedMmPerMin = 4456;
    c.axes[3].maxJumpMmPerS = 1.73;
    gcode::Toolpath tp;
    tp.setOrigin({40, 30, -12, 1});
    double a = 1, z = -12;
    std::uint32_t line = 1;
    for (int i = 0; i < 4; ++i) {
        for (int j = 0; j < 3; ++j)
            tp.appendFeed({40, 30, z, a += 0.19}, 5053, line++);
        tp.appendFeed({40, 30, z -= 1 / 29.426, a}, 5053, line++);
    }
    const PlanResult r = planOk(tp, c);
    const auto vs = replay(r.program);
    const std::int64_t own = static_cast<std::int64_t>(std::floor(667.76 * 1914.593 / 1000));
    int afterRest = 0;
    for (std::size_t k = 1; k < vs.size(); ++k) {
        if (vs[k].d[3] != 0 && vs[k - 1].d[3] == 0) { // the first A vector after a Z move
            ++afterRest;
            EXPECT_EQ(vs[k].a, own) << "vector " << k;
        }
    }
    EXPECT_EQ(afterRest, 3);
    expectValid(r);
}
