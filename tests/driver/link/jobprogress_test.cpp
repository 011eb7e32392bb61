// The job's estimate of where the unit is in the program (the executing command, from the polled
// counters and from F), on the in-process emulator: it never keeps the job from sending.

#include "simfixture.h"

#include <gtest/gtest.h>

using namespace frezka;
using namespace frezka::driver;
using namespace frezka::driver::test;
using protocol::Variant;

namespace {

// One long vector along X, then short ones back and forth over the same stretch of it: every
// position of the later ones lies inside the first one's box.
machine::UnitProgram backAndForth(int shortVectors)
{
    using machine::UnitOp;
    ProgramBuilder b(3);
    auto add = [&b](UnitOp op, std::int64_t value, std::array<std::int32_t, 4> d = {}) {
        b.add(op, value, d);
    };
    add(UnitOp::Accel, 200);
    add(UnitOp::Speed, 4000);
    add(UnitOp::Brake, 4000);
    add(UnitOp::Vector, 0, {4000, 0, 0, 0});
    for (int i = 0; i < shortVectors; ++i)
        add(UnitOp::Vector, 0, {i % 2 ? 40 : -40, 0, 0, 0});
    add(UnitOp::ProgramEnd, 0);
    return b.program;
}

} // namespace

// The counters alone put the standing unit inside the first vector's box for good; before F's
// RUN = 0 counted, the job took the GVE84's queue of 64 for full from there on and never sent
// again: the unit stood and the job never ended.
TEST(JobProgress, AStandingUnitHasRunEverythingItAccepted)
{
    Sim sim(Variant::Gve84);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    const auto program = backAndForth(300);
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front());
    EXPECT_EQ(sim.port.unit().stats().motion.vectorsExecuted, 301);
    for (int a = 0; a < 3; ++a)
        EXPECT_EQ(sim.port.unit().position()[a], program.commands.back().endSteps[a]);
}
