#pragma once
// Helpers of the EEPROM behaviour tests (issue 20 item 3): the profile's EEPROM settings
// written to the emulated unit through the driver (MachineCore::writeEeprom, what Machine ›
// Unit configuration and the connect comparison use), then the unit is watched.

#include "simfixture.h"

#include <gtest/gtest.h>

#include <functional>

namespace frezka::driver::test {

// Changes the profile, writes its EEPROM settings to the unit through the driver and waits
// until the read-back compare has found no difference.
inline ::testing::AssertionResult
writeThroughDriver(Sim &sim, const std::function<void(machine::MachineConfig &)> &change)
{
    change(sim.config);
    sim.core.setConfig(sim.config);
    if (auto refused = sim.core.writeEeprom(sim.runner.now()))
        return ::testing::AssertionFailure() << "writeEeprom refused: " << refused->message;
    sim.runner.runFor(4.0);
    if (!sim.errors.empty())
        return ::testing::AssertionFailure() << sim.lastLog();
    if (!sim.core.state().eepromDifferences.empty())
        return ::testing::AssertionFailure()
               << "unit differs: " << sim.core.state().eepromDifferences.front().text();
    return ::testing::AssertionSuccess();
}

// The MPG switched on through the driver (Y&), as the jog panel's MPG switch does.
inline ::testing::AssertionResult mpgOn(Sim &sim)
{
    if (auto refused = sim.core.setMpg(true, sim.runner.now()))
        return ::testing::AssertionFailure() << "setMpg refused: " << refused->message;
    sim.runner.runFor(0.5);
    if (!(sim.port.unit().status(6) & 0x40))
        return ::testing::AssertionFailure() << "the unit's MPG is not on\n" << sim.lastLog();
    return ::testing::AssertionSuccess();
}

} // namespace frezka::driver::test
