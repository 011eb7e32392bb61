// ActualSpeed: see actualspeed.h.

#include "actualspeed.h"

#include <algorithm>
#include <cmath>

namespace frezka::gui {

void ActualSpeed::reset()
{
    m_readings.clear();
    m_haveLast = false;
    m_distance = 0;
}

bool ActualSpeed::add(double timeS, const std::array<double, 4> &positionMm)
{
    double d = 0;
    if (m_haveLast) {
        double d2 = 0;
        for (std::size_t i = 0; i < 3; ++i)
            d2 += (positionMm[i] - m_last[i]) * (positionMm[i] - m_last[i]);
        d = std::sqrt(d2);
    }
    m_last = positionMm;
    m_haveLast = true;
    m_distance += d;
    // A snapshot with the position unchanged while moving carries no new reading (a status poll
    // between two position polls): its later time would stretch the window and read low. Once
    // nothing has moved for a window the machine stands, and that is a reading too.
    if (d == 0 && m_haveLast && !m_readings.empty() && timeS < m_readings.back().t + m_windowS)
        return false;
    if (!m_readings.empty() && timeS <= m_readings.back().t) {
        m_readings.back().distance = m_distance; // the same instant: the later reading counts
        return d > 0;
    }
    m_readings.push_back({timeS, m_distance});
    // Keep the newest reading older than the window as its start.
    while (m_readings.size() > 2 && m_readings[1].t <= timeS - m_windowS)
        m_readings.pop_front();
    return d > 0;
}

double ActualSpeed::speed() const
{
    if (m_readings.size() < 2)
        return 0;
    const Reading &a = m_readings.front();
    const Reading &b = m_readings.back();
    const double dt = b.t - a.t;
    if (dt <= 0)
        return 0;
    const double v = (b.distance - a.distance) / dt * 60.0;
    return m_ceiling > 0 ? std::min(v, m_ceiling) : v;
}

} // namespace frezka::gui
