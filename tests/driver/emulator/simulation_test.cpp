// The unit behind the wire model: timing on the virtual clock, and the link-recovery rules of
// §8 (@, >) keeping every position command exactly once over a noisy line.

#include "emulator_test_util.h"

#include "driver/emulator/simulation.h"

#include <gtest/gtest.h>

#include <optional>

using namespace frezka::emulator;
using namespace frezka::emulator::test;

namespace {

// A minimal PC side that follows docs/gve-protocol.md §8: checksums on; after a garbled or
// missing reply ask '@' whether the command arrived, then '>' for its reply; resend only when
// it did not arrive.
class RecoveringPc
{
public:
    RecoveringPc(Simulation &sim, int index)
        : m_sim(sim)
        , m_index(index)
    {}

    // Sends one command until it is known to have been executed once; returns its reply line.
    std::string transact(const std::string &command)
    {
        for (int attempt = 0; attempt < 100; ++attempt) {
            m_sim.pcWrite(withChecksum(command));
            std::optional<std::string> reply = readValid();
            if (reply && ((*reply)[0] == '4' || (*reply)[0] == '2')) {
                // Refused, not executed. A 4 can also answer a garbled command whose checksum
                // still matched (a dropped and a duplicated byte keep the sum): that one did
                // advance the index, so learn it again.
                m_index = askIndex();
                continue;
            }
            if (reply) {
                m_index = (m_index + 1) % 256;
                return *reply;
            }
            const int index = askIndex();
            if (index == m_index)
                continue; // it never arrived: send it again
            EXPECT_EQ(index, (m_index + 1) % 256);
            m_index = index;
            ++recovered;
            for (;;) {
                m_sim.pcWrite(withChecksum("!0>"));
                // A 4 (or 2) here is the unit's complaint about a garbled '>' itself.
                auto repeated = readValid();
                if (repeated && (*repeated)[0] != '4' && (*repeated)[0] != '2')
                    return *repeated;
            }
        }
        ADD_FAILURE() << "no way through for " << command;
        return {};
    }

    int recovered = 0;

private:
    // A reply line with a valid checksum, or nullopt (garbled, or nothing within 50 ms).
    std::optional<std::string> readValid()
    {
        std::string line = m_sim.pcReadLine(0.05);
        while (line == "\r") // a stray CR (a duplicated byte): not a reply
            line = m_sim.pcReadLine(0.05);
        if (line.size() < 5 || line.back() != '\r') {
            drain();
            return std::nullopt;
        }
        const std::string body = line.substr(0, line.size() - 3); // "...," without HH CR
        if (withChecksum(body.substr(0, body.size() - 1)) != line)
            return std::nullopt;
        return line.substr(0, line.size() - 4); // without ",HH\r"
    }

    // After a bad read, let the line go quiet and forget what is left of it, so that a late
    // line is never taken for the answer to the next question.
    void drain()
    {
        m_sim.advance(0.02);
        m_sim.pcRead();
    }

    int askIndex()
    {
        for (;;) {
            m_sim.pcWrite(withChecksum("!0@"));
            if (auto r = readValid(); r && r->starts_with("0,"))
                return std::stoi(r->substr(2));
        }
    }

    Simulation &m_sim;
    int m_index;
};

} // namespace

TEST(Simulation, HaltReplyTravelsBackAfterTheStop)
{
    SimulationOptions o;
    o.unit.variant = Variant::Gve84;
    o.wire.baud = 38400;
    o.wire.latencyPcToUnitS = o.wire.latencyUnitToPcS = 0.004;
    Simulation sim(o);
    sim.pcWrite("!0A10\r!0V10000\r!0L100000,0,0\r");
    EXPECT_EQ(sim.pcReadLine(1), "0\r");
    EXPECT_EQ(sim.pcReadLine(1), "0\r");
    EXPECT_EQ(sim.pcReadLine(1), "0\r");
    sim.advance(2.0 - sim.now());
    sim.pcWrite("!0H\r");
    const double sent = sim.now();
    EXPECT_EQ(sim.pcReadLine(5), "8\r");
    // 4 bytes to the unit, 1 s of braking from full speed, 2 bytes back, both latencies.
    const double byte = 10.0 / 38400;
    EXPECT_NEAR(sim.now() - sent, 4 * byte + 0.004 + 1.0 + 2 * byte + 0.004, 1e-6);
    EXPECT_EQ(sim.unit().pathSpeed(), 0);
}

TEST(Simulation, EveryVectorExactlyOnceOverANoisyLine)
{
    SimulationOptions o;
    o.unit.variant = Variant::Gve64;
    o.wire.latencyPcToUnitS = o.wire.latencyUnitToPcS = 0.002;
    o.wire.seed = 11;
    o.wire.pcToUnit = {0.002, 0.002, 0.002, 0};
    o.wire.unitToPc = {0.002, 0.002, 0.002, 0.03};
    Simulation sim(o);
    // Set-up straight into the unit (not over the noisy wire): MPG off, checksums on.
    EXPECT_EQ(ask(sim.unit(), "!0Y-\r!0%+\r"), "0,Y-\r0,5C\r");
    RecoveringPc pc(sim, 2);
    EXPECT_EQ(pc.transact("!0V20000").substr(0, 1), "0");
    EXPECT_EQ(pc.transact("!0A200").substr(0, 1), "0");
    std::array<std::int64_t, 4> sum{};
    SplitMix64 rng(5);
    for (int i = 0; i < 400;) {
        const std::int64_t dx = static_cast<std::int64_t>(rng.next() % 2001) - 1000;
        const std::int64_t dy = static_cast<std::int64_t>(rng.next() % 2001) - 1000;
        const std::string reply =
            pc.transact("!0C" + std::to_string(dx) + "," + std::to_string(dy) + ",0");
        if (reply == "0") {
            sum[0] += dx;
            sum[1] += dy;
            ++i;
        } else {
            ASSERT_EQ(reply, "1");
        }
    }
    while (pc.transact("!0L0,0,0") != "0") {
    }
    EXPECT_EQ(sim.unit().position(), sum);
    const WireStats lost = sim.wire().toPc().stats();
    EXPECT_GT(lost.messagesLost, 0);
    EXPECT_GT(sim.wire().toUnit().stats().bytesCorrupted, 0);
    EXPECT_GT(pc.recovered, 0); // some replies were recovered with '>' instead of a resend
}
