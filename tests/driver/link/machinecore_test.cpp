// MachineCore on the in-process emulator (virtual clock): connect, stream, operations.

#include "simfixture.h"
#include "wiretap.h"

#include "gcode/interpreter.h"
#include "gcode/toolpath.h"
#include "machine/planner.h"
#include "machine/unitwire.h"

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

namespace {

machine::Steps4 endOf(const machine::UnitProgram &p)
{
    return p.commands.back().endSteps;
}

void expectAt(Sim &sim, const machine::Steps4 &want)
{
    const auto pos = sim.port.unit().position();
    for (int a = 0; a < 3; ++a)
        EXPECT_EQ(pos[a], want[a]) << "axis " << a << "\n" << sim.lastLog();
}

} // namespace

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

// X steps a second over `seconds` of the emulator's time (the job's vectors run along X).
double xRate(Sim &sim, double seconds)
{
    const auto from = sim.port.unit().position()[0];
    sim.runner.runFor(seconds);
    return static_cast<double>(sim.port.unit().position()[0] - from) / seconds;
}

// A new feed given when the tool is lowered is the feed override from there on (issue 14): XM
// on the wire, no XA (which set only the queued vectors, all to one speed, and let the vectors
// streamed after them run at the planned speed again while the window showed the new one).
TEST(MachineCore, ANewFeedAfterALiftHoldsForTheRestOfTheJob)
{
    Sim sim;
    WireTap tap(sim.port);
    ASSERT_TRUE(sim.connect());
    const auto program = slowProgram(300); // X 400 steps a vector at V4000
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    sim.runner.runFor(3.0);
    EXPECT_NEAR(xRate(sim, 1.0), 4000, 200);
    ASSERT_FALSE(sim.core.pause(sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Paused));
    ASSERT_FALSE(sim.core.toolLift(false, sim.runner.now())) << sim.lastLog();
    ASSERT_TRUE(sim.until(MachineMode::ToolLifted)) << sim.lastLog();
    const std::size_t lower = tap.size();
    ASSERT_FALSE(sim.core.toolLower(2000, sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Paused)) << sim.lastLog();
    EXPECT_EQ(sim.core.state().overridePercent, 50);
    EXPECT_EQ(tap.matching("!0XA", lower).size(), 0u);
    ASSERT_EQ(tap.matching("!0XM", lower).size(), 1u);
    EXPECT_EQ(tap.matching("!0XM", lower)[0], "!0XM50");
    ASSERT_FALSE(sim.core.resume(sim.runner.now())) << sim.lastLog();
    sim.runner.runFor(1.0);
    EXPECT_NEAR(xRate(sim, 1.0), 2000, 100) << "the queued vectors at the new feed";
    sim.runner.runFor(8.0); // well past what the unit held when the tool was lowered
    EXPECT_NEAR(xRate(sim, 1.0), 2000, 100) << "the vectors streamed later at the new feed too";
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front());
    expectAt(sim, endOf(program));
    EXPECT_EQ(sim.core.state().overridePercent, 50) << "the window shows what the unit runs";
}

// A program whose V changes after more than the GVE64's queue holds: 500 vectors at V3000, then
// 150 at V4000.
machine::UnitProgram twoSpeedProgram()
{
    ProgramBuilder b(3);
    b.add(machine::UnitOp::Accel, 200);
    b.add(machine::UnitOp::Brake, 4000);
    for (const auto [v, n] : {std::pair{3000, 500}, std::pair{4000, 150}}) {
        b.add(machine::UnitOp::Speed, v);
        for (int i = 0; i < n; ++i)
            b.add(machine::UnitOp::Vector, 0, {400, 0, 0, 0}, static_cast<std::uint32_t>(10 + i));
    }
    b.add(machine::UnitOp::ProgramEnd, 0);
    return b.program;
}

