// ProbeSurface (issue 19): a simulated work top trips the tool probe input (IN15) exactly where
// a vertical probe move reaches it, under whatever X/Y the machine stands at.
#include "driver/emulator/surface.h"
#include "driver/emulator/unit.h"
#include "emulator_test_util.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace frezka::emulator;
using namespace frezka::emulator::test;
using frezka::protocol::Variant;

namespace {

Unit surfaceUnit(const std::string &spec)
{
    UnitOptions o = optionsFor(Variant::Gve64);
    EXPECT_TRUE(parseProbeSurface(spec, &o.surface));
    Unit unit(o);
    ask(unit, "!0Y-\r");
    EXPECT_EQ(ask(unit, "!0A10\r!0V400\r!0T1\r"), "0\r0\r0\r");
    return unit;
}

// Moves to counters (x, y) at Z 0, then probes down 3000 steps with IN15 armed; returns the
// Z counter at the event where the input first reads 1 (or 1 when it never did).
std::int64_t probeAt(Unit &unit, std::int64_t x, std::int64_t y)
{
    const auto at = unit.position();
    ask(unit, "!0L" + std::to_string(x - at[0]) + "," + std::to_string(y - at[1]) + "," +
                  std::to_string(-at[2]) + "\r");
    runUntilIdle(unit);
    EXPECT_FALSE(unit.input(15));
    ask(unit, "!0SW1,80\r!0SW3,80\r!0L0,0,-3000\r"); // IN15 armed, contact = 1
    while (unit.nextEventIn() < kNever) {
        unit.advance(unit.nextEventIn());
        if (unit.input(15))
            return unit.position()[2];
    }
    return 1;
}

} // namespace

TEST(ProbeSurface, ParsesPlaneAndSineAndRefusesTheRest)
{
    ProbeSurface s;
    ASSERT_TRUE(parseProbeSurface("plane:-5,0.01,-0.02", &s));
    EXPECT_EQ(s.kind, ProbeSurface::Kind::Plane);
    EXPECT_DOUBLE_EQ(s.heightMm(10, 20), -5 + 0.1 - 0.4);
    ASSERT_TRUE(parseProbeSurface("sine:0.15,100", &s));
    EXPECT_NEAR(s.heightMm(25, 25), 0.15, 1e-12);
    ASSERT_TRUE(parseProbeSurface("warp:-20,0.002,0.001,0.05,100", &s)); // plane + sine
    EXPECT_EQ(s.kind, ProbeSurface::Kind::Warp);
    EXPECT_NEAR(s.heightMm(25, 75), -20 + 0.05 + 0.075 - 0.05, 1e-12);
    for (const char *bad : {"plane:1,2", "sine:1,0", "cone:1,2,3", "plane:1,2,x", "plane",
                            "plane:1,2,3,4", "warp:1,2,3,4", "warp:1,2,3,4,0", "warp:1,2,3,4,5,6"})
        EXPECT_FALSE(parseProbeSurface(bad, &s)) << bad;
}

TEST(ProbeSurface, TiltedPlaneTripsTheProbeAtItsStepUnderEachPoint)
{
    Unit unit = surfaceUnit("plane:-5,0.01,-0.02"); // 200 steps/mm
    for (auto [x, y] : {std::pair{0, 0}, {2000, 4000}, {4000, 0}, {1000, 3000}}) {
        const double zMm = -5 + 0.01 * x / 200.0 - 0.02 * y / 200.0;
        EXPECT_EQ(probeAt(unit, x, y), std::int64_t(std::floor(zMm * 200 + 1e-9))) << x << "," << y;
        runUntilIdle(unit); // the unit brakes after the interrupt; the input stays on below
        EXPECT_TRUE(unit.input(15));
        ask(unit, "!0D\r"); // the rest dropped, the interrupt cleared (as ProbeMove does)
    }
    EXPECT_EQ(unit.stats().interrupts, 4);
}
