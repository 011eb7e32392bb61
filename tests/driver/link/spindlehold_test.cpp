// Issue 14: the spindle and the outputs follow the operator's word through pauses, tool lifts,
// M0/M6 and Abort, judged by what reaches the wire (the commands the core sends, with the time)
// and by what the emulated unit did (its spindle, outputs, counters and safety counters).

#include "simfixture.h"
#include "wiretap.h"

#include "gcode/interpreter.h"
#include "machine/planner.h"

#include <gtest/gtest.h>

#include <algorithm>

namespace frezka::driver::test {
namespace {

using machine::UnitProgram;

UnitProgram planText(const char *text, const machine::MachineConfig &config)
{
    const gcode::Result g = gcode::interpretText(text);
    EXPECT_TRUE(g.ok());
    machine::PlanResult p = machine::plan(g.toolpath, config);
    EXPECT_TRUE(p.ok());
    return p.program;
}

// A slow cut with the spindle and coolant on: 12000 rpm of 24000 = !7V500, M8 = OUT1 (bit2).
const char *kCut = "G21 G90\nM3 S12000\nM8\nG0 X10 Y10\nG0 Z-8\nG1 Z-10 F600\nG1 X60 F300\n"
                   "G1 Y40\nG1 X10\nG1 Y10\nG0 Z0\nM9\nM5\nM2\n";

constexpr std::uint8_t kCoolantBit = 0x04; // OUT1, active low
constexpr double kSpinUpS = 2.0;           // the default profile's spindle.spinUpMs

// The core on the emulator of the default GVE64 profile (spin-up 2 s, axis maxima, switches),
// every command sent recorded with its time.
struct Wire
{
    struct Sent
    {
        double t;
        std::string text;
    };

