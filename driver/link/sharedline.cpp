// SharedLine: one serial line, several units, one transaction on the wire at a time. See
// sharedline.h.

#include "sharedline.h"

#include <algorithm>

namespace frezka::driver {

SharedLine::SharedLine(std::vector<MachineCore *> cores, SharedLineOptions options)
    : m_cores(std::move(cores))
    , m_options(options)
{
    m_stats.units.resize(m_cores.size());
}

void SharedLine::log(const std::string &text)
{
    if (onLog)
        onLog(text);
}

void SharedLine::linkOpened(double now)
{
    m_open = true;
    m_holder = m_lastHolder = -1;
    m_partial.clear();
    m_held.clear();
    m_out.clear();
    m_txDoneAt = now;
    m_lastByteAt = now - m_options.quietS;
    m_stats = {};
    m_stats.units.resize(m_cores.size());
    m_stats.startS = now;
    for (MachineCore *core : m_cores)
        core->linkOpened(now);
    settle(now);
}

void SharedLine::linkClosed(const std::string &why, double now)
{
    if (m_holder >= 0)
        release(now);
    m_open = false;
    m_partial.clear();
    m_held.clear();
    m_out.clear();
    for (MachineCore *core : m_cores)
        core->linkClosed(why, now);
}

// The holder's bytes go out after whatever is still on the wire; when they have left, a reply
// can begin. A new request of the holder (a recovery's '@' after its settle time) ends whatever
// broken line came before it, as the engine's own settle does.
void SharedLine::collectOutput(double now)
{
    for (std::size_t i = 0; i < m_cores.size(); ++i) {
        std::string out = m_cores[i]->takeOutput();
        if (out.empty())
            continue;
        if (static_cast<int>(i) != m_holder)
            log("unit " + std::to_string(i) + " wrote without holding the line"); // a bug
        if (!m_partial.empty() || !m_held.empty()) {
            ++m_stats.strayLines;
            m_partial.clear();
            m_held.clear();
        }
        const double byteS = 10.0 / std::max(1, m_options.baud);
        m_txDoneAt = std::max(now, m_txDoneAt) + static_cast<double>(out.size()) * byteS;
        m_stats.units[i].bytesOut += static_cast<std::int64_t>(out.size());
        m_out += out;
    }
}

void SharedLine::release(double now)
{
    auto &unit = m_stats.units[static_cast<std::size_t>(m_holder)];
    unit.holdS += now - m_grantedAt;
    m_stats.busyS += now - m_grantedAt;
    if (!m_partial.empty() || !m_held.empty())
        ++m_stats.strayLines; // came after its transaction had ended: nobody's
    m_partial.clear();
    m_held.clear();
    m_lastHolder = m_holder;
    m_holder = -1;
}

// Round robin from the unit after the last holder: a unit that streams cannot keep the other
// from its polls.
void SharedLine::grantNext(double now)
{
    if (now < m_lastByteAt + m_options.quietS)
        return;
    const int n = static_cast<int>(m_cores.size());
    for (int k = 1; k <= n; ++k) {
        const int i = (m_lastHolder + k + n) % n;
        if (!m_cores[static_cast<std::size_t>(i)]->wantsLine())
            continue;
        m_holder = i;
        m_grantedAt = now;
        ++m_stats.units[static_cast<std::size_t>(i)].exchanges;
        m_cores[static_cast<std::size_t>(i)]->grantLine(now);
        return;
    }
}

void SharedLine::settle(double now)
{
    if (!m_open)
        return;
    for (int guard = 0; guard < 64; ++guard) {
        collectOutput(now);
        if (m_holder >= 0 && !m_cores[static_cast<std::size_t>(m_holder)]->holdsLine())
            release(now);
        if (m_holder >= 0)
            return;
        grantNext(now);
        if (m_holder < 0)
            return;
    }
}

void SharedLine::takeLines(double now)
{
    for (auto cr = m_partial.find('\r'); cr != std::string::npos; cr = m_partial.find('\r')) {
        std::string line = m_partial.substr(0, cr + 1);
        m_partial.erase(0, cr + 1);
        if (now < m_txDoneAt) {
            ++m_stats.earlyLines; // complete before the command had left: not its reply
            log("line '" + line.substr(0, line.size() - 1) +
                "' came before the command had left: not taken");
            continue;
        }
        m_held.push_back(std::move(line));
        m_heldAt = now;
    }
}

void SharedLine::receive(std::string_view bytes, double now)
{
    if (bytes.empty())
        return;
    m_lastByteAt = now;
    if (m_holder < 0) {
        const auto lines = std::count(bytes.begin(), bytes.end(), '\r');
        m_stats.strayLines += lines;
        log("bytes while no unit was addressed: not taken");
        return;
    }
    m_partial += bytes;
    takeLines(now);
    deliverHeld(now);
    settle(now);
}

// Two lines within the quiet time are two units talking at once: the holder gets them as one
// line, which does not decode, and recovers on its own address.
void SharedLine::deliverHeld(double now)
{
    if (m_held.empty() || !m_partial.empty() || now < m_heldAt + m_options.quietS)
        return;
    std::string text;
    for (const std::string &line : m_held)
        text += line.substr(0, line.size() - 1);
    text += '\r';
    const auto unit = static_cast<std::size_t>(m_holder);
    if (m_held.size() > 1) {
        ++m_stats.units[unit].collisions;
        log("two replies at once for unit " + std::to_string(unit) + ": taken as garbled");
    }
    m_held.clear();
    m_stats.units[unit].bytesIn += static_cast<std::int64_t>(text.size());
    m_cores[unit]->receive(text, now);
}

void SharedLine::onTime(double now)
{
    for (MachineCore *core : m_cores)
        if (core->deadline() <= now)
            core->onTime(now);
    if (m_holder >= 0)
        deliverHeld(now);
    settle(now);
}

double SharedLine::deadline() const
{
    double d = kNoDeadline;
    for (const MachineCore *core : m_cores)
        d = std::min(d, core->deadline());
    if (m_holder >= 0 && !m_held.empty() && m_partial.empty())
        d = std::min(d, m_heldAt + m_options.quietS);
    if (m_holder < 0 && m_open)
        for (const MachineCore *core : m_cores)
            if (core->wantsLine())
                d = std::min(d, m_lastByteAt + m_options.quietS);
    return d;
}

std::string SharedLine::takeOutput()
{
    std::string out;
    out.swap(m_out);
    return out;
}

double SharedLine::unitShare(std::size_t unit, double now) const
{
    double hold = m_stats.units.at(unit).holdS;
    if (m_holder == static_cast<int>(unit))
        hold += now - m_grantedAt;
    const double span = now - m_stats.startS;
    return span > 0 ? hold / span : 0;
}

double SharedLine::lineShare(double now) const
{
    double busy = m_stats.busyS;
    if (m_holder >= 0)
        busy += now - m_grantedAt;
    const double span = now - m_stats.startS;
    return span > 0 ? busy / span : 0;
}

} // namespace frezka::driver
