#pragma once
// The lead-in of a chain from rest: whether the wire can feed it from an empty queue, and where a
// unit held at the chain's start (driver/link/leadinhold.h) is let go. One computation for the
// driver, which holds the unit, and the planner, whose estimate pays for the hold (docs/planner.md
// §4 and §7).
//
// A chain begins where the unit stands (the program's start, after an L or a PC-side wait) and a
// C follows before the next rest. Free, the unit starts with the chain's first packet (after the
// commands that travel alone: A, V, ...) and the wire must bring every later vector before the
// vector before it brakes for good; where it cannot (an A or a V a vector in, a slow link while
// the unit accelerates), the unit runs dry in the lead-in and may stop dead in a short vector.

#include "machine/unitprogram.h"

#include <cstddef>
#include <cstdint>
#include <span>

namespace frezka::machine {

// Where the unit's queue drains: an L (stand-alone) or a PC-side wait.
inline bool restsAt(UnitOp op)
{
    return op == UnitOp::Line || op > UnitOp::Spindle;
}

struct LeadInLink
{
    double roundTripS = 0;     // a command's or a packet's round trip beyond its bytes
    double secondsPerByte = 0; // on the wire
    bool packets = true;       // runs of C/B travel as packets
    std::size_t maxPacket = 1; // commands in the largest packet
    double steadyHeldS = 0.25; // machine::detail::LinkTiming::kSteadyHeldS
    // Time to spare the lead-in must leave: a packet's reserve and a poll's round trip.
    double reserveS() const { return 0.02 + roundTripS; }
};

// Per-command figures of the commands [base, base + n): each array has n + 1 entries, entry i
// belonging to command base + i (a prefix: the sum before it).
struct LeadInPrefixes
{
    const UnitCommands &commands; // the whole program
    std::size_t base = 0;
    std::span<const double> timeS;           // motion seconds before each
    std::span<const std::int64_t> bytes;     // wire bytes before each
    std::span<const std::int64_t> trips;     // round trips before each (a packet's run counts one)
    std::span<const double> brakeS;          // braking from the last V at the last A, before each
    std::span<const std::size_t> lastMotion; // 1 + the last motion command before each (global)
    std::size_t end() const { return base + timeS.size() - 1; }
};

// A chain begins at index i of `commands`.
bool chainStartsAt(const UnitCommands &commands, std::size_t i);
// Where a free unit's first packet of the chain at `start` ends: the commands that travel alone
// before it, then C/B up to the largest packet (one command without packets).
std::size_t firstPacketEnd(const UnitCommands &commands, std::size_t start,
                           const LeadInLink &link);
// The time the wire leaves to spare when the unit starts the chain at `start` with
// [start, queuedEnd) queued: the least, over the chain's next vectors, of when the unit needs
// each (its motion from the start divided by `rate`, less the braking of the vector before it)
// less when the wire brings it (bytes and round trips after the start at full packets, with the
// steady pace's margin). Negative: the unit runs dry in the lead-in.
double leadInSlackS(const LeadInPrefixes &p, const LeadInLink &link, std::size_t start,
                    std::size_t queuedEnd, double rate = 1.0);
// Where a unit held at `start` is let go: the first packet's end or later, as soon as the slack
// covers the reserve, the chain is all queued, or `queueVectors` vectors are.
std::size_t leadInRelease(const LeadInPrefixes &p, const LeadInLink &link, std::size_t start,
                          std::int64_t queueVectors);

} // namespace frezka::machine
