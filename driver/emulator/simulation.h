#pragma once
// A unit and the wire on one virtual clock: what an in-process transport or a test drives.
// pcWrite() puts bytes on the line at now(); advance() moves time, delivering bytes to the unit
// as they arrive and the unit's replies back along the wire; pcRead() returns what has reached
// the PC. Everything is deterministic for given options.

#include "driver/emulator/unit.h"
#include "driver/emulator/wire.h"

#include <string>
#include <string_view>

namespace frezka::emulator {

struct SimulationOptions
{
    UnitOptions unit{};
    WireOptions wire{};
    bool operator==(const SimulationOptions &) const = default;
};

class Simulation
{
public:
    explicit Simulation(SimulationOptions options = {});

    // Bytes the PC writes now.
    void pcWrite(std::string_view bytes);
    // Moves the clock by `seconds` (>= 0).
    void advance(double seconds);
    // Bytes that have reached the PC since the last call.
    std::string pcRead();
    double now() const { return m_now; }
    // Seconds until anything happens by itself (a byte arrives, the unit changes); kNever
    // when nothing is under way.
    double nextEventIn() const;
    // Advances until the PC has received a complete line (CR) or `timeoutS` passed; returns
    // the bytes received (possibly without CR on timeout). For tests and benchmarks.
    std::string pcReadLine(double timeoutS);

    Unit &unit() { return m_unit; }
    const Unit &unit() const { return m_unit; }
    const Wire &wire() const { return m_wire; }

private:
    void deliverUntil(double t);
    bool speedsMatch() const;

    Unit m_unit;
    Wire m_wire;
    double m_now = 0;
    std::string m_pcInbox;
};

} // namespace frezka::emulator
