// Programs that probe for themselves (issue 19 item 4): RunWorkflow with a ProbeFollow on the
// in-process emulator with a simulated work top. After each probe move the rest of the program
// is interpreted again with the trip point and runs on from there; asserted on the unit's own
// counters (its position and the motion events it traced), not on the plan.
#include "probefollow_programs.h"
#include "session/probefollow.h"
#include "session/runworkflow.h"
#include "session/simlink.h"

#include "machine/planner.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

namespace frezka::session {
namespace {

using test::autolevelProgram;
using test::kTouchOff;
using test::tilted;

constexpr double kStepsPerMm = 200; // the GVE64's default profile, X Y Z

struct FollowBench
{
    FollowBench(const char *surface, const char *program, bool follow = true)
        : config(machine::defaultMachineConfig(protocol::Variant::Gve64))
        , link(config, unitWith(config, surface), driver::WireOptions{}, driver::CoreOptions{})
        , workflow(link)
        , probes(request(program), config)
    {
        workflow.setProfile(config);
        workflow.setEndOnHold(true);
        if (follow)
            workflow.setProbeFollow(&probes);
        QObject::connect(&workflow, &RunWorkflow::runEnded, [this](bool ok) { ended = ok; });
        QObject::connect(&workflow, &RunWorkflow::probeFollowed,
                         [this](std::uint32_t line, const ProbeFollow::Next &next) {
                             followedLines.push_back(line);
                             provisional.push_back(next.provisionalLine);
                             lastToolTable = next.toolTable;
                             lastWorkOffsets = next.workOffsetsMm;
                         });
        const InterpretOutcome g = interpretProgram(request(program));
        EXPECT_TRUE(g.errors.empty()) << (g.errors.empty() ? "" : g.errors[0].text.toStdString());
        whole = g.toolpath;
        firstProvisionalLine = g.provisionalLine;
        if (!follow) { // the whole program planned as it is interpreted before it runs
            PlanOutcome p = planProgram(*g.toolpath, config, QStringLiteral("test.ngc"));
            EXPECT_TRUE(p.ok());
            workflow.setProgram(p.program, {}, QStringLiteral("test.ngc"));
        }
    }
    static InterpretRequest request(const char *program)
    {
        InterpretRequest r;
        r.text = program;
        r.fileName = QStringLiteral("test.ngc");
        r.toolTable = gcode::ToolTable{};
        r.toolTable->tools.push_back({1, 1, {}, 6, 0, 0, 0, "reference"});
        return r;
    }
    static emulator::UnitOptions unitWith(const machine::MachineConfig &c, const char *surface)
    {
        emulator::UnitOptions unit = driver::unitOptionsFor(c);
        EXPECT_TRUE(driver::setProbeSurface(unit, surface, c));
        unit.trace = true;
        return unit;
    }
    // Connects, runs the program to its end; every position the unit's motion events saw.
    void run()
    {
        workflow.start(RunWorkflow::connectionFor(config), false);
        link.runUntil(
            [&] {
                emulator::Unit &u = link.port().unit();
                for (const emulator::TracePoint &p : u.trace())
                    seen.push_back(p.position);
                u.clearTrace();
                return workflow.hasEnded();
            },
            3600);
        seen.push_back(link.port().unit().position());
    }
    std::array<std::int64_t, 4> unitAt() { return link.port().unit().position(); }
    const emulator::Stats unitStats() { return link.port().unit().stats(); }