// A unit without XM (GVE64 before v19): XD lowers only the queued speeds, so the driver streams
// every later V lowered alike and the percentage shown is what the rest of the job runs; above 100
// % nothing would keep the axes under their maxima (no VL), so XU stops there; a new feed at the
// tool's lowering is refused with the reason.
TEST(MachineCore, OverrideStepsWithoutXmHoldForTheRestOfTheJob)
{
    Sim sim(protocol::Variant::Gve64, {}, {}, false, "IP64MPG v18 1.2.2010");
    sim.config.unit.firmwareVersion = 18;
    sim.core.setConfig(sim.config);
    WireTap tap(sim.port);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_FALSE(sim.core.state().features.vlVkXmNa);
    const auto refusedUp = sim.core.overrideStep(true, sim.runner.now());
    ASSERT_TRUE(refusedUp.has_value());
    EXPECT_EQ(refusedUp->reason.code, DriverCode::OverrideAboveWithoutVl);
    const auto program = twoSpeedProgram();
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    sim.runner.runFor(2.0);
    EXPECT_NEAR(xRate(sim, 1.0), 3000, 150);
    const std::size_t before = tap.size();
    for (int i = 0; i < 2; ++i) {
        ASSERT_FALSE(sim.core.overrideStep(false, sim.runner.now())) << sim.lastLog();
        sim.runner.runFor(0.2);
    }
    EXPECT_EQ(tap.matching("!0XD", before).size(), 2u);
    EXPECT_EQ(sim.core.state().overridePercent, 88); // (15/16)^2 = 87.9 %
    EXPECT_NEAR(xRate(sim, 1.0), 3000 * 225.0 / 256.0, 150);
    // The second V is streamed after the XD: lowered alike (4000 x 225/256 = 3516).
    ASSERT_TRUE(sim.runner.runUntil([&] { return !tap.matching("!0V", before).empty(); }, 300));
    EXPECT_EQ(tap.matching("!0V", before)[0], "!0V3516");
    ASSERT_TRUE(
        sim.runner.runUntil([&] { return sim.port.unit().position()[0] > 510 * 400; }, 300));
    const double r = xRate(sim, 1.0);
    EXPECT_NEAR(r, 3516, 150) << "the later vectors at the percentage shown";
    ASSERT_FALSE(sim.core.overrideStep(true, sim.runner.now()));
    sim.runner.runFor(0.2);
    EXPECT_EQ(sim.core.state().overridePercent, 93);
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front());
    EXPECT_EQ(sim.port.unit().position()[0], program.commands.back().endSteps[0]);
    EXPECT_EQ(sim.port.unit().stats().motion.brakeViolations, 0);
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

TEST(MachineCore, SpindleOutputsOverride)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.setSpindleRpm(sim.config.spindle.maxRpm * 0.3, sim.runner.now()));
    ASSERT_FALSE(sim.core.setOutputs(0x04, 0x04, sim.runner.now())); // coolant (OUT1) on
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

namespace {

machine::UnitProgram probeProgram(gcode::ProbeKind kind, std::int32_t dz, bool moveAfter)
{
    using machine::UnitOp;
    machine::UnitProgram p;
    p.axisCount = 3;
    auto add = [&p](UnitOp op, std::int64_t value, std::array<std::int32_t, 4> d,
                    std::int32_t aux) {
        machine::UnitCommand c;
        c.op = op;
        c.value = value;
        c.d = d;
        c.aux = aux;
        c.sourceLine = static_cast<std::uint32_t>(p.commands.size() + 1);
        c.endSteps = p.commands.empty() ? p.startSteps : p.commands.back().endSteps;
        for (int a = 0; a < 4; ++a)
            c.endSteps[a] += d[a];
        p.commands.push_back(c);
    };
    add(UnitOp::Accel, 50, {}, 0);
    add(UnitOp::Speed, 2000, {}, 0);
    add(UnitOp::Probe, 0, {0, 0, dz, 0}, static_cast<std::int32_t>(kind));
    if (moveAfter)
        add(UnitOp::Line, 0, {100, 0, 0, 0}, 0);
    add(UnitOp::ProgramEnd, 0, {}, 0);
    return p;
}

} // namespace

