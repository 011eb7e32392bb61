#include "simulation.h"

#include <algorithm>
#include <utility>

namespace frezka::emulator {

Simulation::Simulation(SimulationOptions options)
    : m_unit(std::move(options.unit))
    , m_wire(options.wire)
{}

void Simulation::pcWrite(std::string_view bytes)
{
    m_wire.toUnit().send(m_now, bytes);
}

double Simulation::nextEventIn() const
{
    const double unitEvent = m_unit.nextEventIn();
    const double arrival =
        std::min(m_wire.toUnit().nextArrivalS(), m_wire.toPc().nextArrivalS()) - m_now;
    return std::max(0.0, std::min(unitEvent, arrival));
}

void Simulation::deliverUntil(double t)
{
    // Bytes to the unit arrive one by one at their own times: the unit's watchdog and reply
    // times depend on them. Its replies enter the wire at the unit's time.
    for (;;) {
        const double toUnit = m_wire.toUnit().nextArrivalS();
        const double unitEvent = m_unit.now() + m_unit.nextEventIn();
        const double next = std::min(toUnit, unitEvent);
        if (next > t)
            break;
        m_unit.advance(std::max(0.0, next - m_unit.now()));
        const std::string in = m_wire.toUnit().takeArrived(m_unit.now());
        if (speedsMatch())
            m_unit.receive(in);
        if (std::string out = m_unit.takeTransmit(); !out.empty() && speedsMatch())
            m_wire.toPc().send(m_unit.now(), out);
    }
    m_unit.advance(std::max(0.0, t - m_unit.now()));
    if (std::string out = m_unit.takeTransmit(); !out.empty() && speedsMatch())
        m_wire.toPc().send(m_unit.now(), out);
    m_pcInbox += m_wire.toPc().takeArrived(t);
}

// A UART at another speed than the line's sees framing errors, not bytes: nothing gets through
// either way (the unit's speed: COM SPEED switch and EEPROM 0x0D, Unit::lineBaud()).
bool Simulation::speedsMatch() const
{
    const int unitBaud = m_unit.lineBaud();
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
