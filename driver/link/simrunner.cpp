#include "simrunner.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

void SimRunner::open()
{
    m_open = true;
    m_core.linkOpened(m_port.now());
    exchange();
}

void SimRunner::unplug(const std::string &why)
{
    m_open = false;
    m_port.read(); // whatever was on its way is lost with the cable
    m_core.linkClosed(why, m_port.now());
}

// Moves bytes both ways until neither side has anything more at this instant.
void SimRunner::exchange()
{
    for (int guard = 0; guard < 1000; ++guard) {
        bool moved = false;
        const std::string out = m_core.takeOutput();
        if (!out.empty() && m_open) {
            m_port.write(out);
            moved = true;
        }
        const std::string in = m_port.read();
        if (!in.empty() && m_open) {
            m_core.receive(in, m_port.now());
            moved = true;
        }
        if (m_core.deadline() <= m_port.now()) {
            m_core.onTime(m_port.now());
            moved = true;
        }
        if (!moved)
            return;
    }
}

void SimRunner::step(double limit)
{
    // What the caller's predicate started (SimLink delivers events there, and a workflow answers
    // them with operations) is still in the core's output: on the wire with it before the clock
    // moves, or it waited until the next deadline, the reply's own timeout (frezka-cli run: the
    // job's first command "no reply" on a clean link and every reply after it one late).
    exchange();
    const double now = m_port.now();
    double next = std::min(m_core.deadline(), now + m_port.nextEventIn());
    next = std::min(next, limit);
    // A deadline that is already due but changes nothing must not stall the clock.
    m_port.advance(std::max(next - now, 1e-6));
    exchange();
}

bool SimRunner::runUntil(const std::function<bool()> &done, double limitS)
{
    const double limit = m_port.now() + limitS;
    exchange();
    while (!done() && m_port.now() < limit)
        step(limit);
    return done();
}

void SimRunner::runFor(double seconds)
{
    runUntil([] { return false; }, seconds);
}

} // namespace frezka::driver
