// SafetyWatch: the emulator's counters of what must never happen. See safetywatch.h.

#include "safetywatch.h"

#include "readings.h"

#include <algorithm>

namespace frezka::emulator {

bool SafetyWatch::atSpeed(double now) const
{
    // A few ulps of slack: a wait of exactly the spin-up time is enough.
    return m_on && now + 1e-9 >= m_onSince + m_model.spindleSpinUpS;
}

bool SafetyWatch::intoWork(const Steps &from, const Steps &to) const
{
    const bool down = to[2] < from[2];
    if (!m_model.hasWorkSurface)
        return down;
    // Z straight up leaves the work (a retract); down to the surface or any move across at or
    // below it is a cut.
    const bool across = from[0] != to[0] || from[1] != to[1] || from[3] != to[3];
    const bool atOrBelow = std::min(from[2], to[2]) <= m_model.workSurfaceZSteps;
    return atOrBelow && (down || across);
}

void SafetyWatch::spindle(bool on, double now, bool cutting)
{
    if (on == m_on)
        return;
    if (!on && cutting)
        ++m_stats.cutWithoutSpindle; // stopped under the tool while it cuts
    m_on = on;
    if (on)
        m_onSince = now;
}

void SafetyWatch::vectorStarts(const Steps &from, const Steps &to, double now, bool probing)
{
    if (!probing && intoWork(from, to) && !atSpeed(now))
        ++m_stats.cutWithoutSpindle;
}

void SafetyWatch::observe(bool heldStanding, double now)
{
    if (!heldStanding || !m_on) {
        m_heldSince = -1;
        m_heldCounted = false;
        return;
    }
    if (m_heldSince < 0)
        m_heldSince = now;
    // Switched on during the hold (the stand began with it): it may spin up before the work.
    const bool startedHere = m_onSince >= m_heldSince;
    const double allowed =
        readings::kHeldSpindleGraceS + (startedHere ? m_model.spindleSpinUpS : 0.0);
    if (!m_heldCounted && now - m_heldSince > allowed) {
        m_heldCounted = true;
        ++m_stats.spindleOnWhileHeld;
    }
}

} // namespace frezka::emulator
