// LineSync: the units' sync points released together. See linesync.h.

#include "linesync.h"

#include <algorithm>

namespace frezka::driver {

LineSync::LineSync(std::vector<MachineCore *> cores)
    : m_cores(std::move(cores))
    , m_reached(m_cores.size(), -1)
    , m_reachedAt(m_cores.size(), 0)
{
    m_stats.units.resize(m_cores.size());
    for (std::size_t i = 0; i < m_cores.size(); ++i)
        m_cores[i]->setSyncReadyHandler(
            [this, i](std::size_t index, double now) { reached(i, index, now); });
}

LineSync::~LineSync()
{
    for (MachineCore *core : m_cores)
        core->setSyncReadyHandler(nullptr);
}

// Called from inside unit `unit`'s core: that core sees its release when this returns; the
// others are pumped here so that their G (or their next command) goes on the line now.
void LineSync::reached(std::size_t unit, std::size_t index, double now)
{
    m_reached[unit] = std::max(m_reached[unit], static_cast<std::int64_t>(index));
    m_reachedAt[unit] = now;
    const std::int64_t all = *std::min_element(m_reached.begin(), m_reached.end());
    if (all < m_stats.released)
        return;
    for (; m_stats.released <= all; ++m_stats.released) {
        for (std::size_t i = 0; i < m_cores.size(); ++i) {
            if (i != unit && now > m_reachedAt[i]) {
                ++m_stats.units[i].waits;
                m_stats.units[i].waitS += now - m_reachedAt[i];
            }
        }
        m_stats.releasedAtS.push_back(now);
    }
    for (MachineCore *core : m_cores)
        core->releaseSync(static_cast<std::size_t>(all));
    for (std::size_t i = 0; i < m_cores.size(); ++i)
        if (i != unit)
            m_cores[i]->onTime(now);
}

} // namespace frezka::driver
