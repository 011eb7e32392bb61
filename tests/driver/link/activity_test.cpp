// The core's one current activity (MachineState::activity, issue 13): every transition of the
// operations state machine is published, in the order the core goes through them.

#include "simfixture.h"

#include "gcode/toolpath.h"

#include <gtest/gtest.h>

using namespace frezka;
using namespace frezka::driver;
using namespace frezka::driver::test;
using A = MachineActivity;

namespace {

// Records each published change of the activity.
struct Recorder
{
    explicit Recorder(Sim &sim)
    {
        sim.core.onStateChanged = [this](const MachineState &s) {
            if (seen.empty() || seen.back() != s.activity)
                seen.push_back(s.activity);
        };
    }
    std::string text() const
    {
        std::string t;
        for (A a : seen)
            t += std::string(t.empty() ? "" : " > ") + machineActivityName(a);
        return t;
    }
    std::vector<A> seen;
};

std::string names(std::initializer_list<A> list)
{
    std::string t;
    for (A a : list)
        t += std::string(t.empty() ? "" : " > ") + machineActivityName(a);
    return t;
}

} // namespace

TEST(Activity, ConnectHomeJog)
{
    Sim sim;
    sim.port.unit().setSwitches(unitOptionsFor(sim.config).switches);
    Recorder r(sim);
    ASSERT_TRUE(sim.connect());
    ASSERT_FALSE(sim.core.execute(op::Home{}, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return sim.core.state().homed; }, 600));
    ASSERT_FALSE(sim.core.execute(op::JogStep{0, 5, 3000}, sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Idle)) << sim.lastLog();
    EXPECT_EQ(r.text(), names({A::Connecting, A::None, A::Homing, A::None, A::Jogging, A::None}));
}

TEST(Activity, JobWithToolLift)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    Recorder r(sim);
    ASSERT_FALSE(sim.core.execute(op::Run{slowProgram(200)}, sim.runner.now()));
    sim.runner.runFor(2.0);
    EXPECT_EQ(sim.core.state().activity, A::Job);
    ASSERT_FALSE(sim.core.execute(op::Pause{}, sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Paused));
    EXPECT_EQ(sim.core.state().activity, A::Job) << "a held job is still the job";
    ASSERT_FALSE(sim.core.execute(op::ToolLift{false}, sim.runner.now()));
    EXPECT_EQ(sim.core.state().activity, A::ToolLift) << "from the moment it is accepted";
    ASSERT_TRUE(sim.until(MachineMode::ToolLifted));
    ASSERT_FALSE(sim.core.execute(op::ToolLower{0}, sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Paused)) << sim.lastLog();
    ASSERT_FALSE(sim.core.execute(op::Resume{}, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600));
    EXPECT_EQ(r.text(), names({A::Job, A::ToolLift, A::Job, A::None}));
}

TEST(Activity, LinkLossChecksProgress)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    Recorder r(sim);
    ASSERT_FALSE(sim.core.execute(op::Run{slowProgram(900)}, sim.runner.now()));
    sim.runner.runFor(2.0);
    sim.runner.unplug("converter unplugged");
    EXPECT_EQ(sim.core.state().activity, A::CheckingProgress) << "the job waits for the link";
    sim.runner.runFor(1.0);
    sim.runner.open();
    bool resumed = false; // resume is refused while the progress is being checked
    ASSERT_TRUE(sim.runner.runUntil(
        [&] {
            return resumed ||
                   (resumed = !sim.core.execute(op::Resume{}, sim.runner.now()).has_value());
        },
        120))
        << sim.lastLog();
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600));
    EXPECT_TRUE(sim.finished.front());
    EXPECT_EQ(r.text(), names({A::Job, A::CheckingProgress, A::Connecting, A::CheckingProgress,
                               A::Job, A::None}));
}

TEST(Activity, ProbeMove)
{
    using machine::UnitOp;
    Sim sim;
    sim.config.eeprom.polarityHigh = 0x80; // IN15 contact reads 1 in the emulator
    sim.core.setConfig(sim.config);
    sim.port.unit().setSwitches({{15, 2, -1000, -1}});
    ASSERT_TRUE(sim.connect());
    machine::UnitProgram p;
    p.axisCount = 3;
    auto add = [&p](UnitOp op, std::int64_t value, std::array<std::int32_t, 4> d, int aux) {
        machine::UnitCommand c;
        c.op = op;
        c.value = value;
        c.d = d;
        c.aux = aux;
        c.endSteps = p.commands.empty() ? p.startSteps : p.commands.back().endSteps;
        for (int a = 0; a < 4; ++a)
            c.endSteps[a] += d[a];
        p.commands.push_back(c);
    };
    add(UnitOp::Speed, 2000, {}, 0);
    add(UnitOp::Probe, 0, {0, 0, -3000, 0},
        static_cast<int>(gcode::ProbeKind::TowardErrorIfNoContact));
    add(UnitOp::ProgramEnd, 0, {}, 0);
    Recorder r(sim);
    ASSERT_FALSE(sim.core.execute(op::Run{p}, sim.runner.now()));
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 120)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front()) << sim.lastLog();
    EXPECT_EQ(r.text(), names({A::Job, A::Probing, A::Job, A::None}));
}

// A vector damaged so that its checksum still matches (a dropped and a doubled '0'): the path
// guard stops the job and holds it; resuming returns to the path and the job runs on.
TEST(Activity, PathFaultHoldReturnRunOn)
{
    Sim sim;
    ASSERT_TRUE(sim.connect());
    auto seen = std::make_shared<int>(0);
    sim.port.tamper = [seen](std::string_view bytes) {
        std::string s(bytes);
        const std::string from = "!0C400,133,-1,", to = "!0C40,1330,-1,";
        for (auto at = s.find(from); at != std::string::npos; at = s.find(from, at + 1)) {
            if ((*seen)++ == 100) {
                s.replace(at, from.size(), to);
                break;
            }
        }
        return s;
    };
    Recorder r(sim);
    ASSERT_FALSE(sim.core.execute(op::Run{slowProgram(300)}, sim.runner.now()));
    ASSERT_TRUE(sim.until(MachineMode::Paused, 600)) << sim.lastLog();
    ASSERT_EQ(sim.core.state().hold, HoldReason::PathFault);
    EXPECT_EQ(sim.core.state().activity, A::PathFault);
    ASSERT_FALSE(sim.core.execute(op::Resume{}, sim.runner.now()));
    EXPECT_EQ(sim.core.state().activity, A::ReturnToPath);
    ASSERT_TRUE(sim.runner.runUntil([&] { return !sim.finished.empty(); }, 600)) << sim.lastLog();
    EXPECT_TRUE(sim.finished.front());
    EXPECT_EQ(r.text(), names({A::Job, A::PathFault, A::ReturnToPath, A::Job, A::None}));
}
