// The bundled benchmark programs (tests/bench/planner/programs) hold the targets, judged
// by the emulator core on its virtual clock: within 2 % of the time-optimal bound, no brake
// violation, no starvation, no vertex over the velocity-jump or turn-acceleration limit, final
// counters exactly at the rounded end position. The figures are in docs/benchmarks.md.
#include "emulatorrun.h"

#include "gcode/interpreter.h"
#include "machine/planner.h"

#include <gtest/gtest.h>

#include <string>

using namespace frezka;
using namespace frezka::machine;
using namespace frezka::machine::test;

namespace {

class BundledProgram : public testing::TestWithParam<const char *>
{
protected:
    gcode::Toolpath load()
    {
        const std::string path =
            std::string(FREZKA_SOURCE_DIR) + "/tests/bench/planner/programs/" + GetParam() + ".nc";
        gcode::Result r = gcode::interpretFile(path);
        EXPECT_TRUE(r.ok()) << path;
        return std::move(r.toolpath);
    }
};

} // namespace

TEST_P(BundledProgram, MeetsTheTargetsOnTheEmulator)
{
    const MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    const PlanResult r = plan(load(), c);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.stats.curveAccelOverLimit, 0u);
    const EmulatorRun run = runOnEmulator(r.program, c);
    ASSERT_TRUE(run.error.empty()) << run.error;
    EXPECT_LE(run.jobS, 1.02 * r.stats.boundS);
    EXPECT_NEAR(run.jobS, r.stats.estimatedS, 1e-6 * run.jobS);
    EXPECT_EQ(run.brakeViolations, 0);
    EXPECT_EQ(run.starvationStops, 0);
    EXPECT_EQ(run.jumpOverLimit, 0u);
    EXPECT_TRUE(run.countersMatch);
}

TEST_P(BundledProgram, WholeProgramPassesBeatGrblsLookaheadUnderTheSameLimits)
{
    const MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    const gcode::Toolpath tp = load();
    PlanOptions grbl;
    grbl.strategy = PlanStrategy::GrblJunction;
    grbl.grblKeepsAllLimits = true;
    grbl.accelWindowSteps = 0; // grbl: each block's own acceleration
    grbl.accelTolerance = 0;
    const PlanResult full = plan(tp, c);
    const PlanResult g = plan(tp, c, grbl);
    ASSERT_TRUE(full.ok() && g.ok());
    EXPECT_LE(full.stats.estimatedS, g.stats.estimatedS * 1.0001);
}

INSTANTIATE_TEST_SUITE_P(Planner, BundledProgram,
                         testing::Values("pocket", "contour", "surface", "engrave", "adaptive"));

TEST(BundledPrograms, TheDenseRasterBeatsPlainGrblByAThird)
{
    const MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    const gcode::Result g = gcode::interpretFile(std::string(FREZKA_SOURCE_DIR) +
                                                 "/tests/bench/planner/programs/surface.nc");
    ASSERT_TRUE(g.ok());
    PlanOptions grbl;
    grbl.strategy = PlanStrategy::GrblJunction;
    grbl.accelWindowSteps = 0;
    grbl.accelTolerance = 0;
    const PlanResult full = plan(g.toolpath, c);
    const PlanResult plain = plan(g.toolpath, c, grbl);
    EXPECT_LT(full.stats.estimatedS, 0.75 * plain.stats.estimatedS);
}
