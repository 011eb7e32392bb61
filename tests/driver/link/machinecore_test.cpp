// MachineCore on the in-process emulator (virtual clock): connect, stream, operations.

#include "simchecks.h"
#include "simfixture.h"
#include "wiretap.h"

#include "gcode/interpreter.h"
#include "gcode/toolpath.h"
#include "machine/planner.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace frezka;
using namespace frezka::driver;
using namespace frezka::driver::test;
using protocol::Variant;

TEST(MachineCore, ConnectSequence)
{
    for (Variant v : {Variant::Gve84, Variant::Gve64, Variant::Gve64Phantom, Variant::Gve114}) {
        Sim sim(v);
        ASSERT_TRUE(sim.connect()) << sim.lastLog();
        const MachineState &s = sim.core.state();
        EXPECT_TRUE(s.checksums);
        EXPECT_TRUE(sim.port.unit().checksumsOn());
        EXPECT_EQ(s.firmware, std::string(protocol::variantInfo(v).firmware));
        EXPECT_EQ(s.unitId, std::string(protocol::variantInfo(v).defaultId));
        EXPECT_FALSE(s.run) << "MPG must be off after connecting";
        EXPECT_TRUE(sim.errors.empty()) << sim.errors.front().message;
    }
}

TEST(MachineCore, StreamsADenseJobExactly)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    const auto program = denseProgram(3000);
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front());
    const auto pos = sim.port.unit().position();
    for (int a = 0; a < 3; ++a)
        EXPECT_EQ(pos[a], program.commands.back().endSteps[a]) << "axis " << a;
    EXPECT_EQ(sim.core.jobReport().vectors, 3000);
    EXPECT_EQ(sim.port.unit().stats().motion.vectorsExecuted, 3000);
    EXPECT_EQ(sim.core.state().mode, MachineMode::Idle);
}

// 1 byte error per 1000 bytes (corrupted, dropped or duplicated) plus lost replies: every run
// must end at exactly the expected counters with every vector executed exactly once.
TEST(MachineCore, FaultSoakEndsExact)
{
    for (std::uint32_t seed = 1; seed <= 12; ++seed) {
        WireOptions wire;
        wire.latencyS = 0.004;
        wire.byteErrorRate = 1e-3;
        wire.replyLossRate = 1e-3;
        wire.seed = seed;
        Sim sim(Variant::Gve64, wire);
        ASSERT_TRUE(sim.connect(120)) << "seed " << seed << "\n" << sim.lastLog();
        const auto program = denseProgram(1500);
        ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
        ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 900))
            << "seed " << seed << "\n"
            << sim.lastLog();
        EXPECT_TRUE(sim.finished.front()) << "seed " << seed;
        const auto pos = sim.port.unit().position();
        for (int a = 0; a < 3; ++a)
            EXPECT_EQ(pos[a], program.commands.back().endSteps[a]) << "seed " << seed;
        EXPECT_EQ(sim.port.unit().stats().motion.vectorsExecuted, 1500) << "seed " << seed;
        EXPECT_GT(sim.port.wireStats().corrupted + sim.port.wireStats().dropped, 0);
    }
}

TEST(MachineCore, PauseResumeEndsExact)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    const auto program = slowProgram(300);
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    sim.runner.runFor(2.0);
    ASSERT_FALSE(sim.core.pause(sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Paused)) << sim.lastLog();
    EXPECT_EQ(sim.core.state().hold, HoldReason::User);
    const auto stopped = sim.port.unit().position();
    sim.runner.runFor(1.0);
    EXPECT_EQ(sim.port.unit().position(), stopped) << "the machine must stand while paused";
    ASSERT_FALSE(sim.core.resume(sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    expectAt(sim, endOf(program));
}

TEST(MachineCore, ToolLiftKeepRestoreEndsExact)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    const auto program = slowProgram(300);
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    sim.runner.runFor(3.0);
    ASSERT_FALSE(sim.core.pause(sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Paused));
    const auto before = sim.port.unit().position();
    ASSERT_FALSE(sim.core.toolLift(false, sim.runner.now())) << sim.lastLog();
    ASSERT_TRUE(sim.until(MachineMode::ToolLifted)) << sim.lastLog();
    const auto lifted = sim.port.unit().position();
    EXPECT_EQ(lifted[0], before[0]);
    EXPECT_GT(lifted[2], before[2]);
    EXPECT_LE(lifted[2], 0) << "never beyond the upper soft limit of Z";
    ASSERT_FALSE(sim.core.toolLower(0, sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Paused)) << sim.lastLog();
    EXPECT_EQ(sim.port.unit().position(), before);
    ASSERT_FALSE(sim.core.resume(sim.runner.now())) << sim.lastLog();
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front());
    expectAt(sim, endOf(program));
    EXPECT_EQ(sim.port.unit().stats().motion.vectorsExecuted, 300 + 2); // + lift and lower
}

