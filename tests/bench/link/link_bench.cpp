// Link benchmarks on the in-process emulator (virtual clock, so the figures are the modelled
// wire's, deterministic, independent of this machine's load):
//
//  1. Link efficiency: achieved vectors/s while streaming a dense program (motion faster than
//     the wire) divided by the wire limit (baud/10 / bytes per vector), at 115 200 Bd with 0, 1,
//     8 and 16 ms latency per direction, with packets and against the one-command-one-reply
//     baseline. Polling (PF/P4 + F) stays on.
//  2. Starvation: a program whose motion is slower than the wire, at 16 ms latency: starvation
//     stops must be 0.
//  3. Fault soak (LINK_BENCH_SOAK_FROM=<run> starts at that run): many runs with 1 byte error per
//  1000 bytes (corrupted, dropped or duplicated)
//     and 1 lost reply per 1000; counts runs whose final counters differ from the expected steps
//     or whose executed vector count differs from the program's.
//
// Usage: link_bench [soak-runs (default 50)]

#include "simfixture.h"

#include <cstdio>
#include <cstdlib>

using namespace frezka;
using namespace frezka::driver;
using namespace frezka::driver::test;

namespace {

struct Result
{
    double vectorsPerS = 0;
    double wireLimit = 0;
    double pollHz = 0;       // position polls while vectors were to send, per second of the stream
    double steadyPollHz = 0; // ... from the first such poll on (after the first packet)
    double maxPollGapS = 0;  // the longest time without a poll meanwhile, from the job's start
    std::int64_t starvation = 0;
    std::int64_t brake = 0;
    bool exact = false;
};

double bytesPerVector(const machine::UnitProgram &p)
{
    double bytes = 0;
    int n = 0;
    for (const auto &c : p.commands) {
        if (c.op != machine::UnitOp::Vector)
            continue;
        bytes += static_cast<double>(
            protocol::encode(protocol::cmd::vector(c.d[0], c.d[1], c.d[2]), true).size());
        ++n;
    }
    return bytes / n;
}

Result stream(const machine::UnitProgram &program, double latencyS, bool packets,
              protocol::Variant variant = protocol::Variant::Gve64)
{
    WireOptions wire;
    wire.latencyS = latencyS;
    CoreOptions options;
    options.packets = packets;
    Sim sim(variant, wire, options);
    Result r;
    if (!sim.connect())
        return r;
    if (const char *t = getenv("LINK_BENCH_TRACE");
        t && std::atof(t) == latencyS * 1000 && packets && variant == protocol::Variant::Gve64 &&
        program.commands.size() > 6000 &&
        program.commands[5].d[0] ==
            (getenv("LINK_BENCH_STEPS") ? std::atoi(getenv("LINK_BENCH_STEPS")) : 30)) {
        sim.core.onLog = [&sim](const std::string &line) {
            std::printf("%10.4f %s\n", sim.runner.now(), line.substr(0, 60).c_str());
        };
    }
    if (sim.core.run(program, sim.runner.now()))
        return r;
    sim.runner.runUntil([&] { return !sim.finished.empty(); }, 3600);
    const JobReport &rep = sim.core.jobReport();
    const double streamS = rep.lastVectorAckS - rep.startS;
    r.vectorsPerS = static_cast<double>(rep.vectors) / streamS;
    r.wireLimit = 115200.0 / 10.0 / bytesPerVector(program);
    r.pollHz = static_cast<double>(rep.streamPolls) / streamS;
    if (rep.streamPolls > 1)
        r.steadyPollHz =
            static_cast<double>(rep.streamPolls - 1) / (rep.lastStreamPollS - rep.firstStreamPollS);
    r.maxPollGapS = rep.maxStreamPollGapS;
    if (getenv("LINK_BENCH_DEBUG"))
        std::printf("  packets %lld, vectors %lld, stream %.3f s\n",
                    static_cast<long long>(rep.packets), static_cast<long long>(rep.vectors),
                    streamS);
    const auto stats = sim.port.unit().stats().motion;
    r.starvation = stats.starvationStops;
    r.brake = stats.brakeViolations;
    const auto pos = sim.port.unit().position();
    r.exact = !sim.finished.empty() && sim.finished.front();
    for (int a = 0; a < 3; ++a)
        r.exact = r.exact && pos[a] == program.commands.back().endSteps[a];
    return r;
}

} // namespace

