// The stream property test: random programs on random machine profiles over random links
// (tests/machine/randomjob.h), each planned, streamed through the driver to the in-process
// emulator on a virtual clock, and judged.
//
// Asserted on every case: the job never ends wrong (final counters exactly the program's end,
// every vector executed exactly once) and the plan keeps every limit of the machine (no vertex
// over a jump limit, no brake violation in the unit's model, none over a jump limit on the unit
// as it passed the vertices). Measured and printed, not yet asserted (issue 12, see
// docs/benchmarks.md "Random jobs"): starvation stops, the job time against the estimate, the
// estimate against the bound, jobs that stopped with a named error.
//
// 300 cases in 6 shards. A failing case prints its seed; FREZKA_PROPERTY_SEED=<seed> runs that one
// case alone and FREZKA_PROPERTY_DUMP=<dir> writes each failing case's program and profile there
// (seed-N.nc, seed-N.json, for `frezka-cli run seed-N.nc --machine seed-N.json --port sim`).
// The long soak of the same cases: tests/bench/planner/stream_soak.
#include "randomjob.h"

#include "gcode/interpreter.h"
#include "protocol/variant.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <string>

using namespace frezka::machine::test;

namespace {

constexpr int kShards = 6;
constexpr int kCasesPerShard = 50;

std::uint64_t envNumber(const char *name, std::uint64_t fallback)
{
    const char *v = std::getenv(name);
    return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

std::string list(const std::vector<std::string> &items)
{
    std::string out;
    for (const std::string &f : items)
        out += "\n  - " + f;
    return out;
}

void dump(const RandomJob &job)
{
    const char *dir = std::getenv("FREZKA_PROPERTY_DUMP");
    if (!dir)
        return;
    const std::string base = std::string(dir) + "/seed-" + std::to_string(job.seed);
    std::ofstream(base + ".nc") << job.program;
    frezka::machine::saveMachineConfig(job.config, base + ".json");
}

class StreamProperty : public ::testing::TestWithParam<int>
{
};

} // namespace

TEST_P(StreamProperty, NeverEndsWrongAndKeepsTheMachinesLimits)
{
    const std::uint64_t only = envNumber("FREZKA_PROPERTY_SEED", 0);
    if (only && GetParam() != 0)
        return; // one case: the first shard runs it
    const std::uint64_t first =
        only ? only : 1 + static_cast<std::uint64_t>(GetParam()) * kCasesPerShard;
    const std::uint64_t cases = only ? 1 : kCasesPerShard;
    int paceCases = 0, brakeCases = 0, starvedCases = 0;
    for (std::uint64_t seed = first; seed < first + cases; ++seed) {
        const RandomJob job = drawJob(seed, 600);
        // A profile as a user could write it: every key within its range and the rules.
        for (const frezka::machine::ConfigError &e :
             frezka::machine::validateMachineConfig(job.config))
            ADD_FAILURE() << "seed " << seed << ": the drawn profile breaks " << e.key << ": "
                          << e.message;
        const JobOutcome o = runJob(job);
        if (!o.ok())
            dump(job);
        EXPECT_TRUE(o.wrong.empty()) << "seed " << seed << " (FREZKA_PROPERTY_SEED=" << seed
                                     << "): " << job.summary << list(o.wrong) << list(o.pace);
        // On a clean link the unit never stops from speed without its ramp (issue 12 item 3;
        // on faulty links not yet: property seed 188, a GVE84 at 38 400 Bd and 15 ms, one).
        if (job.wire.byteErrorRate == 0 && job.wire.replyLossRate == 0)
            EXPECT_EQ(o.brakeViolations, 0) << "seed " << seed << " (FREZKA_PROPERTY_SEED=" << seed
                                            << "): " << job.summary << list(o.pace);
        brakeCases += o.brakeViolations > 0 ? 1 : 0;
        starvedCases += o.starvationStops > 0 ? 1 : 0;
        if (!o.pace.empty()) {
            ++paceCases;
            if (only)
                std::printf("seed %llu: %s%s\n", static_cast<unsigned long long>(seed),
                            job.summary.c_str(), list(o.pace).c_str());
        }
    }
    std::printf("seeds %llu..%llu: %d of %llu cases off the link's pace or the estimate (issue "
                "12); with brake violations %d, with starvation stops %d\n",
                static_cast<unsigned long long>(first),
                static_cast<unsigned long long>(first + cases - 1), paceCases,
                static_cast<unsigned long long>(cases), brakeCases, starvedCases);
}

INSTANTIATE_TEST_SUITE_P(Shards, StreamProperty, ::testing::Range(0, kShards));

namespace {

// The commands of one kind in the plan of a job's program.
std::size_t countInPlan(const RandomJob &job, frezka::machine::UnitOp op)
{
    const frezka::machine::PlanResult plan =
        frezka::machine::plan(frezka::gcode::interpretText(job.program).toolpath, job.config);
    EXPECT_TRUE(plan.errors.empty());
    std::size_t n = 0;
    for (const frezka::machine::UnitCommand &c : plan.program.commands)
        n += c.op == op ? 1 : 0;
    return n;
}

// Streams the job on its link: it ends right, the unit never ran dry nor braked late.
void expectKeepsThePace(const RandomJob &job)
{
    const JobOutcome o = runJob(job);
    if (!o.ok())
        dump(job);
    EXPECT_TRUE(o.wrong.empty()) << list(o.wrong);
    EXPECT_EQ(o.starvationStops, 0) << list(o.pace);
    EXPECT_EQ(o.brakeViolations, 0);
}

} // namespace

// Property seed 29's failure, built by hand: a slow plunge of vectors one to three steps long
// on a stiff Z axis, where the link's pace lowers V itself. Each vector's own V differed from
// its neighbours' by a unit or two, so the plan sent a V (a round trip outside the packets)
// before nearly every vector and the unit ran dry at each (194 stops in 345 vectors, the job
// 68 % over its estimate). The stretch now shares one V.
TEST(StreamPace, APacedPlungeSharesOneSpeedAndNeverRunsDry)
{
    RandomJob job;
    job.config = frezka::machine::defaultMachineConfig(frezka::protocol::Variant::Gve64);
    frezka::machine::AxisConfig &z = job.config.axes[2];
    z.stepsPerMm = 368;
    z.accelMmPerS2 = 12800;
    z.maxSpeedMmPerMin = 16849;
    job.config.unit.maxPulseRate = 125000; // an orderable GVE64 rate that carries that speed
    job.config.link.baud = 115200;
    job.config.link.latencyMs = 6.8;
    job.wire.baud = job.config.link.baud;
    job.wire.latencyS = job.config.link.latencyMs / 1000.0;
    std::string program = "G21 G90 G94\nG0 X5 Y5 Z-1\nG1 F1000\n";
    double depth = -1;
    for (int i = 0; i < 400; ++i) {
        depth -= 0.0027 * (1 + i % 3); // 1, 2 and 3 steps
        program += "G1 Z" + std::to_string(depth) + "\n";
    }
    program += "G0 Z-1\nM2\n";
    job.program = program;
    job.summary = "paced plunge";
    const std::size_t speeds = countInPlan(job, frezka::machine::UnitOp::Speed);
    const std::size_t vectors = countInPlan(job, frezka::machine::UnitOp::Vector);
    EXPECT_LE(speeds * 20, vectors) << speeds << " V commands for " << vectors << " vectors";
    expectKeepsThePace(job);
}

// A raster whose Z steps up and down in a sawtooth (a stair-stepped 3D finish): the A the axes
// allow drifts with the slope at every vector, and quick vectors held their own A while the caps
// differed by more than the tolerance, one A round trip every few vectors: 702 A commands and
// 50 starvation stops at 8 ms. Now the lower A is shared while it costs less than the round
// trips it saves.
TEST(StreamPace, AStairRasterSharesOneAccelerationAndNeverRunsDry)
{
    RandomJob job;
    job.config = frezka::machine::defaultMachineConfig(frezka::protocol::Variant::Gve64);
    job.config.link.latencyMs = 8;
    job.wire.baud = job.config.link.baud;
    job.wire.latencyS = job.config.link.latencyMs / 1000.0;
    std::string program = "G21 G90 G0 X0 Y0 Z-1\nG1 F2000\n";
    char line[64];
    for (int i = 1; i <= 2500; ++i) {
        std::snprintf(line, sizeof line, "X%.2f Y%.2f Z%.3f\n", 0.04 * i, (i / 250) % 2 ? 0.5 : 0.0,
                      -1 - 0.01 * (i % 7));
        program += line;
    }
    program += "M2\n";
    job.program = program;
    EXPECT_LE(countInPlan(job, frezka::machine::UnitOp::Accel), 20u);
    expectKeepsThePace(job);
}

// Property seed 4's failure, built by hand: on a GVE84 at 38 400 Bd and 9.6 ms, a Z axis of
// 1 784 steps/mm whose jump limit is 0 plunges and rises in waves of three or four segments
// (every reversal a rest). The link's pace gave each segment its own V: a chain of three
// vectors sent V, packet, V, packet, V, packet, and the unit, holding one short vector each
// time, ran dry at nearly every change (24 stops in the job). The stretch before a change now
// runs slower by the time the change costs, or shares the next stretch's V.
TEST(StreamPace, AShortChainWithASpeedPerVectorNeverRunsDry)
{
    RandomJob job;
    job.config = frezka::machine::defaultMachineConfig(frezka::protocol::Variant::Gve84);
    job.config.unit.maxPulseRate = 50000;
    job.config.motion.speedMode = frezka::machine::SpeedModeChoice::Vk;
    frezka::machine::AxisConfig &z = job.config.axes[2];
    z.stepsPerMm = 1784.242;
    z.maxSpeedMmPerMin = 1292;
    z.accelMmPerS2 = 1408.78;
    z.maxJumpMmPerS = 0;
    job.config.link.baud = 38400;
    job.config.link.latencyMs = 9.6;
    job.wire.baud = job.config.link.baud;
    job.wire.latencyS = job.config.link.latencyMs / 1000.0;
    const double wave[] = {-12.0695, -12.2474, -12.3710, -12.4131, -12.3645, -12.2359, -12.0555,
                           -12.0142, -12.2008, -12.3432, -12.4103, -12.3873, -12.2793, -12.1099};
    std::string program = "G21 G90 G17 G94 G64\nG0 X40 Y30 Z-12\nF1331\n";
    for (int i = 0; i < 20; ++i)
        for (const double zAt : wave)
            program += "G1 Z" + std::to_string(zAt - 0.002 * i) + "\n";
    program += "G0 Z-1\nM2\n";
    job.program = program;
    expectKeepsThePace(job);
}

// The operator's feed override above 100 % (XM) runs the unit faster than the plan: the driver's
// estimate of what the unit holds must follow it, or the unit runs dry. A raster of 3 mm
// segments at F3000 on a GVE64 at 9 600 Bd: 16 vectors/s at 100 %, within the wire's 50 at
// 150 % and 200 %; before, 1 starvation stop (and 2 brake violations at 150 %).
TEST(StreamPace, AFeedOverrideAboveHundredKeepsTheUnitFed)
{
    std::string program = "G21 G90 G17 G94 G64\nG0 X10 Y10\nG1 Z-6 F300\nF3000\n";
    char line[96];
    for (int row = 0; row < 20; ++row) {
        for (int j = 0; j < 30; ++j) {
            const int t = row % 2 == 0 ? j : 30 - j;
            std::snprintf(line, sizeof line, "G1 X%.4f Y%.4f\n", 10.0 + 3 * t,
                          10 + row * 0.5 + 0.05 * (j % 2));
            program += line;
        }
    }
    program += "G0 Z-1\nM2\n";
    for (const int percent : {150, 200}) {
        for (const int baud : {9600, 19200}) {
            SCOPED_TRACE(std::to_string(percent) + " % at " + std::to_string(baud) + " Bd");
            RandomJob job;
            job.config = frezka::machine::defaultMachineConfig(frezka::protocol::Variant::Gve64);
            job.config.link.baud = baud;
            job.config.link.latencyMs = 8;
            job.wire.baud = baud;
            job.wire.latencyS = 0.008;
            job.program = program;
            job.overridePercent = percent;
            expectKeepsThePace(job);
        }
    }
}

// An override the wire cannot carry: 1 mm segments at F3000 on a GVE64 at 9 600 Bd, which the
// plan paces to the wire at 100 %. XM200 doubled those speeds and the unit ran dry (1 stop and 1
// brake violation, the job 34 % longer than at 100 %). The driver now lowers XM to what the link
// can feed (JobOverride::follow), and the job takes no longer than at 100 %.
TEST(StreamPace, AFeedOverrideIsKeptWithinWhatTheLinkCanFeed)
{
    std::string program = "G21 G90 G17 G94 G64\nG0 X10 Y10\nG1 Z-6 F300\nF3000\n";
    char line[96];
    for (int row = 0; row < 10; ++row) {
        for (int j = 0; j < 60; ++j) {
            const int t = row % 2 == 0 ? j : 60 - j;
            std::snprintf(line, sizeof line, "G1 X%.4f Y%.4f\n", 10.0 + t,
                          10 + row * 0.5 + 0.02 * (j % 2));
            program += line;
        }
    }
    program += "G0 Z-1\nM2\n";
    RandomJob job;
    job.config = frezka::machine::defaultMachineConfig(frezka::protocol::Variant::Gve64);
    job.config.link.baud = 9600;
    job.config.link.latencyMs = 8;
    job.wire.baud = 9600;
    job.wire.latencyS = 0.008;
    job.program = program;
    const JobOutcome plain = runJob(job);
    ASSERT_TRUE(plain.wrong.empty()) << list(plain.wrong);
    ASSERT_EQ(plain.starvationStops, 0) << list(plain.pace);
    for (const int percent : {150, 200}) {
        SCOPED_TRACE(std::to_string(percent) + " %");
        job.overridePercent = percent;
        expectKeepsThePace(job);
        EXPECT_LE(runJob(job).jobS, plain.jobS * 1.01);
    }
}

// The spindle's spin-up is a dwell on the PC side. The driver's estimate of the unit's queue
// counted those seconds as motion run, took the unit for empty when the raster after it began,
// and sent its first packet as long as the GVE114's queue (2 047 commands, 2.4 s on the wire)
// after two short ones: the unit ran dry mid-chain at 12704,12000 (the bundled surface program,
// 1 starvation stop and 1 brake violation at 1 and 8 ms).
TEST(StreamPace, AChainAfterTheSpinUpIsFedFromItsStart)
{
    std::string program =
        "G21 G90 G17 G94 G64\nM3 S12000\nG0 Z-1\nG0 X30 Y30\nG1 Z-5 F300\nF3500\n";
    char line[96];
    for (int j = 0; j < 6000; ++j) {
        const double x = 30 + 0.04 * (j % 1000 < 500 ? j % 500 : 500 - j % 500);
        const double y = 30 + 0.5 * (j / 500);
        std::snprintf(line, sizeof line, "G1 X%.4f Y%.4f Z%.4f\n", x, y,
                      -3.6 - 0.2 * std::sin(x * 0.7));
        program += line;
    }
    program += "G0 Z-1\nM5\nM2\n";
    const auto loaded = frezka::machine::loadMachineConfig(std::string(FREZKA_SOURCE_DIR) +
                                                           "/resources/machines/gve114.json");
    ASSERT_TRUE(loaded.config);
    for (const double ms : {1.0, 8.0}) {
        SCOPED_TRACE(std::to_string(ms) + " ms");
        RandomJob job;
        job.config = *loaded.config;
        job.config.link.latencyMs = ms;
        job.wire.baud = job.config.link.baud;
        job.wire.latencyS = ms / 1000.0;
        job.program = program;
        expectKeepsThePace(job);
    }
}

// Issue 12's raster: 12 000 segments of 0.1 mm over a wavy surface at F12000, three times the
// bundled GVE64 and GVE84 profiles' 4000 mm/min, at 1, 8 and 16 ms (tests/bench/link/overfeed.sh
// runs the same through frezka-cli). Before the fixes it sent a V before nearly every vector and
// the unit ran dry thousands of times; the GVE84 at 16 ms still ran dry 19 times while its
// packets were counted at half its queue.
TEST(StreamPace, RasterAtThreeTimesTheMaximumFeedKeepsThePace)
{
    std::string program = "G21 G90 G17 G94 G64\nG0 X30 Y30\nG1 Z-5 F300\nF12000\n";
    char line[96];
    for (int row = 0; row < 12; ++row) {
        const double y = 30 + row * 0.5;
        for (int j = 0; j < 1000; ++j) {
            const double x = 30 + 0.1 * (row % 2 == 0 ? j : 1000 - j);
            const double z = -5 + 0.3 * std::sin(x * 0.7) * std::cos(y * 0.3);
            std::snprintf(line, sizeof line, "G1 X%.4f Y%.4f Z%.4f\n", x, y, z);
            program += line;
        }
    }
    program += "G0 Z-1\nM2\n";
    for (const char *unit : {"gve64", "gve84"}) {
        for (const double ms : {1.0, 8.0, 16.0}) {
            SCOPED_TRACE(std::string(unit) + " at " + std::to_string(ms) + " ms");
            const auto loaded = frezka::machine::loadMachineConfig(
                std::string(FREZKA_SOURCE_DIR) + "/resources/machines/" + unit + ".json");
            ASSERT_TRUE(loaded.config);
            RandomJob job;
            job.config = *loaded.config;
            job.config.link.latencyMs = ms;
            job.wire.baud = job.config.link.baud;
            job.wire.latencyS = ms / 1000.0;
            job.program = program;
            const JobOutcome o = runJob(job);
            EXPECT_TRUE(o.wrong.empty()) << list(o.wrong);
            EXPECT_EQ(o.starvationStops, 0);
            EXPECT_EQ(o.brakeViolations, 0);
            EXPECT_NEAR(o.jobS / o.stats.estimatedS, 1.0, 0.02);
            // Not yet within 1.02 of the bound (1.029-1.039 here): measured, in the soak.
            std::printf("%s at %.0f ms: job %.2f s, estimate %.2f s, bound %.2f s\n", unit, ms,
                        o.jobS, o.stats.estimatedS, o.stats.boundS);
        }
    }
}

// Property seed 154 (a GVE64 at 57 600 Bd, 15 ms): after a V inside a chain the unit held a
// few milliseconds of motion, too little for any packet budget, and the driver sent a full
// packet (30 commands, 40 ms on the wire): the unit ran dry before its *E. The smallest packet,
// one vector, is the one that may still come in time (driver/link/job.cpp, sendPacket).
TEST(StreamPace, AUnitHoldingLittleGetsTheSmallestPacket)
{
    expectKeepsThePace(drawJob(154, 300));
}

// Property seed 95 (a GVE84 at 38 400 Bd, 11.5 ms, VN): a chain's first vector from rest with a
// V after it. The pace slowed that vector for the V's round trip but counted the time gained at
// cruise; from rest it is mostly acceleration, which a lower V lengthens less, and the unit ran
// dry behind the V. What slowing gains is now the stretch's own time (machine/chainpace.cpp).
TEST(StreamPace, AVectorSlowedFromRestGainsWhatItsAccelerationGives)
{
    expectKeepsThePace(drawJob(95, 300));
}

// Property seed 13 (a GVE114 without packets, one-step vectors, the operator's override at
// 160 %): the override's ceiling counted one round trip per window of commands, as with packets;
// without them each command waits for its own reply, the unit ran at 160 % and ran dry twice.
TEST(StreamPace, AnOverrideWithoutPacketsIsKeptWithinOneReplyPerCommand)
{
    expectKeepsThePace(drawJob(13, 300));
}

// Property seed 14 (a GVE64 at 38 400 Bd, 15 ms, one byte in a thousand garbled): packets grew
// back to 200 commands after each whole one, and a packet of 200 lines arrives whole about one
// time in twenty; half the wire went to resends. Their growth is now capped by the rate of
// damaged lines seen (driver/link/lineerrors.h): a quarter of the commands are sent again, a
// third before. Where the damage falls is a draw (any change to the polls moves it: one draw
// came to 0.301), so the share is judged over the same job on five draws of the damage.
TEST(StreamPace, PacketsOnANoisyLinkStaySmallEnoughToArriveWhole)
{
    double share = 0;
    for (std::uint32_t draw = 1; draw <= 5; ++draw) {
        RandomJob job = drawJob(14, 300);
        job.wire.seed += draw - 1;
        const JobOutcome o = runJob(job);
        EXPECT_TRUE(o.wrong.empty()) << "damage draw " << job.wire.seed << ": " << list(o.wrong);
        std::printf("damage draw %u: resent share %.3f\n", job.wire.seed, o.resendShare);
        share += o.resendShare / 5;
    }
    EXPECT_LT(share, 0.30);
}

// Property seed 34 (a GVE114 at 19 200 Bd): a poll saw the unit at rest, then an A and a V went
// out before the chain's first packet. The job's model ran the unit from the poll on, 0.13 s
// ahead of it, took it for holding nothing while it held 0.1 s, and sent a packet of 199
// commands (1.2 s on the wire): the unit ran dry at speed. The model now waits where the unit
// waited for its vectors (driver/link/jobpace.cpp, noteArrival).
TEST(StreamPace, TheUnitsWaitForItsVectorsHoldsTheModelBack)
{
    expectKeepsThePace(drawJob(34, 300));
}

// Property seed 320 (a GVE84 at 115 200 Bd, 14.7 ms, XM 200): A alternated between 5 and 1142
// at every one-step vector, so each C went alone, a round trip each. The override's ceiling
// counted one round trip per queue-full as if all travelled in packets, kept XM 200, and the
// unit ran dry 454 times. Each command outside a packet, and each packet, is now a round trip.
TEST(StreamPace, AnOverrideCountsARoundTripPerCommandOutsideAPacket)
{
    expectKeepsThePace(drawJob(320, 300));
}

// Property seed 344 (a GVE84, an X raster over the same line): a poll's position lay in the
// boxes of several passes; the job took the first, 70 vectors behind the unit, thought it held
// 0.25 s where it held 0.11 s, waited, and the unit ran dry at speed. The pace now takes the
// pass nearest to its model (driver/link/jobtracker.cpp); the screen still shows the first.
TEST(StreamPace, APollOnAPathThatComesBackIsPlacedNearTheModel)
{
    expectKeepsThePace(drawJob(344, 300));
}

// Property seed 376 (a chain's first vector from rest, then a V or an A): the pace counted the
// first vector's whole time as what the unit holds, but with nothing after it queued the unit
// brakes from the vector's midpoint; the change's round trips and the next packet arrived after
// that, 10 starvation stops. From rest the pace now counts to the brake point
// (RunPlanner::fromRestS), and a stretch it slows outlasts that, not just its cruise time.
TEST(StreamPace, AChainsFirstVectorCountsUntilTheUnitMustBrake)
{
    expectKeepsThePace(drawJob(376, 300));
}

// Property seed 390 (a GVE64 at 57 600 Bd, XM 170): the plan slowed a chain's first vector to
// V53 so that the V2447 after it and the next packet arrive before it ends; XM 170 ran it at 90
// pulses/s, and the unit ran dry 19 times. The override's ceiling now keeps each change inside a
// chain within the stretch before it (JobPace::overrideCeiling).
TEST(StreamPace, AnOverrideLeavesAChangeInsideAChainTheTimeItNeeds)
{
    expectKeepsThePace(drawJob(390, 300));
}

// Property seed 255 (a GVE64 at 19 200 Bd, 11.5 ms): an A and a V at nearly every vector after a
// first move of 9 s. The stream counted the bytes ahead, not their round trips, so it took the
// motion ahead for slower than the wire; the poller read position, F and inputs at full rate
// while the long move ran, one command went out between polls, and the unit ran dry 17 times
// once the short vectors came. JobPace::wireBoundAhead now counts a round trip per command
// outside a packet.
TEST(StreamPace, RoundTripsAheadCountWhenThePollerShares)
{
    expectKeepsThePace(drawJob(255, 300));
}
