#pragma once
// EmulatorPort: the in-process emulator behind a modelled serial line, on a virtual clock.
//
// Wire model (issue 2 item 5): each byte occupies 10 bit times at the baud rate on its line
// (one line each way, full duplex), then arrives `latencyS` later (USB-serial latency per
// direction). A seeded fault injector hits each byte with probability byteErrorRate: corrupted
// (a different random value), dropped, or duplicated, one third each; and loses a whole reply
// line with probability replyLossRate. Deterministic for a given seed.

#include "driver/emulator/unit.h"
#include "driver/link/simrunner.h"
#include "machine/machineconfig.h"

#include <cstdint>
#include <deque>
#include <random>

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
// (IN0..IN3) for every homed axis, 5 mm from the counter's zero in the homing direction.
emulator::UnitOptions unitOptionsFor(const machine::MachineConfig &config);

class EmulatorPort : public VirtualPort
{
public:
    EmulatorPort(emulator::UnitOptions unit, WireOptions wire);

    void write(std::string_view bytes) override;
    std::string read() override;
    double now() const override { return m_unit.now(); }
    double nextEventIn() const override;
    void advance(double seconds) override;

    emulator::Unit &unit() { return m_unit; }
    const WireStats &wireStats() const { return m_stats; }
    // Changes the fault rates from now on (e.g. a clean connect, then a noisy job).
    void setFaults(double byteErrorRate, double replyLossRate);

private:
    struct Timed
    {
        double at;
        char byte;
    };
    void enqueue(std::deque<Timed> &q, double &lineFreeAt, std::string_view bytes, bool toUnit);
    void collectTransmit();
    double nextArrival() const;

    emulator::Unit m_unit;
    WireOptions m_wire;
    std::mt19937 m_rng;
    std::deque<Timed> m_toUnit;
    std::deque<Timed> m_toPc;
    double m_pcLineFreeAt = 0;
    double m_unitLineFreeAt = 0;
    std::string m_replyLine; // the unit's reply line being assembled (for whole-line loss)
    WireStats m_stats;
};

} // namespace frezka::driver