    machine::MachineConfig config;
    SimLink link;
    RunWorkflow workflow;
    ProbeFollow probes;
    std::shared_ptr<const gcode::Toolpath> whole;
    std::uint32_t firstProvisionalLine = 0;
    std::optional<bool> ended;
    std::vector<std::uint32_t> followedLines, provisional;
    std::vector<std::array<std::int64_t, 4>> seen;
    std::optional<gcode::ToolTable> lastToolTable; // the last followed part's (Next::toolTable)
    std::optional<std::array<std::array<double, 4>, 9>> lastWorkOffsets;
};

TEST(ProbeFollow, TouchOffThenCutEndsOnTheUnitAtTheSurfaceMinusTheDepth)
{
    FollowBench b("plane:-3.2,0,0", kTouchOff);
    EXPECT_EQ(b.firstProvisionalLine, 3u); // before it runs: provisional after the probe
    b.run();
    ASSERT_TRUE(b.ended && *b.ended) << b.workflow.error().toStdString();
    EXPECT_EQ(b.workflow.probesFollowed(), 1);
    EXPECT_EQ(b.followedLines, std::vector<std::uint32_t>{3});
    EXPECT_EQ(b.provisional, std::vector<std::uint32_t>{0}); // nothing provisional after it
    const auto at = b.unitAt();
    EXPECT_EQ(at[0], 20 * kStepsPerMm);
    EXPECT_EQ(at[1], 10 * kStepsPerMm);
    EXPECT_NEAR(double(at[2]), -3.3 * kStepsPerMm, 1.0); // the surface - 0.1, within a step
    // Never deeper than that on the way (the probe stopped at the surface, within a step).
    std::int64_t lowest = std::numeric_limits<std::int64_t>::max();
    for (const auto &p : b.seen)
        lowest = std::min(lowest, p[2]);
    EXPECT_GE(double(lowest), -3.3 * kStepsPerMm - 1);
    // (The emulator counts the probe itself, a move down with the spindle off, as a cut without
    // the spindle: no work surface is set for its safety watch here.)
    EXPECT_EQ(b.unitStats().motion.brakeViolations, 0);
    EXPECT_EQ(b.unitStats().motion.axisOverMax, 0);
}

TEST(ProbeFollow, WhatTheProgramsG10SetAfterAProbeIsTakenFromItsResult)
{
    // A tool measured by probing (G10 L10) and a work zero set there (G10 L20): what the caller
    // keeps once the program has run (the window's offsets, the tool table file) must be the
    // probe's result, -3.2, not the programmed end's -10 it was interpreted with before it ran.
    const char *program = "G21 G90 G54 G49\n"
                          "G0 X10 Y10\n"
                          "G38.2 Z-10 F50\n" // 3
                          "G10 L10 P1 Z0\n"
                          "G10 L20 P2 Z0\n"
                          "G0 Z0\n"
                          "M2\n";
    FollowBench b("plane:-3.2,0,0", program);
    const InterpretOutcome before = interpretProgram(FollowBench::request(program));
    ASSERT_TRUE(before.toolTableChanged && before.workOffsetsChanged);
    EXPECT_EQ(before.toolTable.find(1)->offsetMm[2], -10);
    EXPECT_EQ(before.workOffsetsMm[1][2], -10);
    b.run();
    ASSERT_TRUE(b.ended && *b.ended) << b.workflow.error().toStdString();
    ASSERT_EQ(b.followedLines, std::vector<std::uint32_t>{3});
    ASSERT_TRUE(b.lastToolTable && b.lastWorkOffsets);
    // Where the unit stopped: the surface within a step (its braking after the trip).
    EXPECT_NEAR(b.lastToolTable->find(1)->offsetMm[2], -3.2, 1.0 / kStepsPerMm);
    EXPECT_NEAR((*b.lastWorkOffsets)[1][2], -3.2, 1.0 / kStepsPerMm);
    EXPECT_EQ((*b.lastWorkOffsets)[0], (std::array<double, 4>{})); // G54 untouched
}

TEST(ProbeFollow, WithoutFollowingTheProbeTheJobEndsThereAsBefore)
{
    // The old behaviour, for comparison: the plan took the probe's programmed end (Z -10) as the
    // work's zero, so the driver ends the job where the probe stopped short.
    FollowBench b("plane:-3.2,0,0", kTouchOff, false);
    b.run();
    ASSERT_TRUE(b.ended);
    EXPECT_FALSE(*b.ended);
    ASSERT_TRUE(b.link.state().lastError);
    EXPECT_EQ(b.link.state().lastError->reason.code, driver::DriverCode::ProbeTrippedElsewhere);
    EXPECT_EQ(b.workflow.probesFollowed(), 0);
    EXPECT_EQ(b.unitAt()[0], 10 * kStepsPerMm); // it never cut
    // The static plan's cut lies at the probe's programmed depth: 6.9 mm below the surface.
    EXPECT_NEAR(b.whole->end(b.whole->size() - 3).z, -10.1, 1e-9);
}

TEST(ProbeFollow, AutolevelGridCutsFollowTheTiltedSurfaceOnTheUnit)
{
    const std::string program = autolevelProgram();
    FollowBench b("plane:-2,0.02,-0.015", program.c_str());
    b.run();
    ASSERT_TRUE(b.ended && *b.ended) << b.workflow.error().toStdString();
    EXPECT_EQ(b.workflow.probesFollowed(), 10); // the zero and the nine grid points
    ASSERT_EQ(b.provisional.size(), 10u);
    EXPECT_NE(b.provisional[8], 0u); // the last grid probe still to run
    EXPECT_EQ(b.provisional[9], 0u); // after the last one nothing is provisional
    // Every position the unit reached below the surface by more than 0.05 mm is a cut point:
    // 0.1 below the surface there, within a step (and the plan's rounding of the corner).
    int cutPoints = 0;
    for (const auto &p : b.seen) {
        const double x = p[0] / kStepsPerMm, y = p[1] / kStepsPerMm, z = p[2] / kStepsPerMm;
        const double depth = tilted(x, y) - z;
        if (depth < 0.05)
            continue;
        ++cutPoints;
        EXPECT_NEAR(depth, 0.1, 1.5 / kStepsPerMm) << "at " << x << ", " << y << ", " << z;
    }
    EXPECT_GE(cutPoints, 5);
    EXPECT_EQ(b.unitStats().motion.brakeViolations, 0);
    EXPECT_EQ(b.unitStats().motion.axisOverMax, 0);
}

TEST(ProbeFollow, AProbeThatNeverTripsStillStopsWithItsError)
{
    // (d) The work lies below the probe's depth: the G38.2 ends at Z -10 without contact.
    FollowBench b("plane:-12,0,0", kTouchOff);
    b.run();
    ASSERT_TRUE(b.ended);
    EXPECT_FALSE(*b.ended);
    ASSERT_TRUE(b.link.state().lastError);
    EXPECT_EQ(b.link.state().lastError->reason.code, driver::DriverCode::ProbeNotTripped);
    EXPECT_EQ(b.workflow.probesFollowed(), 0);
    EXPECT_GE(b.unitAt()[2], -10 * kStepsPerMm); // never past the probe's end
    EXPECT_EQ(b.unitAt()[0], 10 * kStepsPerMm);  // no cut
    EXPECT_EQ(b.link.state().hold, driver::HoldReason::ProbeFailed);
}

TEST(ProbeFollow, TheRestAfterAProbePutsBackTheSpindleCoolantAndPathMode)
{
    const char *text = "G21 G90 G64 P0.01\nM3 S9000\nM8\nG38.2 Z-5 F40\nG1 X5 F300\nM2\n";
    gcode::Options o;
    o.probeResults = {{{0, 0, -2, 0}, true}};
    const gcode::Result g = gcode::interpretText(text, o);
    ASSERT_TRUE(g.ok());
    std::size_t probe = 0;
    while (g.toolpath.kind(probe) != gcode::MotionKind::Probe)
        ++probe;
    const auto rest = restAfterProbe(g.toolpath, probe);
    EXPECT_EQ(restAfterProbe(g.toolpath, probe, probe + 2)->size(), 4u); // up to an end
    EXPECT_EQ(rest->origin(), (gcode::Point4{0, 0, -2, 0}));
    ASSERT_GE(rest->size(), 4u);
    EXPECT_EQ(rest->event(0).kind, gcode::EventKind::PathMode);
    EXPECT_EQ(rest->event(1).kind, gcode::EventKind::SpindleCw);
    EXPECT_EQ(rest->event(1).value, 9000);
    EXPECT_EQ(rest->event(2).kind, gcode::EventKind::CoolantFlood);
    EXPECT_EQ(rest->kind(3), gcode::MotionKind::Feed);
    EXPECT_EQ(rest->start(3), (gcode::Point4{0, 0, -2, 0}));
    EXPECT_EQ(rest->line(3), 5u);
}

} // namespace
} // namespace frezka::session
