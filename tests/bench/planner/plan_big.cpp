// plan_big: the planner alone on bench_gui_load's spiral (issue 17): one chain of N short G1
// moves (default 1 000 000), interpreted, then planned with the link's pace as the program
// session plans it. Prints the seconds and the peak resident memory of each stage, and the
// plan's size and estimate; not run by ctest. For profiling the planner without the GUI:
//   build/tests/bench/planner/plan_big [lines] [gve64|gve84|gve114]
//   perf record -g build/tests/bench/planner/plan_big 1000000
#include "gcode/interpreter.h"
#include "machine/planner.h"

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <string>

#include <sys/resource.h>

namespace {

double statusMb(const char *key)
{
    std::FILE *f = std::fopen("/proc/self/status", "r");
    if (!f)
        return 0;
    char line[256];
    double mb = 0;
    while (std::fgets(line, sizeof line, f)) {
        if (std::strncmp(line, key, std::strlen(key)) == 0)
            mb = std::strtod(line + std::strlen(key), nullptr) / 1024.0;
    }
    std::fclose(f);
    return mb;
}

void resetPeak()
{
    if (std::FILE *f = std::fopen("/proc/self/clear_refs", "w")) {
        std::fputs("5", f);
        std::fclose(f);
    }
}

// User + system CPU seconds of the process: on a shared machine a steadier figure than the wall
// clock (the other processes' load lengthens the wall time, not this).
double cpuS()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_utime.tv_sec + u.ru_stime.tv_sec) +
           double(u.ru_utime.tv_usec + u.ru_stime.tv_usec) / 1e6;
}

struct Clock
{
    std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
    double startCpuS = cpuS();
    void done(const char *stage)
    {
        const auto now = std::chrono::steady_clock::now();
        std::printf("%-12s %8.3f s wall %8.3f s cpu  peak %7.0f MB  resident %7.0f MB\n", stage,
                    std::chrono::duration<double>(now - start).count(), cpuS() - startCpuS,
                    statusMb("VmHWM:"), statusMb("VmRSS:"));
        std::fflush(stdout);
        resetPeak();
        start = std::chrono::steady_clock::now();
        startCpuS = cpuS();
    }
};

} // namespace

int main(int argc, char **argv)
{
    using namespace frezka;
    const long lines = argc > 1 ? std::atol(argv[1]) : 1'000'000;
    const std::string unit = argc > 2 ? argv[2] : "gve64";
    const protocol::Variant variant = unit == "gve84"    ? protocol::Variant::Gve84
                                      : unit == "gve114" ? protocol::Variant::Gve114
                                                         : protocol::Variant::Gve64;
    resetPeak();
    Clock clock;
    std::string text = "G21 G90 G94\nG0 X0 Y0 Z0\nG1 Z-1 F1500\n";
    text.reserve(std::size_t(lines) * 22);
    char buf[64];
    for (long i = 3; i < lines - 1; ++i) { // as bench_gui_load writes it
        const double t = double(i) * 0.002;
        const double r = 10 + double(i) * 120.0 / double(lines);
        std::snprintf(buf, sizeof buf, "G1 X%.3f Y%.3f\n", 200 + r * std::cos(t),
                      150 + r * std::sin(t));
        text += buf;
    }
    text += "M30\n";
    clock.done("generate");
    gcode::Result g = gcode::interpretText(text);
    clock.done("interpret");
    const machine::MachineConfig config = machine::defaultMachineConfig(variant);
    const machine::PlanResult r = machine::plan(g.toolpath, config);
    clock.done("plan");
    std::printf("%ld lines, %s: %zu commands, %zu vectors, %zu chains, estimated %.3f s, bound "
                "%.3f s, %zu errors, %.2f plans a move (at most %d a run)\n",
                lines, unit.c_str(), r.program.commands.size(), r.stats.vectors, r.stats.chains,
                r.stats.estimatedS, r.stats.boundS, r.errors.size(),
                r.stats.vectors ? double(r.stats.movePlans) / double(r.stats.vectors) : 0.0,
                r.stats.mostPlans);
    return 0;
}
