#include "linerunner.h"

#include <algorithm>

namespace frezka::driver {

void LineRunner::open()
{
    m_open = true;
    m_line.linkOpened(m_port.now());
    exchange();
}

void LineRunner::unplug(const std::string &why)
{
    m_open = false;
    m_port.read();
    m_line.linkClosed(why, m_port.now());
}

// Moves bytes both ways until neither side has anything more at this instant.
void LineRunner::exchange()
{
    for (int guard = 0; guard < 1000; ++guard) {
        bool moved = false;
        const std::string out = m_line.takeOutput();
        if (!out.empty() && m_open) {
            m_port.write(out);
            moved = true;
        }
        const std::string in = m_port.read();
        if (!in.empty() && m_open) {
            m_line.receive(in, m_port.now());
            moved = true;
        }
        if (m_line.deadline() <= m_port.now()) {
            m_line.onTime(m_port.now());
            moved = true;
        }
        if (!moved)
            return;
    }
}

void LineRunner::step(double limit)
{
    exchange();
    const double now = m_port.now();
    double next = std::min(m_line.deadline(), now + m_port.nextEventIn());
    next = std::min(next, limit);
    m_port.advance(std::max(next - now, 1e-6));
    exchange();
}

bool LineRunner::runUntil(const std::function<bool()> &done, double limitS)
{
    const double limit = m_port.now() + limitS;
    exchange();
    while (!done() && m_port.now() < limit)
        step(limit);
    return done();
}

void LineRunner::runFor(double seconds)
{
    runUntil([] { return false; }, seconds);
}

} // namespace frezka::driver
