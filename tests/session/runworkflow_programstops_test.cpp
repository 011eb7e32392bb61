// The program's own stops (M0, M1, M6) in the headless run (issue 16 item 8), on the in-process
// emulator and a virtual clock: ProgramStops::Continue runs on with the spindle switched back on
// (and its spin-up waited) before the machine moves, Ask puts the stop to the front end and
// nothing moves until resume(), End ends the run at the stop. Asserted on the wire and the unit.
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
using Stops = RunWorkflow::ProgramStops;

const char *kStops = "G21 G90\n"
                     "M3 S12000\n"
                     "G0 X10 Y10\n"
                     "G1 Z-2 F300\n"
                     "G1 X30 F1200\n"
                     "M0\n"
                     "G1 Y30\n"
                     "G0 Z0\n"
                     "M6 T2\n"
                     "G1 X10 F1200\n"
                     "M5\n"
                     "M2\n";

struct Bench
{
    Bench()
        : config(machine::defaultMachineConfig(protocol::Variant::Gve64))
        , link(config, driver::unitOptionsFor(config), driver::WireOptions{}, driver::CoreOptions{})
        , workflow(link)
        , wire(link.port())
    {
        config.motion.runBeforeHoming = true;
        workflow.setProfile(config);
        workflow.setEndOnHold(true);
        const gcode::Result g = gcode::interpretText(kStops, {});
        EXPECT_TRUE(g.ok());
        machine::PlanResult p = machine::plan(g.toolpath, config);
        EXPECT_TRUE(p.ok());
        plan = std::make_shared<machine::UnitProgram>(std::move(p.program));
        workflow.setProgram(plan, {}, QStringLiteral("stops.nc"));
        QObject::connect(&workflow, &RunWorkflow::runEnded, [this](bool ok) { ended = ok; });
        QObject::connect(&workflow, &RunWorkflow::programStopped,
                         [this](std::uint32_t line, const QString &text) {
                             asked.push_back(line);
                             texts << text;
                         });
    }
    bool runToEnd()
    {
        return link.runUntil([this] { return workflow.hasEnded(); }, 3600);
    }
    void expectExactEnd()
    {
        const auto end = plan->commands.back().endSteps;
        for (std::size_t a = 0; a < 3; ++a)
            EXPECT_EQ(link.port().unit().position()[a], end[a]) << "axis " << a;
        EXPECT_EQ(link.port().unit().stats().safety.cutWithoutSpindle, 0);
        EXPECT_EQ(link.port().unit().stats().safety.spindleOnWhileHeld, 0);
    }

    machine::MachineConfig config;
    SimLink link;
    RunWorkflow workflow;
    WireTap wire;
    std::shared_ptr<const machine::UnitProgram> plan;
    std::optional<bool> ended;
    std::vector<std::uint32_t> asked;
    QStringList texts;
};

// Continue: each stop switches the spindle off (the profile's stopAtProgramStop,
// stopAtToolChange) and on again before the job goes on; the job ends exactly.
TEST(RunWorkflowProgramStops, ContinueRunsOnWithTheSpindleBackOnFirst)
{
    Bench b;
    b.workflow.setProgramStops(Stops::Continue);
    b.workflow.start(RunWorkflow::connectionFor(b.config), false);
    ASSERT_TRUE(b.runToEnd());
    ASSERT_EQ(b.ended, std::optional<bool>(true)) << b.workflow.error().toStdString();
    EXPECT_EQ(b.workflow.programStopsSeen(), 2);
    EXPECT_TRUE(b.asked.empty());
    std::vector<std::string> spindle = b.wire.matching("!7V");
    // M3, off and on at M0, off and on at M6, M5 (and the driver's own off at the connect).
    ASSERT_GE(spindle.size(), 6u);
    EXPECT_EQ(spindle.back(), "!7V0");
    int offs = 0;
    for (const std::string &s : spindle)
        offs += s == "!7V0" ? 1 : 0;
    EXPECT_GE(offs, 3) << "off at M0, at M6 and at M5";
    b.expectExactEnd();
}

// Ask: programStopped() names the line; the machine stands until resume().
TEST(RunWorkflowProgramStops, AskWaitsForTheFrontEnd)
{
    Bench b;
    b.workflow.setProgramStops(Stops::Ask);
    b.workflow.start(RunWorkflow::connectionFor(b.config), false);
    ASSERT_TRUE(b.link.runUntil([&] { return !b.asked.empty(); }, 600));
    EXPECT_EQ(b.asked.front(), 6u);
    EXPECT_TRUE(b.texts.front().contains(QLatin1String("M0"))) << b.texts.front().toStdString();
    const auto at = b.link.port().unit().position();
    const std::size_t sent = b.wire.size();
    b.link.runFor(30);
    EXPECT_EQ(b.link.port().unit().position(), at) << "nothing moves while the stop is asked";
    EXPECT_TRUE(b.wire.matching("!0C", sent).empty());
    EXPECT_FALSE(b.workflow.hasEnded());
    EXPECT_EQ(b.asked.size(), 1u) << "asked once";
    b.workflow.resume();
    ASSERT_TRUE(b.link.runUntil([&] { return b.asked.size() == 2; }, 600));
    EXPECT_EQ(b.asked.back(), 9u);
    b.workflow.resume();
    ASSERT_TRUE(b.runToEnd());
    EXPECT_EQ(b.ended, std::optional<bool>(true));
    b.expectExactEnd();
}

// End (the default with setEndOnHold): the run ends at the first stop, the job held.
TEST(RunWorkflowProgramStops, EndEndsTheRunAtTheStop)
{
    Bench b;
    b.workflow.start(RunWorkflow::connectionFor(b.config), false);
    ASSERT_TRUE(b.runToEnd());
    EXPECT_EQ(b.ended, std::optional<bool>(false));
    EXPECT_TRUE(b.workflow.error().contains(QLatin1String("M0")))
        << b.workflow.error().toStdString();
    EXPECT_EQ(b.link.state().mode, MachineMode::Paused);
}

} // namespace
} // namespace frezka::session