    explicit Wire(CoreOptions options = {})
        : sim(protocol::Variant::Gve64, {}, options, true)
    {
        auto previous = sim.core.onLog;
        sim.core.onLog = [this, previous](const std::string &line) {
            if (line.rfind("> ", 0) == 0)
                sent.push_back({sim.runner.now(), line.substr(2)});
            previous(line);
        };
    }
    // Index of the first command starting with `prefix` at or after `from`, or npos.
    std::size_t find(const std::string &prefix, std::size_t from = 0) const
    {
        for (std::size_t i = from; i < sent.size(); ++i) {
            if (sent[i].text.rfind(prefix, 0) == 0)
                return i;
        }
        return std::string::npos;
    }
    bool until(const std::function<bool()> &done, double limitS = 120)
    {
        return sim.runner.runUntil(done, limitS);
    }
    const MachineState &state() const { return sim.core.state(); }
    emulator::Unit &unit() { return sim.port.unit(); }
    // Runs kCut-like programs until the tool is in the cut with the spindle at speed.
    void startCut(const UnitProgram &program)
    {
        ASSERT_TRUE(sim.connect());
        ASSERT_FALSE(sim.core.run(program, sim.runner.now()));
        ASSERT_TRUE(until([&] { return unit().position()[0] > 2400; })) << sim.lastLog();
        ASSERT_TRUE(unit().spindleTurning());
    }
    // Lowers the lifted tool: the spindle on again (!7V500) and spun up before Z goes down into
    // the work; the index in `sent` where the lowering began.
    std::size_t lowerAtSpeed()
    {
        const std::size_t lower = sent.size();
        EXPECT_FALSE(sim.core.toolLower(0, sim.runner.now()));
        EXPECT_TRUE(until([&] { return state().mode == MachineMode::Paused; })) << sim.lastLog();
        const std::size_t on = find("!7V500", lower);
        const std::size_t down = find("!0L0,0,-", lower);
        EXPECT_NE(on, std::string::npos);
        EXPECT_NE(down, std::string::npos);
        if (on != std::string::npos && down != std::string::npos) {
            EXPECT_LT(on, down);
            EXPECT_GE(sent[down].t - sent[on].t, kSpinUpS) << "Z goes down only at speed";
        }
        return lower;
    }
    void expectCleanEnd(const UnitProgram &program)
    {
        ASSERT_TRUE(until([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
        EXPECT_TRUE(sim.finished.front()) << sim.lastLog();
        const machine::Steps4 end = program.commands.back().endSteps;
        for (std::size_t a = 0; a < 3; ++a)
            EXPECT_EQ(unit().position()[a], end[a]);
        const emulator::Stats s = unit().stats();
        EXPECT_EQ(s.motion.brakeViolations, 0);
        EXPECT_EQ(s.motion.axisOverMax, 0);
        EXPECT_EQ(s.safety.cutWithoutSpindle, 0);
        EXPECT_EQ(s.safety.spindleOnWhileHeld, 0);
        EXPECT_FALSE(unit().spindleTurning());
    }

    Sim sim;
    std::vector<Sent> sent;
};

TEST(SpindleHold, ProgramOutputsShowInTheState)
{
    Wire w;
    const UnitProgram program = planText(kCut, w.sim.config);
    w.startCut(program);
    EXPECT_TRUE(w.state().spindleOn);
    EXPECT_EQ(w.state().spindlePermille, 500);
    EXPECT_EQ(w.state().outputs & (kCoolantBit | 0x01), 0) << "coolant and OUT0 on (active low)";
    EXPECT_EQ(w.state().outputs, w.unit().outputs());
    w.expectCleanEnd(program);
    EXPECT_FALSE(w.state().spindleOn);
    EXPECT_EQ(w.state().outputs, 0xFF);
    // Idle with the counters where the machine stopped, before any poll: what the next console
    // line or jog is planned from.
    for (std::size_t a = 0; a < 3; ++a)
        EXPECT_EQ(w.state().positionSteps[a], w.unit().position()[a]) << "axis " << a;
}

TEST(SpindleHold, PauseWithSpindleStopThenResumeSpinsUpBeforeTheCut)
{
    Wire w;
    const UnitProgram program = planText(kCut, w.sim.config);
    w.startCut(program);
    ASSERT_FALSE(w.sim.core.pause(w.sim.runner.now(), true));
    ASSERT_TRUE(w.until([&] {
        return w.state().mode == MachineMode::Paused && !w.state().spindleOn &&
               w.state().outputs == 0xFF;
    })) << w.sim.lastLog();
    const std::size_t h = w.find("!0H");
    ASSERT_NE(h, std::string::npos);
    EXPECT_NE(w.find("!7V0", h), std::string::npos) << "the spindle off on the wire after H";
    EXPECT_FALSE(w.unit().spindleTurning());
    EXPECT_EQ(w.unit().outputs() & kCoolantBit, kCoolantBit) << "coolant off at the unit";
    EXPECT_TRUE(w.state().outputsHeld);
    w.sim.runner.runFor(3);
    const std::size_t before = w.sent.size();
    ASSERT_FALSE(w.sim.core.resume(w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::Running; })) << w.sim.lastLog();
    const std::size_t on = w.find("!7V500", before);
    const std::size_t go = w.find("!0G", before);
    ASSERT_NE(on, std::string::npos);
    ASSERT_NE(go, std::string::npos);
    EXPECT_LT(on, go);
    EXPECT_GE(w.sent[go].t - w.sent[on].t, kSpinUpS) << "G only once the spindle is at speed";
    EXPECT_NE(w.find("!0O0,", on), std::string::npos) << "coolant on again";
    w.expectCleanEnd(program);
}

TEST(SpindleHold, ToolLiftStopsTheSpindleAndLowersOnlyAtSpeed)
{
    Wire w;
    const UnitProgram program = planText(kCut, w.sim.config);
    w.startCut(program);
    ASSERT_FALSE(w.sim.core.pause(w.sim.runner.now())); // without the box: the lift stops it
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::Paused; }));
    const std::size_t lift = w.sent.size();
    ASSERT_FALSE(w.sim.core.toolLift(false, w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::ToolLifted; }))
        << w.sim.lastLog();
    const std::size_t k = w.find("!0K", lift);
    ASSERT_NE(k, std::string::npos);
    EXPECT_NE(w.find("!7V0", k), std::string::npos);
    EXPECT_FALSE(w.unit().spindleTurning()) << "the tool stands lifted, the spindle off";
    EXPECT_EQ(w.unit().outputs() & kCoolantBit, kCoolantBit);
    w.sim.runner.runFor(5);
    const std::size_t lower = w.lowerAtSpeed();
    EXPECT_LT(w.find("!0L0,0,-", lower), w.find("!0R", lower));
    ASSERT_FALSE(w.sim.core.resume(w.sim.runner.now()));
    w.expectCleanEnd(program);
}

