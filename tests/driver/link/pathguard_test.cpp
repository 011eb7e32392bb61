// The path guard (driver/link/pathguard.h): a command damaged on the line so that
// its checksum still matches makes the unit run a vector nobody planned. The driver must see it
// from the counters, stop, hold the job (or return on its own when told to), and end exactly
// where the plan ends.

#include "simfixture.h"

#include <gtest/gtest.h>

using namespace frezka;
using namespace frezka::driver;
using namespace frezka::driver::test;
using protocol::Variant;

namespace {

// Rewrites occurrence `nth` (0-based, counted over everything the PC writes) of `from` into
// `to`. `to` must hold the same bytes in another order (or the same sum), so that the line's
// checksum still matches: the damage the protocol cannot detect.
std::function<std::string(std::string_view)> damage(std::string from, std::string to, int nth)
{
    auto seen = std::make_shared<int>(0);
    return [from, to, nth, seen](std::string_view bytes) {
        std::string s(bytes);
        for (std::size_t at = s.find(from); at != std::string::npos; at = s.find(from, at + 1)) {
            if ((*seen)++ == nth) {
                s.replace(at, from.size(), to);
                break;
            }
        }
        return s;
    };
}

int byteSum(const std::string &s)
{
    int sum = 0;
    for (unsigned char c : s)
        sum += c;
    return sum % 256;
}

bool finishedAt(Sim &sim, const machine::Steps4 &end)
{
    const auto pos = sim.port.unit().position();
    return pos[0] == end[0] && pos[1] == end[1] && pos[2] == end[2];
}

} // namespace

// A vector turned into another by a dropped and a doubled '0' (same checksum) while the job runs
// slower than the wire (polled at 20 Hz): the job stops on the first poll off the path and holds
// with the reason; resuming returns to the path and the job ends exactly.
TEST(PathGuard, DamagedVectorHoldsTheJobAndResumeEndsExact)
{
    const std::string from = "!0C400,133,-1,", to = "!0C40,1330,-1,";
    ASSERT_EQ(byteSum(from), byteSum(to));
    Sim sim;
    ASSERT_TRUE(sim.connect());
    sim.port.tamper = damage(from, to, 100);
    const auto program = slowProgram(300);
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil(
        [&] { return sim.core.state().mode == MachineMode::Paused || !sim.finished.empty(); }, 600))
        << sim.lastLog();
    ASSERT_EQ(sim.core.state().hold, HoldReason::PathFault) << sim.lastLog();
    EXPECT_TRUE(sim.finished.empty());
    ASSERT_TRUE(sim.core.state().lastError.has_value());
    EXPECT_NE(sim.core.state().lastError->message.find("left the planned path"), std::string::npos)
        << sim.core.state().lastError->message;
    EXPECT_EQ(sim.core.jobReport().pathFaults, 1);

    // Held: the machine stands, and nothing is sent to move it.
    const auto stopped = sim.port.unit().position();
    sim.runner.runFor(2.0);
    EXPECT_EQ(sim.port.unit().position(), stopped);

    ASSERT_FALSE(sim.core.resume(sim.runner.now())) << sim.lastLog();
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front()) << sim.lastLog();
    EXPECT_TRUE(finishedAt(sim, program.commands.back().endSteps)) << sim.lastLog();
    const JobReport &r = sim.core.jobReport();
    EXPECT_EQ(r.pathFaults, 1);
    EXPECT_GT(r.returnMoves, 0);
    EXPECT_EQ(r.vectors, 300) << "each program vector counted once";
    EXPECT_GT(r.rerun, 0);
    // Every vector ran once, and the few between the last verified point and the stop (the
    // damaged one among them) once more after the return: the poll caught it at once.
    const std::int64_t again = sim.port.unit().stats().motion.vectorsExecuted - 300 - r.returnMoves;
    EXPECT_GE(again, 0);
    EXPECT_LE(again, 5) << "the return goes to the last verified point, not the start";
}

// The same damage on a dense job that runs faster than the wire (polls are rare there), with
// the automatic return: the job ends exactly without the operator.
TEST(PathGuard, AutomaticReturnOnADenseJob)
{
    const std::string from = "!0C60,20,0,", to = "!0C6,200,0,";
    ASSERT_EQ(byteSum(from), byteSum(to));
    CoreOptions options;
    options.returnToPathAutomatically = true;
    Sim sim(Variant::Gve64, {}, options);
    ASSERT_TRUE(sim.connect());
    sim.port.tamper = damage(from, to, 40);
    const auto program = denseProgram(1500);
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front()) << sim.lastLog();
    EXPECT_TRUE(finishedAt(sim, program.commands.back().endSteps)) << sim.lastLog();
    EXPECT_EQ(sim.core.jobReport().pathFaults, 1) << sim.lastLog();
    EXPECT_EQ(sim.core.jobReport().vectors, 1500);
    EXPECT_TRUE(sim.errors.empty()) << sim.lastLog();
}

// A damage of one step (within the unit's interpolation, invisible to the polls) shows where
// the machine stands: at the end of the job the counters must equal the plan exactly.
TEST(PathGuard, OneStepOffIsCaughtWhereTheMachineStands)
{
    // '0' -> '1' and '1' -> '0': "-0" reads as 0, so X is one step longer and Z one step short.
    const std::string from = "!0C60,20,-1,", to = "!0C61,20,-0,";
    ASSERT_EQ(byteSum(from), byteSum(to));
    CoreOptions options;
    options.returnToPathAutomatically = true;
    Sim sim(Variant::Gve64, {}, options);
    ASSERT_TRUE(sim.connect());
    sim.port.tamper = damage(from, to, 0);
    const auto program = denseProgram(300);
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front()) << sim.lastLog();
    EXPECT_TRUE(finishedAt(sim, program.commands.back().endSteps)) << sim.lastLog();
    EXPECT_EQ(sim.core.jobReport().pathFaults, 1) << sim.lastLog();
}

// Without damage the guard never fires: a clean job, a noisy one, and one paused and resumed.
TEST(PathGuard, QuietOnCleanAndNoisyJobs)
{
    for (std::uint32_t seed = 1; seed <= 4; ++seed) {
        WireOptions wire;
        wire.latencyS = 0.004;
        wire.byteErrorRate = seed == 1 ? 0 : 1e-3;
        wire.replyLossRate = seed == 1 ? 0 : 1e-3;
        wire.seed = seed;
        Sim sim(Variant::Gve64, wire);
        ASSERT_TRUE(sim.connect(120));
        const auto program = slowProgram(120);
        ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
        ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 900))
            << "seed " << seed << "\n"
            << sim.lastLog();
        EXPECT_TRUE(sim.finished.front());
        EXPECT_EQ(sim.core.jobReport().pathFaults, 0) << "seed " << seed << "\n" << sim.lastLog();
        EXPECT_GT(sim.core.jobReport().polls, 100) << "the guard had polls to check";
    }
}
