// Synchronisation points, I/O commands and the errors a plan refuses to run with.
#include "machine/planner.h"

#include "plancheck.h"

#include <gtest/gtest.h>

using namespace frezka;
using namespace frezka::machine;
using namespace frezka::machine::test;
using gcode::Event;
using gcode::EventKind;

namespace {

MachineConfig gve64()
{
    return defaultMachineConfig(protocol::Variant::Gve64);
}

std::vector<UnitOp> opSequence(const PlanResult &r)
{
    std::vector<UnitOp> out;
    for (const UnitCommand &c : r.program.commands) {
        if (c.op != UnitOp::Accel && c.op != UnitOp::Speed && c.op != UnitOp::Brake)
            out.push_back(c.op);
    }
    return out;
}

std::size_t count(const PlanResult &r, UnitOp op)
{
    std::size_t n = 0;
    for (const UnitCommand &c : r.program.commands)
        n += c.op == op ? 1 : 0;
    return n;
}

} // namespace

TEST(Sync, UnchangedSpindleSpeedAndFeedKeepTheChain)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendEvent({EventKind::SpindleCw, 12000}, 1000, 1);
    tp.appendFeed({20, 10, -1, 0}, 1000, 2);
    tp.appendEvent({EventKind::SpindleSpeed, 12000}, 1000, 3); // same S
    tp.appendFeed({30, 11, -1, 0}, 1500, 4);                   // new F
    tp.appendFeed({40, 11, -1, 0}, 1500, 5);
    const PlanResult r = plan(tp, gve64());
    ASSERT_TRUE(r.ok());
    using O = UnitOp;
    const std::vector<UnitOp> expected{O::SpeedModeVk, O::ShortThreshold, O::Pause,
                                       O::Spindle,     O::Dwell,          O::Vector,
                                       O::Vector,      O::Vector,         O::WaitIdle};
    EXPECT_EQ(opSequence(r), expected);
    EXPECT_EQ(r.stats.chains, 1u);
    EXPECT_EQ(count(r, UnitOp::Speed), 2u);       // F1000 then F1500
    EXPECT_EQ(r.program.commands[3].value, 500);  // 12000 of 24000 rpm = 500 ‰
    EXPECT_EQ(r.program.commands[4].value, 2000); // spin-up wait, ms
}

TEST(Sync, ChangedSpindleSpeedCoolantAndEndAreSyncPoints)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendEvent({EventKind::SpindleCw, 12000}, 1000, 1);
    tp.appendFeed({20, 10, -1, 0}, 1000, 2);
    tp.appendEvent({EventKind::SpindleSpeed, 6000}, 1000, 3);
    tp.appendEvent({EventKind::CoolantFlood}, 1000, 4);
    tp.appendFeed({30, 10, -1, 0}, 1000, 5);
    tp.appendEvent({EventKind::CoolantOff}, 1000, 6);
    tp.appendEvent({EventKind::ProgramEnd}, 1000, 7);
    const PlanResult r = plan(tp, gve64());
    ASSERT_TRUE(r.ok());
    using O = UnitOp;
    const std::vector<UnitOp> expected{O::SpeedModeVk, O::ShortThreshold, O::Pause,    O::Spindle,
                                       O::Dwell,       O::Vector,         O::WaitIdle, O::Spindle,
                                       O::Output,      O::Vector,         O::WaitIdle, O::Output,
                                       O::Spindle,     O::ProgramEnd};
    EXPECT_EQ(opSequence(r), expected);
    std::vector<std::int64_t> ports;
    for (const UnitCommand &c : r.program.commands) {
        if (c.op == UnitOp::Output)
            ports.push_back(c.value);
    }
    // Active low: coolant (OUT1, bit2) on with the spindle (bit0) running, then coolant off.
    EXPECT_EQ(ports, (std::vector<std::int64_t>{0xFA, 0xFE}));
    for (const UnitCommand &c : r.program.commands) {
        if (c.op == UnitOp::Output) {
            EXPECT_GT(c.sourceLine, 0u);
        }
    }
}