TEST(MachineCore, ProbeStopsAtContact)
{
    Sim sim;
    sim.config.eeprom.polarityHigh = 0x80; // IN15 contact reads 1 in the emulator
    sim.core.setConfig(sim.config);
    // The probe touches when Z reaches -1000 steps.
    sim.port.unit().setSwitches({{15, 2, -1000, -1}});
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.run(probeProgram(gcode::ProbeKind::TowardErrorIfNoContact, -3000, false),
                              sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 120)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front()) << sim.lastLog();
    EXPECT_TRUE(sim.core.state().probeTripped);
    const auto z = sim.core.state().probeSteps[2];
    EXPECT_LE(z, -1000);
    EXPECT_GT(z, -3000);
    EXPECT_EQ(sim.port.unit().position()[2], z);
}

TEST(MachineCore, ProbeWithoutContactIsAnErrorForG38_2)
{
    Sim sim;
    sim.config.eeprom.polarityHigh = 0x80;
    sim.core.setConfig(sim.config);
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.run(probeProgram(gcode::ProbeKind::TowardErrorIfNoContact, -500, true),
                              sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 120)) << sim.lastLog();
    EXPECT_FALSE(sim.finished.front());
    EXPECT_EQ(sim.core.state().mode, MachineMode::Alarm);
    ASSERT_FALSE(sim.errors.empty());
    EXPECT_NE(sim.errors.back().message.find("without the probe tripping"), std::string::npos);
    // G38.3: no contact is fine and the program goes on from the planned end point.
    Sim sim3;
    sim3.config.eeprom.polarityHigh = 0x80;
    sim3.core.setConfig(sim3.config);
    ASSERT_TRUE(sim3.connect());
    const auto p = probeProgram(gcode::ProbeKind::Toward, -500, true);
    ASSERT_FALSE(sim3.core.run(p, sim3.runner.now()));
    ASSERT_TRUE(sim3.runner.runUntil([&] { return !sim3.finished.empty(); }, 120))
        << sim3.lastLog();
    EXPECT_TRUE(sim3.finished.front()) << sim3.lastLog();
    expectAt(sim3, endOf(p));
}

TEST(MachineCore, ProbeTrippedWithMotionAfterEndsTheJob)
{
    Sim sim;
    sim.config.eeprom.polarityHigh = 0x80;
    sim.core.setConfig(sim.config);
    sim.port.unit().setSwitches({{15, 2, -1000, -1}});
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(
        sim.core.run(probeProgram(gcode::ProbeKind::Toward, -3000, true), sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 120)) << sim.lastLog();
    EXPECT_FALSE(sim.finished.front());
    ASSERT_FALSE(sim.errors.empty());
    EXPECT_NE(sim.errors.back().message.find("plan it again"), std::string::npos);
    EXPECT_EQ(sim.port.unit().position()[0], 0) << "nothing after the probe ran";
}

TEST(MachineCore, BuiltInEmulatorHoldsTheProfilesEeprom)
{
    for (Variant v : {Variant::Gve64, Variant::Gve114}) {
        Sim sim(v, {}, {}, true);
        ASSERT_TRUE(sim.connect());
        EXPECT_TRUE(sim.core.state().eepromDifferences.empty())
            << sim.core.state().eepromDifferences.front().text;
    }
}

TEST(MachineCore, EepromComparedOnConnectWrittenOnlyWhenAsked)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    const auto differences = sim.core.state().eepromDifferences;
    ASSERT_FALSE(differences.empty()) << "the emulator's defaults differ from the profile";
    const auto before = sim.port.unit().eepromByte(0x01);
    sim.runner.runFor(1.0);
    EXPECT_EQ(sim.port.unit().eepromByte(0x01), before) << "connecting never writes";
    ASSERT_FALSE(sim.core.writeEeprom(sim.runner.now()));
    sim.runner.runFor(2.0);
    EXPECT_TRUE(sim.core.state().eepromDifferences.empty())
        << sim.core.state().eepromDifferences.front().text;
    EXPECT_TRUE(sim.errors.empty()) << sim.errors.front().message;
}

