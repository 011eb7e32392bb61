#pragma once
// SharedLine: several units on one serial line (GVE114 manual §9.5 and §13.6: further units on
// the EXT branch cable, one baud rate, each with its own address fixed at order time), each
// driven by its own MachineCore. The arbiter sits under the cores: each core's LinkEngine
// (LinkOptions::sharedLine, unitAddress) sees the line as its own, and the arbiter decides whose
// transaction is on the wire.
//
// Clock-free like the cores: the owner (LineRunner on the emulator's virtual clock) passes bytes
// and time in and writes out what takeOutput() returns.
//
//   - One exchange on the wire at a time: a core's transaction (its command or packet and any
//     '@' / '>' recovery of it) holds the line from its grant until it ends. Cores that want the
//     line take turns (round robin from the one after the last holder), so polling and
//     streaming of every unit share the line fairly.
//   - Replies carry no address (docs/gve-protocol.md §2): a reply is taken only by the core
//     whose transaction holds the line. A line that cannot be the holder's reply is not given to
//     anyone: bytes while nobody holds the line, and a line complete before the holder's own
//     bytes have left the PC (no unit answers before it has heard the command). Two lines that
//     come within `quietS` of each other are two units talking at once (a unit answering out of
//     turn): the holder gets them as one garbled line and recovers with '@' and '>' on its own
//     address (LinkEngine), so a foreign reply is never taken for its own.
//   - A grant waits until the line has been quiet for `quietS`: a late reply of one exchange
//     does not land in the next one.
//   - The wire's use is counted per unit (time holding the line, bytes) and for the line.

#include "driver/link/machinecore.h"

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace frezka::driver {

struct SharedLineOptions
{
    int baud = kDefaultBaud;
    // A reply is handed to its core only after the line has been quiet this long; a second
    // line within it makes both one garbled line. A few byte times, above the PC's own jitter.
    double quietS = 0.002;
};

struct SharedLineUnitStats
{
    std::int64_t exchanges = 0; // transactions that held the line
    double holdS = 0;           // time holding the line
    std::int64_t bytesOut = 0;
    std::int64_t bytesIn = 0;    // bytes handed to the core
    std::int64_t collisions = 0; // replies merged with a foreign line (recovered by the core)
};

struct SharedLineStats
{
    std::vector<SharedLineUnitStats> units; // in the order of the cores
    std::int64_t strayLines = 0;            // lines nobody's transaction was waiting for
    std::int64_t earlyLines = 0;            // lines complete before the holder's command left
    double startS = 0;
    double busyS = 0; // time some transaction held the line
};

class SharedLine
{
public:
    // The cores must have LinkOptions::sharedLine set and each its own unitAddress.
    SharedLine(std::vector<MachineCore *> cores, SharedLineOptions options = {});

    void linkOpened(double now);
    void linkClosed(const std::string &why, double now);
    void receive(std::string_view bytes, double now);
    void onTime(double now);
    double deadline() const;
    std::string takeOutput();

    const SharedLineStats &stats() const { return m_stats; }
    // Share of the line's time (0..1) the unit's transactions held it since linkOpened.
    double unitShare(std::size_t unit, double now) const;
    // Share of the line's time some transaction held it.
    double lineShare(double now) const;
    int holder() const { return m_holder; } // -1 when the line is free
    std::size_t unitCount() const { return m_cores.size(); }

    std::function<void(const std::string &)> onLog;

private:
    void settle(double now); // releases a finished holder, grants the next, collects output
    void release(double now);
    void grantNext(double now);
    void collectOutput(double now);
    void deliverHeld(double now);
    void takeLines(double now);
    void log(const std::string &text);

    std::vector<MachineCore *> m_cores;
    SharedLineOptions m_options;
    SharedLineStats m_stats;
    bool m_open = false;
    int m_holder = -1;
    int m_lastHolder = -1;
    double m_grantedAt = 0;
    double m_txDoneAt = 0; // when the holder's bytes have left the PC
    double m_lastByteAt = -1e9;
    std::string m_out;
    std::string m_partial;           // bytes of a line not complete yet
    std::vector<std::string> m_held; // complete lines waiting for the quiet time
    double m_heldAt = 0;             // when the last held line completed
};

} // namespace frezka::driver