TEST(Sync, DwellToolChangeAndPauseStopTheQueue)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendFeed({20, 10, -1, 0}, 1000, 1);
    tp.appendEvent({EventKind::Dwell, 0.5}, 1000, 2);
    tp.appendFeed({30, 10, -1, 0}, 1000, 3);
    tp.appendEvent({EventKind::ToolChange, 3}, 1000, 4);
    tp.appendEvent({EventKind::Pause}, 1000, 5);
    const PlanResult r = plan(tp, gve64());
    ASSERT_TRUE(r.ok());
    using O = UnitOp;
    const std::vector<UnitOp> expected{O::SpeedModeVk,  O::ShortThreshold, O::Pause,  O::Vector,
                                       O::WaitIdle,     O::Dwell,          O::Vector, O::WaitIdle,
                                       O::OperatorStop, O::OperatorStop};
    EXPECT_EQ(opSequence(r), expected);
    const UnitCommand &tool = r.program.commands[r.program.commands.size() - 2];
    EXPECT_EQ(tool.value, static_cast<std::int64_t>(StopReason::ToolChange));
    EXPECT_EQ(tool.aux, 3);
    EXPECT_EQ(tool.sourceLine, 4u);
    EXPECT_EQ(r.stats.chains, 2u);
    EXPECT_NEAR(r.stats.waitS, 0.5, 1e-12);
}

TEST(Sync, ExactStopModeStopsAtEveryVertex)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendEvent({EventKind::PathMode, 0}, 1000, 1); // G61
    tp.appendFeed({20, 10, -1, 0}, 1000, 2);
    tp.appendFeed({30, 10, -1, 0}, 1000, 3);
    tp.appendEvent({EventKind::PathMode, 2}, 1000, 4); // G64
    tp.appendFeed({40, 10, -1, 0}, 1000, 5);
    tp.appendFeed({50, 10, -1, 0}, 1000, 6);
    const PlanResult r = plan(tp, gve64());
    ASSERT_TRUE(r.ok());
    const auto vs = replay(r.program);
    ASSERT_EQ(vs.size(), 4u);
    EXPECT_EQ(vs[0].b, 10); // G61: straight on, yet a stop
    EXPECT_EQ(vs[1].b, 10); // the first G64 vector still starts from the G61 stop
    EXPECT_EQ(vs[2].b, vs[2].v);
}

TEST(Errors, SoftLimitNamesTheLineAndNothingRuns)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendFeed({20, 10, -1, 0}, 1000, 6);
    tp.appendFeed({500, 10, -1, 0}, 1000, 7);
    const PlanResult r = plan(tp, gve64());
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].code, PlanErrorCode::SoftLimit);
    EXPECT_EQ(r.errors[0].line, 7u);
    EXPECT_EQ(r.errors[0].message,
              "line 7: X 500.000 is outside the soft limits 0.000 .. 400.000 mm; check the work "
              "offset and the program");
    EXPECT_TRUE(r.program.commands.empty());
}

TEST(Errors, ASoftLimitOfTheRotaryAxisIsInDegrees)
{
    machine::MachineConfig c = gve64();
    c.axes[3].present = true;
    c.axes[3].softMinMm = -10;
    c.axes[3].softMaxMm = 10;
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendFeed({20, 10, -1, 45}, 1000, 4);
    const PlanResult r = plan(tp, c);
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].code, PlanErrorCode::SoftLimit);
    EXPECT_EQ(r.errors[0].message,
              "line 4: A 45.000 is outside the soft limits -10.000 .. 10.000 deg; check the work "
              "offset and the program");
}

TEST(Errors, ArcBulgingOutOfTheTravelIsCaught)
{
    gcode::Toolpath tp;
    tp.setOrigin({5, 10, -1, 0});
    gcode::ArcInfo arc; // half circle below y = 10 around (10, 10): reaches y = 5 - fine;
    arc.centre = {10, 10, -1, 0};
    arc.turns = 1; // counter-clockwise from (5,10) to (15,10) goes through (10, 5)
    tp.appendArc({15, 10, -1, 0}, arc, 1000, 3);
    EXPECT_TRUE(plan(tp, gve64()).ok());
    gcode::Toolpath bad;
    bad.setOrigin({5, 3, -1, 0});
    arc.centre = {10, 3, -1, 0};
    bad.appendArc({15, 3, -1, 0}, arc, 1000, 4); // dips to y = -2
    const PlanResult r = plan(bad, gve64());
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].line, 4u);
    EXPECT_NE(r.errors[0].message.find("Y -"), std::string::npos) << r.errors[0].message;
}

