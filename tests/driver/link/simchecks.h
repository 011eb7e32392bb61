#pragma once
// Checks of the MachineCore tests on the in-process emulator (simfixture.h), for gtest.

#include "simfixture.h"

#include <gtest/gtest.h>

namespace frezka::driver::test {

// Where the program ends, in steps.
inline machine::Steps4 endOf(const machine::UnitProgram &p)
{
    return p.commands.back().endSteps;
}

// The emulated unit's counters (X, Y, Z) are exactly at `want`.
inline void expectAt(Sim &sim, const machine::Steps4 &want)
{
    const auto pos = sim.port.unit().position();
    for (int a = 0; a < 3; ++a)
        EXPECT_EQ(pos[a], want[a]) << "axis " << a << "\n" << sim.lastLog();
}

} // namespace frezka::driver::test
