#pragma once
// LineErrors: how often a packet line arrives damaged on this link, and the packet size that
// keeps resends cheap (issue 12 item 5).
//
// A packet runs up to its first damaged line and everything after it goes again, so on a link
// that garbles one byte in a thousand (a line of 15 bytes in about 70) a packet of 200 lines
// arrives whole one time in twenty and the wire carries a third of what it could: the unit ran
// dry where the plan had paced the wire (property seed 14, 17 stops). The driver halves its
// packets after a damaged one and lets them grow again after each whole one; this caps the
// growth at the size that arrives whole about three times in five, from the rate of damaged
// lines seen lately. A clean link has no cap. Estimates only: they size packets, never motion.

#include <algorithm>
#include <cmath>
#include <limits>

namespace frezka::driver {

class LineErrors
{
public:
    // A packet's outcome: `lines` of it were judged (all of a whole one; those up to and with
    // the damaged line of a damaged one), `damaged` of them arrived damaged (0 or 1).
    void note(int lines, int damaged)
    {
        m_lines = m_lines * kKeep + lines;
        m_damaged = m_damaged * kKeep + damaged;
    }
    void reset() { m_lines = m_damaged = 0; }
    // The largest packet worth sending (commands); no cap on a clean link.
    int packetCap() const
    {
        if (m_damaged <= 0 || m_lines < kMinLines)
            return std::numeric_limits<int>::max();
        const double q = std::clamp(m_damaged / m_lines, 1e-6, 0.5);
        const double whole = std::log(kWholeShare) / std::log1p(-q);
        return std::max(kMinCap, static_cast<int>(whole));
    }

private:
    static constexpr double kKeep = 0.99;      // about the last hundred packets count
    static constexpr double kMinLines = 200;   // too few lines to judge before this
    static constexpr double kWholeShare = 0.6; // packets arriving whole at the cap
    static constexpr int kMinCap = 8;
    double m_lines = 0;
    double m_damaged = 0;
};

} // namespace frezka::driver
