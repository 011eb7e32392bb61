#include "driver/emulator/unit.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace frezka::emulator;
using frezka::protocol::Variant;

namespace {

std::string ask(Unit &unit, std::string_view command)
{
    unit.receive(command);
    return unit.takeTransmit();
}

} // namespace

TEST(Unit, ManualExamplesGve64)
{
    Unit unit({.variant = Variant::Gve64});
    EXPECT_EQ(ask(unit, "!0?\r"), "0,IP64MPG v19 10.9.2010\r");
    EXPECT_EQ(ask(unit, "!0L1000,0,0\r"), "7\r"); // MPG on after reset
    EXPECT_EQ(ask(unit, "!0Y-\r"), "0,Y-\r");
    EXPECT_EQ(ask(unit, "!0L1000,0,0\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0SW8,F1\r"), "5\r");
    EXPECT_EQ(ask(unit, "!0%+\r"), "0,5C\r");
    EXPECT_EQ(ask(unit, "!0A100,4F\r"), "0,5C\r");
    EXPECT_EQ(ask(unit, "!0%-,CF\r"), "0\r");
}

TEST(Unit, VectorsRunToExactPositions)
{
    Unit unit({.variant = Variant::Gve64});
    ask(unit, "!0Y-\r");
    EXPECT_EQ(ask(unit, "!0V10000\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0A100\r"), "0\r");
    EXPECT_EQ(ask(unit, "!0B5000\r"), "0\r");
    for (int i = 0; i < 10; ++i)
        EXPECT_EQ(ask(unit, "!0C697,30,-3\r"), "0\r");
    while (unit.nextEventIn() < kNever)
        unit.advance(unit.nextEventIn());
    EXPECT_EQ(unit.position(), (std::array<std::int64_t, 4>{6970, 300, -30, 0}));
    const Stats s = unit.stats();
    EXPECT_EQ(s.motion.vectorsExecuted, 10);
    EXPECT_EQ(s.motion.brakeViolations, 0);
    EXPECT_EQ(s.motion.starvationStops, 0);
    // Middle vectors enter and leave at B=5000 and peak where the two ramps meet.
    EXPECT_NEAR(s.motion.peakAxisSpeedPulsesPerS[0], std::sqrt(5000.0 * 5000 + 100000.0 * 697),
                1e-6);
    EXPECT_EQ(ask(unit, "!0PF\r"), "0,6970,300,-30\r");
}