TEST(SpindleHold, JogWhileLiftedReturnsToTheLiftPointBeforeLowering)
{
    Wire w;
    const UnitProgram program = planText(kCut, w.sim.config);
    w.startCut(program);
    ASSERT_FALSE(w.sim.core.pause(w.sim.runner.now(), true));
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::Paused; }));
    ASSERT_FALSE(w.sim.core.toolLift(true, w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::ToolLifted; }));
    const auto liftPoint = w.unit().position();
    const std::size_t sentBefore = w.sent.size();
    const auto continuous = w.sim.core.jogContinuous(0, 1, 1200, w.sim.runner.now());
    ASSERT_TRUE(continuous.has_value()) << "a continuous jog's stop would need H and D beside K";
    EXPECT_EQ(continuous->reason.code, DriverCode::ContinuousJogWhileLifted);
    EXPECT_EQ(w.sent.size(), sentBefore) << "nothing sent";
    auto jog = [&](int axis, double mm) {
        const auto before = w.unit().position();
        ASSERT_FALSE(w.sim.core.jogStep(axis, mm, 1200, w.sim.runner.now())) << w.sim.lastLog();
        ASSERT_TRUE(w.until([&] { return w.unit().position() != before && !w.unit().isMoving(); }));
        w.sim.runner.runFor(0.5);
    };
    jog(0, 20);
    jog(1, -5);
    jog(2, 3); // up: the emulator knows no work surface here, so any Z down counts as a cut
    EXPECT_EQ(w.state().mode, MachineMode::ToolLifted);
    EXPECT_NE(w.unit().position(), liftPoint);
    const std::size_t lower = w.sent.size();
    ASSERT_FALSE(w.sim.core.toolLower(0, w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.find("!0L0,0,-1000", lower) != std::string::npos; }))
        << w.sim.lastLog();
    EXPECT_EQ(w.unit().position(), liftPoint) << "exactly back at the lift point first";
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::Paused; })) << w.sim.lastLog();
    ASSERT_FALSE(w.sim.core.resume(w.sim.runner.now()));
    w.expectCleanEnd(program);
}

TEST(SpindleHold, AbortWhileLiftedEndsTheJobToolUpSpindleOff)
{
    Wire w;
    const UnitProgram program = planText(kCut, w.sim.config);
    w.startCut(program);
    ASSERT_FALSE(w.sim.core.pause(w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::Paused; }));
    ASSERT_FALSE(w.sim.core.toolLift(false, w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::ToolLifted; }));
    const auto lifted = w.unit().position();
    const std::size_t abort = w.sent.size();
    ASSERT_FALSE(w.sim.core.abort(w.sim.runner.now())) << "an operator with a broken tool";
    ASSERT_TRUE(w.until([&] { return !w.sim.finished.empty(); })) << w.sim.lastLog();
    EXPECT_FALSE(w.sim.finished.front());
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::Idle; })) << w.sim.lastLog();
    EXPECT_LT(w.find("!0R", abort), w.find("!0D", abort)) << "the kept queue back, then dropped";
    EXPECT_EQ(w.unit().position(), lifted) << "the job ends where it is, the tool up";
    EXPECT_EQ(w.unit().queueLength(), 0u);
    EXPECT_FALSE(w.unit().spindleTurning());
    EXPECT_EQ(w.unit().stats().safety.cutWithoutSpindle, 0);
    // The unit holds nothing aside any more: it takes a C again (under K it refuses one).
    ASSERT_FALSE(w.sim.core.sendRaw("C0,0,10", w.sim.runner.now())) << w.sim.lastLog();
    ASSERT_TRUE(w.until([&] { return w.unit().position()[2] == lifted[2] + 10; }))
        << w.sim.lastLog();
}

