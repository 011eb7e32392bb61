// RunWorkflow headless, on the in-process emulator and a virtual clock (SimLink): the sequence
// frezka-cli run drives (connect, home, run to the end), a hold ending a run nobody attends,
// pause / tool lift / "lower and continue", planning again from where the machine is, and a
// run refused while not connected. The GUI drives the same class (tests/gui/workflow_test).
#include "session/consolesession.h"
#include "session/runworkflow.h"
#include "session/simlink.h"
#include "session/workoffsets.h"

#include "gcode/interpreter.h"
#include "machine/planner.h"
#include "machine/steps.h"

#include <QCoreApplication>

#include <gtest/gtest.h>

#include <cmath>
#include <memory>
#include <optional>

namespace frezka::session {
namespace {

using driver::MachineMode;

std::shared_ptr<const machine::UnitProgram> planOf(const char *text,
                                                   const machine::MachineConfig &config,
                                                   const RunWorkflow::Position &start = {})
{
    gcode::Options options;
    options.startMm = {start[0], start[1], start[2], start[3]};
    const gcode::Result g = gcode::interpretText(text, options);
    EXPECT_TRUE(g.ok());
    machine::PlanResult p = machine::plan(g.toolpath, config);
    EXPECT_TRUE(p.ok());
    return std::make_shared<machine::UnitProgram>(std::move(p.program));
}

struct Headless
{
    explicit Headless(
        machine::MachineConfig c = machine::defaultMachineConfig(protocol::Variant::Gve64))
        : config(c)
        , link(config, driver::unitOptionsFor(config), driver::WireOptions{}, driver::CoreOptions{})
        , workflow(link)
    {
        workflow.setProfile(config);
        QObject::connect(&workflow, &RunWorkflow::runEnded, [this](bool ok) { ended = ok; });
        QObject::connect(&workflow, &RunWorkflow::failed,
                         [this](const QString &why) { failures << why; });
        QObject::connect(&workflow, &RunWorkflow::jobFinished,
                         [this](bool ok) { jobs.push_back(ok); });
    }
    bool runToEnd(double limitS = 3600)
    {
        return link.runUntil([this] { return workflow.hasEnded(); }, limitS);
    }
    bool until(MachineMode mode, double limitS = 60)
    {
        return link.runUntil([&] { return link.state().mode == mode; }, limitS);
    }
    machine::MachineConfig config;
    SimLink link;
    RunWorkflow workflow;
    std::optional<bool> ended;
    QStringList failures;
    std::vector<bool> jobs;
};

const char *kSquare = "G21 G90\nG0 X10 Y10\nG1 Z-2 F600\nG1 X30 F2400\nG1 Y25\nG1 X10\n"
                      "G1 Y10\nG0 Z-1\nM2\n";

TEST(RunWorkflow, ConnectsHomesAndRunsToTheEnd)
{
    Headless h;
    const auto plan = planOf(kSquare, h.config);
    h.workflow.setProgram(plan, {}, QStringLiteral("square.nc"));
    h.workflow.start(RunWorkflow::connectionFor(h.config), true);
    ASSERT_TRUE(h.runToEnd()) << driver::machineModeName(h.link.liveState().mode) << " "
                              << h.link.now() << " " << h.workflow.error().toStdString();
    ASSERT_TRUE(h.ended.has_value());
    EXPECT_TRUE(*h.ended) << h.workflow.error().toStdString();
    EXPECT_TRUE(h.link.state().homed);
    EXPECT_EQ(h.jobs, std::vector<bool>{true});
    EXPECT_EQ(h.link.liveState().positionSteps, plan->commands.back().endSteps);
    EXPECT_EQ(h.link.port().unit().stats().motion.brakeViolations, 0u);
}

// The workflow answers the link's events with operations from inside SimLink's predicate; what
// they queue must reach the wire before the virtual clock moves on. It waited until the next
// deadline, the reply timeout of that very command: on a clean link the job's first command
// had "no reply", every reply after it came one late, and frezka-cli run's figures showed
// starvation stops the link did not cause.
TEST(RunWorkflow, ACleanLinkWithLatencyNeedsNoResend)
{
    machine::MachineConfig config = machine::defaultMachineConfig(protocol::Variant::Gve84);
    config.link.latencyMs = 16;
    driver::WireOptions wire;
    wire.latencyS = 0.016;
    SimLink link(config, driver::unitOptionsFor(config), wire, driver::CoreOptions{});
    RunWorkflow workflow(link);
    workflow.setProfile(config);
    workflow.setProgram(planOf(kSquare, config), {}, QStringLiteral("square.nc"));
    workflow.start(RunWorkflow::connectionFor(config), false);
    ASSERT_TRUE(link.runUntil([&] { return workflow.hasEnded(); }, 600));
    EXPECT_TRUE(workflow.error().isEmpty()) << workflow.error().toStdString();
    EXPECT_EQ(link.jobReport().resent, 0);
    EXPECT_EQ(link.jobReport().recovered, 0);
}

TEST(RunWorkflow, AHoldEndsARunNobodyAttends)
{
    Headless h;
    h.workflow.setEndOnHold(true);
    h.workflow.setProgram(planOf("G21 G90\nG1 X5 F600\nM0\nG1 X10\nM2\n", h.config), {},
                          QStringLiteral("stop.nc"));
    h.workflow.start(RunWorkflow::connectionFor(h.config), false);
    ASSERT_TRUE(h.runToEnd());
    EXPECT_FALSE(h.ended.value_or(true));
    EXPECT_TRUE(h.workflow.error().startsWith(QStringLiteral("the job stopped")))
        << h.workflow.error().toStdString();
    EXPECT_EQ(h.link.state().mode, MachineMode::Paused);
}

TEST(RunWorkflow, PauseLiftAndLowerAndContinueEndsTheJob)
{
    Headless h;
    const auto plan = planOf("G21 G90\nG1 Z-10 F600\nG1 X60 F300\nG1 Y20\nM2\n", h.config);
    h.workflow.setProgram(plan, {}, QStringLiteral("slow.nc"));
    h.workflow.start(RunWorkflow::connectionFor(h.config), false);
    ASSERT_TRUE(h.until(MachineMode::Running));
    h.link.runFor(4);
    h.workflow.pause();
    ASSERT_TRUE(h.until(MachineMode::Paused));
    h.workflow.toolLift(false);
    ASSERT_TRUE(h.until(MachineMode::ToolLifted));
    const double liftedZ = h.link.state().positionMm[2];
    EXPECT_NEAR(liftedZ, -10 + h.config.motion.toolLiftMm, 0.01);
    // What the unit itself did, not only what the state says: the tool stands lifted there, and
    // what was executed of the job is kept (K) for after the lower.
    const auto unitLifted = h.link.port().unit().position();
    EXPECT_EQ(unitLifted[2],
              machine::stepsOf(-10 + h.config.motion.toolLiftMm, h.config.axes[2].stepsPerMm));
    h.workflow.lowerTool(0, true); // back down, then on by itself
    ASSERT_TRUE(h.runToEnd());
    EXPECT_TRUE(h.ended.value_or(false)) << h.workflow.error().toStdString();
    EXPECT_EQ(h.link.liveState().positionSteps, plan->commands.back().endSteps);
    // The unit's own counters end exactly at the program's end, every vector ran once (plus the
    // lift and the lower) and it never stopped without its ramp.
    const auto end = plan->commands.back().endSteps;
    const auto unitEnd = h.link.port().unit().position();
    for (int a = 0; a < 3; ++a)
        EXPECT_EQ(unitEnd[static_cast<std::size_t>(a)], end[static_cast<std::size_t>(a)]);
    const auto motion = h.link.port().unit().stats().motion;
    std::int64_t planned = 0;
    for (const machine::UnitCommand &c : plan->commands)
        planned += c.op == machine::UnitOp::Vector || c.op == machine::UnitOp::Line ? 1 : 0;
    EXPECT_EQ(motion.vectorsExecuted, planned + 2);
    EXPECT_EQ(motion.brakeViolations, 0);
}

TEST(RunWorkflow, PlansAgainFromWhereTheMachineIs)
{
    Headless h;
    h.workflow.connectToUnit(RunWorkflow::connectionFor(h.config));
    ASSERT_TRUE(h.until(MachineMode::Idle));
    h.link.run(*planOf("G21 G90\nG1 X7 F600\nM2\n", h.config)); // elsewhere than the plan
    ASSERT_TRUE(h.until(MachineMode::Running));
    ASSERT_TRUE(h.until(MachineMode::Idle));
    std::vector<RunWorkflow::Position> asked;
    const char *text = "G21 G91\nG1 X5 F600\nM2\n";
    h.workflow.setReplanner([&](const RunWorkflow::Position &start) {
        asked.push_back(start);
        h.workflow.setProgram(planOf(text, h.config, start), start, QStringLiteral("rel.nc"));
    });
    h.workflow.setProgram(planOf(text, h.config), {}, QStringLiteral("rel.nc"));
    h.workflow.start(RunWorkflow::connectionFor(h.config), false); // already connected
    ASSERT_TRUE(h.runToEnd());
    EXPECT_TRUE(h.ended.value_or(false)) << h.workflow.error().toStdString();
    ASSERT_EQ(asked.size(), 1u);
    EXPECT_NEAR(asked.front()[0], 7, 1e-3);
    EXPECT_NEAR(h.link.liveState().positionMm[0], 12, 1e-3);
}

// Issue 15: a spline reaches the unit as the chords of its curve. The emulator's position on
// the way passes the parabola's apex (control point (20, 20) between (10, 10) and (30, 10):
// y = 15 at x = 20) and ends where the NURBS after it ends.
TEST(RunWorkflow, ASplineRunsOnTheUnitAlongItsCurve)
{
    Headless h;
    const auto plan = planOf("G21 G90\nG0 X10 Y10\nG1 Z-2 F600\nG5.1 X30 Y10 I10 J10 F1200\n"
                             "G5.2 X40 Y20 P1\nX30 Y30 P2\nX20 Y25 P1\nG5.3\nG0 Z-1\nM2\n",
                             h.config);
    h.workflow.setProgram(plan, {}, QStringLiteral("spline.nc"));
    h.workflow.start(RunWorkflow::connectionFor(h.config), true);
    double apex = 0, nearApex = 1e9; // highest Y before X 30, and how far X was from 20 there
    const bool ended = h.link.runUntil(
        [&] {
            const auto &p = h.link.liveState().positionMm;
            if (p[2] < -1.5 && p[0] < 29.9 && p[1] <= 15.5 && p[1] > apex &&
                std::abs(p[0] - 20) < 10) {
                apex = p[1];
                nearApex = std::abs(p[0] - 20);
            }
            return h.workflow.hasEnded();
        },
        3600);
    ASSERT_TRUE(ended) << h.workflow.error().toStdString();
    EXPECT_TRUE(h.ended.value_or(false)) << h.workflow.error().toStdString();
    EXPECT_NEAR(apex, 15, 0.05);
    EXPECT_LT(nearApex, 1.0);
    const auto &end = h.link.liveState().positionSteps;
    EXPECT_EQ(end[0], machine::stepsOf(20, h.config.axes[0].stepsPerMm));
    EXPECT_EQ(end[1], machine::stepsOf(25, h.config.axes[1].stepsPerMm));
    EXPECT_EQ(end[2], machine::stepsOf(-1, h.config.axes[2].stepsPerMm));
    EXPECT_EQ(h.link.port().unit().stats().motion.brakeViolations, 0u);
}

TEST(RunWorkflow, RefusesToRunWhenNotConnected)
{
    Headless h;
    h.workflow.setProgram(planOf(kSquare, h.config), {}, QStringLiteral("square.nc"));
    h.workflow.runProgram();
    ASSERT_EQ(h.failures.size(), 1);
    EXPECT_TRUE(h.failures.front().contains(QStringLiteral("Not connected")));
    h.workflow.setProgram(nullptr, {}, QStringLiteral("bad.nc"), QStringLiteral("bad.nc:2: Q"));
    h.workflow.runProgram();
    ASSERT_EQ(h.failures.size(), 2);
    EXPECT_TRUE(h.failures.back().contains(QStringLiteral("bad.nc:2: Q")));
}

// The reconnect timer needs an event loop: one application for the tests that use it.
void ensureApplication()
{
    static int argc = 1;
    static char name[] = "session_test";
    static char *argv[] = {name, nullptr};
    static QCoreApplication *app =
        QCoreApplication::instance() ? nullptr : new QCoreApplication(argc, argv);
    (void)app;
}

TEST(RunWorkflow, ReconnectsByItselfAfterALostLinkButNotAfterADisconnect)
{
    ensureApplication();
    Headless h;
    int lost = 0;
    QObject::connect(&h.workflow, &RunWorkflow::linkLost, [&] { ++lost; });
    h.workflow.setAutoReconnect(true, 0);
    EXPECT_FALSE(h.workflow.connectionAsked());
    h.workflow.connectToUnit(RunWorkflow::connectionFor(h.config));
    EXPECT_TRUE(h.workflow.connectionAsked()); // the window's first connect is behind it
    ASSERT_TRUE(h.until(MachineMode::Idle));
    h.link.unplug("USB adapter unplugged");
    ASSERT_TRUE(h.until(MachineMode::LinkLost));
    EXPECT_EQ(lost, 1);
    for (int i = 0; i < 100 && h.link.liveState().mode == MachineMode::LinkLost; ++i)
        QCoreApplication::processEvents(); // the reconnect timer
    ASSERT_TRUE(h.until(MachineMode::Idle)) << driver::machineModeName(h.link.liveState().mode);

    h.workflow.disconnectFromUnit();
    ASSERT_TRUE(h.until(MachineMode::Disconnected));
    for (int i = 0; i < 20; ++i)
        QCoreApplication::processEvents();
    h.link.runFor(5);
    EXPECT_EQ(h.link.liveState().mode, MachineMode::Disconnected);
    EXPECT_EQ(lost, 1);
}

TEST(RunWorkflow, ConsoleLinesMoveTheMachineInTheirModes)
{
    Headless h;
    WorkOffsets offsets;
    ConsoleSession console(h.workflow, offsets);
    QStringList failures;
    QObject::connect(&console, &ConsoleSession::failed,
                     [&](const QString &why) { failures << why; });
    h.workflow.connectToUnit(RunWorkflow::connectionFor(h.config));
    ASSERT_TRUE(h.until(MachineMode::Idle));
    auto line = [&](const char *text) {
        console.execute(QLatin1String(text));
        h.link.runUntil([&] { return h.link.liveState().mode != MachineMode::Idle; }, 1);
        ASSERT_TRUE(h.until(MachineMode::Idle)) << text;
    };
    line("G91");
    line("G1 X1 F600");
    line("G1 X1");
    EXPECT_NEAR(h.link.state().positionMm[0], 2.0, 1e-9);
    line("G20");
    line("Y1"); // G1, incremental, inches
    EXPECT_NEAR(h.link.state().positionMm[1], 25.4, 1e-3);
    EXPECT_TRUE(failures.isEmpty()) << failures.join(QLatin1Char('\n')).toStdString();
    EXPECT_EQ(console.modal().text(), QStringLiteral("G1 G17 G20 G91 G94 G54 F600 S0"));
}

} // namespace
} // namespace frezka::session
