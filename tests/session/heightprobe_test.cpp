// HeightProbe (issue 19): the grid and its serpentine order, and the probing sequence on the
// in-process emulator (SimLink) with a simulated work top: Cancel stops the motion and takes the
// tool back up to the clearance; a probe already in contact is refused before it moves.
#include "session/heightprobe.h"
#include "session/runworkflow.h"
#include "session/simlink.h"

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

using driver::MachineMode;

TEST(HeightProbe, GridCoversTheAreaAndIsProbedInSerpentineOrder)
{
    HeightProbeSettings s{.x0Mm = 10,
                          .y0Mm = 5,
                          .x1Mm = 35,
                          .y1Mm = 15,
                          .spacingMm = 10,
                          .clearanceZMm = -4,
                          .bottomZMm = -8,
                          .feedMmPerMin = 100};
    QString error;
    const auto grid = heightProbeGrid(s, &error);
    ASSERT_TRUE(grid) << error.toStdString();
    EXPECT_EQ(grid->countX(), 4); // 25 mm at most 10 apart: 3 gaps of 8.333
    EXPECT_EQ(grid->countY(), 2);
    EXPECT_DOUBLE_EQ(grid->endX(), 35);
    EXPECT_DOUBLE_EQ(grid->endY(), 15);
    const std::vector<std::pair<int, int>> order{{0, 0}, {1, 0}, {2, 0}, {2, 1}, {1, 1}, {0, 1}};
    EXPECT_EQ(serpentineOrder(3, 2), order);

    s.bottomZMm = -4; // no depth
    EXPECT_FALSE(heightProbeGrid(s, &error));
    EXPECT_NE(error.indexOf(QStringLiteral("give a depth above 0 mm")), -1) << error.toStdString();
    s.bottomZMm = -8;
    s.x1Mm = 10;
    EXPECT_FALSE(heightProbeGrid(s, &error));
    EXPECT_NE(error.indexOf(QStringLiteral("area to probe is empty")), -1);
}

struct Bench
{
    explicit Bench(const char *surface)
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
        return unit;
    }
    machine::MachineConfig config;
    SimLink link;
    HeightProbe probe;
    std::optional<bool> result;
};

const HeightProbeSettings kGrid{.x0Mm = 10,
                                .y0Mm = 10,
                                .x1Mm = 30,
                                .y1Mm = 30,
                                .spacingMm = 10,
                                .clearanceZMm = -4,
                                .bottomZMm = -7,
                                .feedMmPerMin = 50};

TEST(HeightProbe, CancelStopsTheProbeAndTakesTheToolUp)
{
    Bench b("plane:-5,0,0");
    ASSERT_TRUE(b.probe.start(kGrid)) << b.probe.error().toStdString();
    ASSERT_TRUE(b.link.runUntil([&] { return b.probe.pointsDone() == 1; }, 600));
    // Over the second node, half-way down to the surface: the probe move runs.
    ASSERT_TRUE(b.link.runUntil(
        [&] {
            const auto at = b.link.port().unit().position();
            return at[0] == 20 * 200 && at[2] < -4.5 * 200;
        },
        600));
    ASSERT_EQ(b.probe.pointsDone(), 1);
    b.probe.cancel();
    ASSERT_TRUE(b.link.runUntil([&] { return b.result.has_value(); }, 600));
    EXPECT_FALSE(*b.result);
    EXPECT_NE(b.probe.error().indexOf(QStringLiteral("cancelled after 1 of 9 points")), -1)
        << b.probe.error().toStdString();
    EXPECT_EQ(b.probe.pointsDone(), 1);
    // Stopped above the surface (the probe never reached it), then back up to the clearance.
    const auto at = b.link.port().unit().position();
    EXPECT_EQ(at[2], -4 * 200);
    EXPECT_EQ(at[0], 20 * 200);
    EXPECT_EQ(b.link.state().mode, MachineMode::Idle)
        << (b.link.state().lastError ? b.link.state().lastError->message : std::string());
}

TEST(HeightProbe, AProbeAlreadyInContactIsRefusedBeforeItMoves)
{
    Bench b("plane:-3,0,0"); // above the clearance: the probe touches the work at -4 already
    ASSERT_TRUE(b.probe.start(kGrid));
    ASSERT_TRUE(b.link.runUntil([&] { return b.result.has_value(); }, 600));
    EXPECT_FALSE(*b.result);
    EXPECT_NE(b.probe.error().indexOf(
                  QStringLiteral("The probe at X 10.000, Y 10.000 was already in contact")),
              -1)
        << b.probe.error().toStdString();
    EXPECT_EQ(b.link.port().unit().position()[2], -4 * 200); // never below the clearance
    EXPECT_EQ(b.probe.pointsDone(), 0);
}

TEST(HeightProbe, TheBuiltInEmulatorTakesItsSurfaceFromTheEnvironment)
{
    machine::MachineConfig c = machine::defaultMachineConfig(protocol::Variant::Gve64);
    qputenv("FREZKA_EMULATOR_SURFACE", "plane:-5,0,0");
    EXPECT_EQ(RunWorkflow::connectionFor(c).surface, QStringLiteral("plane:-5,0,0"));
    qunsetenv("FREZKA_EMULATOR_SURFACE");
    EXPECT_TRUE(RunWorkflow::connectionFor(c).surface.isEmpty());
}

} // namespace
} // namespace frezka::session
