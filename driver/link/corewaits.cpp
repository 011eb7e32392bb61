// CoreWaits: the core's waits on the unit's status and its timers. See corewaits.h.

#include "corewaits.h"

#include <algorithm>

namespace frezka::driver {

void CoreWaits::stopped()
{
    if (m_stop.empty())
        return;
    auto stop = std::move(m_stop);
    m_stop.clear();
    for (auto &w : stop)
        w();
}

void CoreWaits::idle(bool jobCounts)
{
    auto waiters = std::move(m_idle);
    m_idle.clear();
    if (jobCounts) {
        for (auto &w : m_jobIdle)
            waiters.push_back(std::move(w));
        m_jobIdle.clear();
    }
    for (auto &w : waiters) {
        if (w)
            w();
    }
}

void CoreWaits::runDue(double now)
{
    for (;;) {
        auto due = std::find_if(m_timers.begin(), m_timers.end(),
                                [now](const auto &t) { return t.first <= now; });
        if (due == m_timers.end())
            return;
        std::function<void()> then = std::move(due->second);
        m_timers.erase(due);
        if (then)
            then();
    }
}

double CoreWaits::nextTime(double deadline) const
{
    for (const auto &t : m_timers)
        deadline = std::min(deadline, t.first);
    return deadline;
}

} // namespace frezka::driver
