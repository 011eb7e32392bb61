#include "lines.h"

namespace frezka::protocol {

void LineAssembler::feed(std::string_view bytes)
{
    for (char ch : bytes) {
        const bool afterCr = m_lastWasCr;
        m_lastWasCr = ch == '\r';
        if (ch == '\n' && afterCr)
            continue;
        if (ch == '\r') {
            if (m_discarding)
                m_discarding = false;
            else
                m_ready.push_back({std::move(m_current), false});
            m_current.clear();
            continue;
        }
        if (m_discarding)
            continue;
        if (m_current.size() == kMaxLineLength) {
            m_ready.push_back({std::move(m_current), true});
            m_current.clear();
            m_discarding = true;
            continue;
        }
        m_current += ch;
    }
}

Line LineAssembler::next()
{
    if (m_ready.empty())
        return {};
    Line l = std::move(m_ready.front());
    m_ready.pop_front();
    return l;
}

void LineAssembler::clear()
{
    m_ready.clear();
    m_current.clear();
    m_discarding = false;
    m_lastWasCr = false;
}

} // namespace frezka::protocol
