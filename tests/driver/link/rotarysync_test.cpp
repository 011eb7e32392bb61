// A rotary table on its own GVE114 on the machine's line (machine/rotarysplit.h,
// driver/link/synchold.h, driver/link/linesync.h): one 4-axis program split into the machine's
// X Y Z and the rotary unit's A, run on two emulated units sharing one wire. Checked on the
// emulator's side (its motion trace: every motion event of each unit): both units end at
// exact counters; no motion of one unit overlaps a block of the other except the block that
// moves X Y Z and A together, which starts on both within one exchange and ends within the
// bound of docs/architecture.md; the wire shows H and G to the right unit at each sync point.

#include "simfixture.h"

#include "driver/link/linerunner.h"
#include "driver/link/linesync.h"
#include "driver/link/sharedline.h"
#include "gcode/interpreter.h"
#include "machine/planner.h"
#include "machine/rotarysplit.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

namespace frezka::driver::test {
namespace {

using protocol::Variant;

// XYZ-only blocks, A-only indexing, one block that moves X Y Z and A together, more XYZ.
constexpr const char *kProgram = "G21 G90 G94\n"
                                 "G1 X10 Y10 F3000\n"
                                 "G1 X40 Y10 Z-2 F1200\n"
                                 "G1 X40 Y40\n"
                                 "G0 A90\n"
                                 "G1 X10 Y40 F1200\n"
                                 "G1 X10 Y10\n"
                                 "G1 X30 Y20 Z-4 A180 F600\n"
                                 "G1 X50 Y20\n"
                                 "G0 A45\n"
                                 "G0 A0\n"
                                 "G0 X0 Y0 Z0\n"
                                 "M2\n";
constexpr std::uint32_t kJointLine = 8; // G1 X30 Y20 Z-4 A180

machine::MachineConfig rotaryConfig()
{
    machine::MachineConfig c = machine::defaultMachineConfig(Variant::Gve114);
    c.axes[3].present = true;
    c.axes[3].stepsPerMm = 100; // steps per degree
    c.axes[3].softMinMm = 0;
    c.axes[3].softMaxMm = 360;
    c.unit.address = 1;
    return c;
}

CoreOptions optionsFor(int address)
{
    CoreOptions o;
    o.link.sharedLine = true;
    o.link.unitAddress = address;
    return o;
}

struct Interval
{
    double startS = 0, endS = 0;
    std::array<std::int64_t, 4> from{}, to{};
};

// When the unit moved, from its motion trace (a point at every motion event): spans between
// points whose positions differ or between which the unit had speed (inside its last step the
// counters stay while it still brakes), merged where they touch.
std::vector<Interval> movements(const std::vector<emulator::TracePoint> &trace)
{
    std::vector<Interval> out;
    for (std::size_t i = 1; i < trace.size(); ++i) {
        const auto &p = trace[i - 1], &q = trace[i];
        if (p.position == q.position && p.pathSpeedPulsesPerS <= 0)
            continue;
        std::array<std::int64_t, 4> from{}, to{};
        std::copy_n(p.position.begin(), 4, from.begin());
        std::copy_n(q.position.begin(), 4, to.begin());
        if (!out.empty() && out.back().endS >= p.timeS - 1e-12 && out.back().to == from) {
            out.back().endS = q.timeS;
            out.back().to = to;
        } else {
            out.push_back({p.timeS, q.timeS, from, to});
        }
    }
    return out;
}

struct RotaryLine
{
    RotaryLine()
        : machineConfig(machine::defaultMachineConfig(Variant::Gve114))
        , rotary(rotaryConfig())
        , port(units(), {})
        , core0(machineConfig, optionsFor(0))
        , core1(rotary, optionsFor(1))
        , line({&core0, &core1})
        , sync({&core0, &core1})
        , runner(line, port)
    {
        port.tamper = [this](std::string_view bytes) {
            m_pending += bytes;
            for (std::size_t cr; (cr = m_pending.find('\r')) != std::string::npos;) {
                std::string l = m_pending.substr(0, cr);
                m_pending.erase(0, cr + 1);
                const auto comma = l.rfind(',');
                if (comma != std::string::npos && comma + 3 == l.size())
                    l.resize(comma); // the checksum
                wire.push_back(l);
            }
            return std::string(bytes);
        };
        for (MachineCore *core : {&core0, &core1})
            core->onError = [this](const MachineError &e) { errors.push_back(e.message); };
        core0.onJobFinished = [this](bool ok) { done0 = ok ? 1 : 0; };
        core1.onJobFinished = [this](bool ok) { done1 = ok ? 1 : 0; };
    }
    std::vector<emulator::UnitOptions> units() const
    {
        emulator::UnitOptions a = unitOptionsFor(machineConfig);
        emulator::UnitOptions b = unitOptionsFor(rotary);
        b.address = 1;
        b.spindleAddress = false;
        a.trace = b.trace = true;
        return {a, b};
    }
    bool run(const machine::RotarySplit &split)
    {
        runner.open();
        if (!runner.runUntil(
                [this] {
                    return core0.state().mode == MachineMode::Idle &&
                           core1.state().mode == MachineMode::Idle;
                },
                60))
            return false;
        if (core0.runSynced(split.machine, runner.now()) ||
            core1.runSynced(split.rotary, runner.now()))
            return false;
        runner.runUntil([this] { return done0 >= 0 && done1 >= 0; }, 600);
        return done0 == 1 && done1 == 1;
    }