TEST(SpindleHold, AbortSwitchesSpindleAndCoolantOff)
{
    Wire w;
    const UnitProgram program = planText(kCut, w.sim.config);
    w.startCut(program);
    const std::size_t abort = w.sent.size();
    ASSERT_FALSE(w.sim.core.abort(w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::Idle; })) << w.sim.lastLog();
    const std::size_t h = w.find("!0H", abort);
    ASSERT_NE(h, std::string::npos);
    EXPECT_NE(w.find("!7V0", h), std::string::npos);
    EXPECT_FALSE(w.unit().spindleTurning());
    EXPECT_EQ(w.unit().outputs(), 0xFF);
    EXPECT_FALSE(w.state().spindleOn);
    EXPECT_EQ(w.state().outputs, 0xFF);
}

TEST(SpindleHold, ToolChangeStopsTheSpindleAndContinuesAtSpeed)
{
    Wire w;
    const UnitProgram program =
        planText("G21 G90\nM3 S12000\nM8\nG0 X10 Y10\nG1 Z-10 F600\nG1 X30 F600\nG0 Z-5\nT2 M6\n"
                 "G1 Z-10 F600\nG1 X10 F600\nG0 Z0\nM9\nM5\nM2\n",
                 w.sim.config);
    ASSERT_TRUE(w.sim.connect());
    ASSERT_FALSE(w.sim.core.run(program, w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] {
        return w.state().mode == MachineMode::Paused &&
               w.state().hold == HoldReason::OperatorStop && !w.state().spindleOn &&
               w.state().outputs == 0xFF;
    })) << w.sim.lastLog();
    EXPECT_NE(w.find("!7V0"), std::string::npos) << "M6 switches the spindle off on the wire";
    EXPECT_FALSE(w.unit().spindleTurning());
    EXPECT_EQ(w.unit().outputs() & kCoolantBit, kCoolantBit);
    const std::size_t before = w.sent.size();
    w.sim.runner.runFor(4);
    ASSERT_FALSE(w.sim.core.resume(w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.unit().spindleTurning(); }));
    EXPECT_NE(w.find("!7V500", before), std::string::npos);
    w.expectCleanEnd(program);
}

TEST(SpindleHold, ProgramStopFollowsTheProfile)
{
    Wire w;
    w.sim.config.spindle.stopAtProgramStop = false; // this machine keeps turning at M0
    w.sim.core.setConfig(w.sim.config);
    const UnitProgram program = planText(
        "G21 G90\nM3 S12000\nG0 X10 Y10\nG0 Z-1\nM0\nG1 X20 F600\nG0 Z0\nM5\nM2\n", w.sim.config);
    ASSERT_TRUE(w.sim.connect());
    ASSERT_FALSE(w.sim.core.run(program, w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.state().hold == HoldReason::OperatorStop; }));
    w.sim.runner.runFor(1);
    EXPECT_TRUE(w.unit().spindleTurning());
    EXPECT_EQ(w.find("!7V0"), std::string::npos);
}