TEST(MachineCore, AbortStopsAndDropsTheQueue)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.run(slowProgram(300), sim.runner.now()));
    sim.runner.runFor(1.0);
    ASSERT_FALSE(sim.core.abort(sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Idle)) << sim.lastLog();
    ASSERT_EQ(sim.finished.size(), 1u);
    EXPECT_FALSE(sim.finished.front());
    const auto stopped = sim.port.unit().position();
    // Idle with the counters where the machine stopped, before any poll: what the next console
    // line or jog is planned from (one was planned from the last poll's, short of it).
    EXPECT_EQ(sim.core.state().positionSteps, stopped);
    sim.runner.runFor(2.0);
    EXPECT_EQ(sim.port.unit().position(), stopped);
    EXPECT_EQ(sim.port.unit().queueLength(), 0u);
}

TEST(MachineCore, StopButtonHoldsTheJobAndResumes)
{
    Sim sim;
    sim.config.eeprom.interruptEnable = 0x80; // IN7 = STOP
    sim.config.eeprom.polarity = 0x80;        // active high (pressed reads 1 in the emulator)
    sim.core.setConfig(sim.config);
    ASSERT_TRUE(sim.connect());
    const auto program = slowProgram(200);
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    sim.runner.runFor(1.5);
    sim.port.unit().setStopButton(true);
    ASSERT_TRUE(sim.until(MachineMode::Paused, 5)) << sim.lastLog();
    EXPECT_EQ(sim.core.state().hold, HoldReason::Interrupt);
    sim.runner.runFor(0.5);
    EXPECT_NE(sim.core.state().holdText.find("IN7"), std::string::npos)
        << sim.core.state().holdText;
    sim.port.unit().setStopButton(false);
    ASSERT_FALSE(sim.core.resume(sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    expectAt(sim, endOf(program));
}

TEST(MachineCore, LinkLostMidJobResumesExactlyAfterReconnecting)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    const auto program = slowProgram(900); // more than the unit's queue holds
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    sim.runner.runFor(2.0);
    sim.runner.unplug("converter unplugged");
    EXPECT_EQ(sim.core.state().mode, MachineMode::LinkLost);
    ASSERT_FALSE(sim.errors.empty());
    sim.runner.runFor(5.0); // the unit runs on what it has
    sim.runner.open();      // plugged in again
    ASSERT_TRUE(sim.until(MachineMode::Paused, 120)) << sim.lastLog();
    // Resume is refused while the progress is being checked against the counters.
    bool resumed = false;
    ASSERT_TRUE(sim.runner.runUntil(
        [&] { return resumed || (resumed = !sim.core.resume(sim.runner.now()).has_value()); }, 60))
        << sim.lastLog();
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.back());
    expectAt(sim, endOf(program));
    EXPECT_EQ(sim.port.unit().stats().motion.vectorsExecuted, 900);
    EXPECT_GE(sim.core.jobReport().verified, 1);
}

