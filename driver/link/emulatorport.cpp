#include "emulatorport.h"

#include "machine/steps.h"

#include <cmath>

namespace frezka::driver {

bool setProbeSurface(emulator::UnitOptions &unit, const std::string &spec,
                     const machine::MachineConfig &config)
{
    emulator::ProbeSurface surface = unit.surface;
    if (!emulator::parseProbeSurface(spec, &surface))
        return false;
    for (std::size_t i = 0; i < 3; ++i)
        surface.stepsPerMm[i] = config.axes[i].stepsPerMm;
    surface.contactHigh = (config.eeprom.polarityHigh & 0x80) != 0; // as the profile
    unit.surface = surface;
    return true;
}

emulator::UnitOptions unitOptionsFor(const machine::MachineConfig &config)
{
    emulator::UnitOptions o;
    o.variant = config.unit.variant;
    o.maxPulseRate = config.unit.maxPulseRate;
    o.address = config.unit.address;
    for (int a = 0; a < 4; ++a) {
        const machine::AxisConfig &ax = config.axes[static_cast<std::size_t>(a)];
        if (!ax.present || ax.homing.order <= 0)
            continue;
        const int d = ax.homing.direction < 0 ? -1 : 1;
        o.switches.push_back({a, a, d * machine::stepsOf(5.0, ax.stepsPerMm), d});
    }
    // The machine behind it, for the counters of what must never happen (issue 14).
    o.machine.spindleSpinUpS = config.spindle.spinUpMs / 1000.0;
    for (std::size_t a = 0; a < 4; ++a) {
        const machine::AxisConfig &ax = config.axes[a];
        o.machine.axisMaxPulsesPerS[a] =
            ax.present ? machine::pulseRateOf(ax.maxSpeedMmPerMin, ax.stepsPerMm) : 0;
    }
    // The built-in unit was configured for this machine, as the vendor's tool would have done:
    // its EEPROM holds the profile's settings, so connecting reports no differences.
    for (const machine::EepromEntry &e : machine::eepromEntries(config)) {
        using Kind = emulator::EepromPreset::Kind;
        const Kind kind = e.kind == machine::EepromKind::Float    ? Kind::Float
                          : e.kind == machine::EepromKind::Uint32 ? Kind::Uint32
                                                                  : Kind::Byte;
        o.eepromPreset.push_back({e.address, kind, e.value});
    }
    return o;
}

emulator::WireOptions emulatorWireOptions(const WireOptions &wire)
{
    emulator::WireOptions o;
    o.baud = wire.baud;
    o.latencyPcToUnitS = wire.latencyS;
    o.latencyUnitToPcS = wire.latencyS;
    o.seed = wire.seed;
    const double third = wire.byteErrorRate / 3.0;
    o.pcToUnit = {third, third, third, 0.0};
    o.unitToPc = {third, third, third, wire.replyLossRate};
    return o;
}

EmulatorPort::EmulatorPort(emulator::UnitOptions unit, WireOptions wire)
    : m_sim(emulator::SimulationOptions{std::move(unit), emulatorWireOptions(wire)})
{}

namespace {
emulator::SimulationOptions lineOf(std::vector<emulator::UnitOptions> units, WireOptions wire)
{
    emulator::SimulationOptions o{std::move(units.front()), emulatorWireOptions(wire), {}};
    o.moreUnits.assign(units.begin() + 1, units.end());
    return o;
}
} // namespace

EmulatorPort::EmulatorPort(std::vector<emulator::UnitOptions> units, WireOptions wire)
    : m_sim(lineOf(std::move(units), wire))
{}

WireStats EmulatorPort::wireStats() const
{
    const emulator::WireStats &up = m_sim.wire().toUnit().stats();
    const emulator::WireStats &down = m_sim.wire().toPc().stats();
    WireStats s;
    s.bytesToUnit = up.bytesSent;
    s.bytesToPc = down.bytesSent;
    s.corrupted = up.bytesCorrupted + down.bytesCorrupted;
    s.dropped = up.bytesDropped + down.bytesDropped;
    s.duplicated = up.bytesDuplicated + down.bytesDuplicated;
    s.repliesLost = down.messagesLost;
    return s;
}

} // namespace frezka::driver
