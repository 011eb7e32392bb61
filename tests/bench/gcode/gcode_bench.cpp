// G-code interpreter benchmark (issue 3). Not run by ctest.
//
// Generates the 1 000 000-line dense 3D-finishing program and the 200 000-line arc-heavy 2.5D
// program (into DIR, default /tmp/frezka-gcode-bench), then for each:
//   - parse + interpret in this process: wall time, lines/s, MB/s, toolpath bytes per move and
//     the peak RSS growth per move (the file's mapped pages included);
//   - `frezka-cli toolpath FILE > /dev/null` (the whole CLI: start-up, interpretation and the
//     JSON Lines output) and LinuxCNC's `rs274 -g FILE > /dev/null` side by side, best of 3.
//
// usage: gcode_bench [DIR]
#include "generate.h"

#include "gcode/interpreter.h"

#include <chrono>
#include <cstdio>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <string>

#include <sys/resource.h>

using namespace frezka::gcode;
namespace fs = std::filesystem;
using Clock = std::chrono::steady_clock;

namespace {

long statusKb(const char *field)
{
    std::ifstream in("/proc/self/status");
    std::string key;
    long value = 0;
    while (in >> key) {
        if (key == field) {
            in >> value;
            return value;
        }
        std::getline(in, key);
    }
    return -1;
}

double seconds(Clock::time_point a, Clock::time_point b)
{
    return std::chrono::duration<double>(b - a).count();
}

double childCpuSeconds()
{
    rusage usage{};
    getrusage(RUSAGE_CHILDREN, &usage);
    return static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
           static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec) / 1e6;
}

struct Timing
{
    double wall = -1; // best of three, s
    double cpu = -1;  // user + system of that run, s
};

// Best of three runs of a shell command (wall clock; the machine is shared, so the CPU time
// of the same run is printed as well). wall < 0 if the command fails.
Timing timeCommand(const std::string &command)
{
    Timing best;
    for (int i = 0; i < 3; ++i) {
        const double cpu0 = childCpuSeconds();
        const auto t0 = Clock::now();
        const int rc = std::system(command.c_str());
        const double wall = seconds(t0, Clock::now());
        const double cpu = childCpuSeconds() - cpu0;
        if (rc != 0)
            return {};
        if (best.wall < 0 || wall < best.wall)
            best = {wall, cpu};
    }
    return best;
}

// Resets VmHWM to the current RSS (Linux >= 4.0), so each run's peak is its own.
void resetPeakRss()
{
    std::ofstream("/proc/self/clear_refs") << "5";
}

void benchFile(const fs::path &file, const char *title)
{
    const double mb = static_cast<double>(fs::file_size(file)) / 1e6;
    std::printf("\n== %s: %s (%.1f MB)\n", title, file.c_str(), mb);

    resetPeakRss();
    const long rssBefore = statusKb("VmRSS:");
    const auto t0 = Clock::now();
    const Result r = interpretFile(file.string());
    const double s = seconds(t0, Clock::now());
    const long hwm = statusKb("VmHWM:");
    if (!r.ok()) {
        std::printf("  error: %s\n", englishMessage(r.errors[0]).c_str());
        return;
    }
    const double moves = static_cast<double>(r.toolpath.size());
    std::printf("  interpret (in process): %.3f s, %.2f M lines/s, %.0f MB/s, %zu entries\n", s,
                static_cast<double>(r.linesRead) / s / 1e6, mb / s, r.toolpath.size());
    std::printf("  memory: toolpath %.1f bytes/move, peak RSS growth %.1f bytes/move\n",
                static_cast<double>(r.toolpath.memoryBytes()) / moves,
                static_cast<double>(hwm - rssBefore) * 1024.0 / moves);

    const std::string quoted = "'" + file.string() + "'";
    const Timing cli =
        timeCommand(std::string(FREZKA_CLI_PATH) + " toolpath " + quoted + " > /dev/null");
    const Timing rs = timeCommand("rs274 -g " + quoted + " > /dev/null 2>&1");
    std::printf("  frezka-cli toolpath > /dev/null: wall %.3f s, cpu %.3f s\n", cli.wall, cli.cpu);
    if (rs.wall > 0) {
        std::printf("  rs274 -g > /dev/null:            wall %.3f s, cpu %.3f s\n", rs.wall,
                    rs.cpu);
        std::printf("  frezka-cli is %.1fx faster (wall), %.1fx (cpu)\n", rs.wall / cli.wall,
                    rs.cpu / cli.cpu);
    } else {
        std::printf("  rs274: not available (install linuxcnc-uspace)\n");
    }
}

} // namespace

int main(int argc, char **argv)
{
    const fs::path dir = argc > 1 ? argv[1] : "/tmp/frezka-gcode-bench";
    fs::create_directories(dir);
    const fs::path dense = dir / "dense_finishing_1M.nc";
    const fs::path arcs = dir / "arc_heavy_200k.nc";
    if (!fs::exists(dense))
        std::ofstream(dense, std::ios::binary) << bench::denseFinishing(1'000'000);
    if (!fs::exists(arcs))
        std::ofstream(arcs, std::ios::binary) << bench::arcHeavy(200'000);
    benchFile(dense, "dense 3D finishing, 1M lines");
    benchFile(arcs, "arc-heavy 2.5D, 200k lines");
    return 0;
}
