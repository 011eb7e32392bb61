#include "emulatorport.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frezka::driver {

namespace {
constexpr double kInf = std::numeric_limits<double>::infinity();
}

emulator::UnitOptions unitOptionsFor(const machine::MachineConfig &config)
{
    emulator::UnitOptions o;
    o.variant = config.unit.variant;
    o.maxPulseRate = config.unit.maxPulseRate;
    for (int a = 0; a < 4; ++a) {
        const machine::AxisConfig &ax = config.axes[static_cast<std::size_t>(a)];
        if (!ax.present || ax.homing.order <= 0)
            continue;
        const int d = ax.homing.direction < 0 ? -1 : 1;
        o.switches.push_back({a, a, d * std::llround(5.0 * ax.stepsPerMm), d});
    }
    return o;
}

EmulatorPort::EmulatorPort(emulator::UnitOptions unit, WireOptions wire)
    : m_unit(std::move(unit))
    , m_wire(wire)
    , m_rng(wire.seed)
{}

void EmulatorPort::setFaults(double byteErrorRate, double replyLossRate)
{
    m_wire.byteErrorRate = byteErrorRate;
    m_wire.replyLossRate = replyLossRate;
}

void EmulatorPort::enqueue(std::deque<Timed> &q, double &lineFreeAt, std::string_view bytes,
                           bool toUnit)
{
    const double byteTime = 10.0 / m_wire.baud;
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (char c : bytes) {
        const double start = std::max(now(), lineFreeAt);
        lineFreeAt = start + byteTime;
        const double at = lineFreeAt + m_wire.latencyS;
        (toUnit ? m_stats.bytesToUnit : m_stats.bytesToPc) += 1;
        if (m_wire.byteErrorRate > 0 && u(m_rng) < m_wire.byteErrorRate) {
            switch (m_rng() % 3) {
            case 0: { // corrupted
                char bad = c;
                while (bad == c)
                    bad = static_cast<char>(m_rng() & 0xFF);
                q.push_back({at, bad});
                ++m_stats.corrupted;
                continue;
            }
            case 1: // dropped
                ++m_stats.dropped;
                continue;
            default: // duplicated
                q.push_back({at, c});
                lineFreeAt += byteTime;
                q.push_back({lineFreeAt + m_wire.latencyS, c});
                ++m_stats.duplicated;
                continue;
            }
        }
        q.push_back({at, c});
    }
}

void EmulatorPort::write(std::string_view bytes)
{
    enqueue(m_toUnit, m_pcLineFreeAt, bytes, true);
}

std::string EmulatorPort::read()
{
    std::string out;
    while (!m_toPc.empty() && m_toPc.front().at <= now()) {
        out += m_toPc.front().byte;
        m_toPc.pop_front();
    }
    return out;
}

// The unit's replies go onto its line; a whole line may be lost.
void EmulatorPort::collectTransmit()
{
    const std::string tx = m_unit.takeTransmit();
    std::uniform_real_distribution<double> u(0.0, 1.0);
    for (char c : tx) {
        m_replyLine += c;
        if (c != '\r')
            continue;
        if (m_wire.replyLossRate > 0 && u(m_rng) < m_wire.replyLossRate) {
            ++m_stats.repliesLost;
        } else {
            enqueue(m_toPc, m_unitLineFreeAt, m_replyLine, false);
        }
        m_replyLine.clear();
    }
}

double EmulatorPort::nextArrival() const
{
    double t = kInf;
    if (!m_toUnit.empty())
        t = std::min(t, m_toUnit.front().at);
    if (!m_toPc.empty())
        t = std::min(t, m_toPc.front().at);
    return t;
}

double EmulatorPort::nextEventIn() const
{
    const double t = std::min(nextArrival(), now() + m_unit.nextEventIn());
    return std::max(0.0, t - now());
}

void EmulatorPort::advance(double seconds)
{
    const double target = now() + seconds;
    int stalled = 0;
    while (true) {
        const double before = now();
        const double nextIn = m_toUnit.empty() ? kInf : m_toUnit.front().at;
        const double unitEvent = now() + m_unit.nextEventIn();
        double t = std::min({target, nextIn, unitEvent});
        // An event due now that does not go away must not stop the clock.
        if (t <= before && stalled > 2)
            t = std::min(target, before + 1e-9);
        m_unit.advance(std::max(0.0, t - before));
        collectTransmit();
        bool delivered = false;
        while (!m_toUnit.empty() && m_toUnit.front().at <= now()) {
            m_unit.receive(std::string_view(&m_toUnit.front().byte, 1));
            m_toUnit.pop_front();
            collectTransmit();
            delivered = true;
        }
        stalled = (now() <= before && !delivered) ? stalled + 1 : 0;
        if (now() >= target)
            return;
    }
}

} // namespace frezka::driver
