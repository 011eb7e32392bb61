// HomingCycle on the in-process emulator (issue 14): the position is read between the legs of
// the switch search, the operator can stop homing at any moment and the axis then counts as
// not homed, and a new link forgets every homed mark. Asserted on the wire (WireTap) and on
// the emulated unit itself.
#include "simfixture.h"
#include "wiretap.h"

#include <gtest/gtest.h>

#include <cmath>

namespace frezka::driver::test {
namespace {

std::int64_t steps(const Sim &sim, int axis, double mm)
{
    return std::llround(mm * sim.config.axes[static_cast<std::size_t>(axis)].stepsPerMm);
}

// Z jogged 60 mm down, away from its switch (5 mm above the counter's zero): homing it takes
// seconds, time to watch and to stop it.
void jogZDown(Sim &sim)
{
    sim.port.unit().setSwitches(unitOptionsFor(sim.config).switches);
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.jogStep(2, -60, 3000, sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Idle, 60)) << sim.lastLog();
    ASSERT_EQ(sim.port.unit().position()[2], steps(sim, 2, -60));
}

TEST(HomingCycle, ThePositionIsReadWhileTheAxisSeeksItsSwitch)
{
    Sim sim;
    jogZDown(sim);
    WireTap wire(sim.port);
    ASSERT_FALSE(sim.core.home(sim.runner.now(), 1u << 2));
    // The state published during homing follows the axis, several times a second.
    std::vector<std::int64_t> seen;
    ASSERT_TRUE(sim.runner.runUntil(
        [&] {
            if (sim.core.state().mode == MachineMode::Homing &&
                (seen.empty() || seen.back() != sim.core.state().positionSteps[2]))
                seen.push_back(sim.core.state().positionSteps[2]);
            return sim.core.state().mode == MachineMode::Idle;
        },
        120))
        << sim.lastLog();
    EXPECT_EQ(sim.core.state().homedAxes, 0b100) << sim.lastLog();
    EXPECT_EQ(sim.port.unit().position()[2], 0) << "counter set to the home position";
    // 65 mm at 10 mm/s: 6.5 s in legs of 0.25 s; the display moved with it.
    EXPECT_GE(seen.size(), 20u);
    const auto legs = wire.matching("!0WZ");
    EXPECT_GE(legs.size(), 20u);
    EXPECT_EQ(legs.front(), "!0WZ," + std::to_string(HomingCycle::legSteps(2000)) + ",2000," +
                                std::to_string(steps(sim, 2, 10)) + ",200");
    EXPECT_GE(wire.matching("!0P4").size(), legs.size()) << "a position read after every leg";
}

TEST(HomingCycle, StopMidwayEndsHomingAndTheAxisIsNotHomed)
{
    Sim sim;
    jogZDown(sim);
    ASSERT_FALSE(sim.core.home(sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil(
        [&] { return sim.port.unit().position()[2] > steps(sim, 2, -50); }, 60));
    WireTap wire(sim.port);
    ASSERT_FALSE(sim.core.pause(sim.runner.now())) << "Stop is accepted during homing";
    const std::int64_t atStop = sim.port.unit().position()[2];
    ASSERT_TRUE(sim.until(MachineMode::Idle, 5)) << sim.lastLog();
    EXPECT_FALSE(sim.core.state().homed);
    EXPECT_EQ(sim.core.state().homedAxes, 0) << "Z stopped before its switch; X, Y not reached";
    EXPECT_TRUE(sim.errors.empty()) << sim.lastLog();
    // At most the leg that was running went on (0.25 s at 10 mm/s = 2.5 mm), then nothing.
    EXPECT_LE(wire.matching("!0W").size(), 1u);
    const std::int64_t stopped = sim.port.unit().position()[2];
    EXPECT_LE(stopped - atStop, steps(sim, 2, 2.5));
    sim.runner.runFor(5);
    EXPECT_EQ(sim.port.unit().position()[2], stopped) << "the unit stands";
    EXPECT_FALSE(sim.port.unit().isMoving());
    EXPECT_EQ(sim.core.state().positionSteps[2], stopped) << "the display shows where it stands";
    // Abort stops it the same way; homing again afterwards works.
    ASSERT_FALSE(sim.core.home(sim.runner.now()));
    sim.runner.runFor(0.6);
    ASSERT_FALSE(sim.core.abort(sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Idle, 5)) << sim.lastLog();
    EXPECT_EQ(sim.core.state().homedAxes, 0);
    ASSERT_FALSE(sim.core.home(sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return sim.core.state().homed; }, 600)) << sim.lastLog();
}

TEST(HomingCycle, ANewLinkForgetsTheHomedAxes)
{
    Sim sim;
    sim.port.unit().setSwitches(unitOptionsFor(sim.config).switches);
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.home(sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return sim.core.state().homed; }, 600)) << sim.lastLog();
    sim.runner.unplug("cable pulled");
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    EXPECT_FALSE(sim.core.state().homed);
    EXPECT_EQ(sim.core.state().homedAxes, 0);
}

} // namespace
} // namespace frezka::driver::test