// An older GVE64 firmware (v17: no VK/VL/XM/N<axis>): with a profile that says so, connecting
// sends nothing the unit lacks, a plan in VN runs (its VN is not sent: the unit knows no modes),
// a plan in VK and the XM override are refused with the reason, and homing zeroes all counters
// with N. With a profile that promises v19 the connect ends in an Alarm that names the fix.
TEST(MachineCore, OlderFirmwareGatesFeatures)
{
    const std::string firmware = "IP64MPG v17 1.2.2009";
    Sim sim(Variant::Gve64, {}, {}, false, firmware);
    sim.config.unit.firmwareVersion = 17;
    sim.core.setConfig(sim.config);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    EXPECT_TRUE(sim.errors.empty()) << sim.lastLog();
    EXPECT_EQ(sim.core.state().firmwareVersion, 17);
    EXPECT_FALSE(sim.core.state().features.vlVkXmNa);
    EXPECT_TRUE(sim.core.state().features.mpg);

    auto program = denseProgram(50);
    machine::UnitCommand mode;
    mode.op = machine::UnitOp::SpeedModeVk;
    program.commands.insert(program.commands.begin(), mode);
    auto refused = sim.core.run(program, sim.runner.now());
    ASSERT_TRUE(refused);
    EXPECT_NE(refused->message.find("VK"), std::string::npos) << refused->message;
    program.commands.front().op = machine::UnitOp::SpeedModeVn;
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 60)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front()) << sim.lastLog();
    EXPECT_EQ(sim.port.unit().position()[0], program.commands.back().endSteps[0]);
    EXPECT_TRUE(sim.errors.empty()) << sim.lastLog();

    auto xm = sim.core.setOverride(120, sim.runner.now());
    ASSERT_TRUE(xm);
    EXPECT_NE(xm->message.find("v19"), std::string::npos) << xm->message;
}

// Homing on v17: one axis alone is refused (its counter cannot be set by itself); all axes with
// home position 0 end with N, every counter 0.
TEST(MachineCore, OlderFirmwareHomesWithN)
{
    Sim sim(Variant::Gve64, {}, {}, true, "IP64MPG v17 1.2.2009");
    sim.config.unit.firmwareVersion = 17;
    for (auto &ax : sim.config.axes)
        ax.homing.homePositionMm = 0;
    sim.config.axes[3].present = false; // the profile homes X, Y and Z; N also zeroes A
    sim.core.setConfig(sim.config);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    auto one = sim.core.home(sim.runner.now(), 0x1);
    ASSERT_TRUE(one);
    EXPECT_NE(one->message.find("N<axis>"), std::string::npos) << one->message;
    const auto homing = sim.core.home(sim.runner.now());
    ASSERT_FALSE(homing) << homing->message;
    ASSERT_TRUE(sim.runner.runUntil(
        [&] { return sim.core.state().mode == MachineMode::Idle && sim.core.state().homed; }, 120))
        << sim.lastLog();
    EXPECT_TRUE(sim.errors.empty()) << sim.lastLog();
    for (int a = 0; a < sim.core.state().axisCount; ++a)
        EXPECT_EQ(sim.port.unit().position()[a], 0) << "axis " << a;
    bool sawN = false;
    for (const std::string &line : sim.log)
        sawN = sawN || line.rfind("> !0N,", 0) == 0 || line == "> !0N";
    EXPECT_TRUE(sawN) << sim.lastLog(60);
}

