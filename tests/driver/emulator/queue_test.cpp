// Queue control (§7: H, G, D, K, R), inputs and interrupts (§10), homing (§6).

#include "emulator_test_util.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

using namespace frezka::emulator;
using namespace frezka::emulator::test;

namespace {

// A = 10 000 pulses/s^2, V = 10 000 pulses/s: 1 s and 5 000 steps to reach or leave full speed.
Unit fastUnit(UnitOptions o = optionsFor(Variant::Gve64))
{
    Unit unit(o);
    if (unit.variantInfo().hasMpg)
        ask(unit, "!0Y-\r");
    EXPECT_EQ(ask(unit, "!0A10\r!0V10000\r!0T1\r"), "0\r0\r0\r");
    return unit;
}

} // namespace

TEST(Queue, HaltRepliesOnlyWhenStopped)
{
    Unit unit = fastUnit();
    ask(unit, "!0L100000,0,0\r");
    unit.advance(2.0); // 1 s up, 1 s at full speed: x = 15 000
    EXPECT_EQ(ask(unit, "!0H\r"), "");
    EXPECT_NEAR(unit.nextEventIn(), 1.0, 1e-9);
    unit.advance(0.999);
    EXPECT_EQ(unit.takeTransmit(), "");
    EXPECT_EQ(ask(unit, "!0Q\r"), ""); // the link waits for the HALT reply
    unit.advance(0.002);
    EXPECT_EQ(unit.takeTransmit(), "8\r8,25020304\r"); // then the waiting command is answered
    EXPECT_EQ(ask(unit, "!0P\r"), "8,20000,0\r");
    EXPECT_EQ(ask(unit, "!0SR6\r"), "8,D0\r"); // INTA, RUN (vector left), INTCOM
    EXPECT_EQ(ask(unit, "!0F\r"), "8,D0\r");
    EXPECT_EQ(ask(unit, "!0N\r"), "F\r"); // 7 (RUN=1) with INTA
    unit.advance(5.0);
    EXPECT_EQ(unit.position()[0], 20000); // held until G
    EXPECT_EQ(ask(unit, "!0G\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0SR6\r"), "0,40\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.position()[0], 100000);
    EXPECT_EQ(ask(unit, "!0SR6\r"), "0,00\r");
    EXPECT_EQ(ask(unit, "!0G\r"), "6\r"); // nothing interrupted
}

TEST(Queue, HaltWhenIdleAndWhenVectorsRunOut)
{
    Unit unit = fastUnit();
    EXPECT_EQ(ask(unit, "!0H\r"), "8\r");
    EXPECT_EQ(ask(unit, "!0SR6\r"), "8,90\r"); // INTA + INTCOM, RUN = 0
    EXPECT_EQ(ask(unit, "!0G\r"), "6\r");      // flags cleared, nothing to continue
    EXPECT_EQ(ask(unit, "!0SR6\r"), "0,00\r");
    // Braking needs 5 000 steps but only 3 100 are queued: the vectors run out, INTA=1 RUN=0.
    ask(unit, "!0B10000\r!0C10000,0,0\r!0C100,0,0\r");
    unit.advance(1.2);
    EXPECT_EQ(ask(unit, "!0H\r"), "");
    runUntilIdle(unit);
    EXPECT_EQ(unit.takeTransmit(), "8\r");
    EXPECT_EQ(ask(unit, "!0SR6\r"), "8,90\r");
    EXPECT_EQ(unit.position()[0], 10100);
    // It ran off its queue at sqrt(10 000^2 - 2 * 10 000 * 3 100) pulses/s: a stop past the
    // ramp, counted as a brake violation (the vectors alone would have been one too).
    const MotionStats s = unit.stats().motion;
    EXPECT_EQ(s.brakeViolations, 1);
    EXPECT_NEAR(s.worstBrakeExcessPulsesPerS, std::sqrt(1e8 - 2e4 * 3100), 1.0);
}

TEST(Queue, HaltWithinTheQueuedRampIsNoBrakeViolation)
{
    Unit unit = fastUnit();
    // A chain of two vectors passed at full speed (B = V); the H comes near the end of the first
    // and brakes into the second.
    ask(unit, "!0B10000\r!0C10000,0,0\r!0C10000,0,0\r");
    unit.advance(1.4); // 10 000 pulses/s at x 9 000: braking to zero takes 5 000 steps
    ask(unit, "!0H\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.takeTransmit(), "8\r");
    EXPECT_EQ(unit.stats().motion.brakeViolations, 0); // stopped in the second vector
    EXPECT_EQ(unit.position()[0], 14000);
    ask(unit, "!0G\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.position()[0], 20000);
    EXPECT_EQ(unit.stats().motion.brakeViolations, 0);

    // The last queued vector, halted while it cruises: it holds the ramp itself.
    Unit late = fastUnit();
    ask(late, "!0B2000\r!0C20000,0,0\r");
    late.advance(1.6); // x 11 000, cruising; its own brake to zero starts at x 15 000
    ask(late, "!0H\r");
    runUntilIdle(late);
    EXPECT_EQ(late.stats().motion.brakeViolations, 0); // within its own ramp: stops at 16 000
    EXPECT_EQ(late.position()[0], 16000);
}

TEST(Queue, HaltBrakesAcrossQueuedVectorsAndGoFinishesExactly)
{
    Unit unit = fastUnit();
    ask(unit, "!0B10000\r");
    for (int i = 0; i < 30; ++i)
        ask(unit, "!0C1000,7,0\r");
    unit.advance(1.5); // 10 000 pulses/s, braking takes 5 000 steps: five more vectors
    ask(unit, "!0H\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.takeTransmit(), "8\r");
    EXPECT_EQ(unit.position()[0], 15000);
    EXPECT_GT(unit.queueLength(), 0u);
    EXPECT_EQ(ask(unit, "!0G\r"), "0\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.position(), (std::array<std::int64_t, 4>{30000, 210, 0, 0}));
}

TEST(Queue, DeleteOnlyWhenStopped)
{
    Unit unit = fastUnit();
    ask(unit, "!0C100000,0,0\r!0C100000,0,0\r");
    unit.advance(0.5);
    EXPECT_EQ(ask(unit, "!0D\r"), "7\r");
    EXPECT_EQ(ask(unit, "!0K\r"), "7\r");
    EXPECT_EQ(ask(unit, "!0R\r"), "7\r");
    ask(unit, "!0H\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.takeTransmit(), "8\r");
    const auto pos = unit.position();
    EXPECT_EQ(ask(unit, "!0D\r"), "0\r");
    EXPECT_EQ(unit.queueLength(), 0u);
    EXPECT_EQ(unit.position(), pos); // counters untouched
    EXPECT_EQ(ask(unit, "!0SR6\r"), "0,00\r");
    EXPECT_EQ(ask(unit, "!0G\r"), "6\r");
}

// The vendor's tool-lift example (docs/gve-protocol.md §7), command by command.
TEST(Queue, KeepRestoreToolLiftSequence)
{
    UnitOptions o = optionsFor(Variant::Gve64);
    o.trace = true;
    Unit unit = fastUnit(o);
    ask(unit, "!0B2000\r");
    for (int i = 0; i < 5; ++i)
        ASSERT_EQ(ask(unit, "!0C20000,100,0\r"), "0\r");
    unit.advance(3.0);
    ASSERT_EQ(ask(unit, "!0H\r"), "");
    runUntilIdle(unit);
    ASSERT_EQ(unit.takeTransmit(), "8\r");
    const auto stop = unit.position();
    EXPECT_EQ(ask(unit, "!0P\r"),
              "8," + std::to_string(stop[0]) + "," + std::to_string(stop[1]) + "\r");
    EXPECT_EQ(ask(unit, "!0SR4\r"), "8,00\r");
    EXPECT_EQ(ask(unit, "!0SR5\r"), "8,00\r");
    EXPECT_EQ(ask(unit, "!0SR6\r"), "8,D0\r");
    EXPECT_EQ(ask(unit, "!0SW0,1A\r"), "8\r");
    EXPECT_EQ(ask(unit, "!0SW1,3F\r"), "8\r");
    EXPECT_EQ(ask(unit, "!0K\r"), "0\r");      // ST4-6 saved and cleared: INTA=0
    EXPECT_EQ(ask(unit, "!0K\r"), "7\r");      // only once without R
    EXPECT_EQ(ask(unit, "!0C1,0,0\r"), "1\r"); // only L fits
    EXPECT_EQ(ask(unit, "!0L0,0,-1000\r"), "0\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.position()[2], -1000);
    EXPECT_EQ(ask(unit, "!0L0,0,1000\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0R\r"), "7\r"); // not while the L runs
    runUntilIdle(unit);
    EXPECT_EQ(unit.position(), stop);
    EXPECT_EQ(ask(unit, "!0R\r"), "8\r"); // the interrupted state is back
    EXPECT_EQ(ask(unit, "!0R\r"), "F\r"); // 7 with INTA: nothing kept any more
    EXPECT_EQ(ask(unit, "!0V500\r"), "8\r");
    EXPECT_EQ(ask(unit, "!0XA\r"), "8\r");
    EXPECT_EQ(ask(unit, "!0SW0,A2\r"), "8\r");
    EXPECT_EQ(ask(unit, "!0SW1,78\r"), "8\r");
    const double goTime = unit.now();
    EXPECT_EQ(ask(unit, "!0G\r"), "0\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.position(), (std::array<std::int64_t, 4>{100000, 500, 0, 0}));
    double fastest = 0;
    for (const TracePoint &p : unit.trace()) {
        if (p.timeS > goTime)
            fastest = std::max(fastest, p.pathSpeedPulsesPerS);
    }
    EXPECT_NEAR(fastest, 500, 1e-6); // the rest of the queue ran at the new speed
    EXPECT_EQ(unit.stats().motion.vectorsExecuted, 7);
}

TEST(Queue, StopButtonInterrupt)
{
    Unit unit = fastUnit();
    EXPECT_EQ(ask(unit, "!0SW0,80\r!0SW2,80\r"), "0\r0\r"); // IN7 enabled, active when 1
    ask(unit, "!0L100000,0,0\r");
    unit.advance(2.0);
    unit.setStopButton(true);
    EXPECT_EQ(ask(unit, "!0SR6\r"), "8,C1\r"); // INTA, RUN, STOP request while braking
    unit.advance(1.0);
    EXPECT_EQ(unit.position()[0], 20000);
    EXPECT_EQ(ask(unit, "!0SR4\r"), "8,80\r");
    EXPECT_EQ(ask(unit, "!0I1\r"), "8,80\r");
    EXPECT_EQ(ask(unit, "!0SR6\r"), "8,C0\r");
    unit.setStopButton(false);
    EXPECT_EQ(ask(unit, "!0G\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0SR4\r"), "0,00\r");
    runUntilIdle(unit);
    EXPECT_EQ(unit.position()[0], 100000);
    EXPECT_EQ(unit.stats().interrupts, 1);
}

TEST(Queue, InterruptPolarityEdgesAndMasks)
{
    Unit unit = fastUnit();
    // ST2 = 0: active low. All inputs read 0 after reset, so they are active but no edge came.
    EXPECT_EQ(ask(unit, "!0SW0,08\r"), "0\r");
    unit.setInput(3, true);  // inactive
    unit.setInput(3, false); // active: edge
    EXPECT_EQ(ask(unit, "!0SR4\r"), "8,08\r");
    EXPECT_EQ(ask(unit, "!0SR6\r"), "8,80\r"); // idle: INTA, RUN = 0
    EXPECT_EQ(ask(unit, "!0G\r"), "6\r");
    unit.setInput(4, true); // not enabled
    unit.setInput(4, false);
    EXPECT_EQ(ask(unit, "!0SR4\r"), "0,00\r");
    // IN15 (tool probe) on ST1/ST3/ST5, read with I2 bit 7.
    EXPECT_EQ(ask(unit, "!0SW1,80\r!0SW3,80\r"), "0\r0\r");
    unit.setProbe(true);
    EXPECT_EQ(ask(unit, "!0SR5\r"), "8,80\r");
    EXPECT_EQ(ask(unit, "!0I2\r"), "8,80\r");
    EXPECT_EQ(ask(unit, "!0D\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0SR5\r"), "0,00\r");
    // SW6 can set and clear INTA directly.
    EXPECT_EQ(ask(unit, "!0SW6,80\r"), "8\r");
    EXPECT_EQ(ask(unit, "!0SW6,00\r"), "0\r");
}

TEST(Queue, LimitSwitchAtAPosition)
{
    UnitOptions o = optionsFor(Variant::Gve64);
    o.switches = {{6, 0, 5000, +1}}; // IN6 = end X, open at x >= 5000
    Unit unit = fastUnit(o);
    ask(unit, "!0SW0,40\r!0SW2,40\r");
    EXPECT_EQ(ask(unit, "!0I1\r"), "0,00\r");
    ask(unit, "!0L100000,0,0\r");
    runUntilIdle(unit);
    // Reached at 10 000 pulses/s after 5 000 steps, 5 000 more to stop.
    EXPECT_EQ(unit.position()[0], 10000);
    EXPECT_EQ(ask(unit, "!0SR4\r"), "8,40\r");
    EXPECT_EQ(ask(unit, "!0I1\r"), "8,40\r");
    EXPECT_TRUE(unit.input(6));
}

TEST(Homing, FindsTheSwitchAndBacksOff)
{
    UnitOptions o = optionsFor(Variant::Gve64);
    o.switches = {{0, 0, -3000, -1}}; // home X on IN0, pressed at x <= -3000
    Unit unit = fastUnit(o);
    EXPECT_EQ(ask(unit, "!0WX,-20000,1000,2000,500\r"), "");
    EXPECT_EQ(ask(unit, "!0SR6\r"), ""); // waits behind W
    unit.advance(2.9);
    EXPECT_EQ(unit.takeTransmit(), "");
    runUntilIdle(unit);
    EXPECT_EQ(unit.takeTransmit(), "0\r0,00\r");
    EXPECT_NEAR(unit.now(), 3.0 + 1.0 / 500, 1e-9);
    EXPECT_EQ(ask(unit, "!0P\r"), "0,-2999,0\r");
    EXPECT_EQ(ask(unit, "!0NX0\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0P\r"), "0,0,0\r");
    EXPECT_EQ(unit.stats().motion.vectorsExecuted, 0);
}

TEST(Homing, SwitchNotFoundIsCode5)
{
    UnitOptions o = optionsFor(Variant::Gve114);
    o.switches = {{1, 1, -30000, -1}};
    Unit unit = fastUnit(o);
    EXPECT_EQ(ask(unit, "!0WY-20000,1000,2000,500\r"), ""); // the GVE114 form
    runUntilIdle(unit);
    EXPECT_EQ(unit.takeTransmit(), "5\r");
    EXPECT_EQ(unit.position()[1], -20000);
}

TEST(Homing, StartingOnTheSwitch)
{
    UnitOptions o = optionsFor(Variant::Gve64);
    o.switches = {{2, 2, 100, +1}}; // home Z pressed at z >= 100
    Unit unit = fastUnit(o);
    ask(unit, "!0NZ2000\r");
    EXPECT_EQ(ask(unit, "!0WZ,5000,1000,1000,500\r"), "");
    runUntilIdle(unit);
    EXPECT_EQ(unit.takeTransmit(), "5\r"); // 1 000 steps back are not enough
    EXPECT_EQ(unit.position()[2], 1000);
    EXPECT_EQ(ask(unit, "!0WZ,5000,1000,1000,500\r"), "");
    runUntilIdle(unit);
    EXPECT_EQ(unit.takeTransmit(), "0\r");
    EXPECT_EQ(unit.position()[2], 99);
    EXPECT_EQ(ask(unit, "!0WZ,5000,1000,0,500\r"), ""); // runs to the switch, no back-off
    runUntilIdle(unit);
    EXPECT_EQ(unit.takeTransmit(), "5\r");
    EXPECT_EQ(unit.position()[2], 100);
}

TEST(Homing, BadParametersAndInterrupts)
{
    UnitOptions o = optionsFor(Variant::Gve84);
    Unit unit = fastUnit(o);
    EXPECT_EQ(ask(unit, "!0WQ,-100,1000,10,100\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0WA,-100,1000,10,100\r"), "4\r"); // no A on the GVE84
    EXPECT_EQ(ask(unit, "!0WX,-100,1000,10\r"), "4\r");
    EXPECT_EQ(ask(unit, "!0WX,0,1000,10,100\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0WX,-100,5,10,100\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0WX,-100,1000,10,60000\r"), "5\r");
    ask(unit, "!0L100000,0,0\r");
    EXPECT_EQ(ask(unit, "!0WX,-100,1000,10,100\r"), "7\r");
    ask(unit, "!0H\r");
    runUntilIdle(unit);
    ask(unit, "!0D\r");
    unit.takeTransmit();
    // An enabled interrupt aborts homing: code 5 with INTA.
    ask(unit, "!0SW0,02\r!0SW2,02\r");
    EXPECT_EQ(ask(unit, "!0WX,-100000,1000,10,100\r"), "");
    unit.advance(1.0);
    unit.setInput(1, true);
    EXPECT_EQ(unit.takeTransmit(), "D\r");
    EXPECT_EQ(ask(unit, "!0SR4\r"), "8,02\r");
}
