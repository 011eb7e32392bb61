// Jobs over slow serial lines (9 600 - 38 400 Bd) on the in-process emulator: a clean line never
// produces a timeout, a recovery or a garbled reply, whatever the length of the packets.

#include "simfixture.h"

#include <gtest/gtest.h>

using namespace frezka;
using namespace frezka::driver;
using namespace frezka::driver::test;
using protocol::Variant;

namespace {

struct SlowLine
{
    SlowLine(Variant variant, int baud, double latencyS, CoreOptions options = {})
        : config(withBaud(machine::defaultMachineConfig(variant), baud))
        , port(unitOptionsFor(config), WireOptions{.baud = baud, .latencyS = latencyS})
        , core(config, options)
        , runner(core, port)
    {
        core.onJobFinished = [this](bool ok) { finished.push_back(ok); };
        core.onError = [this](const MachineError &e) { errors.push_back(e.message); };
    }
    static machine::MachineConfig withBaud(machine::MachineConfig c, int baud)
    {
        c.link.baud = baud;
        return c;
    }

    machine::MachineConfig config;
    EmulatorPort port;
    MachineCore core;
    SimRunner runner;
    std::vector<bool> finished;
    std::vector<std::string> errors;
};

} // namespace

// The driver's timeouts allow for the time its own bytes take on the line at the profile's rate.
// With 115 200 Bd assumed on a 19 200 Bd line, a packet of 400 vectors (3 s on the wire) timed
// out after 0.3 s, '@' went into the packet still on its way (the unit ended the packet there
// and ran its remaining lines as single commands), and the replies that followed were read as
// the answers to later questions: "reply checksum wrong; gave up after 10 attempts".
TEST(SlowLine, ACleanLineAtTheProfilesBaudNeverTimesOut)
{
    for (int baud : {19200, 38400}) {
        SCOPED_TRACE(baud);
        SlowLine line(Variant::Gve64, baud, 0.0105);
        line.runner.open();
        ASSERT_TRUE(line.runner.runUntil(
            [&] { return line.core.state().mode != MachineMode::Connecting; }, 60));
        ASSERT_EQ(line.core.state().mode, MachineMode::Idle);
        const auto program = denseProgram(2500);
        ASSERT_FALSE(line.core.run(program, line.runner.now()));
        ASSERT_TRUE(line.runner.runUntil([&] { return !line.finished.empty(); }, 600));
        EXPECT_TRUE(line.finished.front()) << (line.errors.empty() ? "" : line.errors.front());
        const LinkStats &stats = line.core.engine().stats();
        EXPECT_EQ(stats.timeouts, 0);
        EXPECT_EQ(stats.garbledLines, 0);
        EXPECT_EQ(stats.recovered, 0);
        EXPECT_EQ(stats.resent, 0);
        EXPECT_GT(line.core.jobReport().packets, 5) << "the test needs long packets";
        // What the unit did: every vector once, the counters at the program's end.
        EXPECT_EQ(line.port.unit().stats().motion.vectorsExecuted, 2500);
        EXPECT_EQ(line.port.unit().stats().checksumErrors, 0);
        for (int a = 0; a < 3; ++a)
            EXPECT_EQ(line.port.unit().position()[a], program.commands.back().endSteps[a]);
    }
}

// A rate given in the core's options (frezka-cli run --baud) wins over the profile's.
TEST(SlowLine, TheOptionsBaudWinsOverTheProfiles)
{
    CoreOptions options;
    options.link.baud = 9600;
    SlowLine line(Variant::Gve64, 19200, 0, options);
    EXPECT_EQ(line.core.engine().options().baud, 9600);
    SlowLine fromProfile(Variant::Gve64, 38400, 0);
    EXPECT_EQ(fromProfile.core.engine().options().baud, 38400);
    fromProfile.core.setConfig(SlowLine::withBaud(fromProfile.config, 19200));
    EXPECT_EQ(fromProfile.core.engine().options().baud, 19200);
}

// Where the unit holds little, the job sizes a packet to half of what it holds. A packet whose
// first command is a B then ended before its C, the job took "no C in the packet" for a full
// queue and waited a poll interval, and the unit ran dry (property seed 100, 38 400 Bd at
// 0.5 ms: a V before each short vector; here 2 stops). Each vector lasts 15-45 ms, longer than its
// V, its packet and a poll on this line take: the unit never runs dry.
TEST(SlowLine, APacketAfterASpeedChangeCarriesItsVector)
{
    SlowLine line(Variant::Gve64, 38400, 0.0005);
    line.runner.open();
    ASSERT_TRUE(line.runner.runUntil(
        [&] { return line.core.state().mode != MachineMode::Connecting; }, 60));
    ASSERT_EQ(line.core.state().mode, MachineMode::Idle);
    using machine::UnitOp;
    ProgramBuilder b(3);
    b.add(UnitOp::Accel, 200, {});
    std::int64_t steps = 0;
    for (int i = 0; i < 60; ++i) {
        const std::int64_t speed = 2000 + 40 * (i % 7); // pulses/s: a V of its own each time
        const int length = static_cast<int>(speed * (0.015 + 0.0005 * i)); // 15-45 ms
        b.add(UnitOp::Speed, speed, {});
        b.add(UnitOp::Brake, 1000, {});
        b.add(UnitOp::Vector, 0, {length, 0, 0, 0});
        steps += length;
    }
    b.add(UnitOp::ProgramEnd, 0, {});
    ASSERT_FALSE(line.core.run(b.program, line.runner.now()));
    ASSERT_TRUE(line.runner.runUntil([&] { return !line.finished.empty(); }, 600));
    EXPECT_TRUE(line.finished.front()) << (line.errors.empty() ? "" : line.errors.front());
    EXPECT_EQ(line.port.unit().position()[0], steps);
    EXPECT_EQ(line.port.unit().stats().motion.starvationStops, 0);
}