    machine::MachineConfig machineConfig;
    machine::MachineConfig rotary;
    EmulatorPort port;
    MachineCore core0;
    MachineCore core1;
    SharedLine line;
    LineSync sync;
    LineRunner runner;
    std::vector<std::string> wire;
    std::vector<std::string> errors;
    int done0 = -1, done1 = -1;

private:
    std::string m_pending;
};

machine::RotarySplit splitProgram(const machine::MachineConfig &machineConfig,
                                  const machine::MachineConfig &rotary, const char *text = kProgram)
{
    machine::PlanOptions options;
    options.restAroundA = true;
    const auto toolpath = gcode::interpretText(text).toolpath;
    const auto plan = machine::plan(toolpath, machine::withRotaryA(machineConfig, rotary), options);
    EXPECT_TRUE(plan.ok()) << (plan.errors.empty() ? "" : plan.errors.front().message);
    return machine::splitRotaryA(plan.program);
}

std::int64_t vectorsOf(const machine::UnitProgram &p)
{
    return std::count_if(p.commands.begin(), p.commands.end(),
                         [](const auto &c) { return c.op == machine::UnitOp::Vector; });
}

std::int64_t count(const std::vector<std::string> &wire, const std::string &line)
{
    return std::count(wire.begin(), wire.end(), line);
}

std::int64_t heldCount(const machine::SyncedProgram &p)
{
    return std::count_if(p.syncs.begin(), p.syncs.end(), [](const auto &s) { return s.held; });
}

// The trapezoid's time (§4.2) of a unit's vector from `line` that runs from rest to rest:
// cruise reached, or a triangle.
double partTimeS(const machine::UnitProgram &p, std::uint32_t line)
{
    std::int64_t accel = 0, speed = 0;
    for (const auto &c : p.commands) {
        if (c.op == machine::UnitOp::Accel)
            accel = c.value;
        if (c.op == machine::UnitOp::Speed)
            speed = c.value;
        if (c.op != machine::UnitOp::Vector || c.sourceLine != line)
            continue;
        double d = 0;
        for (auto v : c.d)
            d = std::max(d, std::abs(double(v)));
        const double a = 1000.0 * double(accel), v = double(speed);
        return d >= v * v / a ? d / v + v / a : 2 * std::sqrt(d / a);
    }
    return -1;
}

} // namespace

TEST(RotarySync, SplitGivesEachUnitItsAxesAndOneSyncPointPerBlock)
{
    const auto split = splitProgram(machine::defaultMachineConfig(Variant::Gve114), rotaryConfig());
    ASSERT_TRUE(split.ok()) << split.error;
    EXPECT_EQ(split.blocks, 4u); // A90, the joint block, A45, A0
    EXPECT_EQ(split.machine.syncs.size(), split.rotary.syncs.size());
    for (const auto &c : split.machine.program.commands)
        EXPECT_EQ(c.d[3], 0);
    for (const auto &c : split.rotary.program.commands)
        EXPECT_TRUE(c.d[0] == 0 && c.d[1] == 0 && c.d[2] == 0);
    EXPECT_EQ(heldCount(split.rotary), 4);
    EXPECT_EQ(heldCount(split.machine), 1); // only the joint block moves the machine
    EXPECT_EQ(split.rotary.program.commands.back().endSteps[3], 0);
    EXPECT_EQ(vectorsOf(split.rotary.program), 4);
    // Planned without a rest around each A move, A's vectors flow with the others: refused.
    const auto flowing = machine::plan(
        gcode::interpretText(kProgram).toolpath,
        machine::withRotaryA(machine::defaultMachineConfig(Variant::Gve114), rotaryConfig()));
    ASSERT_TRUE(flowing.ok());
    const auto refused = machine::splitRotaryA(flowing.program);
    EXPECT_FALSE(refused.ok());
    EXPECT_NE(refused.error.find("restAroundA"), std::string::npos) << refused.error;
}

// Without A motion the machine's unit gets the program as planned, with no sync point: chains
// that do not touch A run as they would on the machine alone.
TEST(RotarySync, AProgramWithoutAIsTheMachinesAlone)
{
    const auto machineConfig = machine::defaultMachineConfig(Variant::Gve114);
    machine::PlanOptions options;
    options.restAroundA = true;
    const auto toolpath =
        gcode::interpretText("G21 G90\nG1 X10 Y10 F3000\nG1 X40 Y10 Z-2 F1200\nG0 X0 Y0 Z0\nM2\n")
            .toolpath;
    const auto plan =
        machine::plan(toolpath, machine::withRotaryA(machineConfig, rotaryConfig()), options);
    ASSERT_TRUE(plan.ok());
    const auto split = machine::splitRotaryA(plan.program);
    ASSERT_TRUE(split.ok());
    EXPECT_EQ(split.blocks, 0u);
    EXPECT_TRUE(split.machine.syncs.empty());
    EXPECT_TRUE(split.rotary.syncs.empty());
    EXPECT_EQ(split.machine.program, plan.program);
    EXPECT_EQ(vectorsOf(split.rotary.program), 0);
    // The option changes nothing where A does not move.
    EXPECT_EQ(plan.program,
              machine::plan(toolpath, machine::withRotaryA(machineConfig, rotaryConfig())).program);
}

TEST(RotarySync, RotaryTableOnItsOwnUnitRunsInStepWithTheMachine)
{
    RotaryLine t;
    const auto split = splitProgram(t.machineConfig, t.rotary);
    ASSERT_TRUE(split.ok()) << split.error;
    ASSERT_TRUE(t.run(split)) << (t.errors.empty() ? "" : t.errors.front());
    EXPECT_TRUE(t.errors.empty()) << t.errors.front();

    // Exact counters and vector counts on both units, no brake violation, no starvation.
    const emulator::Unit &u0 = t.port.simulation().unit(0);
    const emulator::Unit &u1 = t.port.simulation().unit(1);
    const auto e0 = split.machine.program.commands.back().endSteps;
    const auto e1 = split.rotary.program.commands.back().endSteps;
    EXPECT_EQ(u0.position(), (std::array<std::int64_t, 4>{e0[0], e0[1], e0[2], e0[3]}));
    EXPECT_EQ(u1.position(), (std::array<std::int64_t, 4>{e1[0], e1[1], e1[2], e1[3]}));
    EXPECT_EQ(u0.position(), (std::array<std::int64_t, 4>{0, 0, 0, 0}));
    EXPECT_EQ(u0.stats().motion.vectorsExecuted, vectorsOf(split.machine.program));
    EXPECT_EQ(u1.stats().motion.vectorsExecuted, vectorsOf(split.rotary.program));
    EXPECT_EQ(u0.stats().motion.brakeViolations + u1.stats().motion.brakeViolations, 0);
    // A C after a planned rest counts as a restart from a dry queue: none but those.
    EXPECT_EQ(u0.stats().motion.starvationStops, machine::plannedRestarts(split.machine.program));
    EXPECT_EQ(u1.stats().motion.starvationStops, machine::plannedRestarts(split.rotary.program));
    EXPECT_EQ(t.sync.stats().released, static_cast<std::int64_t>(split.machine.syncs.size()));

    // The rotary unit moved in 4 blocks; the machine's motion overlaps only its joint one.
    const auto m = movements(u0.trace());
    const auto r = movements(u1.trace());
    EXPECT_EQ(r.size(), 4u);
    const auto isJoint = [](const Interval &b) { return b.from[3] == 9000 && b.to[3] == 18000; };
    EXPECT_EQ(std::count_if(r.begin(), r.end(), isJoint), 1);
    int overlapping = 0;
    for (const Interval &a : m) {
        for (const Interval &b : r) {
            if (a.endS <= b.startS || b.endS <= a.startS)
                continue;
            ++overlapping;
            EXPECT_TRUE(isJoint(b)) << "machine " << a.startS << ".." << a.endS << " overlaps A "
                                    << b.startS << ".." << b.endS;
            // The joint block starts on both within one exchange (!1G and its reply and the
            // line's quiet time: under 3 ms at 115 200 Bd) and ends within the bound: the
            // difference of the two parts' trapezoid times plus that start skew.
            const double skew = std::abs(a.startS - b.startS);
            const double exchangeS = (7 + 5) * 10.0 / 115200 + SharedLineOptions{}.quietS;
            EXPECT_LE(skew, exchangeS + 1e-6); // "!1G,HH" CR and "0,HH" CR, then quiet
            const double tm = partTimeS(split.machine.program, kJointLine);
            const double tr = partTimeS(split.rotary.program, kJointLine);
            ASSERT_GT(tm, 0);
            ASSERT_GT(tr, 0);
            EXPECT_LE(std::abs(a.endS - b.endS), skew + std::abs(tm - tr) + 1e-3)
                << "machine " << a.startS << ".." << a.endS << " (model " << tm << " s), A "
                << b.startS << ".." << b.endS << " (model " << tr << " s)";
            // The parts' times differ only by the rounding of the scaled A and V.
            EXPECT_LT(std::abs(tm - tr), 0.02 * std::max(tm, tr));
        }
    }
    EXPECT_EQ(overlapping, 1);

    // H and G to each unit at each of its held sync points, and nothing else sends them here.
    EXPECT_EQ(count(t.wire, "!0H"), heldCount(split.machine));
    EXPECT_EQ(count(t.wire, "!1H"), heldCount(split.rotary));
    EXPECT_EQ(count(t.wire, "!0G"), heldCount(split.machine));
    EXPECT_EQ(count(t.wire, "!1G"), heldCount(split.rotary));
    // Per unit, every H is followed by its G before the next H: held, then started.
    for (const std::string address : {"!0", "!1"}) {
        std::string seen;
        for (const std::string &l : t.wire)
            if (l == address + "H" || l == address + "G")
                seen += l.back();
        std::string expected;
        for (std::size_t i = 0; i < seen.size() / 2; ++i)
            expected += "HG";
        EXPECT_EQ(seen, expected) << address;
    }
    // The joint block's two G's follow each other on the line.
    const auto g0 = std::find(t.wire.begin(), t.wire.end(), "!0G");
    ASSERT_NE(g0, t.wire.end());
    EXPECT_TRUE((g0 + 1 != t.wire.end() && g0[1] == "!1G") ||
                (g0 != t.wire.begin() && g0[-1] == "!1G"));
}

} // namespace frezka::driver::test

