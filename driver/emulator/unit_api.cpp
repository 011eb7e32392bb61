// Unit's public functions: thin forwards to Unit::Impl (unit.cpp, unit_commands.cpp).

#include "driver/emulator/unit_impl.h"

#include <algorithm>
#include <utility>

namespace frezka::emulator {

// ---- public API ------------------------------------------------------------------------------

Unit::Unit(UnitOptions options)
    : m_impl(std::make_unique<Impl>(std::move(options)))
{}
Unit::~Unit() = default;
Unit::Unit(Unit &&) noexcept = default;
Unit &Unit::operator=(Unit &&) noexcept = default;

void Unit::receive(std::string_view bytes)
{
    Impl &d = *m_impl;
    for (std::size_t i = 0; i < bytes.size(); ++i) {
        if (d.deafUntil > d.engine.now()) {
            d.stats.discardedBytes += 1;
            continue;
        }
        if (d.deferred != Impl::Deferred::None) {
            const std::string_view rest = bytes.substr(i);
            const std::size_t room = readings::kReceiveBufferBytes -
                                     std::min(d.backlog.size(), readings::kReceiveBufferBytes);
            d.backlog.append(rest.substr(0, room));
            d.stats.discardedBytes +=
                static_cast<std::int64_t>(rest.size() - std::min(room, rest.size()));
            return;
        }
        d.feed(bytes[i]);
    }
}

std::string Unit::takeTransmit()
{
    return std::exchange(m_impl->tx, {});
}

void Unit::advance(double seconds)
{
    m_impl->advanceBy(seconds);
}

double Unit::now() const
{
    return m_impl->engine.now();
}

double Unit::nextEventIn() const
{
    return m_impl->nextEventIn();
}

Stats Unit::stats() const
{
    Stats s = m_impl->stats;
    s.motion = m_impl->engine.stats();
    s.safety = m_impl->safety.stats();
    return s;
}

std::array<std::int64_t, 4> Unit::position() const
{
    return m_impl->counters();
}

double Unit::pathSpeed() const
{
    return m_impl->engine.pathSpeed();
}

std::size_t Unit::queueLength() const
{
    return m_impl->engine.queueLength();
}

bool Unit::isMoving() const
{
    return m_impl->engine.isMoving();
}

const std::vector<TracePoint> &Unit::trace() const
{
    return m_impl->engine.trace();
}

void Unit::clearTrace()
{
    m_impl->engine.clearTrace();
}

void Unit::setInput(int input, bool level)
{
    if (input < 0 || input > 15)
        return;
    const auto bit = static_cast<std::uint16_t>(1u << input);
    m_impl->manualInputs = level ? (m_impl->manualInputs | bit) : (m_impl->manualInputs & ~bit);
    m_impl->checkInterrupts();
    m_impl->checkHoming();
}

bool Unit::input(int input) const
{
    return input >= 0 && input < 16 && ((m_impl->inputLevels() >> input) & 1);
}

void Unit::setSwitches(std::vector<PositionSwitch> switches)
{
    m_impl->switches = std::move(switches);
    m_impl->updateWatches();
    m_impl->checkInterrupts();
}

std::uint8_t Unit::outputs() const
{
    return m_impl->outputs;
}

int Unit::spindlePermille() const
{
    return m_impl->spindle;
}

bool Unit::spindleTurning() const
{
    return m_impl->spindleTurning();
}

std::uint8_t Unit::status(int n) const
{
    if (n == 6)
        return m_impl->st6();
    return (n >= 0 && n < 6) ? m_impl->st[n] : 0;
}

std::uint8_t Unit::eepromByte(int address) const
{
    return m_impl->eeprom.byte(address);
}

bool Unit::checksumsOn() const
{
    return m_impl->checksums;
}

const UnitOptions &Unit::options() const
{
    return m_impl->options;
}

const protocol::VariantInfo &Unit::variantInfo() const
{
    return *m_impl->info;
}

std::string Unit::eepromError() const
{
    return m_impl->eepromError;
}

} // namespace frezka::emulator
