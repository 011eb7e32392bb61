#pragma once
// EmulatorPort: the in-process emulator behind a modelled serial line, on a virtual clock.
//
// A thin VirtualPort over emulator::Simulation (driver/emulator/simulation.h), which owns the
// unit and the wire model (driver/emulator/wire.h): each byte occupies 10 bit times at the baud
// rate on its direction of the line, then arrives `latencyS` later (USB-serial latency per
// direction). WireOptions here is the driver's short form of the emulator's fault options: each
// byte, both ways, is hit with probability byteErrorRate — a flipped bit, a lost byte or a
// doubled byte, one third each — and a whole reply line is lost with probability replyLossRate.
// Deterministic for a given seed (the emulator's SplitMix64).

#include "driver/emulator/simulation.h"
#include "driver/link/simrunner.h"
#include "machine/machineconfig.h"

#include <cstdint>
#include <functional>
#include <string>
#include <vector>

namespace frezka::driver {

struct WireOptions
{
    int baud = 115200;
    double latencyS = 0;      // per direction
    double byteErrorRate = 0; // per byte, both directions
    double replyLossRate = 0; // per reply line
    std::uint32_t seed = 1;
    friend bool operator==(const WireOptions &, const WireOptions &) = default;
};

struct WireStats
{
    std::int64_t bytesToUnit = 0;
    std::int64_t bytesToPc = 0;
    std::int64_t corrupted = 0;
    std::int64_t dropped = 0;
    std::int64_t duplicated = 0;
    std::int64_t repliesLost = 0;
};

// An emulated unit for a machine profile: its variant and maximum pulse rate, and a home switch
// (IN0..IN3) for every homed axis, 5 mm from the counter's zero in the homing direction; the
// machine model of its safety counters: the spindle's spin-up and the axes' maximum speeds (the
// work surface is not known from a profile: set it where the program tells it).
emulator::UnitOptions unitOptionsFor(const machine::MachineConfig &config);
// Gives the unit the simulated work top of `spec` (driver/emulator/surface.h) with the profile's
// steps per mm and its probe input's contact level (EEPROM polarity, ST3 bit 7); false and
// nothing changed when the spec is malformed.
bool setProbeSurface(emulator::UnitOptions &unit, const std::string &spec,
                     const machine::MachineConfig &config);

// The emulator's wire options for the driver's short form.
emulator::WireOptions emulatorWireOptions(const WireOptions &wire);

class EmulatorPort : public VirtualPort
{
public:
    EmulatorPort(emulator::UnitOptions unit, WireOptions wire);
    // Several units on the one line (a shared line, emulator::Simulation's moreUnits).
    EmulatorPort(std::vector<emulator::UnitOptions> units, WireOptions wire);

    void write(std::string_view bytes) override
    {
        if (tamper)
            m_sim.pcWrite(tamper(bytes));
        else
            m_sim.pcWrite(bytes);
    }
    std::string read() override { return m_sim.pcRead(); }
    double now() const override { return m_sim.now(); }
    double nextEventIn() const override { return m_sim.nextEventIn(); }
    void advance(double seconds) override { m_sim.advance(seconds); }

    emulator::Unit &unit() { return m_sim.unit(); }
    emulator::Simulation &simulation() { return m_sim; }
    WireStats wireStats() const;

    // Test hook: rewrites what the PC writes before it enters the line, e.g. to damage a command
    // in a way its checksum cannot show. Empty: the bytes go as written.
    std::function<std::string(std::string_view)> tamper;

private:
    emulator::Simulation m_sim;
};

} // namespace frezka::driver
