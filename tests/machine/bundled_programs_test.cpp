// The bundled benchmark programs (tests/bench/planner/programs) hold the targets, judged
// by the emulator core on its virtual clock: within 2 % of the time-optimal bound, no brake
// violation, no starvation, no vertex over the velocity-jump or turn-acceleration limit, final
// counters exactly at the rounded end position. The figures are in docs/benchmarks.md.
#include "emulatorrun.h"

#include "gcode/interpreter.h"
#include "machine/planner.h"
#include "machine/unitmodel.h"
#include "machine/unitwire.h"

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
    EXPECT_LE(run.jobS + r.stats.linkWaitS, 1.02 * r.stats.boundS);
    // The emulator here is fed without a link: the plan's model without the link's rests.
    EXPECT_NEAR(run.jobS + r.stats.linkWaitS, r.stats.estimatedS, 1e-6 * run.jobS);
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
    // Within 0.02 %: the full plan also pays where a V or an A changes early in a chain (the
    // pace waits for the change's round trips, RunPlanner::paceModalChanges), which the grbl
    // baseline does not model (its A changes at every block; on a link it would run dry).
    // Contour: 0.011 % above since a stretch from rest counts only until the unit must brake.
    EXPECT_LE(full.stats.estimatedS, g.stats.estimatedS * 1.0002);
}

INSTANTIATE_TEST_SUITE_P(Planner, BundledProgram,
                         testing::Values("pocket", "contour", "surface", "engrave", "adaptive"));

TEST(BundledPrograms, TheDenseRasterBeatsPlainGrblByAThird)
{
    const MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    const gcode::Result g = gcode::interpretFile(std::string(FREZKA_SOURCE_DIR) +
                                                 "/tests/bench/planner/programs/surface.nc");
    ASSERT_TRUE(g.ok());
    // The planning itself, on a link fast enough for it: the link's pace would hold both back.
    PlanOptions fullOptions;
    fullOptions.wireLimited = false;
    PlanOptions grbl = fullOptions;
    grbl.strategy = PlanStrategy::GrblJunction;
    grbl.accelWindowSteps = 0;
    grbl.accelTolerance = 0;
    const PlanResult full = plan(g.toolpath, c, fullOptions);
    const PlanResult plain = plan(g.toolpath, c, grbl);
    EXPECT_LT(full.stats.estimatedS, 0.75 * plain.stats.estimatedS);
}

// The link's pace (PlanOptions::wireLimited): over every 256 vectors of a chain the unit's motion
// lasts at least as long as their commands (C and B, with checksums) take on the wire at the
// profile's baud rate, so a driver that streams at the wire's pace never lets the unit's queue
// run dry mid-chain. Without it the dense raster asks for vectors half again faster than the
// wire carries them.
TEST(BundledPrograms, DenseProgramsKeepTheLinksPace)
{
    const MachineConfig c = defaultMachineConfig(protocol::Variant::Gve64);
    for (const char *name : {"surface", "engrave", "adaptive"}) {
        const gcode::Result g = gcode::interpretFile(
            std::string(FREZKA_SOURCE_DIR) + "/tests/bench/planner/programs/" + name + ".nc");
        ASSERT_TRUE(g.ok());
        for (bool limited : {true, false}) {
            PlanOptions o;
            o.wireLimited = limited;
            const PlanResult r = plan(g.toolpath, c, o);
            ASSERT_TRUE(r.ok());
            const ModelResult model = runUnitModel(r.program);
            // Per vector: its model time and the bytes sent for it (its C and the B before it).
            std::vector<double> times, bytes;
            std::vector<bool> chainStart;
            double pending = 0;
            bool start = true;
            for (const UnitCommand &cmd : r.program.commands) {
                if (cmd.op == UnitOp::Brake) {
                    pending +=
                        static_cast<double>(commandText(cmd, r.program.axisCount).size()) + 4;
                } else if (cmd.op == UnitOp::Vector) {
                    times.push_back(model.vectorTimes[times.size()]);
                    bytes.push_back(
                        pending +
                        static_cast<double>(commandText(cmd, r.program.axisCount).size()) + 4);
                    chainStart.push_back(start);
                    pending = 0;
                    start = false;
                } else if (cmd.op == UnitOp::Line) {
                    times.push_back(model.vectorTimes[times.size()]);
                    bytes.push_back(0);
                    chainStart.push_back(true);
                    start = true;
                } else if (cmd.op == UnitOp::WaitIdle || cmd.op == UnitOp::ProgramEnd) {
                    start = true;
                }
            }
            const double byteS = 10.0 / c.link.baud;
            const std::size_t kWindow = 256; // well inside the GVE64's queue of 420
            std::size_t slower = 0;
            double least = 1e9;
            for (std::size_t k = 0; k + kWindow <= times.size(); ++k) {
                double t = 0, w = 0;
                bool chain = true;
                for (std::size_t j = k; j < k + kWindow; ++j) {
                    chain = chain && (j == k || !chainStart[j]);
                    t += times[j];
                    w += bytes[j] * byteS;
                }
                slower += chain && t < w ? 1 : 0;
                if (chain)
                    least = std::min(least, t / w);
            }
            if (limited) {
                EXPECT_EQ(slower, 0u)
                    << name
                    << ": windows of 256 vectors faster than the wire (least time / wire time "
                    << least << ")";
            } else if (std::string(name) == "surface") {
                EXPECT_GT(slower, 1000u) << name << ": the test would not see it";
            }
        }
    }
}
