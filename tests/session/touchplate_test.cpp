// Probing one point fast then slow (issue 19 item 2, the touch plate): HeightProbe::startAt on
// the in-process emulator with a simulated work top: the slow trip point is the top within a
// step, the tool never below the probe's depth, back up by the retract; a probe that never trips
// fails with its error and the tool back at the clearance; touchPlateZero puts Z 0 on the work.
#include "session/heightprobe.h"
#include "session/runworkflow.h"
#include "session/simlink.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <limits>

namespace frezka::session {
namespace {

using driver::MachineMode;

struct PlateBench
{
    explicit PlateBench(const char *surface)
        : config(machine::defaultMachineConfig(protocol::Variant::Gve64))
        , link(config, unitWith(config, surface), driver::WireOptions{}, driver::CoreOptions{})
        , probe(link, config)
    {
        QObject::connect(&probe, &HeightProbe::finished, [this](bool ok) { result = ok; });
        link.connectTo(RunWorkflow::connectionFor(config));
        EXPECT_TRUE(link.runUntil([&] { return link.state().mode == MachineMode::Idle; }, 30));
    }
    static emulator::UnitOptions unitWith(const machine::MachineConfig &c, const char *surface)
    {
        emulator::UnitOptions unit = driver::unitOptionsFor(c);
        EXPECT_TRUE(driver::setProbeSurface(unit, surface, c));
        unit.trace = true; // the lowest Z reached, from every motion event
        return unit;
    }
    // Runs until finished(); the lowest Z counter the unit reached on the way.
    std::int64_t runToEnd()
    {
        std::int64_t lowest = std::numeric_limits<std::int64_t>::max();
        link.runUntil(
            [&] {
                emulator::Unit &u = link.port().unit();
                for (const emulator::TracePoint &p : u.trace()) {
                    lowest = std::min(lowest, p.position[2]);
                    const bool below = p.position[2] < touchBelowSteps;
                    touches += below && !wasBelow ? 1 : 0;
                    wasBelow = below;
                }
                lowest = std::min(lowest, u.position()[2]);
                u.clearTrace();
                return result.has_value();
            },
            600);
        return lowest;
    }
    machine::MachineConfig config;
    SimLink link;
    HeightProbe probe;
    std::optional<bool> result;
    std::int64_t touchBelowSteps = std::numeric_limits<std::int64_t>::min();
    bool wasBelow = false;
    int touches = 0; // times the tool went down below touchBelowSteps
};

// Over X 10 Y 10 at Z -4, down to -7 at most: fast at 200 mm/min, back 0.5 mm, slow at 20.
const HeightProbeSettings kPlate{.clearanceZMm = -4,
                                 .bottomZMm = -7,
                                 .feedMmPerMin = 200,
                                 .slowFeedMmPerMin = 20,
                                 .retractMm = 0.5};

TEST(TouchPlate, FastThenSlowFindsTheTopAndBacksOffByTheRetract)
{
    PlateBench b("plane:-5.3,0,0");
    b.touchBelowSteps = -5.25 * 200;
    ASSERT_TRUE(b.probe.startAt(10, 10, kPlate)) << b.probe.error().toStdString();
    const std::int64_t lowest = b.runToEnd();
    EXPECT_EQ(b.touches, 2); // the fast probe, back off, the slow probe
    ASSERT_TRUE(b.result && *b.result) << b.probe.error().toStdString();
    ASSERT_TRUE(b.probe.pointZMm());
    EXPECT_NEAR(*b.probe.pointZMm(), -5.3, 1.0 / 200);
    EXPECT_EQ(b.probe.pointsDone(), 1);
    const auto at = b.link.port().unit().position();
    EXPECT_EQ(at[0], 10 * 200);
    EXPECT_EQ(at[1], 10 * 200);
    EXPECT_NEAR(at[2], -4.8 * 200, 1); // 0.5 mm above the trip point
    // The fast probe stops after the trip within its deceleration (5 steps at 200 mm/min), far
    // from the depth.
    EXPECT_GE(lowest, -5.3 * 200 - 10);
    EXPECT_EQ(b.link.state().mode, MachineMode::Idle);
}

TEST(TouchPlate, AProbeThatNeverTripsStopsAtTheDepthWithItsError)
{
    PlateBench b("plane:-9,0,0"); // the work below the depth
    ASSERT_TRUE(b.probe.startAt(10, 10, kPlate)) << b.probe.error().toStdString();
    const std::int64_t lowest = b.runToEnd();
    ASSERT_TRUE(b.result);
    EXPECT_FALSE(*b.result);
    EXPECT_NE(b.probe.error().indexOf(QStringLiteral(
                  "The probe at X 10.000, Y 10.000 went down to Z -7.000 without touching")),
              -1)
        << b.probe.error().toStdString();
    EXPECT_FALSE(b.probe.pointZMm());
    EXPECT_GE(lowest, -7 * 200);                             // never below the depth
    EXPECT_EQ(b.link.port().unit().position()[2], -4 * 200); // back at the clearance
    EXPECT_EQ(b.link.state().mode, MachineMode::Idle);
}

TEST(TouchPlate, SlowProbingNeedsARetract)
{
    PlateBench b("plane:-5,0,0");
    HeightProbeSettings s = kPlate;
    s.retractMm = 0;
    EXPECT_FALSE(b.probe.startAt(10, 10, s));
    EXPECT_NE(b.probe.error().indexOf(QStringLiteral("needs a retract above 0 mm")), -1);
}

// A turning spindle: probing is refused before anything moves (the unit's counters unchanged,
// no move on the wire); with the spindle stopped the same probe runs.
TEST(TouchPlate, ATurningSpindleIsRefusedBeforeTheToolMoves)
{
    PlateBench b("plane:-5.3,0,0");
    b.link.setSpindleRpm(12000);
    ASSERT_TRUE(b.link.runUntil([&] { return b.link.port().unit().spindleTurning(); }, 10));
    ASSERT_TRUE(b.link.runUntil([&] { return b.link.state().spindleOn; }, 10));
    const auto before = b.link.port().unit().position();
    EXPECT_FALSE(b.probe.startAt(10, 10, kPlate));
    EXPECT_NE(b.probe.error().indexOf(QStringLiteral("The spindle is turning")), -1)
        << b.probe.error().toStdString();
    EXPECT_FALSE(b.probe.running());
    b.link.runFor(2);
    EXPECT_EQ(b.link.port().unit().position(), before);
    EXPECT_TRUE(b.link.port().unit().trace().empty() ||
                std::all_of(b.link.port().unit().trace().begin(),
                            b.link.port().unit().trace().end(),
                            [&](const emulator::TracePoint &p) { return p.position == before; }));

    b.link.setSpindleRpm(0);
    ASSERT_TRUE(b.link.runUntil([&] { return !b.link.port().unit().spindleTurning(); }, 10));
    ASSERT_TRUE(b.link.runUntil([&] { return !b.link.state().spindleOn; }, 10));
    ASSERT_TRUE(b.probe.startAt(10, 10, kPlate)) << b.probe.error().toStdString();
    b.runToEnd();
    ASSERT_TRUE(b.result && *b.result) << b.probe.error().toStdString();
    EXPECT_NEAR(*b.probe.pointZMm(), -5.3, 1.0 / 200);
}

// The spindle switched on while probing (after the fast trip): the slow probe is not run, the
// tool goes up and never touches again; the error says why.
TEST(TouchPlate, ASpindleSwitchedOnWhileProbingEndsItBeforeTheNextProbeMove)
{
    PlateBench b("plane:-5.3,0,0");
    b.touchBelowSteps = -5.25 * 200;
    ASSERT_TRUE(b.probe.startAt(10, 10, kPlate)) << b.probe.error().toStdString();
    bool switched = false;
    b.link.runUntil(
        [&] {
            if (!switched && b.link.state().probeTripped) {
                b.link.setSpindleRpm(12000);
                switched = true;
            }
            return b.result.has_value();
        },
        600);
    ASSERT_TRUE(switched);
    ASSERT_TRUE(b.result);
    EXPECT_FALSE(*b.result);
    EXPECT_NE(b.probe.error().indexOf(QStringLiteral("The spindle is turning")), -1)
        << b.probe.error().toStdString();
    // Up at the clearance (a single point's failure: no trip recorded), not down at the work.
    EXPECT_EQ(b.link.port().unit().position()[2], -4 * 200);
    EXPECT_TRUE(b.link.port().unit().spindleTurning());
}

TEST(TouchPlate, TheActiveSystemsZPutsTheWorkTopAtZero)
{
    OffsetState o;
    o.active = 1; // G55
    o.g92 = {0, 0, 0.25, 0};
    o.systems[1] = {5, 6, 7, 0};
    const OffsetState next = touchPlateZero(o, -20, 1.5);
    EXPECT_DOUBLE_EQ(next.systems[1][2], -21.75);
    EXPECT_DOUBLE_EQ(next.systems[1][0], 5);
    EXPECT_EQ(next.systems[0], o.systems[0]);
    // The plate's top (the trip point) is work Z 1.5, the work's top 1.5 below is Z 0.
    EXPECT_DOUBLE_EQ(next.workPosition({0, 0, -20, 0})[2], 1.5);
}

} // namespace
} // namespace frezka::session
