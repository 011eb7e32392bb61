// LiveModel (issue 16 item 3): the position shown between the polls of a wire-bound job, on the
// emulator's virtual clock.

#include "simfixture.h"

#include "gcode/interpreter.h"
#include "machine/planner.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <gtest/gtest.h>
#include <map>

using namespace frezka;
using namespace frezka::driver;
using namespace frezka::driver::test;

namespace {

double distanceMm(const machine::MachineConfig &c, const std::array<std::int64_t, 4> &a,
                  const std::array<std::int64_t, 4> &b)
{
    double d2 = 0;
    for (std::size_t i = 0; i < 3; ++i) {
        const double mm = double(a[i] - b[i]) / c.axes[i].stepsPerMm;
        d2 += mm * mm;
    }
    return std::sqrt(d2);
}

// One vector at a program command: the longest motion from the one before it to the one after.
double vectorNear(const machine::MachineConfig &c, const machine::UnitProgram &p, std::size_t k)
{
    double longest = 1e-3; // the DRO's last digit
    for (std::size_t j = k > 0 ? k - 1 : 0; j <= k + 1 && j < p.commands.size(); ++j) {
        const auto &d = p.commands[j].d;
        longest = std::max(longest, distanceMm(c, {d[0], d[1], d[2], d[3]}, {}));
    }
    return longest;
}

} // namespace

// The bundled dense raster at 8 ms latency each way is wire-bound: the counters are polled a few
// times a second (186 polls in 42 s). Between the polls the driver publishes its model of the unit
// at 25 Hz: each modelled figure lies on a command the unit accepted, within one vector of where
// the emulated unit is at that moment, and the polled counters (the path guard's input) change only
// at polls.
TEST(LiveModel, WireBoundRasterShowsTheModelBetweenPolls)
{
    const gcode::Result g = gcode::interpretFile(std::string(FREZKA_SOURCE_DIR) +
                                                 "/tests/bench/planner/programs/surface.nc");
    ASSERT_TRUE(g.ok());
    WireOptions wire;
    wire.latencyS = 0.008;
    Sim sim(protocol::Variant::Gve64, wire);
    const machine::PlanResult plan = machine::plan(g.toolpath, sim.config);
    ASSERT_TRUE(plan.ok());
    ASSERT_TRUE(sim.connect()) << sim.lastLog();

    std::map<int, int> figuresPerSecond; // modelled figures made in each whole second
    int modelled = 0, fresh = 0, polls = 0, ahead = 0, offByMore = 0, countersOutsidePolls = 0;
    double worst = 0; // in vectors
    std::array<std::int64_t, 4> counters = sim.core.state().positionSteps;
    sim.core.onStateChanged = [&](const MachineState &s) {
        if (!s.jobActive || s.mode != MachineMode::Running)
            return;
        if (!s.live.modelled) {
            polls += s.positionSteps != counters ? 1 : 0;
            counters = s.positionSteps;
            return;
        }
        countersOutsidePolls += s.positionSteps != counters ? 1 : 0;
        ++modelled;
        ahead += s.live.command >= s.commandsAcked ? 1 : 0;
        if (s.live.atS != sim.runner.now())
            return; // published again with another change: the figure of its own moment
        ++fresh;
        ++figuresPerSecond[int(s.live.atS)];
        const auto &u = sim.port.unit().position();
        const double off = distanceMm(sim.config, s.live.steps, {u[0], u[1], u[2], u[3]});
        const double vector = vectorNear(sim.config, plan.program, std::size_t(s.live.command));
        worst = std::max(worst, off / vector);
        offByMore += off > vector ? 1 : 0;
    };
    ASSERT_FALSE(sim.core.run(plan.program, sim.runner.now()));
    // Which whole seconds the emulated unit moves throughout (sampled every 5 ms): not the
    // spindle's spin-up at the start, when the machine stands and nothing new is published.
    std::map<int, int> standingSamples;
    auto unitWas = sim.port.unit().position();
    while (sim.finished.empty() && sim.runner.now() < 600) {
        sim.runner.runFor(0.005);
        const auto unit = sim.port.unit().position();
        standingSamples[int(sim.runner.now())] += unit == unitWas ? 1 : 0;
        unitWas = unit;
    }
    ASSERT_FALSE(sim.finished.empty()) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front());

    EXPECT_GT(modelled, 20 * 30);
    EXPECT_EQ(ahead, 0);
    EXPECT_EQ(countersOutsidePolls, 0);
    // Within one vector of the unit; a few just after a poll at a row's turn, where the unit
    // accelerates through a short vector from a low brake speed, by up to a few (the poll's
    // share of the vector is its share of the distance, taken as its share of the time).
    EXPECT_LE(offByMore, fresh / 100) << "worst: " << worst << " vectors";
    EXPECT_LE(worst, 4.0);
    // Every whole second in which the unit moves shows at least 20 figures.
    int moving = 0;
    for (const auto &[second, standing] : standingSamples) {
        if (standing > 0 || second + 1 > int(sim.runner.now()))
            continue;
        ++moving;
        EXPECT_GE(figuresPerSecond[second], 20) << "second " << second;
    }
    EXPECT_GT(moving, 30);
    EXPECT_GT(polls, 5);
}
