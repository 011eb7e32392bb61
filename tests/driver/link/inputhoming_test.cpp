// InputHoming (issue 14 item 4): with a homing input in the profile the unit is kept in Y& (the
// MPG on, silent: homing from the input enabled) while idle, and gets Y- only before it moves;
// without one the connect sequence's Y- stays. Asserted on the wire and on the unit's RUN bit.
#include "simfixture.h"
#include "wiretap.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace frezka::driver::test {
namespace {

std::size_t indexOf(const WireTap &wire, const std::string &line, std::size_t from = 0)
{
    const auto &l = wire.lines();
    const auto it = std::find(l.begin() + static_cast<std::ptrdiff_t>(from), l.end(), line);
    return static_cast<std::size_t>(it - l.begin());
}

TEST(InputHoming, TheUnitIsParkedInYAmpersandWhileIdleAndGetsYMinusBeforeMoving)
{
    Sim sim;
    sim.config.eeprom.homingInput = 5;
    sim.core.setConfig(sim.config);
    WireTap wire(sim.port);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    sim.runner.runFor(0.5);
    EXPECT_TRUE(wire.matching("!0Y-").empty()) << "the connect sequence keeps input homing on";
    EXPECT_EQ(wire.matching("!0Y&").size(), 1u);
    EXPECT_TRUE(sim.port.unit().status(6) & 0x40) << "the unit's MPG is on (RUN=1)";
    EXPECT_TRUE(sim.core.state().mpgOn);
    // A jog: Y- first, then the move, then Y& again once the machine stands.
    const std::size_t from = wire.size();
    ASSERT_FALSE(sim.core.jogStep(0, 2, 600, sim.runner.now())) << sim.lastLog();
    ASSERT_TRUE(sim.until(MachineMode::Idle, 30)) << sim.lastLog();
    sim.runner.runFor(0.5);
    const std::size_t off = indexOf(wire, "!0Y-", from);
    const std::size_t move = indexOf(wire, "!0L400,0,0,0", from);
    const std::size_t on = indexOf(wire, "!0Y&", from);
    ASSERT_LT(off, wire.size());
    EXPECT_LT(off, move);
    EXPECT_LT(move, on);
    EXPECT_LT(on, wire.size());
    EXPECT_EQ(sim.port.unit().position()[0], 400) << "the unit moved";
    EXPECT_TRUE(sim.port.unit().status(6) & 0x40) << "parked again";
    EXPECT_TRUE(sim.errors.empty()) << sim.lastLog();
    // Homing by W (refused by the unit while its MPG is on) works the same way.
    sim.port.unit().setSwitches(unitOptionsFor(sim.config).switches);
    ASSERT_FALSE(sim.core.home(sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return sim.core.state().homed; }, 600)) << sim.lastLog();
}

TEST(InputHoming, WithoutAHomingInputTheMpgIsSwitchedOffOnConnect)
{
    Sim sim;
    WireTap wire(sim.port);
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.jogStep(0, 2, 600, sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Idle, 30));
    EXPECT_EQ(wire.matching("!0Y-").size(), 1u);
    EXPECT_TRUE(wire.matching("!0Y&").empty());
    EXPECT_FALSE(sim.port.unit().status(6) & 0x40);
}

} // namespace
} // namespace frezka::driver::test
