#include "machine/unitwire.h"

#include <gtest/gtest.h>

using namespace frezka::machine;

namespace {

UnitCommand command(UnitOp op, std::int64_t value = 0, std::array<std::int32_t, 4> d = {},
                    std::int32_t aux = 0)
{
    UnitCommand c;
    c.op = op;
    c.value = value;
    c.d = d;
    c.aux = aux;
    return c;
}

} // namespace

TEST(UnitWire, MotionAndSpeedCommandsAsOnTheWire)
{
    EXPECT_EQ(commandText(command(UnitOp::Vector, 0, {697, 30, 0, 0}), 3), "!0C697,30,0");
    EXPECT_EQ(commandText(command(UnitOp::Vector, 0, {697, 30, 0, 0}), 4), "!0C697,30,0");
    EXPECT_EQ(commandText(command(UnitOp::Vector, 0, {1, -2, 3, -4}), 4), "!0C1,-2,3,-4");
    EXPECT_EQ(commandText(command(UnitOp::Line, 0, {0, 0, -1000, 0}), 3), "!0L0,0,-1000");
    EXPECT_EQ(commandText(command(UnitOp::Brake, 1200), 3), "!0B1200");
    EXPECT_EQ(commandText(command(UnitOp::Speed, 10000), 3), "!0V10000");
    EXPECT_EQ(commandText(command(UnitOp::Accel, 80), 3), "!0A80");
    EXPECT_EQ(commandText(command(UnitOp::Pause, 10), 3), "!0T10");
    EXPECT_EQ(commandText(command(UnitOp::ShortThreshold, 1), 3), "!0$1");
    EXPECT_EQ(commandText(command(UnitOp::SpeedModeVk), 3), "!0VK");
    EXPECT_EQ(commandText(command(UnitOp::SpeedModeVn), 3), "!0VN");
    EXPECT_EQ(commandText(command(UnitOp::Output, 0xFB), 3), "!0O0,FB");
    EXPECT_EQ(commandText(command(UnitOp::Spindle, 300), 3), "!7V300");
}

TEST(UnitWire, PcSideOpsAreCommentsNotWireCommands)
{
    for (UnitOp op :
         {UnitOp::WaitIdle, UnitOp::Dwell, UnitOp::OperatorStop, UnitOp::Probe, UnitOp::ProgramEnd})
        EXPECT_FALSE(wireCommand(command(op), 3).has_value());
    EXPECT_EQ(commandText(command(UnitOp::WaitIdle), 3), "# wait-idle");
    EXPECT_EQ(commandText(command(UnitOp::Dwell, 500), 3), "# dwell 500 ms");
    EXPECT_EQ(commandText(command(UnitOp::OperatorStop,
                                  static_cast<std::int64_t>(StopReason::ToolChange), {}, 3),
                          3),
              "# operator-stop M6 T3");
    EXPECT_EQ(commandText(command(UnitOp::Probe, 0, {0, 0, -500, 0}, 0), 3),
              "# probe G38.2 !0L0,0,-500");
}
