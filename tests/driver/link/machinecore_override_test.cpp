// MachineCore on the in-process emulator (virtual clock): the feed override (XM, XU/XD without
// XM, a new feed after a lift, the axis maxima, the link's ceiling).

#include "simchecks.h"
#include "simfixture.h"
#include "wiretap.h"

#include "machine/unitwire.h"

#include <cmath>
#include <gtest/gtest.h>

using namespace frezka;
using namespace frezka::driver;
using namespace frezka::driver::test;
using protocol::Variant;

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
    for (const auto &[v, n] : {std::pair{3000, 500}, std::pair{4000, 150}}) {
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
        if (s.overrideHeldPercent() > 0) {
            lowest = lowest ? std::min(lowest, s.overrideHeldPercent()) : s.overrideHeldPercent();
            highest = std::max(highest, s.overrideHeldPercent());
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
    EXPECT_EQ(sim.core.state().overrideHeldPercent(), 0);
    EXPECT_EQ(sim.port.unit().stats().motion.starvationStops, 0);
    EXPECT_EQ(sim.port.unit().stats().motion.brakeViolations, 0);
    EXPECT_EQ(sim.port.unit().position()[0], program.commands.back().endSteps[0]);
}

// Connecting sends the XM the window shows: a unit whose multiplier was changed behind the
// window's back (another program, a console XM, a reset to XM100) runs the operator's 150 % again,
// not what it had while the slider says 150. Read from the wire and from the emulator's speed.
TEST(MachineCore, ConnectingSendsTheOverrideShown)
{
    Sim sim;
    WireTap tap(sim.port);
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    ASSERT_FALSE(sim.core.setOverride(150, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return sim.core.state().overridePercent == 150; }, 5));
    ASSERT_FALSE(sim.core.sendRaw("XM100", sim.runner.now()));
    sim.runner.runFor(0.2);
    sim.runner.unplug("cable pulled");
    const std::size_t before = tap.size();
    ASSERT_TRUE(sim.connect()) << sim.lastLog();
    EXPECT_EQ(tap.matching("!0XM", before), std::vector<std::string>{"!0XM150"});
    EXPECT_EQ(sim.core.state().overridePercent, 150);
    ProgramBuilder b(3); // long X vectors at V3000: they cruise at V times the multiplier
    b.add(machine::UnitOp::Accel, 200);
    b.add(machine::UnitOp::Speed, 3000);
    b.add(machine::UnitOp::Brake, 3000);
    for (int i = 0; i < 4; ++i)
        b.add(machine::UnitOp::Vector, 0, {6000, 0, 0, 0}, static_cast<std::uint32_t>(10 + i));
    b.add(machine::UnitOp::ProgramEnd, 0);
    ASSERT_FALSE(sim.core.run(b.program, sim.runner.now()));
    sim.runner.runFor(1.0);
    EXPECT_NEAR(xRate(sim, 1.0), 4500, 150) << "the unit runs 150 %";
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 60)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front());
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
