// The lead-in of a chain from rest. See leadin.h.

#include "machine/leadin.h"

#include <algorithm>
#include <limits>

namespace frezka::machine {

bool chainStartsAt(const UnitCommands &commands, std::size_t i)
{
    if (i >= commands.size() || (i > 0 && !restsAt(commands.op(i - 1))))
        return false;
    for (std::size_t k = i; k < commands.size() && !restsAt(commands.op(k)); ++k) {
        if (commands.op(k) == UnitOp::Vector)
            return true;
    }
    return false;
}

namespace {
bool packetable(UnitOp op)
{
    return op == UnitOp::Vector || op == UnitOp::Brake;
}
} // namespace

std::size_t firstPacketEnd(const UnitCommands &commands, std::size_t start,
                           const LeadInLink &link)
{
    std::size_t k = start;
    while (k < commands.size() && !restsAt(commands.op(k)) && !packetable(commands.op(k)))
        ++k;
    if (!link.packets) { // one command at a time: the unit starts with the first C
        while (k < commands.size() && !restsAt(commands.op(k)) && commands.op(k) != UnitOp::Vector)
            ++k;
        return std::min(commands.size(), k + 1);
    }
    const std::size_t end = std::min(commands.size(), k + link.maxPacket);
    while (k < end && packetable(commands.op(k)))
        ++k;
    return k;
}

double leadInSlackS(const LeadInPrefixes &p, const LeadInLink &link, std::size_t start,
                    std::size_t queuedEnd, double rate)
{
    const std::size_t b = p.base;
    auto runS = [&](std::size_t from, std::size_t to) {
        return (p.timeS[to - b] - p.timeS[from - b]) / rate;
    };
    // Packets sized to what the unit holds cost their round trip more often than full ones: the
    // planner's steady margin (LinkTiming::vectorWireS).
    const double bytesFactor = link.packets ? 1 + 2 * link.roundTripS / link.steadyHeldS : 1.0;
    double slack = std::numeric_limits<double>::infinity();
    double extraTrips = 0; // a run of C/B longer than a packet goes in several
    std::size_t run = 0;
    const std::size_t last = std::min(p.end(), queuedEnd + 4 * link.maxPacket);
    for (std::size_t k = queuedEnd; k < last; ++k) {
        const UnitOp op = p.commands.op(k);
        if (restsAt(op))
            break;
        run = packetable(op) ? run + 1 : 0;
        if (packetable(op) && run > link.maxPacket) {
            ++extraTrips;
            run = 1;
        }
        if (op != UnitOp::Vector)
            continue;
        const double trips =
            link.packets
                ? static_cast<double>(p.trips[k + 1 - b] - p.trips[queuedEnd - b]) + extraTrips
                : static_cast<double>(k + 1 - queuedEnd);
        const double arrival = static_cast<double>(p.bytes[k + 1 - b] - p.bytes[queuedEnd - b]) *
                                   link.secondsPerByte * bytesFactor +
                               trips * link.roundTripS;
        double reach = runS(start, k);
        if (p.lastMotion[k - b] > start) { // the vector before it brakes when nothing follows
            const std::size_t before = p.lastMotion[k - b] - 1;
            reach -= std::min(p.brakeS[before + 1 - b] * rate, runS(before, before + 1));
        }
        slack = std::min(slack, reach - arrival);
        if (reach - arrival > 1.0)
            break; // well ahead: from here on the planner's steady pace holds
    }
    return slack;
}

std::size_t leadInRelease(const LeadInPrefixes &p, const LeadInLink &link, std::size_t start,
                          std::int64_t queueVectors)
{
    // The chain's end (a rest) or the queue's capacity, whichever comes first.
    std::size_t cap = firstPacketEnd(p.commands, start, link);
    std::int64_t vectors = 0;
    std::size_t limit = start;
    for (; limit < p.end() && !restsAt(p.commands.op(limit)); ++limit) {
        vectors += p.commands.op(limit) == UnitOp::Vector ? 1 : 0;
        if (vectors > queueVectors)
            break;
    }
    if (limit <= cap)
        return limit;
    // The slack grows with what is queued (less left to send, the same motion to reach): the
    // first end that covers the reserve, by bisection.
    std::size_t lo = cap, hi = limit;
    if (leadInSlackS(p, link, start, lo) >= link.reserveS())
        return lo;
    while (hi - lo > 1) {
        const std::size_t mid = lo + (hi - lo) / 2;
        (leadInSlackS(p, link, start, mid) >= link.reserveS() ? hi : lo) = mid;
    }
    return hi;
}

} // namespace frezka::machine
