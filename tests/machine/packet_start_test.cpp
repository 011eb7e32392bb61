// A packet whose start the unit never saw (issue 12, twelfth session): both of its *S lines
// arrive damaged, so the unit runs each C and B as a command of its own and answers each one
// (docs/gve-protocol.md §2.2). Found on the overfeed raster on a faulty link (GVE64 link seed
// 27, GVE84 link seed 51 of tests/machine/held_check_test.cpp's harness, 1 byte in 1 000
// garbled): the driver took a C's plain "queue full" (9) for the packet's "none accepted" and
// later such answers for those of the commands after it; the job stood in an alarm (going on, it
// would have sent the queued vectors again). Now a count-less answer that is no complaint fails
// the packet once its answers have passed, and the job re-establishes its progress from the
// counters (driver/link/progresscheck.h). Asserted on the emulated unit: every vector run once, the
// counters at the program's end, no alarm.

#include "heldjob.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

using namespace frezka;
using namespace frezka::machine::test;

namespace {

RandomJob cleanRaster(const std::string &unit)
{
    RandomJob job;
    job.seed = 1;
    const auto loaded = machine::loadMachineConfig(std::string(FREZKA_SOURCE_DIR) +
                                                   "/resources/machines/" + unit + ".json");
    EXPECT_TRUE(loaded.config.has_value());
    job.config = *loaded.config;
    job.config.link.latencyMs = 8;
    job.wire.baud = job.config.link.baud;
    job.wire.latencyS = 0.008;
    job.wire.seed = 1;
    job.program = overfeedRaster(12000, 4); // 4 rows of it
    return job;
}

// Whether the unit is held by the job's H (no G since) by the wire so far.
bool heldByTheJob(const HeldJob &held)
{
    for (std::size_t i = held.wire.size(); i-- > 0;) {
        if (held.wire[i].starts_with("!0H"))
            return true;
        if (held.wire[i].starts_with("!0G"))
            return false;
    }
    return false;
}

// Runs the job on a clean link but for two faults: one line of the first packet written from
// `damageFromS` on arrives damaged (its checksum wrong: the unit runs the lines before it), and
// both *S of the first packet afterwards that `lostStart` picks. Returns whether both were done.
template<typename Pick>
bool runWithPacketStartLost(HeldJob &held, double damageFromS, Pick lostStart)
{
    const auto record = held.port.tamper;
    bool lineDamaged = false;
    bool startLost = false;
    held.port.tamper = [&](std::string_view bytes) {
        const bool packet = bytes.starts_with("!0*S,FA\r!0*S,FA\r");
        const bool pick = packet && lineDamaged && !startLost && lostStart(bytes);
        std::string out = record(bytes);
        if (packet && !lineDamaged && held.port.now() >= damageFromS &&
            std::count(out.begin(), out.end(), '\r') >= 10) {
            const std::size_t third = out.find('\r', out.find('\r', 16) + 1); // after line 4
            out[third - 1] = out[third - 1] == '0' ? '1' : '0';
            lineDamaged = true;
        } else if (pick) {
            out[6] = 'B';
            out[14] = 'B';
            startLost = true;
        }
        return out;
    };
    EXPECT_TRUE(held.connectAndRun());
    EXPECT_TRUE(held.runner.runUntil([&] { return !held.finished.empty(); }, 600))
        << "the job never ended (mode " << static_cast<int>(held.core.state().mode) << ")";
    return lineDamaged && startLost;
}

void ranOnceToTheEnd(HeldJob &held)
{
    ASSERT_FALSE(held.finished.empty());
    EXPECT_TRUE(held.finished.front());
    const emulator::Unit &unit = held.port.unit();
    EXPECT_EQ(unit.position(), held.plan.program.commands.back().endSteps);
    EXPECT_EQ(unit.stats().motion.vectorsExecuted,
              motionCommands(held.plan.program.commands)); // none lost, none twice
    EXPECT_EQ(held.core.jobReport().pathFaults, 0);
}

} // namespace

// The GVE84 (a queue of 64 vectors) at three times its feed, held by the dry halt after the
// damaged line, the unit standing short of where the job takes it to stand: a packet of more
// vectors than the held queue has room for, its lines answered one by one, "8" for those
// queued, "9" (queue full) for the rest. Without the change the first "9" passed for the
// packet's "none accepted" and the next one for the answer to the SR4 before the G: the job
// stood in an alarm.
TEST(PacketStart, ALostStartOnAHeldUnitIsSettledByTheCounters)
{
    HeldJob held(cleanRaster("gve84"), true);
    ASSERT_TRUE(runWithPacketStartLost(held, 1.5, [&](std::string_view bytes) {
        std::size_t vectors = 0;
        for (std::size_t at = bytes.find("!0C"); at != std::string_view::npos;
             at = bytes.find("!0C", at + 1))
            ++vectors;
        return heldByTheJob(held) && held.port.unit().queueLength() + vectors > 63;
    }));
    ranOnceToTheEnd(held);
    EXPECT_GE(held.core.jobReport().dryHolds, 1);
    EXPECT_GE(held.core.jobReport().verified, 1);
}