// With the shipped profile (spindle.stopAtProgramStop on), M0 switches the spindle off on the
// wire, and Continue switches it on again and waits its spin-up before the next cut.
TEST(SpindleHold, ProgramStopSwitchesTheSpindleOffByDefault)
{
    Wire w;
    ASSERT_TRUE(w.sim.config.spindle.stopAtProgramStop);
    const UnitProgram program = planText(
        "G21 G90\nM3 S12000\nG0 X10 Y10\nG0 Z-1\nM0\nG1 X20 F600\nG0 Z0\nM5\nM2\n", w.sim.config);
    ASSERT_TRUE(w.sim.connect());
    ASSERT_FALSE(w.sim.core.run(program, w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] {
        return w.state().hold == HoldReason::OperatorStop && !w.state().spindleOn;
    })) << w.sim.lastLog();
    EXPECT_NE(w.find("!7V0"), std::string::npos) << "M0 switches the spindle off on the wire";
    EXPECT_FALSE(w.unit().spindleTurning());
    w.sim.runner.runFor(3);
    const std::size_t before = w.sent.size();
    ASSERT_FALSE(w.sim.core.resume(w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.unit().position()[0] > 2400; })) << w.sim.lastLog();
    const std::size_t on = w.find("!7V500", before);
    ASSERT_NE(on, std::string::npos);
    // The first command after the spin-up that is not a poll: the job's next motion.
    std::size_t cut = on + 1;
    while (cut < w.sent.size() && (w.sent[cut].text == "!0P4" || w.sent[cut].text == "!0F" ||
                                   w.sent[cut].text.rfind("!0I", 0) == 0))
        ++cut;
    ASSERT_LT(cut, w.sent.size());
    EXPECT_LT(on, cut);
    EXPECT_GE(w.sent[cut].t - w.sent[on].t, kSpinUpS)
        << "the cut only once the spindle is at speed";
    w.expectCleanEnd(program);
}

// Lift and Lower at an M6 hold: the spindle M6 switched off stays off while the tool is up and
// comes on at its speed, spun up, before Z goes down into the work; the job then ends exact.
TEST(SpindleHold, LowerAfterAToolChangeSpinsUpBeforeTheToolGoesDown)
{
    Wire w;
    const UnitProgram program =
        planText("G21 G90\nM3 S12000\nG0 X10 Y10\nG1 Z-10 F600\nG1 X30 F600\nT2 M6\n"
                 "G1 X10 F600\nG0 Z0\nM5\nM2\n",
                 w.sim.config);
    ASSERT_TRUE(w.sim.connect());
    ASSERT_FALSE(w.sim.core.run(program, w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] {
        return w.state().mode == MachineMode::Paused && w.state().hold == HoldReason::OperatorStop;
    })) << w.sim.lastLog();
    ASSERT_FALSE(w.sim.core.toolLift(true, w.sim.runner.now())) << w.sim.lastLog();
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::ToolLifted; }))
        << w.sim.lastLog();
    EXPECT_FALSE(w.unit().spindleTurning());
    w.sim.runner.runFor(5);
    EXPECT_FALSE(w.unit().spindleTurning()) << "off while the tool is changed";
    w.lowerAtSpeed();
    ASSERT_FALSE(w.sim.core.resume(w.sim.runner.now()));
    w.expectCleanEnd(program);
}

// On a clean link the driver asks the unit for its command index (@) once, before the first
// command, and logs it as an ordinary command (the console showed it as a recovery); none follow
// through a pause, a tool lift, the lowering and the resume (one resume once logged 858).
TEST(SpindleHold, ACleanLinkNeedsNoIndexQueriesThroughALift)
{
    Wire w;
    WireTap tap(w.sim.port);
    const UnitProgram program = planText(kCut, w.sim.config);
    w.startCut(program);
    EXPECT_EQ(tap.matching("!0@").size(), 1u) << "the index is learnt once, on connecting";
    for (const std::string &line : w.sim.log)
        EXPECT_NE(line.rfind("! ", 0), 0u) << "a recovery logged on a clean link: " << line;
    ASSERT_FALSE(w.sim.core.pause(w.sim.runner.now(), true));
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::Paused; }));
    ASSERT_FALSE(w.sim.core.toolLift(true, w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::ToolLifted; }));
    ASSERT_FALSE(w.sim.core.toolLower(0, w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::Paused; })) << w.sim.lastLog();
    ASSERT_FALSE(w.sim.core.resume(w.sim.runner.now()));
    w.expectCleanEnd(program);
    EXPECT_GT(tap.matching("!0R").size(), 0u) << "the tap reads the wire";
    EXPECT_EQ(tap.matching("!0@").size(), 1u) << "index queries on a clean link";
    for (const std::string &line : w.sim.log)
        EXPECT_NE(line.rfind("! ", 0), 0u) << "a recovery logged on a clean link: " << line;
}

