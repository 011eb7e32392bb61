// The stream property test's soak: the same random jobs as tests/machine/stream_property_test
// (random programs, machine profiles and links; tests/machine/randomjob.h), many more of them
// and larger. Prints each failing case with its seed (reproduce one with
// FREZKA_PROPERTY_SEED=<seed> build/tests/machine/stream_property_test), then the figures over
// all cases: the plan's estimate against its bound, the job time against the estimate on clean
// links, the wire spent on resends on faulty ones.
//
//   stream_soak [CASES (default 3000)] [FIRST_SEED (default 1)] [MAX_LINES (default 1200)]
//   stream_soak --one PROGRAM.nc PROFILE.json   one given job (the profile's baud, latency,
//                                                packets) on a clean link
//   stream_soak --dump SEED MAX_LINES DIR       writes that case's program and profile (its link
//                                                in link.baud/latencyMs/packets) to DIR/seed-N.*
//   stream_soak --ratios CASES FIRST_SEED MAX_LINES  each case's estimate / bound as planned,
//                                                without V and A sharing, without the link's pace,
//                                                and without either
//   STREAM_SOAK_VERBOSE=1 also lists every case off the link's pace (else only those that
//   stopped with an error on a clean link, which it must never do).
//   STREAM_SOAK_SPLIT=1 prints, per clean case, where its time went against the estimate: the
//   unit's moving time against the plan's model, the rest standing (rests, holds, T, dwells).
// The clean links' figures against the estimate count the jobs at 100 % only, as the judge
// does (until 2026-11-27 the jobs at a feed override were counted too: 13 of the 32 "more than
// 2 % off" in the 200 cases from seed 1, and the 36-43 % worst).
#include "randomjob.h"

#include "gcode/interpreter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iterator>
#include <string>

using namespace frezka::machine::test;

namespace {

// One given program on one given profile (its link.baud, link.latencyMs and link.packets), on a
// clean link: the judge's verdict (FREZKA_PROPERTY_TRACE=1 adds the link log).
int runOne(const char *programPath, const char *profilePath)
{
    RandomJob job;
    const auto loaded = frezka::machine::loadMachineConfig(profilePath);
    if (!loaded.config) {
        std::fprintf(stderr, "cannot load %s\n", profilePath);
        return 2;
    }
    job.config = *loaded.config;
    job.wire.baud = job.config.link.baud;
    job.wire.latencyS = job.config.link.latencyMs / 1000.0;
    std::ifstream in(programPath);
    job.program.assign(std::istreambuf_iterator<char>(in), {});
    const JobOutcome o = runJob(job);
    std::printf("job %.3f s, estimate %.3f s, bound %.3f s, vectors %lld, starvation stops %lld, "
                "brake violations %lld, exact %d\n",
                o.jobS, o.stats.estimatedS, o.stats.boundS,
                static_cast<long long>(o.vectorsPlanned), static_cast<long long>(o.starvationStops),
                static_cast<long long>(o.brakeViolations), o.exact ? 1 : 0);
    for (const std::string &f : o.wrong)
        std::printf("  wrong: %s\n", f.c_str());
    for (const std::string &f : o.pace)
        std::printf("  pace: %s\n", f.c_str());
    return o.wrong.empty() ? 0 : 1;
}

// Where a case's estimate lies above its bound: the plan's estimate and bound with the link's
// pace as planned, without V and A sharing (speedChangeCost 0), without the link's pace, and
// without either.
int ratios(long cases, long first, int maxLines)
{
    for (long i = 0; i < cases; ++i) {
        const RandomJob job = drawJob(static_cast<std::uint64_t>(first + i), maxLines);
        const auto toolpath = frezka::gcode::interpretText(job.program).toolpath;
        std::printf("seed %ld:", first + i);
        for (int variant = 0; variant < 4; ++variant) {
            frezka::machine::PlanOptions o;
            o.speedChangeCost = variant == 1 || variant == 3 ? 0.0 : 1.0;
            o.wireLimited = variant < 2;
            const auto p = frezka::machine::plan(toolpath, job.config, o);
            std::printf(" %s %.3f/%.3f=%.4f",
                        variant == 0   ? "plan"
                        : variant == 1 ? "noshare"
                        : variant == 2 ? "nopace"
                                       : "neither",
                        p.stats.estimatedS, p.stats.boundS,
                        p.stats.boundS > 0 ? p.stats.estimatedS / p.stats.boundS : 0.0);
        }
        std::printf("  %s\n", job.summary.c_str());
    }
    return 0;
}

// Writes one drawn case as files that --one (or frezka-cli) can take.
int dumpOne(std::uint64_t seed, int maxLines, const std::string &dir)
{
    RandomJob job = drawJob(seed, maxLines);
    job.config.link.baud = job.wire.baud;
    job.config.link.latencyMs = job.wire.latencyS * 1000.0;
    const std::string base = dir + "/seed-" + std::to_string(seed);
    std::ofstream(base + ".nc") << job.program;
    frezka::machine::saveMachineConfig(job.config, base + ".json");
    std::printf("%s\n%s.nc %s.json (byte error rate %g, override %d %%)\n", job.summary.c_str(),
                base.c_str(), base.c_str(), job.wire.byteErrorRate, job.overridePercent);
    return 0;
}

} // namespace

