#pragma once
// Units and the wire on one virtual clock: what an in-process transport or a test drives.
// pcWrite() puts bytes on the line at now(); advance() moves time, delivering bytes to the units
// as they arrive and their replies back along the wire; pcRead() returns what has reached the
// PC. Everything is deterministic for given options.
//
// A shared line (GVE114 manual §9.5: further units on the EXT branch cable, one baud rate, each
// its own fixed address): SimulationOptions::moreUnits puts further units on the same wire.
// Every unit hears every byte and answers only its own address (and address 7 only the one
// whose spindleAddress is set); all replies share the one direction to the PC, so the bytes of
// one exchange delay the others'. A command for an address nobody has gets no reply.

#include "driver/emulator/unit.h"
#include "driver/emulator/wire.h"

#include <string>
#include <string_view>
#include <vector>

namespace frezka::emulator {

struct SimulationOptions
{
    UnitOptions unit{};
    WireOptions wire{};
    // Further units on the same line (docs/emulator.md, "Several units on one line"); each
    // needs its own address, and at most one of all answers address 7.
    std::vector<UnitOptions> moreUnits{};
    bool operator==(const SimulationOptions &) const = default;
};

// Empty when the units can share a line; else English naming the clash ("address 1 is used
// twice", "address 7 (the spindle) is answered by two units").
std::string sharedLineProblem(const SimulationOptions &options);

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
    // Seconds until anything happens by itself (a byte arrives, a unit changes); kNever
    // when nothing is under way.
    double nextEventIn() const;
    // Advances until the PC has received a complete line (CR) or `timeoutS` passed; returns
    // the bytes received (possibly without CR on timeout). For tests and benchmarks.
    std::string pcReadLine(double timeoutS);
    // Bytes a unit sends now although nobody asked it (a unit answering out of turn, a
    // garbled echo): they go onto the line towards the PC like any reply. For tests.
    void unitSideWrite(std::string_view bytes);

    // The first unit (the only one on a line of one unit).
    Unit &unit() { return m_units.front(); }
    const Unit &unit() const { return m_units.front(); }
    // Every unit on the line, in the order of the options (unit, then moreUnits).
    std::size_t unitCount() const { return m_units.size(); }
    Unit &unit(std::size_t i) { return m_units.at(i); }
    const Unit &unit(std::size_t i) const { return m_units.at(i); }
    // The unit with `address` (0..6), nullptr when the line has none.
    Unit *unitAt(int address);
    const Wire &wire() const { return m_wire; }

private:
    void deliverUntil(double t);
    void advanceUnitsTo(double t);
    bool speedsMatch(const Unit &unit) const;

    std::vector<Unit> m_units;
    Wire m_wire;
    double m_now = 0;
    std::string m_pcInbox;
};

} // namespace frezka::emulator