// Issue 16 item 5: the spindle override scales the turning spindle at once (!7V on the wire, the
// emulated unit's speed) and every spindle speed of the rest of the job, a hold's restart too;
// out of range it is refused with nothing sent.
TEST(SpindleOverride, ScalesTheTurningSpindleAndTheRestOfTheJob)
{
    Wire w;
    // 12000 rpm (!7V500), then S6000 (!7V250) after the first side of the cut.
    const UnitProgram program =
        planText("G21 G90\nM3 S12000\nG0 X10 Y10\nG0 Z-8\nG1 Z-10 F600\nG1 X60 F300\n"
                 "S6000\nG1 Y40\nG1 X10\nG0 Z0\nM5\nM2\n",
                 w.sim.config);
    w.startCut(program);
    EXPECT_EQ(w.unit().spindlePermille(), 500);
    const std::size_t before = w.sent.size();
    const auto refused = w.sim.core.execute(op::SetSpindleOverride{151}, w.sim.runner.now());
    ASSERT_TRUE(refused);
    EXPECT_EQ(refused->reason.code, DriverCode::SpindleOverrideRange);
    ASSERT_FALSE(w.sim.core.execute(op::SetSpindleOverride{120}, w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.state().spindlePermille == 600; })) << w.sim.lastLog();
    EXPECT_EQ(w.unit().spindlePermille(), 600);
    EXPECT_EQ(w.find("!7V", before), w.find("!7V600", before)) << "at once, nothing before it";
    EXPECT_EQ(w.state().spindleRpm, 14400);
    EXPECT_EQ(w.state().spindleOverridePercent, 120);
    EXPECT_LT(w.unit().position()[0], 60 * 400) << "while the first side is cut";
    // The program's S6000 at 120 %.
    ASSERT_TRUE(w.until([&] { return w.unit().spindlePermille() == 300; })) << w.sim.lastLog();
    EXPECT_NE(w.find("!7V300", before), std::string::npos);
    EXPECT_EQ(w.find("!7V250", before), std::string::npos) << "the program's own speed unscaled";
    // A pause that stops the spindle, the override lowered meanwhile: the restart at the new one.
    ASSERT_FALSE(w.sim.core.pause(w.sim.runner.now(), true));
    ASSERT_TRUE(w.until(
        [&] { return w.state().mode == MachineMode::Paused && !w.unit().spindleTurning(); }));
    const std::size_t held = w.sent.size();
    ASSERT_FALSE(w.sim.core.execute(op::SetSpindleOverride{50}, w.sim.runner.now()));
    w.sim.runner.runFor(0.5);
    EXPECT_EQ(w.find("!7V", held), std::string::npos) << "a stopped spindle stays stopped";
    ASSERT_FALSE(w.sim.core.resume(w.sim.runner.now()));
    ASSERT_TRUE(w.until([&] { return w.state().mode == MachineMode::Running; })) << w.sim.lastLog();
    EXPECT_NE(w.find("!7V125", held), std::string::npos);
    EXPECT_EQ(w.unit().spindlePermille(), 125);
    w.expectCleanEnd(program);
}

} // namespace
} // namespace frezka::driver::test
