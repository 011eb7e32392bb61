// MachineCore on the in-process emulator (virtual clock): connect, stream, operations.

#include "simfixture.h"

#include <gtest/gtest.h>

using namespace frezka;
using namespace frezka::driver;
using namespace frezka::driver::test;
using protocol::Variant;

TEST(MachineCore, ConnectSequence)
{
    for (Variant v : {Variant::Gve84, Variant::Gve64, Variant::Gve64Phantom, Variant::Gve114}) {
        Sim sim(v);
        ASSERT_TRUE(sim.connect()) << sim.lastLog();
        const MachineState &s = sim.core.state();
        EXPECT_TRUE(s.checksums);
        EXPECT_TRUE(sim.port.unit().checksumsOn());
        EXPECT_EQ(s.firmware, std::string(protocol::variantInfo(v).firmware));
        EXPECT_EQ(s.unitId, std::string(protocol::variantInfo(v).defaultId));
        EXPECT_FALSE(s.run) << "MPG must be off after connecting";
        EXPECT_TRUE(sim.errors.empty()) << sim.errors.front().message;
    }
}

TEST(MachineCore, StreamsADenseJobExactly)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    const auto program = denseProgram(3000);
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front());
    const auto pos = sim.port.unit().position();
    for (int a = 0; a < 3; ++a)
        EXPECT_EQ(pos[a], program.commands.back().endSteps[a]) << "axis " << a;
    EXPECT_EQ(sim.core.jobReport().vectors, 3000);
    EXPECT_EQ(sim.port.unit().stats().motion.vectorsExecuted, 3000);
    EXPECT_EQ(sim.core.state().mode, MachineMode::Idle);
}
