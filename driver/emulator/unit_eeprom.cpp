// What the EEPROM settings change in the emulated unit (unitsettings.h): outputs driven by
// their function, the brake release delay, the analog output, DIR polarity and A slaving in
// the motors' positions, the baud range, the interrupt masks in force. The MPG wheel and the
// homing started from an input are in unit_mpg.cpp.

#include "driver/emulator/unit_impl.h"

#include <algorithm>

namespace frezka::emulator {

void Unit::Impl::settingsChanged()
{
    cfg = decodeSettings(eeprom, options.variant, maxRate);
    updateWatches(); // switches sit in motor coordinates: DIR may have turned them
    checkInterrupts();
}

void Unit::Impl::latchPowerOn()
{
    highBaudRange = cfg.highBaudRange;
    brakeReleaseAt = engine.now() + cfg.brakeReleaseDelayS;
}

// Port 0's bit of OUT1..OUT3 (§10: bit2 OUT1, bit3 OUT2, bit1 OUT3); the GVE84's one relay is
// bit 0.
namespace {
constexpr int kOutputBit[3] = {2, 3, 1};
} // namespace

std::uint8_t Unit::Impl::relayPort() const
{
    std::uint8_t port = outputs;
    const bool is84 = options.variant == protocol::Variant::Gve84;
    for (int i = 0; i < (is84 ? 1 : 3); ++i) {
        const int bit = is84 ? 0 : kOutputBit[i];
        bool on = false;
        switch (cfg.outputFunction[i]) {
        case OutputFunction::Brake: // manuals 11.2: switched on by the unit after the delay
            on = engine.now() >= brakeReleaseAt;
            break;
        case OutputFunction::InterruptSignal:
            on = inta;
            break;
        default:
            continue; // the PC's (O0)
        }
        port = on ? (port & ~(1u << bit)) : (port | (1u << bit));
    }
    return port;
}

std::array<std::int64_t, 4> Unit::Impl::counters() const
{
    auto pos = engine.position();
    if (cfg.aSlavedTo >= 0) // manuals 11.4: the A outputs follow the master axis
        pos[3] = pos[cfg.aSlavedTo];
    return pos;
}

std::array<std::int64_t, 4> Unit::Impl::motorPosition() const
{
    auto pos = counters();
    for (int i = 0; i < 4; ++i) {
        // A slaved: its motor gets the master's STEP and DIR signals.
        const int dirOf = i == 3 && cfg.aSlavedTo >= 0 ? cfg.aSlavedTo : i;
        pos[i] *= axisSign(dirOf);
    }
    return pos;
}

// The interrupt enables (polarity = false) or polarities in force: ST0..ST3 while the PC
// drives; EEPROM 0x08..0x0B while the MPG is on and the unit drives itself (the wheel, homing
// from an input; GVE64 manual 12.3). Adopted reading: the reset state keeps ST0..ST3 = 00 as
// the manuals list it, so the EEPROM masks cannot be the ST registers' power-on values.
std::uint16_t Unit::Impl::interruptMask(bool polarity) const
{
    if (mpgOn() && options.variant != protocol::Variant::Gve84) {
        if (polarity)
            return static_cast<std::uint16_t>(cfg.polarity | (cfg.polarityHigh << 8));
        std::uint16_t m =
            static_cast<std::uint16_t>(cfg.interruptEnable | (cfg.interruptEnableHigh << 8));
        if (cfg.homingInput >= 0) // the homing start input starts, it does not stop
            m = static_cast<std::uint16_t>(m & ~(1u << cfg.homingInput));
        return m;
    }
    const int lo = polarity ? 2 : 0;
    return static_cast<std::uint16_t>(st[lo] | (st[lo + 1] << 8));
}

// ---- public API ------------------------------------------------------------------------------

std::uint8_t Unit::relays() const
{
    return m_impl->relayPort();
}

double Unit::analogOutput() const
{
    return emulator::analogOutput(m_impl->spindle, m_impl->options.analogJumper,
                                  m_impl->cfg.pwmBreakout);
}

std::array<std::int64_t, 4> Unit::motorPosition() const
{
    return m_impl->motorPosition();
}

const UnitSettings &Unit::settings() const
{
    return m_impl->cfg;
}

void Unit::powerCycle()
{
    m_impl->resetState(true);
}

int Unit::lineBaud() const
{
    const int sw = m_impl->options.baudSwitch;
    return sw < 0 ? 0 : switchBaud(sw, m_impl->highBaudRange);
}

void Unit::setWheelAxis(int position)
{
    m_impl->wheel.axis = std::clamp(position, 0, 3);
}

void Unit::setWheelMultiplier(int multiplier)
{
    m_impl->wheel.multiplier = multiplier >= 100 ? 100 : multiplier >= 10 ? 10 : 1;
}

bool Unit::turnWheel(int detents)
{
    return m_impl->turnWheel(detents);
}

int Unit::wheelAxis() const
{
    return m_impl->wheel.axis;
}

int Unit::wheelMultiplier() const
{
    return m_impl->wheel.multiplier;
}

} // namespace frezka::emulator