TEST(MachineCore, FirmwareOlderThanTheProfileIsAnAlarm)
{
    Sim sim(Variant::Gve64, {}, {}, false, "IP64MPG v17 1.2.2009"); // the profile says v19
    sim.connect();
    ASSERT_TRUE(sim.until(MachineMode::Alarm)) << sim.lastLog();
    ASSERT_FALSE(sim.errors.empty());
    EXPECT_NE(sim.errors.front().message.find("unit.firmwareVersion to 17"), std::string::npos)
        << sim.errors.front().message;
    for (const std::string &line : sim.log)
        EXPECT_EQ(line.find("unknown command"), std::string::npos) << line;
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

// Before IP64MPG v10 a GVE64 has no W (manual §14.1): homing is refused with the reason and
// nothing reaches the wire; the unit's counters stay where they were.
TEST(MachineCore, FirmwareBeforeV10RefusesHomingToASwitch)
{
    Sim sim(Variant::Gve64, {}, {}, false, "IP64 v9 1.2.2008");
    sim.config.unit.firmwareVersion = 9;
    sim.config.eeprom.mpg = machine::MpgMode::Off;
    sim.config.eeprom.sync = false;
    sim.core.setConfig(sim.config);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    EXPECT_TRUE(sim.errors.empty()) << sim.lastLog();
    EXPECT_FALSE(sim.core.state().features.switchHoming);
    const auto refused = sim.core.home(sim.runner.now());
    ASSERT_TRUE(refused);
    EXPECT_NE(refused->message.find("has no W"), std::string::npos) << refused->message;
    sim.runner.runFor(1.0);
    for (const std::string &line : sim.log)
        EXPECT_EQ(line.rfind("> !0W", 0), std::string::npos) << line;
    EXPECT_FALSE(sim.core.state().homed);
}

// A GVE114 profile at 921 600 Bd needs the unit's EEPROM 0x0D = 01: connecting to a unit set
// for the low range names the byte among the differences, and writing (asked) sets it.
TEST(MachineCore, Gve114FastBaudRangeIsCheckedAndWrittenWhenAsked)
{
    Sim sim(Variant::Gve114);
    sim.config.link.baud = 921600;
    sim.core.setConfig(sim.config);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    EXPECT_EQ(sim.port.unit().eepromByte(0x0D), 0xFF);
    bool named = false;
    for (const EepromDifference &d : sim.core.state().eepromDifferences)
        named = named || d.text.find("baud range") != std::string::npos;
    EXPECT_TRUE(named) << sim.lastLog();
    ASSERT_FALSE(sim.core.writeEeprom(sim.runner.now()));
    sim.runner.runFor(2.0);
    EXPECT_EQ(sim.port.unit().eepromByte(0x0D), 0x01);
    EXPECT_TRUE(sim.errors.empty()) << sim.errors.front().message;
}

// Connecting sets VL from the profile's axis maxima, so that the feed override at its top
// (XM200) drives no axis over its maximum: X is sampled every 10 ms of the emulator's time.
TEST(MachineCore, FeedOverrideIsCappedByTheAxisMaxima)
{
    Sim sim;
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    const auto vl = machine::axisSpeedLimits(sim.config); // X 4000 mm/min x 200 steps/mm
    EXPECT_EQ(vl[0], 13333);
    bool sawVl = false;
    for (const std::string &line : sim.log)
        sawVl = sawVl || line == "> !0VL13333,13333,6666,50000";
    EXPECT_TRUE(sawVl) << sim.lastLog(80);
    ASSERT_FALSE(sim.core.setOverride(kOverrideMaxPercent, sim.runner.now()));
    const auto program = denseProgram(30, 3, 13000, 13000, 4000);
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    double peak = 0;
    auto last = sim.port.unit().position()[0];
    while (sim.finished.empty() && sim.runner.now() < 120) {
        sim.runner.runFor(0.01);
        const auto x = sim.port.unit().position()[0];
        peak = std::max(peak, std::abs(double(x - last)) / 0.01);
        last = x;
    }
    ASSERT_FALSE(sim.finished.empty()) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front()) << sim.lastLog();
    EXPECT_GT(peak, 10000.0) << "the job ran at speed";
    EXPECT_LE(peak, vl[0] * 1.02) << "X over its maximum with XM" << kOverrideMaxPercent;
    EXPECT_EQ(sim.port.unit().position()[0], program.commands.back().endSteps[0]);
}

