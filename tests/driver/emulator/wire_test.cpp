#include "driver/emulator/simulation.h"
#include "driver/emulator/wire.h"

#include <gtest/gtest.h>

using namespace frezka::emulator;

TEST(Wire, BytesTakeTenBitTimesPlusLatency)
{
    SplitMix64 rng(1);
    ByteChannel ch(115200, 0.004, {}, &rng);
    ch.send(0.0, "!0?\r");
    const double byteTime = 10.0 / 115200;
    EXPECT_DOUBLE_EQ(ch.nextArrivalS(), byteTime + 0.004);
    EXPECT_EQ(ch.takeArrived(0.004 + 3.5 * byteTime), "!0?");
    EXPECT_EQ(ch.takeArrived(0.004 + 4 * byteTime), "\r");
    EXPECT_TRUE(ch.idle());
    // A later send waits for the line only if it is still busy.
    ch.send(1.0, "A");
    EXPECT_DOUBLE_EQ(ch.nextArrivalS(), 1.0 + byteTime + 0.004);
}

TEST(Wire, FaultsAreSeededAndDeterministic)
{
    auto run = [](std::uint64_t seed) {
        WireOptions opt;
        opt.seed = seed;
        opt.pcToUnit = {0.05, 0.05, 0.05, 0.1};
        Wire wire(opt);
        const std::string text(2000, 'x');
        std::string withCr;
        for (int i = 0; i < 100; ++i)
            withCr += "!0C100,200,300\r";
        wire.toUnit().send(0, text + withCr);
        return std::pair{wire.toUnit().takeArrived(1e9), wire.toUnit().stats()};
    };
    const auto a = run(7);
    const auto b = run(7);
    const auto c = run(8);
    EXPECT_EQ(a, b);
    EXPECT_NE(a.first, c.first);
    EXPECT_GT(a.second.bytesCorrupted, 0);
    EXPECT_GT(a.second.bytesDropped, 0);
    EXPECT_GT(a.second.bytesDuplicated, 0);
    EXPECT_GT(a.second.messagesLost, 0);
}

TEST(Simulation, RoundTripTimeFollowsBaudAndLatency)
{
    SimulationOptions opt;
    opt.wire.baud = 9600;
    opt.wire.latencyPcToUnitS = 0.002;
    opt.wire.latencyUnitToPcS = 0.003;
    Simulation sim(opt);
    sim.pcWrite("!0Q\r");
    const std::string reply = sim.pcReadLine(1.0);
    EXPECT_EQ(reply, "0,25020304\r");
    // 4 bytes out + 11 bytes back at 1.0416 ms each, plus both latencies.
    EXPECT_NEAR(sim.now(), 15 * (10.0 / 9600) + 0.005, 1e-9);
}
