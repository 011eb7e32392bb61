// Issue 14: the emulator counts what must never happen at the machine (safetywatch.h): an axis
// over its maximum speed, a cut without the spindle at speed, the spindle on while held.

#include "emulator_test_util.h"

#include "driver/emulator/readings.h"

#include <gtest/gtest.h>

namespace frezka::emulator::test {
namespace {

// A GVE64 on a machine whose spindle needs 2 s and whose axes run at most 10 000 pulses/s.
Unit machineUnit(MachineModel model = {2.0, {10000, 10000, 10000, 0}, false, 0})
{
    UnitOptions o = optionsFor(Variant::Gve64);
    o.machine = model;
    Unit unit(o);
    ask(unit, "!0Y-\r");
    ask(unit, "!0A200\r");
    return unit;
}

TEST(Safety, ZDownWithoutTheSpindleIsACut)
{
    Unit unit = machineUnit();
    ask(unit, "!0V5000\r");
    ASSERT_EQ(ask(unit, "!0L0,0,-1000\r"), "0\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.stats().safety.cutWithoutSpindle, 1);
    ASSERT_EQ(ask(unit, "!0L0,0,1000\r"), "0\r"); // up: never a cut
    runUntilIdle(unit);
    EXPECT_EQ(unit.stats().safety.cutWithoutSpindle, 1);
}

TEST(Safety, TheSpindleMustBeAtSpeedBeforeTheToolGoesDown)
{
    Unit unit = machineUnit();
    ask(unit, "!0V5000\r");
    ask(unit, "!7V500\r");
    EXPECT_TRUE(unit.spindleTurning());
    ask(unit, "!0L0,0,-1000\r"); // at once: not yet at speed
    runUntilIdle(unit);
    EXPECT_EQ(unit.stats().safety.cutWithoutSpindle, 1);
    ask(unit, "!7V0\r");
    ask(unit, "!7V500\r");
    unit.advance(2.0); // the spin-up waited
    ask(unit, "!0L0,0,-1000\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.stats().safety.cutWithoutSpindle, 1) << "at speed: a cut as it should be";
}

TEST(Safety, WithAWorkSurfaceMovesAcrossBelowItAreCuts)
{
    Unit unit = machineUnit({2.0, {}, true, -500});
    ask(unit, "!0V5000\r");
    ask(unit, "!0L1000,0,0\r"); // above the work
    runUntilIdle(unit);
    ask(unit, "!0L0,0,-400\r"); // down, still above
    runUntilIdle(unit);
    EXPECT_EQ(unit.stats().safety.cutWithoutSpindle, 0);
    ask(unit, "!0L0,0,-200\r"); // into the work
    runUntilIdle(unit);
    ask(unit, "!0L1000,0,0\r"); // across in it (a feed move resumed without the spindle)
    runUntilIdle(unit);
    ask(unit, "!0L0,0,600\r"); // straight up out of it: a retract
    runUntilIdle(unit);
    EXPECT_EQ(unit.stats().safety.cutWithoutSpindle, 2);
}

// A probe move (G38.x, the probing workflows) goes toward the work with the spindle stopped, as
// it must: it starts with the probe input (IN15) armed to stop it (ST1 bit 7), and is no cut.
TEST(Safety, AProbeMoveIsNoCut)
{
    Unit unit = machineUnit();
    ask(unit, "!0V5000\r");
    ASSERT_EQ(ask(unit, "!0SW3,80\r"), "0\r"); // IN15 active high: contact; it reads 0 now
    ASSERT_EQ(ask(unit, "!0SW1,80\r"), "0\r"); // armed
    ASSERT_EQ(ask(unit, "!0L0,0,-1000\r"), "0\r");
    runUntilIdle(unit);
    ASSERT_EQ(unit.position()[2], -1000) << "the probe never touched: the whole move ran";
    EXPECT_EQ(unit.stats().safety.cutWithoutSpindle, 0);
    ASSERT_EQ(ask(unit, "!0SW1,00\r"), "0\r"); // disarmed: the same move down is a cut
    ASSERT_EQ(ask(unit, "!0L0,0,-1000\r"), "0\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.stats().safety.cutWithoutSpindle, 1);
}

TEST(Safety, SpindleStoppedUnderACut)
{
    Unit unit = machineUnit();
    ask(unit, "!7V500\r");
    unit.advance(2.5);
    ask(unit, "!0V1000\r");
    ask(unit, "!0L0,0,-2000\r");
    unit.advance(0.5);
    ASSERT_TRUE(unit.isMoving());
    ask(unit, "!7V0\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.stats().safety.cutWithoutSpindle, 1);
}

TEST(Safety, SpindleOnWhileHeld)
{
    Unit unit = machineUnit();
    ask(unit, "!7V500\r");
    unit.advance(2.5);
    ask(unit, "!0V2000\r");
    ask(unit, "!0C4000,0,0\r");
    ask(unit, "!0C4000,0,0\r");
    unit.advance(0.5);
    unit.receive("!0H\r");
    runUntilIdle(unit);
    unit.takeTransmit();
    unit.advance(readings::kHeldSpindleGraceS / 2);
    ask(unit, "!7V0\r"); // switched off in time after the stop
    unit.advance(3);
    EXPECT_EQ(unit.stats().safety.spindleOnWhileHeld, 0);
    ask(unit, "!7V500\r"); // on again while held: spin-up allowed, then it must go on
    unit.advance(2.0 + readings::kHeldSpindleGraceS / 2);
    EXPECT_EQ(unit.stats().safety.spindleOnWhileHeld, 0);
    ASSERT_EQ(ask(unit, "!0G\r"), "0\r");
    unit.advance(0.2);
    unit.receive("!0H\r"); // held again and left turning
    unit.advance(5);
    unit.takeTransmit();
    ask(unit, "!0F\r");
    EXPECT_EQ(unit.stats().safety.spindleOnWhileHeld, 1);
    unit.advance(5);
    ask(unit, "!0F\r");
    EXPECT_EQ(unit.stats().safety.spindleOnWhileHeld, 1) << "once per held stand";
}

TEST(Safety, KeptAndLiftedWithTheSpindleOnCounts)
{
    Unit unit = machineUnit();
    ask(unit, "!7V500\r");
    unit.advance(2.5);
    ask(unit, "!0V2000\r");
    ask(unit, "!0C4000,0,0\r");
    unit.advance(0.5);
    unit.receive("!0H\r");
    runUntilIdle(unit);
    unit.takeTransmit();
    ASSERT_EQ(ask(unit, "!0K\r"), "0\r");
    ask(unit, "!0L0,0,1000\r");
    runUntilIdle(unit);
    unit.advance(1);
    ask(unit, "!0F\r");
    EXPECT_EQ(unit.stats().safety.spindleOnWhileHeld, 1);
}

TEST(Safety, AxisOverItsMaximum)
{
    Unit unit = machineUnit();
    ask(unit, "!0V9000\r");
    ask(unit, "!0L5000,0,0\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.stats().motion.axisOverMax, 0);
    ask(unit, "!0V12000\r");
    ask(unit, "!0L5000,0,0\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.stats().motion.axisOverMax, 1);
    ask(unit, "!0XM200\r"); // the override doubles the speed, nothing caps it without VL
    ask(unit, "!0V6000\r");
    ask(unit, "!0L0,5000,0\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.stats().motion.axisOverMax, 2);
}

} // namespace
} // namespace frezka::emulator::test
