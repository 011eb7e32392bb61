// The stream property test: random programs on random machine profiles over random links
// (tests/machine/randomjob.h), each planned, streamed through the driver to the in-process
// emulator on a virtual clock, and judged against every invariant the plan and the stream claim.
// A failing case prints its seed; FREZKA_PROPERTY_SEED=<seed> runs that one case alone,
// FREZKA_PROPERTY_CASES=<n> changes how many run (default 300), FREZKA_PROPERTY_DUMP=<dir>
// writes each failing case's program and profile there (seed-N.nc, seed-N.json: for
// `frezka-cli run seed-N.nc --machine seed-N.json --port sim --latency-ms ...`). The long soak of
// the same cases: tests/bench/planner/stream_soak.
#include "randomjob.h"

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

using namespace frezka::machine::test;

namespace {

std::uint64_t envNumber(const char *name, std::uint64_t fallback)
{
    const char *v = std::getenv(name);
    return v && *v ? std::strtoull(v, nullptr, 10) : fallback;
}

} // namespace

TEST(StreamProperty, RandomProgramsProfilesAndLinks)
{
    const std::uint64_t only = envNumber("FREZKA_PROPERTY_SEED", 0);
    const std::uint64_t cases = only ? 1 : envNumber("FREZKA_PROPERTY_CASES", 300);
    int failed = 0;
    for (std::uint64_t i = 0; i < cases; ++i) {
        const std::uint64_t seed = only ? only : i + 1;
        const RandomJob job = drawJob(seed, 600);
        const JobOutcome o = runJob(job);
        if (o.failures.empty())
            continue;
        ++failed;
        if (const char *dir = std::getenv("FREZKA_PROPERTY_DUMP")) {
            const std::string base = std::string(dir) + "/seed-" + std::to_string(seed);
            std::ofstream(base + ".nc") << job.program;
            frezka::machine::saveMachineConfig(job.config, base + ".json");
        }
        std::string what;
        for (const std::string &f : o.failures)
            what += "\n  - " + f;
        ADD_FAILURE() << "seed " << seed << " (FREZKA_PROPERTY_SEED=" << seed
                      << "): " << job.summary << what;
    }
    EXPECT_EQ(failed, 0) << "of " << cases << " cases";
}
