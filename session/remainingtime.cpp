#include "remainingtime.h"

#include <algorithm>

namespace frezka::session {

RemainingTime::RemainingTime(std::vector<float> lineEndS, double totalS)
    : m_lineEndS(std::move(lineEndS))
    , m_totalS(totalS)
{}

double RemainingTime::endOf(std::uint32_t line) const
{
    if (m_lineEndS.empty())
        return 0;
    return double(m_lineEndS[std::min<std::size_t>(line, m_lineEndS.size() - 1)]);
}

double RemainingTime::at(std::uint32_t line, double nowS, bool running)
{
    if (m_totalS < 0 || m_lineEndS.empty())
        return -1;
    if (line != m_line) {
        m_line = line;
        m_onLineS = 0;
        m_lastS = nowS;
    }
    if (running)
        m_onLineS += std::max(0.0, nowS - m_lastS);
    m_lastS = nowS;
    if (line == 0)
        return m_totalS;
    // The lines before it in the file that plan nothing carry the end of the one before them.
    const double duration = std::max(0.0, endOf(line) - endOf(line - 1));
    const double left = std::clamp(duration - m_onLineS, 0.0, duration);
    return std::max(0.0, m_totalS - endOf(line)) + left;
}

} // namespace frezka::session
