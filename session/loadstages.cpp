#include "loadstages.h"

#include <cstdio>
#include <cstdlib>
#include <cstring>

#if defined(__GLIBC__)
#include <malloc.h>
#endif

namespace frezka::session {

namespace {

// A "VmRSS:   1234 kB" line of /proc/self/status in MB (0 when there is none).
double statusMb(const char *key)
{
    std::FILE *f = std::fopen("/proc/self/status", "r");
    if (!f)
        return 0;
    char line[256];
    double mb = 0;
    const std::size_t n = std::strlen(key);
    while (std::fgets(line, sizeof line, f)) {
        if (std::strncmp(line, key, n) == 0) {
            mb = std::strtod(line + n, nullptr) / 1024.0;
            break;
        }
    }
    std::fclose(f);
    return mb;
}

} // namespace

double residentMb()
{
    return statusMb("VmRSS:");
}

double peakResidentMb()
{
    return statusMb("VmHWM:");
}

bool resetPeakResident()
{
    std::FILE *f = std::fopen("/proc/self/clear_refs", "w");
    if (!f)
        return false;
    const bool ok = std::fputs("5", f) >= 0;
    return std::fclose(f) == 0 && ok;
}

void returnFreeMemory()
{
#if defined(__GLIBC__)
    ::malloc_trim(0);
#endif
}

StageClock::StageClock(bool measurePeaks)
    : m_measurePeaks(measurePeaks && resetPeakResident())
    , m_start(std::chrono::steady_clock::now())
{}

void StageClock::done(const char *name)
{
    const auto now = std::chrono::steady_clock::now();
    LoadStage stage;
    stage.name = name;
    stage.seconds = std::chrono::duration<double>(now - m_start).count();
    stage.residentMb = residentMb();
    if (m_measurePeaks) {
        stage.peakMb = peakResidentMb();
        resetPeakResident();
    }
    m_stages.push_back(std::move(stage));
    m_start = std::chrono::steady_clock::now(); // the measuring itself is not a stage's
}

} // namespace frezka::session
