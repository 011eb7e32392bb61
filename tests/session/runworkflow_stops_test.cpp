// The operator's stops and starts in RunWorkflow (issue 14 item 3, 4), headless on the
// in-process emulator (SimLink): Stop is H along the ramp and the job resumes to its exact end,
// Abort drops the queue, the machine's START button starts and resumes, and a run before
// homing asks for homing first. Asserted on the wire (what the driver sent) and on the unit.
#include "../driver/link/wiretap.h"

#include "session/runworkflow.h"
#include "session/simlink.h"

#include "gcode/interpreter.h"
#include "machine/planner.h"

#include <gtest/gtest.h>

#include <memory>

namespace frezka::session {
namespace {

using driver::MachineMode;
using driver::test::WireTap;

std::shared_ptr<const machine::UnitProgram> planOf(const char *text,
                                                   const machine::MachineConfig &config)
{
    const gcode::Result g = gcode::interpretText(text, {});
    EXPECT_TRUE(g.ok());
    machine::PlanResult p = machine::plan(g.toolpath, config);
    EXPECT_TRUE(p.ok());
    return std::make_shared<machine::UnitProgram>(std::move(p.program));
}

const char *kSlow = "G21 G90\nG1 Z-10 F600\nG1 X60 F300\nG1 Y20\nM2\n";

struct Bench
{
    explicit Bench(machine::MachineConfig c)
        : config(c)
        , link(config, driver::unitOptionsFor(config), driver::WireOptions{}, driver::CoreOptions{})
        , workflow(link)
        , wire(link.port())
    {
        workflow.setProfile(config);
        QObject::connect(&workflow, &RunWorkflow::homingNeeded, [this] { ++homingAsked; });
        QObject::connect(&workflow, &RunWorkflow::jobFinished,
                         [this](bool ok) { jobs.push_back(ok); });
    }
    bool until(MachineMode mode, double limitS = 60)
    {
        return link.runUntil([&] { return link.state().mode == mode; }, limitS);
    }
    bool connect()
    {
        workflow.connectToUnit(RunWorkflow::connectionFor(config));
        return until(MachineMode::Idle);
    }
    bool home()
    {
        link.home(0xF);
        return link.runUntil([&] { return link.state().homed; }, 600) && until(MachineMode::Idle);
    }
    // The unit's own counters at the program's end, and every vector of it run exactly once.
    void expectExactEnd(const machine::UnitProgram &plan, std::int64_t extraVectors = 0)
    {
        const auto end = plan.commands.back().endSteps;
        const auto unit = link.port().unit().position();
        for (std::size_t a = 0; a < 3; ++a)
            EXPECT_EQ(unit[a], end[a]) << "axis " << a;
        std::int64_t planned = 0;
        for (const machine::UnitCommand &c : plan.commands)
            planned += c.op == machine::UnitOp::Vector || c.op == machine::UnitOp::Line ? 1 : 0;
        EXPECT_EQ(link.port().unit().stats().motion.vectorsExecuted - vectorsBefore,
                  planned + extraVectors);
    }
    machine::MachineConfig config;
    SimLink link;
    RunWorkflow workflow;
    WireTap wire;
    int homingAsked = 0;
    std::vector<bool> jobs;
    std::int64_t vectorsBefore = 0;
};

machine::MachineConfig gve64()
{
    return machine::defaultMachineConfig(protocol::Variant::Gve64);
}

TEST(RunWorkflowStops, StopIsAControlledHaltAndTheJobResumesToItsExactEnd)
{
    Bench b(gve64());
    ASSERT_TRUE(b.connect());
    ASSERT_TRUE(b.home());
    const auto plan = planOf(kSlow, b.config);
    b.workflow.setProgram(plan, {}, QStringLiteral("slow.nc"));
    b.vectorsBefore = b.link.port().unit().stats().motion.vectorsExecuted;
    b.workflow.runProgram();
    ASSERT_TRUE(b.until(MachineMode::Running));
    b.link.runFor(4);
    const auto from = b.wire.size();
    b.workflow.stop();
    ASSERT_TRUE(b.until(MachineMode::Paused));
    EXPECT_EQ(b.wire.matching("!0H", from).size(), 1u) << "Stop sends H";
    EXPECT_TRUE(b.wire.matching("!0D", from).empty()) << "Stop keeps the queue";
    EXPECT_EQ(b.link.state().hold, driver::HoldReason::User);
    // The unit stands where the state says.
    b.link.runFor(2);
    EXPECT_FALSE(b.link.port().unit().isMoving());
    EXPECT_EQ(b.link.state().positionSteps[0], b.link.port().unit().position()[0]);
    b.workflow.resume();
    ASSERT_TRUE(b.link.runUntil([&] { return !b.jobs.empty(); }, 600));
    EXPECT_TRUE(b.jobs.front());
    b.expectExactEnd(*plan);
    EXPECT_EQ(b.link.port().unit().stats().motion.brakeViolations, 0);
}

// Stop with the spindle turning: H, then !7V0 once the machine stands (the unit's spindle off
// while held); resume switches it on again before G, and the job ends exactly.
TEST(RunWorkflowStops, StopSwitchesTheSpindleOffAndResumeBackOnBeforeMotion)
{
    Bench b(gve64());
    ASSERT_TRUE(b.connect());
    ASSERT_TRUE(b.home());
    const auto plan =
        planOf("G21 G90\nM3 S12000\nG1 Z-10 F600\nG1 X60 F300\nG1 Y20\nM5\nM2\n", b.config);
    b.workflow.setProgram(plan, {}, QStringLiteral("spindle.nc"));
    b.workflow.runProgram();
    ASSERT_TRUE(b.until(MachineMode::Running));
    b.link.runFor(6);
    ASSERT_GT(b.link.port().unit().spindlePermille(), 0) << "the program's M3 runs the spindle";
    const auto from = b.wire.size();
    b.workflow.stop();
    ASSERT_TRUE(b.until(MachineMode::Paused));
    b.link.runFor(1);
    EXPECT_EQ(b.wire.matching("!0H", from).size(), 1u);
    EXPECT_EQ(b.wire.matching("!7V0", from).size(), 1u) << "Stop switches the spindle off";
    EXPECT_EQ(b.link.port().unit().spindlePermille(), 0);
    const auto resumed = b.wire.size();
    b.workflow.resume();
    ASSERT_TRUE(b.link.runUntil([&] { return !b.jobs.empty(); }, 600));
    EXPECT_TRUE(b.jobs.front());
    const auto on = b.wire.matching("!7V", resumed);
    ASSERT_FALSE(on.empty()) << "resume switches the spindle on again";
    EXPECT_NE(on.front(), "!7V0");
    b.expectExactEnd(*plan);
}

TEST(RunWorkflowStops, AbortDropsTheQueue)
{
    Bench b(gve64());
    ASSERT_TRUE(b.connect());
    ASSERT_TRUE(b.home());
    b.workflow.setProgram(planOf(kSlow, b.config), {}, QStringLiteral("slow.nc"));
    b.workflow.runProgram();
    ASSERT_TRUE(b.until(MachineMode::Running));
    b.link.runFor(4);
    const auto from = b.wire.size();
    b.workflow.abort();
    ASSERT_TRUE(b.until(MachineMode::Idle));
    EXPECT_EQ(b.wire.matching("!0H", from).size(), 1u);
    EXPECT_EQ(b.wire.matching("!0D", from).size(), 1u);
    EXPECT_EQ(b.link.port().unit().queueLength(), 0u);
    EXPECT_FALSE(b.link.state().jobActive);
}

TEST(RunWorkflowStops, StopEndsHomingAndTheAxesStayNotHomed)
{
    Bench b(gve64());
    ASSERT_TRUE(b.connect());
    b.link.home(0xF);
    ASSERT_TRUE(b.until(MachineMode::Homing));
    b.link.runFor(0.3);
    const auto from = b.wire.size();
    b.workflow.stop();
    ASSERT_TRUE(b.until(MachineMode::Idle, 5));
    EXPECT_FALSE(b.link.state().homed);
    EXPECT_LE(b.wire.matching("!0W", from).size(), 1u) << "no leg after the one running";
    b.link.runFor(2);
    EXPECT_FALSE(b.link.port().unit().isMoving());
}

TEST(RunWorkflowStops, ARunBeforeHomingAsksForHomingFirst)
{
    Bench b(gve64());
    ASSERT_TRUE(b.connect());
    const auto plan = planOf(kSlow, b.config);
    b.workflow.setProgram(plan, {}, QStringLiteral("slow.nc"));
    const auto from = b.wire.size();
    b.workflow.runProgram();
    b.link.runFor(1);
    EXPECT_EQ(b.homingAsked, 1);
    EXPECT_TRUE(b.wire.matching("!0*S", from).empty() && b.wire.matching("!0C", from).empty())
        << "nothing of the job was sent";
    EXPECT_EQ(b.link.state().mode, MachineMode::Idle);
    b.vectorsBefore = b.link.port().unit().stats().motion.vectorsExecuted;
    b.workflow.homeThenRun();
    ASSERT_TRUE(b.link.runUntil([&] { return !b.jobs.empty(); }, 600));
    EXPECT_TRUE(b.link.state().homed);
    EXPECT_FALSE(b.wire.matching("!0W", from).empty());
    b.expectExactEnd(*plan);
}

TEST(RunWorkflowStops, TheProfileMayAllowARunBeforeHomingWithAWarning)
{
    machine::MachineConfig c = gve64();
    c.motion.runBeforeHoming = true;
    Bench b(c);
    QStringList said;
    QObject::connect(&b.workflow, &RunWorkflow::message, [&](const QString &m) { said << m; });
    ASSERT_TRUE(b.connect());
    b.workflow.setProgram(planOf(kSlow, b.config), {}, QStringLiteral("slow.nc"));
    b.workflow.runProgram();
    ASSERT_TRUE(b.link.runUntil([&] { return !b.jobs.empty(); }, 600));
    EXPECT_EQ(b.homingAsked, 0);
    EXPECT_TRUE(said.join(QLatin1Char('|')).contains(QStringLiteral("not homed")));
}

TEST(RunWorkflowStops, TheStartButtonRunsAndResumes)
{
    machine::MachineConfig c = gve64();
    c.unit.startInput = 3; // GVE64 IN3, active low (eeprom.polarity bit 3 = 0)
    Bench b(c);
    auto &unit = b.link.port().unit();
    unit.setInput(3, true); // released: the input pulled up
    ASSERT_TRUE(b.connect());
    ASSERT_TRUE(b.home());
    const auto plan = planOf(kSlow, b.config);
    b.workflow.setProgram(plan, {}, QStringLiteral("slow.nc"));
    b.vectorsBefore = unit.stats().motion.vectorsExecuted;
    b.link.runFor(1);
    EXPECT_EQ(b.link.state().mode, MachineMode::Idle) << "nothing starts by itself";
    unit.setInput(3, false); // pressed
    ASSERT_TRUE(b.until(MachineMode::Running, 2)) << "START runs the loaded program";
    unit.setInput(3, true);
    b.link.runFor(3);
    b.workflow.stop();
    ASSERT_TRUE(b.until(MachineMode::Paused));
    b.link.runFor(1);
    unit.setInput(3, false); // pressed again: resume
    ASSERT_TRUE(b.until(MachineMode::Running, 2)) << "START resumes the held job";
    unit.setInput(3, true);
    ASSERT_TRUE(b.link.runUntil([&] { return !b.jobs.empty(); }, 600));
    EXPECT_TRUE(b.jobs.front());
    b.expectExactEnd(*plan);
}

TEST(RunWorkflowStops, WithoutAStartButtonTheInputDoesNothing)
{
    Bench b(gve64()); // unit.startInput 0
    auto &unit = b.link.port().unit();
    unit.setInput(3, true);
    ASSERT_TRUE(b.connect());
    ASSERT_TRUE(b.home());
    b.workflow.setProgram(planOf(kSlow, b.config), {}, QStringLiteral("slow.nc"));
    unit.setInput(3, false);
    b.link.runFor(2);
    EXPECT_EQ(b.link.state().mode, MachineMode::Idle);
    EXPECT_TRUE(b.jobs.empty());
}

} // namespace
} // namespace frezka::session