// An override the link cannot feed: 9 600 Bd carries a 120-step vector in about as long as the
// unit runs it at 4 000 pulses/s, so XM200 would run the queue dry. The driver holds XM at what
// the link can feed while the job streams, shows that ceiling beside the operator's 200 %, and
// sends the operator's XM again when the job has ended.
TEST(MachineCore, AnOverrideTheLinkCannotFeedIsHeldToWhatItCan)
{
    Sim sim(protocol::Variant::Gve64, WireOptions{.baud = 9600});
    sim.config.link.baud = 9600;
    sim.core.setConfig(sim.config);
    WireTap tap(sim.port);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    const auto program = denseProgram(400, 3, 4000, 4000, 300);
    ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil(
        [&] { return sim.port.unit().stats().motion.vectorsExecuted > 20; }, 30));
    const std::size_t before = tap.size();
    ASSERT_FALSE(sim.core.setOverride(200, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return sim.core.state().overridePercent == 200; }, 5));
    int lowest = 0, highest = 0;
    while (sim.finished.empty() && sim.runner.now() < 120) {
        const driver::MachineState &s = sim.core.state();
        EXPECT_EQ(s.overridePercent, 200) << "the operator's word is kept";
        if (s.overrideCeilingPercent > 0) {
            lowest = lowest ? std::min(lowest, s.overrideCeilingPercent) : s.overrideCeilingPercent;
            highest = std::max(highest, s.overrideCeilingPercent);
        }
        sim.runner.runFor(0.05);
    }
    ASSERT_FALSE(sim.finished.empty()) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front()) << sim.lastLog();
    EXPECT_GT(lowest, 100) << "the link feeds more than 100 % here";
    EXPECT_LT(highest, 200) << "the link cannot feed XM200 here";
    const auto xm = tap.matching("!0XM", before);
    ASSERT_GE(xm.size(), 2u);
    for (std::size_t i = 0; i + 1 < xm.size(); ++i) {
        const int percent = std::stoi(xm[i].substr(4));
        EXPECT_GE(percent, lowest) << xm[i];
        EXPECT_LE(percent, highest) << xm[i];
    }
    EXPECT_LE(xm.size(), 8u) << "XM follows the ceiling without a command storm";
    sim.runner.runFor(0.5);
    EXPECT_EQ(tap.matching("!0XM", before).back(), "!0XM200") << "the operator's XM after the job";
    EXPECT_EQ(sim.core.state().overrideCeilingPercent, 0);
    EXPECT_EQ(sim.port.unit().stats().motion.starvationStops, 0);
    EXPECT_EQ(sim.port.unit().stats().motion.brakeViolations, 0);
    EXPECT_EQ(sim.port.unit().position()[0], program.commands.back().endSteps[0]);
}

// With XM the ± steps are exact multipliers (1/16 each way) that stay within the slider's range.
TEST(MachineCore, OverrideStepsAreExactXmMultipliers)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    for (int i = 0; i < 20; ++i) {
        ASSERT_FALSE(sim.core.overrideStep(true, sim.runner.now()));
        sim.runner.runFor(0.1);
    }
    EXPECT_EQ(sim.core.state().overridePercent, kOverrideMaxPercent);
    bool sawXm = false, sawXu = false;
    for (const std::string &line : sim.log) {
        sawXm = sawXm || line == "> !0XM200";
        sawXu = sawXu || line == "> !0XU";
    }
    EXPECT_TRUE(sawXm) << sim.lastLog(60);
    EXPECT_FALSE(sawXu) << "XU changes only the queued vectors";
}