namespace frezka::driver::test {

// A helix that turns A runs chord by chord, each chord a block of its own (the parts of two
// chords have different speed ratios: as one chain, the machine's unit entered the next chord
// faster than its part was planned for and arrived too fast, two brake violations): both units
// end at exact counters without a brake violation.
TEST(RotarySync, AHelixThatTurnsARunsChordByChord)
{
    RotaryLine t;
    const auto split = splitProgram(t.machineConfig, t.rotary,
                                    "G21 G90 G94\nG1 X30 Y30 F3000\n"
                                    "G2 X50 Y30 I10 J0 Z-3 A120 F900\nG1 X60 Y30\nM2\n");
    ASSERT_TRUE(split.ok()) << split.error;
    EXPECT_GT(vectorsOf(split.rotary.program), 5);
    EXPECT_EQ(split.blocks, static_cast<std::size_t>(vectorsOf(split.rotary.program)));
    ASSERT_TRUE(t.run(split)) << (t.errors.empty() ? "" : t.errors.front());
    const emulator::Unit &u0 = t.port.simulation().unit(0);
    const emulator::Unit &u1 = t.port.simulation().unit(1);
    const auto e0 = split.machine.program.commands.back().endSteps;
    EXPECT_EQ(u0.position(), (std::array<std::int64_t, 4>{e0[0], e0[1], e0[2], 0}));
    EXPECT_EQ(u1.position(), (std::array<std::int64_t, 4>{0, 0, 0, 12000}));
    EXPECT_EQ(u0.stats().motion.brakeViolations, 0);
    EXPECT_EQ(u1.stats().motion.brakeViolations, 0);
}

} // namespace frezka::driver::test