int main(int argc, char **argv)
{
    if (argc == 4 && std::string(argv[1]) == "--one")
        return runOne(argv[2], argv[3]);
    if (argc == 5 && std::string(argv[1]) == "--ratios")
        return ratios(std::atol(argv[2]), std::atol(argv[3]), std::atoi(argv[4]));
    if (argc == 5 && std::string(argv[1]) == "--dump")
        return dumpOne(std::strtoull(argv[2], nullptr, 10), std::atoi(argv[3]), argv[4]);
    const long cases = argc > 1 ? std::atol(argv[1]) : 3000;
    const long first = argc > 2 ? std::atol(argv[2]) : 1;
    const int maxLines = argc > 3 ? std::atoi(argv[3]) : 1200;
    const bool verbose = std::getenv("STREAM_SOAK_VERBOSE") != nullptr;
    long offPace = 0, starvedCases = 0, brakeCases = 0, starved = 0, estimateOff = 0;
    long failed = 0, clean = 0, faulty = 0, pathFaults = 0, packetsOff = 0, cleanStopped = 0;
    long heldCases = 0, holds = 0, cleanOverride = 0, cleanOverrideOff = 0;
    long dryHolds = 0, dryCases = 0, dryClean = 0;
    double worstBoundRatio = 0, worstClean = 0, sumClean = 0, worstResend = 0, sumResend = 0;
    double virtualS = 0;
    long vectors = 0;
    for (long i = 0; i < cases; ++i) {
        const auto seed = static_cast<std::uint64_t>(first + i);
        const RandomJob job = drawJob(seed, maxLines);
        const JobOutcome o = runJob(job);
        if (!o.wrong.empty()) {
            ++failed;
            std::printf("WRONG seed %llu: %s\n", static_cast<unsigned long long>(seed),
                        job.summary.c_str());
            for (const std::string &f : o.wrong)
                std::printf("  - %s\n", f.c_str());
            std::fflush(stdout);
        }
        if (!o.pace.empty()) {
            ++offPace;
            const bool stopped = std::any_of(o.pace.begin(), o.pace.end(), [](const auto &p) {
                return p.starts_with("clean link: the job did not finish");
            });
            cleanStopped += stopped ? 1 : 0;
            if (stopped && !verbose)
                std::printf("STOPPED seed %llu: %s\n  - %s\n",
                            static_cast<unsigned long long>(seed), job.summary.c_str(),
                            o.pace.front().c_str());
            starvedCases += o.starvationStops > 0 ? 1 : 0;
            starved += o.starvationStops;
            brakeCases += o.brakeViolations > 0 ? 1 : 0;
            if (verbose) {
                std::printf("pace seed %llu: %s\n", static_cast<unsigned long long>(seed),
                            job.summary.c_str());
                for (const std::string &f : o.pace)
                    std::printf("  - %s\n", f.c_str());
            }
        }
        if (!o.planned)
            continue;
        vectors += o.vectorsPlanned;
        virtualS += o.jobS;
        heldCases += o.leadInHolds > 0 ? 1 : 0;
        holds += o.leadInHolds;
        dryHolds += o.dryHolds;
        dryCases += o.dryHolds > 0 ? 1 : 0;
        dryClean += job.wire.byteErrorRate == 0 ? o.dryHolds : 0;
        packetsOff += job.config.link.packets ? 0 : 1;
        if (o.stats.boundS > 0)
            worstBoundRatio = std::max(worstBoundRatio, o.stats.estimatedS / o.stats.boundS);
        const double off = o.stats.estimatedS > 0 ? o.jobS / o.stats.estimatedS - 1 : 0;
        if (std::getenv("STREAM_SOAK_RESTS") && job.wire.byteErrorRate == 0)
            std::printf("rests %lld latency %.1f baud %d packets %d over %.4f s\n",
                        static_cast<long long>(o.rests), job.wire.latencyS * 1000, job.wire.baud,
                        job.config.link.packets ? 1 : 0, o.jobS - o.stats.estimatedS);
        if (std::getenv("STREAM_SOAK_SPLIT") && job.wire.byteErrorRate == 0)
            std::printf("split seed %llu: off %+.2f %% over %.4f s moving %+.4f s standing %+.4f "
                        "s, held %lld, rests %lld, override %d, %s\n",
                        static_cast<unsigned long long>(seed), 100 * off,
                        o.jobS - o.stats.estimatedS, o.movingS - o.modelMotionS,
                        o.jobS - o.stats.estimatedS - (o.movingS - o.modelMotionS),
                        static_cast<long long>(o.leadInHolds), static_cast<long long>(o.rests),
                        job.overridePercent, job.summary.c_str());
        if (job.wire.byteErrorRate == 0 && job.overridePercent != 100) {
            // The estimate is the plan's at 100 %: timed by the judge only there (randomjob.h).
            ++cleanOverride;
            cleanOverrideOff += std::abs(off) > 0.02 ? 1 : 0;
        } else if (job.wire.byteErrorRate == 0) {
            ++clean;
            worstClean = std::max(worstClean, std::abs(off));
            estimateOff += std::abs(off) > 0.02 ? 1 : 0;
            sumClean += std::abs(off);
        } else {
            ++faulty;
            worstResend = std::max(worstResend, o.resendShare);
            sumResend += o.resendShare;
            pathFaults += o.pathFaults > 0 ? 1 : 0;
        }
    }
    std::printf("\n# stream soak: %ld cases from seed %ld (programs up to %d lines)\n", cases,
                first, maxLines);
    std::printf("cases ending wrong or over a machine limit   %ld\n", failed);
    std::printf("cases off the link's pace or the estimate    %ld\n", offPace);
    std::printf("  with starvation stops                      %ld (%ld stops)\n", starvedCases,
                starved);
    std::printf("  with brake violations on the unit          %ld\n", brakeCases);
    std::printf("  clean links, job stopped with an error     %ld\n", cleanStopped);
    std::printf("  clean links, job more than 2 %% off the estimate %ld\n", estimateOff);
    std::printf("vectors streamed                %ld (%.0f s of virtual job time)\n", vectors,
                virtualS);
    std::printf("packets off                     %ld cases\n", packetsOff);
    std::printf("chains held at their start      %ld (in %ld cases)\n", holds, heldCases);
    std::printf("chains halted before running dry %ld (in %ld cases; on clean links %ld)\n",
                dryHolds, dryCases, dryClean);
    std::printf("estimate / bound, worst         %.4f\n", worstBoundRatio);
    std::printf("clean links: job / estimate - 1 mean %.4f %%, worst %.4f %% (%ld cases)\n",
                clean ? 100 * sumClean / clean : 0.0, 100 * worstClean, clean);
    std::printf("clean links at a feed override (not timed): %ld cases, %ld more than 2 %% off\n",
                cleanOverride, cleanOverrideOff);
    std::printf("faulty links (1/1000 bytes): resent share mean %.2f %%, worst %.2f %%, path "
                "faults returned in %ld of %ld cases\n",
                faulty ? 100 * sumResend / faulty : 0.0, 100 * worstResend, pathFaults, faulty);
    return failed == 0 ? 0 : 1;
}