TEST(MachineCore, HomingThenJogWithinSoftLimits)
{
    Sim sim;
    sim.port.unit().setSwitches(unitOptionsFor(sim.config).switches);
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.home(sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return sim.core.state().homed; }, 600)) << sim.lastLog();
    EXPECT_EQ(sim.core.state().mode, MachineMode::Idle);
    for (int a = 0; a < 3; ++a)
        EXPECT_EQ(sim.port.unit().position()[a], 0);
    // X: 0..400 mm. A step of 10 mm, then a continuous jog toward -X that must stop at 0.
    ASSERT_FALSE(sim.core.jogStep(0, 10, 3000, sim.runner.now()));
    ASSERT_TRUE(
        sim.runner.runUntil([&] { return sim.core.state().mode == MachineMode::Idle; }, 60));
    EXPECT_EQ(sim.port.unit().position()[0], std::llround(10 * sim.config.axes[0].stepsPerMm));
    ASSERT_FALSE(sim.core.jogContinuous(0, -1, 3000, sim.runner.now()));
    sim.runner.runFor(30);
    EXPECT_EQ(sim.port.unit().position()[0], 0) << "continuous jog ends at the soft limit";
    // Beyond the limit: refused.
    sim.runner.runUntil([&] { return sim.core.state().mode == MachineMode::Idle; }, 10);
    EXPECT_TRUE(sim.core.jogStep(0, -5, 3000, sim.runner.now()).has_value());
}

TEST(MachineCore, HomingOneAxisLeavesTheOthers)
{
    Sim sim;
    sim.port.unit().setSwitches(unitOptionsFor(sim.config).switches);
    ASSERT_TRUE(sim.connect());
    // X 10 mm away from where it was; then Z alone is homed: X's counter must not change.
    ASSERT_FALSE(sim.core.jogStep(0, 10, 3000, sim.runner.now()));
    ASSERT_TRUE(
        sim.runner.runUntil([&] { return sim.core.state().mode == MachineMode::Idle; }, 60));
    const std::int64_t x = sim.port.unit().position()[0];
    ASSERT_EQ(x, std::llround(10 * sim.config.axes[0].stepsPerMm));
    ASSERT_FALSE(sim.core.home(sim.runner.now(), 1u << 2));
    ASSERT_TRUE(sim.runner.runUntil(
        [&] {
            return sim.core.state().homedAxes == 0b100 &&
                   sim.core.state().mode == MachineMode::Idle;
        },
        600))
        << sim.lastLog();
    EXPECT_FALSE(sim.core.state().homed) << "X and Y are not homed yet";
    EXPECT_EQ(sim.port.unit().position()[0], x);
    EXPECT_EQ(sim.port.unit().position()[2], 0);
    // An axis the profile does not home (A: order 0) is refused, nothing is sent.
    EXPECT_TRUE(sim.core.home(sim.runner.now(), 1u << 3).has_value());
    // Then X and Y: every homed axis of the profile is homed.
    ASSERT_FALSE(sim.core.home(sim.runner.now(), 0b011));
    ASSERT_TRUE(sim.runner.runUntil([&] { return sim.core.state().homed; }, 600)) << sim.lastLog();
    EXPECT_EQ(sim.core.state().homedAxes, 0b111);
    EXPECT_EQ(sim.port.unit().position()[0], 0);
    EXPECT_TRUE(sim.errors.empty());
}

// Outputs go by their number (OUTn); the driver finds the port bit: OUT2 is bit3 of port 0,
// and a GVE84, which has its relay only, refuses OUT1.
TEST(MachineCore, OutputsByNumber)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.setOutput(2, true, sim.runner.now()));
    sim.runner.runFor(0.5);
    EXPECT_EQ(sim.port.unit().outputs(), 0xF7);
    EXPECT_TRUE(sim.core.state().outputIsOn(2));
    ASSERT_FALSE(sim.core.setOutput(2, false, sim.runner.now()));
    sim.runner.runFor(0.5);
    EXPECT_EQ(sim.port.unit().outputs(), 0xFF);
    Sim g84(protocol::Variant::Gve84);
    ASSERT_TRUE(g84.connect());
    const auto refused = g84.core.setOutput(1, true, g84.runner.now());
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->reason.code, DriverCode::NoSuchOutput);
    EXPECT_EQ(refused->message, "This unit has no output OUT1. Switch one of the outputs the unit "
                                "has (a GVE84 has its relay only).");
}

