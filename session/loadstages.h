#pragma once
// Stages of a program load, timed: how long each took and how much memory the process held
// (issue 17 item 1: the loader's own account, printed by bench_gui_load). The seconds and the
// resident memory at the end of each stage are always kept (reading /proc/self/status costs
// microseconds); the peak within each stage needs the kernel's high-water mark reset at the
// stage's start (Linux: /proc/self/clear_refs), which only a measuring run asks for. Std only.

#include <chrono>
#include <string>
#include <vector>

namespace frezka::session {

struct LoadStage
{
    std::string name;
    double seconds = 0;
    double residentMb = 0; // at the stage's end
    double peakMb = -1;    // the largest resident set during the stage; < 0: not measured
};

class StageClock
{
public:
    explicit StageClock(bool measurePeaks = false);
    // The stage since the clock was made or since the last done() ended.
    void done(const char *name);
    const std::vector<LoadStage> &stages() const { return m_stages; }
    std::vector<LoadStage> take() { return std::move(m_stages); }

private:
    bool m_measurePeaks;
    std::chrono::steady_clock::time_point m_start;
    std::vector<LoadStage> m_stages;
};

// The process's resident memory now and its high-water mark (MB; 0 where unknown), and the
// mark set back to the resident memory now (false where the system cannot).
double residentMb();
double peakResidentMb();
bool resetPeakResident();
// Gives the memory the allocator holds free back to the system (glibc: malloc_trim), so that
// a load's transient peak leaves no high-water mark behind; a no-op elsewhere.
void returnFreeMemory();

} // namespace frezka::session
