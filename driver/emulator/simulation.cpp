#include "simulation.h"

#include <algorithm>
#include <set>
#include <utility>

namespace frezka::emulator {

std::string sharedLineProblem(const SimulationOptions &options)
{
    std::set<int> addresses;
    int spindles = 0;
    auto check = [&](const UnitOptions &u) -> std::string {
        if (!addresses.insert(u.address).second)
            return "address " + std::to_string(u.address) + " is used twice";
        if (u.spindleAddress && protocol::variantInfo(u.variant).hasSpindleAddress7)
            ++spindles;
        return spindles > 1 ? "address 7 (the spindle) is answered by two units" : "";
    };
    if (std::string p = check(options.unit); !p.empty())
        return p;
    for (const UnitOptions &u : options.moreUnits)
        if (std::string p = check(u); !p.empty())
            return p;
    return {};
}

Simulation::Simulation(SimulationOptions options)
    : m_wire(options.wire)
{
    m_units.reserve(1 + options.moreUnits.size());
    m_units.emplace_back(std::move(options.unit));
    for (UnitOptions &u : options.moreUnits)
        m_units.emplace_back(std::move(u));
}

Unit *Simulation::unitAt(int address)
{
    for (Unit &u : m_units)
        if (u.options().address == address)
            return &u;
    return nullptr;
}

void Simulation::pcWrite(std::string_view bytes)
{
    m_wire.toUnit().send(m_now, bytes);
}

void Simulation::unitSideWrite(std::string_view bytes)
{
    m_wire.toPc().send(m_now, bytes);
}

double Simulation::nextEventIn() const
{
    double unitEvent = kNever;
    for (const Unit &u : m_units)
        unitEvent = std::min(unitEvent, u.nextEventIn());
    const double arrival =
        std::min(m_wire.toUnit().nextArrivalS(), m_wire.toPc().nextArrivalS()) - m_now;
    return std::max(0.0, std::min(unitEvent, arrival));
}

// Every unit moves to `t` (they share the clock); what they send enters the one line to the
// PC at their time, in the order of the units, each after what is already on it.
void Simulation::advanceUnitsTo(double t)
{
    for (Unit &u : m_units) {
        u.advance(std::max(0.0, t - u.now()));
        if (std::string out = u.takeTransmit(); !out.empty() && speedsMatch(u))
            m_wire.toPc().send(u.now(), out);
    }
}

void Simulation::deliverUntil(double t)
{
    // Bytes to the units arrive one by one at their own times: the watchdog and reply times
    // depend on them. Every unit hears every byte; each answers only its own address.
    for (;;) {
        double next = m_wire.toUnit().nextArrivalS();
        for (const Unit &u : m_units)
            next = std::min(next, u.now() + u.nextEventIn());
        if (next > t)
            break;
        advanceUnitsTo(next);
        const std::string in = m_wire.toUnit().takeArrived(m_units.front().now());
        for (Unit &u : m_units) {
            if (!in.empty() && speedsMatch(u))
                u.receive(in);
            if (std::string out = u.takeTransmit(); !out.empty() && speedsMatch(u))
                m_wire.toPc().send(u.now(), out);
        }
    }
    advanceUnitsTo(t);
    m_pcInbox += m_wire.toPc().takeArrived(t);
}

// A UART at another speed than the line's sees framing errors, not bytes: nothing gets through
// either way (the unit's speed: COM SPEED switch and EEPROM 0x0D, Unit::lineBaud()).
bool Simulation::speedsMatch(const Unit &unit) const
{
    const int unitBaud = unit.lineBaud();
    return unitBaud == 0 || unitBaud == m_wire.options().baud;
}

void Simulation::advance(double seconds)
{
    m_now += std::max(0.0, seconds);
    deliverUntil(m_now);
}

std::string Simulation::pcRead()
{
    return std::exchange(m_pcInbox, {});
}

std::string Simulation::pcReadLine(double timeoutS)
{
    const double deadline = m_now + timeoutS;
    while (m_pcInbox.find('\r') == std::string::npos && m_now < deadline) {
        const double step = std::min(nextEventIn(), deadline - m_now);
        advance(step);
    }
    const auto cr = m_pcInbox.find('\r');
    if (cr == std::string::npos)
        return pcRead();
    std::string line = m_pcInbox.substr(0, cr + 1);
    m_pcInbox.erase(0, cr + 1);
    return line;
}

} // namespace frezka::emulator
