// The planned speed curve (issue 17): plannedSpeedDecimated, which never holds the three samples
// a vector, gives exactly decimateSpeed(plannedSpeed(...)), for bucket counts that divide the
// samples evenly and ones that do not.
#include "session/plannedspeed.h"

#include "gcode/interpreter.h"
#include "machine/planner.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace frezka::session {
namespace {

TEST(PlannedSpeed, DecimatedWhileWalkingIsDecimatedAfterwards)
{
    // A spiral of short cuts, rapids and a dwell between two of its parts: vectors, lines and
    // zero-length moves (skipped), the speed up and down.
    std::string text = "G21 G90 G17 G94\nG0 X50 Y50 Z-5\nG1 Z-6 F300\n";
    for (int i = 1; i <= 3000; ++i) {
        const double r = 0.5 + i * 0.01, a = i * 0.07;
        text += "G1 X" + std::to_string(50 + r * std::cos(a)) + " Y" +
                std::to_string(50 + r * std::sin(a)) + " F" + std::to_string(600 + (i % 7) * 400) +
                "\n";
        if (i == 1500)
            text += "G1 X80 Y80\nG4 P1\nG0 Z-5\nG0 X10 Y10\nG1 Z-6\n";
    }
    text += "M2\n";
    const gcode::Result g = gcode::interpretText(text, {});
    ASSERT_TRUE(g.ok());
    const auto config = machine::defaultMachineConfig(protocol::Variant::Gve64);
    const machine::PlanResult p = machine::plan(g.toolpath, config);
    ASSERT_TRUE(p.ok()) << (p.errors.empty() ? std::string() : p.errors.front().message);
    const bool vk = p.stats.speedModeVk;
    const std::vector<SpeedSample> all = plannedSpeed(p.program, config, vk);
    ASSERT_GT(all.size(), 9000u);
    for (std::size_t maxPoints :
         {std::size_t(3), std::size_t(4), std::size_t(5), std::size_t(7), std::size_t(100),
          std::size_t(999), std::size_t(4000), std::size_t(8999), all.size(), all.size() + 1}) {
        const std::vector<SpeedSample> expected = decimateSpeed(all, maxPoints);
        EXPECT_EQ(plannedSpeedDecimated(p.program, config, vk, maxPoints), expected)
            << maxPoints << " points of " << all.size();
    }
}

} // namespace
} // namespace frezka::session
