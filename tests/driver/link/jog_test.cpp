// Jog under the soft-limit policy (machine/softlimits.h, issue 14 item 4): before homing the
// limits are off and the jog is slower, after homing a continuous jog stops at the limit and a
// step beyond it is refused. Asserted on the wire and on the emulated unit.
#include "simfixture.h"
#include "wiretap.h"

#include <gtest/gtest.h>

#include <cmath>

namespace frezka::driver::test {
namespace {

TEST(Jog, BeforeHomingGoesBelowTheSoftMinimumAtTheHomingSpeed)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    ASSERT_EQ(sim.core.state().homedAxes, 0);
    WireTap wire(sim.port);
    // X min is 0 and the counter starts at 0: -5 mm is allowed before homing.
    ASSERT_FALSE(sim.core.jogStep(0, -5, 3000, sim.runner.now())) << sim.lastLog();
    ASSERT_TRUE(sim.until(MachineMode::Idle, 60)) << sim.lastLog();
    EXPECT_EQ(sim.port.unit().position()[0], -1000);
    EXPECT_EQ(wire.matching("!0L"), std::vector<std::string>{"!0L-1000,0,0,0"});
    // 3000 mm/min asked, 10 mm/s (the homing speed toward the switch) = 2000 pulses/s sent.
    EXPECT_EQ(wire.matching("!0V"), std::vector<std::string>{"!0V2000"});
    // Continuous toward -Y: runs on below 0 until stopped.
    ASSERT_FALSE(sim.core.jogContinuous(1, -1, 3000, sim.runner.now()));
    sim.runner.runFor(1.0);
    ASSERT_FALSE(sim.core.jogStop(sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Idle, 10)) << sim.lastLog();
    EXPECT_LT(sim.port.unit().position()[1], -1000) << "Y went below its soft minimum";
}

TEST(Jog, AfterHomingContinuousStopsAtTheLimitAndAStepBeyondIsRefused)
{
    Sim sim;
    sim.port.unit().setSwitches(unitOptionsFor(sim.config).switches);
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.home(sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return sim.core.state().homed; }, 600));
    ASSERT_TRUE(sim.until(MachineMode::Idle, 10));
    ASSERT_FALSE(sim.core.jogStep(0, 10, 3000, sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Idle, 60));
    WireTap wire(sim.port);
    ASSERT_FALSE(sim.core.jogContinuous(0, -1, 3000, sim.runner.now()));
    sim.runner.runFor(30);
    EXPECT_EQ(wire.matching("!0L"), std::vector<std::string>{"!0L-2000,0,0,0"})
        << "clipped to the soft minimum 0";
    EXPECT_EQ(wire.matching("!0V"), std::vector<std::string>{"!0V10000"}) << "full jog speed";
    EXPECT_EQ(sim.port.unit().position()[0], 0);
    ASSERT_FALSE(sim.core.jogStop(sim.runner.now())); // the key released
    ASSERT_TRUE(sim.until(MachineMode::Idle, 10));
    const auto before = wire.size();
    EXPECT_TRUE(sim.core.jogStep(0, -5, 3000, sim.runner.now()).has_value());
    EXPECT_TRUE(sim.core.jogContinuous(0, -1, 3000, sim.runner.now()).has_value());
    sim.runner.runFor(1);
    EXPECT_TRUE(wire.matching("!0L", before).empty()) << "nothing sent beyond the limit";
    EXPECT_EQ(sim.port.unit().position()[0], 0);
}

// Releasing a continuous jog is the operator's stop, not an alarm: the H that ends it sets INTA,
// which must not be read as an input interrupt (the log showed "Jogging -> Alarm -> Idle" on every
// release, and an error in between).
// A quick tap (released before the jog's own commands went out) and a long press.
class JogRelease : public ::testing::TestWithParam<double>
{
};

TEST_P(JogRelease, GoesStraightBackToIdle)
{
    const double holdS = GetParam();
    Sim sim;
    ASSERT_TRUE(sim.connect());
    WireTap wire(sim.port);
    const auto logFrom = sim.log.size();
    ASSERT_FALSE(sim.core.jogContinuous(0, 1, 3000, sim.runner.now()));
    sim.runner.runFor(holdS);
    ASSERT_FALSE(sim.core.jogStop(sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Idle, 10)) << sim.lastLog();
    sim.runner.runFor(1.0);
    std::vector<std::string> modes;
    for (std::size_t i = logFrom; i < sim.log.size(); ++i)
        if (sim.log[i].find("mode: ") != std::string::npos)
            modes.push_back(sim.log[i].substr(sim.log[i].find("mode: ")));
    EXPECT_EQ(modes, (std::vector<std::string>{"mode: Idle -> Jogging", "mode: Jogging -> Idle"}))
        << sim.lastLog();
    EXPECT_TRUE(sim.errors.empty()) << sim.lastLog();
    EXPECT_EQ(wire.matching("!0H").size(), 1u);
    EXPECT_GE(sim.port.unit().position()[0], 0);
    EXPECT_FALSE(sim.port.unit().isMoving());
    EXPECT_FALSE(sim.core.state().inta);
}

INSTANTIATE_TEST_SUITE_P(Jog, JogRelease, ::testing::Values(0.0, 0.001, 0.02, 1.0));

} // namespace
} // namespace frezka::driver::test
