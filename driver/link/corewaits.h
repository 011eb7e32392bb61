#pragma once
// CoreWaits: what MachineCore runs later, when the unit's status or the clock says so.
//
// Contract: four lists of continuations the activities leave through CoreHost: waits for the
// unit to stand (F read RUN = 0; afterIdle), the job's own such waits (WaitIdle, M0, ProgramEnd,
// ...; they count only while the job runs, not for a queue kept by K or a pause), waits for it
// to stand or an interrupt to brake it (RUN = 0 or INTA = 1), and timers at a time of the core's
// clock (afterDelay). The core reads F and decides; stopped() and idle() run what is due, each
// list taken whole first, so that a continuation adding a wait of its own waits for the next F;
// runDue() runs the timers due by then, one at a time, in the order they were set. Nothing here
// sends: the core asks for F whenever a wait is added. Each clear*() drops one list unrun.

#include <functional>
#include <utility>
#include <vector>

namespace frezka::driver {

class CoreWaits
{
public:
    void addIdle(std::function<void()> then) { m_idle.push_back(std::move(then)); }
    void addJobIdle(std::function<void()> then) { m_jobIdle.push_back(std::move(then)); }
    void addStop(std::function<void()> then) { m_stop.push_back(std::move(then)); }
    void addTimer(double when, std::function<void()> then)
    {
        m_timers.emplace_back(when, std::move(then));
    }

    // The unit stands or an interrupt braked it: runs the waits for either.
    void stopped();
    // The unit stands: runs the waits for idle, with the job's own when `jobCounts`.
    void idle(bool jobCounts);
    // Runs every timer due at `now`.
    void runDue(double now);
    // The earlier of `deadline` and the first timer, s.
    double nextTime(double deadline) const;

    // The job waits for the unit to stand (its own waits are pending).
    bool jobIdlePending() const { return !m_jobIdle.empty(); }

    void clearIdle() { m_idle.clear(); }
    void clearJobIdle() { m_jobIdle.clear(); }
    void clearStop() { m_stop.clear(); }
    void clearTimers() { m_timers.clear(); }

private:
    std::vector<std::function<void()>> m_idle;    // run when F shows RUN = 0
    std::vector<std::function<void()>> m_jobIdle; // the same, only while the job runs
    std::vector<std::function<void()>> m_stop;    // RUN = 0 or INTA = 1
    std::vector<std::pair<double, std::function<void()>>> m_timers; // (when, what)
};

} // namespace frezka::driver