TEST(Errors, AbsentAxisReverseSpindleAndMissingFeed)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendFeed({10, 10, -1, 90}, 1000, 2); // no A axis on the default GVE64 profile
    tp.appendEvent({EventKind::SpindleCcw, 1000}, 1000, 3);
    tp.appendFeed({20, 10, -1, 0}, 0, 4);
    tp.appendEvent({EventKind::SpindleCw, 50000}, 1000, 5);
    const PlanResult r = plan(tp, gve64());
    ASSERT_EQ(r.errors.size(), 4u);
    EXPECT_EQ(r.errors[0].code, PlanErrorCode::AbsentAxis);
    EXPECT_EQ(r.errors[1].code, PlanErrorCode::Unsupported);
    EXPECT_EQ(r.errors[2].code, PlanErrorCode::NoFeed);
    EXPECT_EQ(r.errors[3].code, PlanErrorCode::SpindleTooFast);
    EXPECT_EQ(r.errors[3].line, 5u);
}

TEST(Sync, Gve84SwitchesItsRelayAndWarnsAboutCoolant)
{
    const MachineConfig c = defaultMachineConfig(protocol::Variant::Gve84);
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendEvent({EventKind::SpindleCw, 10000}, 1000, 1);
    tp.appendEvent({EventKind::CoolantFlood}, 1000, 2);
    tp.appendFeed({20, 10, -1, 0}, 1000, 3);
    const PlanResult r = plan(tp, c);
    ASSERT_TRUE(r.ok());
    EXPECT_EQ(r.program.axisCount, 3);
    EXPECT_EQ(count(r, UnitOp::Spindle), 0u);
    ASSERT_EQ(count(r, UnitOp::Output), 1u);
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].line, 2u);
    EXPECT_TRUE(r.stats.speedModeVk); // the GVE84 has VK
}

TEST(Sync, AFeedBelowTheUnitsSlowestSpeedIsAWarning)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendFeed({11, 10, -1, 0}, 1, 4); // 1 mm/min = 3.3 pulses/s at 200 steps/mm
    const PlanResult r = plan(tp, gve64());
    ASSERT_TRUE(r.ok());
    ASSERT_EQ(r.warnings.size(), 1u);
    EXPECT_EQ(r.warnings[0].line, 4u);
    const auto vs = replay(r.program);
    ASSERT_EQ(vs.size(), 1u);
    EXPECT_EQ(vs[0].v, 10);
    EXPECT_LE(r.stats.estimatedS, 1.02 * r.stats.boundS); // the bound runs at 10 pulses/s too
}

TEST(Sync, ProbeIsAPcSideMoveAfterTheQueueDrains)
{
    gcode::Toolpath tp;
    tp.setOrigin({10, 10, -1, 0});
    tp.appendFeed({20, 10, -1, 0}, 1000, 1);
    tp.appendProbe({20, 10, -11, 0}, gcode::ProbeKind::TowardErrorIfNoContact, 100, 2);
    tp.appendFeed({30, 10, -11, 0}, 1000, 3);
    tp.appendProbe({30, 10, -11, 0}, gcode::ProbeKind::Toward, 100, 4); // no length
    const PlanResult r = plan(tp, gve64());
    ASSERT_EQ(r.errors.size(), 1u);
    EXPECT_EQ(r.errors[0].line, 4u);
    gcode::Toolpath ok;
    ok.setOrigin({10, 10, -1, 0});
    ok.appendFeed({20, 10, -1, 0}, 1000, 1);
    ok.appendProbe({20, 10, -11, 0}, gcode::ProbeKind::TowardErrorIfNoContact, 120, 2);
    const PlanResult p = plan(ok, gve64());
    ASSERT_TRUE(p.ok());
    const auto &cs = p.program.commands;
    ASSERT_GE(cs.size(), 3u);
    const UnitCommand &probe = cs.back();
    EXPECT_EQ(probe.op, UnitOp::Probe);
    EXPECT_EQ(probe.d, (std::array<std::int32_t, 4>{0, 0, -2000, 0}));
    EXPECT_EQ(probe.aux, static_cast<std::int32_t>(gcode::ProbeKind::TowardErrorIfNoContact));
    EXPECT_EQ(cs[cs.size() - 2].op, UnitOp::Speed);
    EXPECT_EQ(cs[cs.size() - 2].value, 400); // 2 mm/s at 200 steps/mm
    bool drained = false;
    for (std::size_t i = 0; i + 1 < cs.size(); ++i)
        drained = drained || cs[i].op == UnitOp::WaitIdle;
    EXPECT_TRUE(drained);
}