TEST(MachineCore, SpindleOutputsOverride)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.setSpindleRpm(sim.config.spindle.maxRpm * 0.3, sim.runner.now()));
    ASSERT_FALSE(sim.core.setOutput(1, true, sim.runner.now())); // coolant (OUT1) on
    ASSERT_FALSE(sim.core.setOverride(150, sim.runner.now()));
    sim.runner.runFor(0.5);
    EXPECT_EQ(sim.port.unit().spindlePermille(), 300);
    EXPECT_EQ(sim.port.unit().outputs(), 0xFB);
    EXPECT_EQ(sim.core.state().overridePercent, 150);
    EXPECT_TRUE(sim.core.setOverride(0, sim.runner.now()).has_value());
    EXPECT_TRUE(sim.core.setSpindleRpm(-1, sim.runner.now()).has_value());
    EXPECT_TRUE(sim.errors.empty());
}

TEST(MachineCore, UnitErrorNamesCommandAndReply)
{
    // No home switches on this emulated unit: W ends with code 5 (adopted reading §6).
    Sim sim;
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.home(sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Alarm, 3600)) << sim.lastLog();
    ASSERT_EQ(sim.errors.size(), 1u);
    const MachineError &e = sim.errors.front();
    EXPECT_EQ(e.command.rfind("!0W", 0), 0u) << e.command;
    EXPECT_EQ(e.unitCode, 5);
    EXPECT_NE(e.message.find("switch was not found"), std::string::npos) << e.message;
    EXPECT_FALSE(e.reply.empty());
    EXPECT_FALSE(sim.core.state().homed);

    // A program the variant refuses before anything is sent: 4 axes on a 3-axis GVE84.
    Sim sim84(protocol::Variant::Gve84);
    ASSERT_TRUE(sim84.connect());
    const auto refused = sim84.core.run(denseProgram(5, 4), sim84.runner.now());
    ASSERT_TRUE(refused.has_value());
    EXPECT_NE(refused->message.find("GVE84"), std::string::npos) << refused->message;
    EXPECT_EQ(sim84.core.state().mode, MachineMode::Idle);
}

TEST(MachineCore, OperatorStopsAndDwellWaitForTheMachine)
{
    using machine::UnitOp;
    Sim sim;
    ASSERT_TRUE(sim.connect());
    auto p = slowProgram(20);
    const auto end = p.commands.back(); // ProgramEnd
    p.commands.pop_back();
    const auto mid = p.commands.back().endSteps;
    machine::UnitCommand m6;
    m6.op = UnitOp::OperatorStop;
    m6.value = static_cast<std::int64_t>(machine::StopReason::ToolChange);
    m6.aux = 3;
    m6.sourceLine = 77;
    m6.endSteps = mid;
    machine::UnitCommand dwell;
    dwell.op = UnitOp::Dwell;
    dwell.value = 1500; // ms
    dwell.endSteps = mid;
    p.commands.push_back(m6);
    p.commands.push_back(dwell);
    p.commands.push_back(end);
    ASSERT_FALSE(sim.core.run(p, sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Paused, 120)) << sim.lastLog();
    EXPECT_EQ(sim.core.state().hold, HoldReason::OperatorStop);
    EXPECT_NE(sim.core.state().holdText.find("tool 3"), std::string::npos);
    EXPECT_NE(sim.core.state().holdText.find("line 77"), std::string::npos);
    expectAt(sim, mid); // all motion before M6 ran, the machine stands
    const double resumed = sim.runner.now();
    ASSERT_FALSE(sim.core.resume(resumed));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 60)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front());
    EXPECT_GE(sim.runner.now() - resumed, 1.5); // the dwell
}

