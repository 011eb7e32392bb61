// Manual moves (machine/manualmoves.h) and the unit's speeds (machine/steps.h): the tool lift
// within Z's upper limit, the lifted tool's hand moves clipped, the ways back (up, across, down),
// the probe input's arming and what a probe move's end means.
#include "machine/manualmoves.h"
#include "machine/steps.h"

#include <gtest/gtest.h>

namespace frezka::machine {
namespace {

// X 0..400, Y 0..300, Z -120..0, 200 steps/mm; Z at most 2000 mm/min; a lift of 5 mm.
MachineConfig gve64()
{
    return defaultMachineConfig(protocol::Variant::Gve64);
}

TEST(SpeedPulses, NearestOrAtMostWithinTheUnitsRange)
{
    EXPECT_DOUBLE_EQ(pulseRateOf(3000, 200), 10000);
    EXPECT_EQ(speedPulses(1234.5, 50000), 1235); // halves away from zero
    EXPECT_EQ(speedPulses(1234.4, 50000), 1234);
    EXPECT_EQ(speedPulsesAtMost(1234.9, 50000), 1234);
    EXPECT_EQ(speedPulses(3, 50000), kMinPulseRate);
    EXPECT_EQ(speedPulsesAtMost(3, 50000), kMinPulseRate);
    EXPECT_EQ(speedPulses(60000, 50000), 50000);
    EXPECT_EQ(speedPulsesAtMost(60000.7, 50000), 50000);
}

TEST(ManualMoves, TheSlowestAxisSetsTheSpeed)
{
    const MachineConfig c = gve64();
    // Z: 2000 mm/min at 200 steps/mm.
    EXPECT_DOUBLE_EQ(slowestAxisPulseRate(c, 3), pulseRateOf(2000, 200));
    EXPECT_DOUBLE_EQ(slowestAxisPulseRate(c, 3, 600), pulseRateOf(600, 200));
    EXPECT_DOUBLE_EQ(slowestAxisPulseRate(c, 3, 9000), pulseRateOf(2000, 200));
    MachineConfig slowUnit = c;
    slowUnit.unit.maxPulseRate = 5000;
    EXPECT_DOUBLE_EQ(slowestAxisPulseRate(slowUnit, 3), 5000);
}

TEST(ManualMoves, TheLiftStopsAtZsUpperLimit)
{
    const MachineConfig c = gve64();
    EXPECT_EQ(toolLiftSteps(c, -4000), 1000); // 5 mm
    EXPECT_EQ(toolLiftSteps(c, -300), 300);   // 1.5 mm below the limit
    EXPECT_EQ(toolLiftSteps(c, 0), 0);
    EXPECT_EQ(toolLiftSteps(c, 50), 0); // above it: no lift, never down
}

TEST(ManualMoves, TheLiftedToolsHandMoveIsClippedToTheLimits)
{
    const MachineConfig c = gve64();
    EXPECT_EQ(liftedJogMove(c, 0, 1000, 2.5), (Steps4{500, 0, 0, 0}));
    EXPECT_EQ(liftedJogMove(c, 1, 1000, -10), (Steps4{0, -1000, 0, 0})); // to Y's 0
    EXPECT_EQ(liftedJogMove(c, 2, 0, 1), (Steps4{0, 0, 0, 0}));          // Z at its top
    EXPECT_EQ(liftedJogMove(c, 0, 80000, 1), (Steps4{0, 0, 0, 0}));      // X at 400 mm
}

TEST(ManualMoves, BackToTheLiftPointUpAcrossDown)
{
    const Steps4 lift{1000, 2000, -3000, 0};
    // Jogged away and down: up to the lift point's height, across, nothing to go down.
    EXPECT_EQ(backToLiftPoint({3000, 500, -5000, 0}, lift, 3),
              (LineMoves{{0, 0, 2000, 0}, {-2000, 1500, 0, 0}}));
    // Jogged up: across at the higher Z, then down.
    EXPECT_EQ(backToLiftPoint({3000, 2000, -1000, 0}, lift, 3),
              (LineMoves{{-2000, 0, 0, 0}, {0, 0, -2000, 0}}));
    EXPECT_TRUE(backToLiftPoint(lift, lift, 3).empty());
    // A moves across with four axes only.
    EXPECT_EQ(backToLiftPoint({1000, 2000, -3000, 70}, lift, 4), (LineMoves{{0, 0, 0, -70}}));
    EXPECT_TRUE(backToLiftPoint({1000, 2000, -3000, 70}, lift, 3).empty());
}

TEST(ManualMoves, TheReturnToThePathTravelsALiftAboveBothEnds)
{
    const MachineConfig c = gve64();
    EXPECT_EQ(travelHeightSteps(c, -8000, -6000), -5000);
    EXPECT_EQ(travelHeightSteps(c, -600, -6000), 0);  // at most Z's upper limit
    EXPECT_EQ(travelHeightSteps(c, 400, -6000), 400); // never below the higher end
    MachineConfig noLift = c;
    noLift.motion.toolLiftMm = 0;
    EXPECT_EQ(travelHeightSteps(noLift, -8000, -6000), -6000);
    EXPECT_EQ(returnToPathMoves(c, {100, 200, -8000, 0}, {400, 0, -6000, 0}, 3),
              (LineMoves{{0, 0, 3000, 0}, {300, -200, 0, 0}, {0, 0, -1000, 0}}));
    // Straight below: up by the lift all the same, then down (nothing across).
    EXPECT_EQ(returnToPathMoves(c, {400, 0, -5000, 0}, {400, 0, -6000, 0}, 3),
              (LineMoves{{0, 0, 1000, 0}, {0, 0, -2000, 0}}));
}

TEST(ProbeMoves, TheInputIsArmedForContactOrItsLoss)
{
    EepromConfig ee;
    ee.polarityHigh = 0x40;        // IN15 active low: contact pulls it low; IN14 kept
    ee.interruptEnableHigh = 0x40; // IN14 enabled
    const ProbeArming toward = probeArming(ee, gcode::ProbeKind::TowardErrorIfNoContact);
    EXPECT_EQ(toward, (ProbeArming{true, 0xC0, 0x40}));
    EXPECT_EQ(probeArming(ee, gcode::ProbeKind::Toward), (ProbeArming{false, 0xC0, 0x40}));
    EXPECT_EQ(probeArming(ee, gcode::ProbeKind::AwayErrorIfNoLoss),
              (ProbeArming{true, 0xC0, 0xC0}));
    EXPECT_EQ(probeArming(ee, gcode::ProbeKind::Away), (ProbeArming{false, 0xC0, 0xC0}));
    // Already in contact (IN15 low) for a move toward the work: it must not start.
    EXPECT_TRUE(probeAlreadyTripped(toward, 0x00));
    EXPECT_FALSE(probeAlreadyTripped(toward, 0x80));
    ee.polarityHigh = 0x80; // active high
    EXPECT_EQ(probeArming(ee, gcode::ProbeKind::Toward).polarityHigh, 0x80);
    EXPECT_EQ(probeArming(ee, gcode::ProbeKind::Away).polarityHigh, 0x00);
}

TEST(ProbeMoves, TheEndOfTheMoveDecidesHowTheJobGoesOn)
{
    UnitProgram p;
    p.axisCount = 3;
    UnitCommand probe{UnitOp::Probe, {0, 0, -2000, 0}};
    probe.endSteps = {0, 0, -2000, 0};
    UnitCommand after{UnitOp::Line, {100, 0, 0, 0}};
    after.endSteps = {100, 0, -2000, 0};
    p.commands = {probe, after};
    const Steps4 end{0, 0, -2000, 0}, short_{0, 0, -1500, 0};
    EXPECT_EQ(probeOutcome(p, 0, end, true, true), ProbeOutcome::AtEnd);
    EXPECT_EQ(probeOutcome(p, 0, short_, true, true), ProbeOutcome::StoppedShortMotion);
    EXPECT_EQ(probeOutcome(p, 0, end, false, true), ProbeOutcome::NotTripped);
    EXPECT_EQ(probeOutcome(p, 0, end, false, false), ProbeOutcome::AtEnd);
    p.commands.pop_back();
    EXPECT_EQ(probeOutcome(p, 0, short_, true, false), ProbeOutcome::StoppedShort);
    // A's counter means nothing on three axes.
    EXPECT_EQ(probeOutcome(p, 0, {0, 0, -2000, 5}, true, true), ProbeOutcome::AtEnd);
}

} // namespace
} // namespace frezka::machine