int main(int argc, char **argv)
{
    const int soakRuns = argc > 1 ? std::atoi(argv[1]) : 50;
    struct Case
    {
        const char *name;
        machine::UnitProgram program;
    };
    // Dense programs: motion faster than the wire, so the wire sets the pace.
    const Case cases[] = {
        {"6000 vectors of 30 steps at 50000 pulses/s (0.6 ms of motion each)",
         denseProgram(6000, 3, 50000, 50000, 30)},
        {"6000 vectors of 60 steps at 50000 pulses/s (1.2 ms of motion each, close to the wire)",
         denseProgram(6000, 3, 50000, 50000, 60)},
    };
    for (const Case &c : cases) {
        const auto &dense = c.program;
        std::printf("# link efficiency, GVE64 at 115200 Bd, dense program: %s, %.1f bytes per "
                    "vector\n",
                    c.name, bytesPerVector(dense));
        std::printf("%-10s %-22s %12s %12s %10s %8s %11s %6s\n", "latency", "mode", "vectors/s",
                    "wire limit", "efficiency", "poll Hz", "starvation", "exact");
        for (double ms : {0.0, 1.0, 8.0, 16.0}) {
            for (bool packets : {true, false}) {
                const Result r = stream(dense, ms / 1000.0, packets);
                std::printf("%-10s %-22s %12.1f %12.1f %9.1f%% %8.1f %11lld %6s\n",
                            (std::to_string(static_cast<int>(ms)) + " ms").c_str(),
                            packets ? "packets" : "one command, one reply", r.vectorsPerS,
                            r.wireLimit, 100.0 * r.vectorsPerS / r.wireLimit, r.pollHz,
                            static_cast<long long>(r.starvation), r.exact ? "yes" : "NO");
            }
        }
        std::printf("\n");
    }
    {
        const auto dense = denseProgram(12000, 3, 50000, 50000, 30);
        std::printf("# the same program A (12000 vectors) on a GVE114 (queue of 2048 vectors)\n");
        for (double ms : {0.0, 8.0, 16.0}) {
            const Result r = stream(dense, ms / 1000.0, true, protocol::Variant::Gve114);
            std::printf("%-10s %-22s %12.1f %12.1f %9.1f%% %8.1f %11lld %6s\n",
                        (std::to_string(static_cast<int>(ms)) + " ms").c_str(), "packets",
                        r.vectorsPerS, r.wireLimit, 100.0 * r.vectorsPerS / r.wireLimit, r.pollHz,
                        static_cast<long long>(r.starvation), r.exact ? "yes" : "NO");
        }
        std::printf("\n");
    }
    // Slow motion: 400-step vectors at 50 000 pulses/s = 8 ms each, slower than the wire.
    const auto slow = denseProgram(2000, 3, 50000, 50000, 400);
    for (double ms : {1.0, 8.0, 16.0}) {
        const Result s = stream(slow, ms / 1000.0, true);
        std::printf("# motion slower than the wire (2000 vectors of 400 steps, 8 ms each), %d ms "
                    "latency: starvation stops %lld, brake violations %lld, polls %.1f Hz "
                    "(%.1f Hz after the first packet, longest gap %.3f s), exact %s\n",
                    static_cast<int>(ms), static_cast<long long>(s.starvation),
                    static_cast<long long>(s.brake), s.pollHz, s.steadyPollHz, s.maxPollGapS,
                    s.exact ? "yes" : "NO");
    }
    std::printf("\n# fault soak: %d runs x 1500 vectors, 1 byte error per 1000 bytes, 1 lost "
                "reply per 1000, 4 ms latency\n",
                soakRuns);
    int bad = 0, faulted = 0;
    std::int64_t corrupted = 0, dropped = 0, duplicated = 0, lost = 0, recovered = 0, resent = 0,
                 verified = 0, again = 0;
    const auto soak = denseProgram(1500);
    // LINK_BENCH_SOAK_FROM=<run>: start there (to look at one run again).
    const char *from = getenv("LINK_BENCH_SOAK_FROM");
    for (int run = from ? std::atoi(from) : 0; run < soakRuns; ++run) {
        WireOptions wire;
        wire.latencyS = 0.004;
        wire.byteErrorRate = 1e-3;
        wire.replyLossRate = 1e-3;
        wire.seed = static_cast<std::uint32_t>(1000 + run);
        CoreOptions options;
        options.returnToPathAutomatically = true; // no operator here
        Sim sim(protocol::Variant::Gve64, wire, options);
        if (const char *t = getenv("LINK_BENCH_SOAK_TRACE"); t && std::atoi(t) == 1000 + run) {
            sim.core.onLog = [&sim](const std::string &line) {
                std::printf("%10.4f %s\n", sim.runner.now(), line.substr(0, 70).c_str());
            };
        }
        bool ok = sim.connect(300) && !sim.core.run(soak, sim.runner.now()) &&
                  sim.runner.runUntil([&] { return !sim.finished.empty(); }, 3600) &&
                  sim.finished.front();
        const auto pos = sim.port.unit().position();
        for (int a = 0; a < 3; ++a)
            ok = ok && pos[a] == soak.commands.back().endSteps[a];
        // Every vector exactly once; after a path fault, also the few between the last
        // verified point and the stop once more (and the L moves back to the path).
        const JobReport &report = sim.core.jobReport();
        const std::int64_t extra =
            sim.port.unit().stats().motion.vectorsExecuted - 1500 - report.returnMoves;
        ok = ok && report.vectors == 1500 &&
             (report.pathFaults == 0 ? extra == 0 : extra >= 0 && extra <= report.rerun);
        if (report.pathFaults > 0) {
            ++faulted;
            again += extra;
            if (ok)
                std::printf("run %d (seed %d): the unit left the path (%lld), returned, %lld "
                            "vectors ran again; final counters exact\n",
                            run, 1000 + run, static_cast<long long>(report.pathFaults),
                            static_cast<long long>(extra));
        }
        if (!ok) {
            ++bad;
            std::printf(
                "run %d (seed %d) FAILED: counters %lld %lld %lld, expected %lld %lld %lld, "
                "%lld vectors executed (job: %lld vectors, %lld path faults, %lld sent again, %lld "
                "moves back)\n%s\n",
                run, 1000 + run, static_cast<long long>(pos[0]), static_cast<long long>(pos[1]),
                static_cast<long long>(pos[2]),
                static_cast<long long>(soak.commands.back().endSteps[0]),
                static_cast<long long>(soak.commands.back().endSteps[1]),
                static_cast<long long>(soak.commands.back().endSteps[2]),
                static_cast<long long>(sim.port.unit().stats().motion.vectorsExecuted),
                static_cast<long long>(report.vectors), static_cast<long long>(report.pathFaults),
                static_cast<long long>(report.rerun), static_cast<long long>(report.returnMoves),
                sim.lastLog(12).c_str());
        }
        const WireStats w = sim.port.wireStats();
        corrupted += w.corrupted;
        dropped += w.dropped;
        duplicated += w.duplicated;
        lost += w.repliesLost;
        recovered += sim.core.jobReport().recovered;
        resent += sim.core.jobReport().resent;
        verified += sim.core.jobReport().verified;
    }
    std::printf("runs with wrong final counters or vector count: %d of %d\n", bad, soakRuns);
    std::printf("runs where the unit ran something other than what was sent (a damage the checksum "
                "passed, or a packet run as loose lines with one missing; caught by the path "
                "guard, returned to the path): %d, vectors run again there: %lld\n",
                faulted, static_cast<long long>(again));
    std::printf("faults injected: %lld corrupted, %lld dropped, %lld duplicated bytes, %lld lost "
                "replies; driver: %lld replies recovered (@/>), %lld commands resent, %lld "
                "progress checks from the counters\n",
                static_cast<long long>(corrupted), static_cast<long long>(dropped),
                static_cast<long long>(duplicated), static_cast<long long>(lost),
                static_cast<long long>(recovered), static_cast<long long>(resent),
                static_cast<long long>(verified));
    return bad == 0 ? 0 : 1;
}