TEST(MachineCore, MpgRawCommandAndOverrideSteps)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.setMpg(true, sim.runner.now()));
    sim.runner.runFor(0.2);
    EXPECT_TRUE(sim.core.state().mpgOn);
    EXPECT_TRUE(sim.core.state().run); // Y& counts as running (§13)
    ASSERT_FALSE(sim.core.setMpg(false, sim.runner.now()));
    sim.runner.runFor(0.2);
    EXPECT_FALSE(sim.core.state().mpgOn);
    EXPECT_FALSE(sim.core.state().run);

    ASSERT_FALSE(sim.core.sendRaw("SW0,80", sim.runner.now()));
    sim.runner.runFor(0.2);
    EXPECT_EQ(sim.port.unit().status(0), 0x80);
    EXPECT_TRUE(sim.core.sendRaw("!0Z", sim.runner.now()).has_value());    // unknown
    EXPECT_TRUE(sim.core.sendRaw("!0T99", sim.runner.now()).has_value());  // out of range
    EXPECT_TRUE(sim.core.sendRaw("!0L1,2", sim.runner.now()).has_value()); // syntax
    // Y+: reports unasked, in no documented form, would be taken for replies (issue 14).
    const auto reports = sim.core.sendRaw("Y+", sim.runner.now());
    ASSERT_TRUE(reports.has_value());
    EXPECT_EQ(reports->reason.code, DriverCode::MpgReportsUnsupported);

    ASSERT_FALSE(sim.core.overrideStep(true, sim.runner.now()));
    sim.runner.runFor(0.2);
    EXPECT_EQ(sim.core.state().overridePercent, 106);
    EXPECT_TRUE(sim.errors.empty());
}

// Where the motion is slower than the wire, the live position keeps its rate while the job
// streams: packets stay short enough for the polls between them (strict request/reply lets no
// poll through a packet on the wire), and the unit still never runs dry. On the virtual clock,
// 8 ms latency each way; before, the first packet held the position for 0.67 s.
TEST(MachineCore, SlowMotionKeepsThePositionFresh)
{
    WireOptions wire;
    wire.latencyS = 0.008;
    Sim sim(Variant::Gve64, wire);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    const auto program = denseProgram(1500, 3, 50000, 50000, 400); // 8 ms a vector
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front());
    const JobReport &r = sim.core.jobReport();
    EXPECT_LT(r.maxStreamPollGapS, 0.25);
    const double hz =
        static_cast<double>(r.streamPolls - 1) / (r.lastStreamPollS - r.firstStreamPollS);
    EXPECT_GE(hz, 19.0);
    EXPECT_EQ(sim.port.unit().stats().motion.starvationStops, 0);
    for (int a = 0; a < 3; ++a)
        EXPECT_EQ(sim.port.unit().position()[a], program.commands.back().endSteps[a]);
}

// The bundled dense 3D raster (0.04 mm vectors at F3500: twice as many vectors a second as the
// wire carries) planned with the link's pace and streamed at 8 ms latency each way: the unit
// never runs dry mid-chain, so it never stops without braking. Planned without the pace, the
// same job stops dozens of times (the GVE84: hundreds).
TEST(MachineCore, DenseRasterPlannedAtTheLinksPaceNeverRunsDry)
{
    const gcode::Result g = gcode::interpretFile(std::string(FREZKA_SOURCE_DIR) +
                                                 "/tests/bench/planner/programs/surface.nc");
    ASSERT_TRUE(g.ok());
    // The GVE64 (queue 420) paced and not, the GVE84 (queue 64: packets must stay short) paced.
    for (auto [variant, paced] : {std::pair{Variant::Gve64, true}, std::pair{Variant::Gve64, false},
                                  std::pair{Variant::Gve84, true}}) {
        SCOPED_TRACE(std::string(protocol::variantInfo(variant).displayName) +
                     (paced ? " paced" : " not paced"));
        WireOptions wire;
        wire.latencyS = 0.008; // as the profile's link.latencyMs says
        Sim sim(variant, wire);
        machine::PlanOptions options;
        options.wireLimited = paced;
        const machine::PlanResult plan = machine::plan(g.toolpath, sim.config, options);
        ASSERT_TRUE(plan.ok());
        ASSERT_TRUE(sim.connect()) << sim.lastLog();
        ASSERT_FALSE(sim.core.run(plan.program, sim.runner.now()));
        ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600))
            << sim.lastLog();
        EXPECT_TRUE(sim.finished.front());
        const auto motion = sim.port.unit().stats().motion;
        if (paced) {
            EXPECT_EQ(motion.starvationStops, 0);
            EXPECT_EQ(motion.brakeViolations, 0);
        } else {
            EXPECT_GT(motion.starvationStops, 20) << "the test would not see it";
        }
        for (int a = 0; a < 3; ++a)
            EXPECT_EQ(sim.port.unit().position()[a], plan.program.commands.back().endSteps[a]);
    }
}
