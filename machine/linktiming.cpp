// The serial link's timing for the link's pace (docs/planner.md §4).
#include "machine/chainparts.h"

#include "machine/unitwire.h"
#include "protocol/variant.h"

#include <algorithm>

namespace frezka::machine::detail {

std::size_t LinkTiming::queueVectors() const
{
    return static_cast<std::size_t>(protocol::variantInfo(m_config.unit.variant).queueCapacity);
}

// The vectors of a packet the pace counts on: half the unit's queue, a third of a short queue
// (below kShortQueue). The driver sends a packet only as long as it arrives before the queue runs
// dry and keeps two round trips of motion in reserve: on the GVE84's 64 vectors at 16 ms that
// reserve is half the queue, packets of half the queue left the pace no room, each packet brought
// a little less motion than its cycle took, the next had to be shorter, and the unit ran dry (the
// overfeed raster: 19 stops; with a third, none).
double LinkTiming::packetVectors() const
{
    const double queue = static_cast<double>(queueVectors());
    return queue < kShortQueue ? queue / 3 : queue / 2;
}

// A packet (packetVectors) costs one round trip (twice the adapter's latency, and the reply's
// few bytes), shared by its vectors.
double LinkTiming::vectorWireS(double bytes) const
{
    if (!m_config.link.packets) // every command waits for its own reply
        return nonPacketS(bytes) * m_options.wireMargin;
    const double wire = bytes * 10.0 / m_config.link.baud;
    // While the unit holds little the driver keeps half of it in reserve, and a packet brings
    // more motion than its cycle only while held > 2 w RTT / (t - w): t - w must leave that
    // true from kSteadyHeldS of motion on, or packets shrink cycle after cycle (docs/planner.md
    // §9; the GVE64 surface at 16 ms ran dry 7 times).
    const double steady = wire + 2 * wire * roundTripS() / kSteadyHeldS;
    return std::max(wire * m_options.wireMargin + roundTripS() / packetVectors(), steady);
}

double LinkTiming::bareVectorWireS(double bytes) const
{
    if (!m_config.link.packets)
        return nonPacketS(bytes);
    return bytes * 10.0 / m_config.link.baud + roundTripS() / packetVectors();
}

double LinkTiming::nonPacketS(double bytes) const
{
    if (m_config.link.baud <= 0)
        return 0;
    return bytes * 10.0 / m_config.link.baud + roundTripS();
}

double LinkTiming::changeLeadS(double vectorBytes) const
{
    if (m_config.link.baud <= 0)
        return 0;
    const double bytes = vectorBytes + kBrakeBytes;
    const double wireBc = bytes * 10.0 / m_config.link.baud;
    return std::max(2 * std::max(kPacedWireS, wireBc), nonPacketS(bytes));
}

double LinkTiming::commandS(double bytes) const
{
    if (m_config.link.baud <= 0)
        return 0;
    return m_config.link.packets ? bytes * 10.0 / m_config.link.baud * m_options.wireMargin
                                 : nonPacketS(bytes) * m_options.wireMargin;
}

double LinkTiming::vectorWireBytes(const std::array<std::int32_t, 4> &d) const
{
    std::uint64_t h = 14695981039346656037ull; // FNV-1a over the components
    for (std::int32_t c : d)
        h = (h ^ static_cast<std::uint32_t>(c)) * 1099511628211ull;
    auto &slot = m_vectorMemo[h % kVectorMemo];
    if (slot.second >= 0 && slot.first == d)
        return slot.second;
    UnitCommand c;
    c.op = UnitOp::Vector;
    c.d = d;
    slot = {d, wireBytes(*wireCommand(c, wireAxisCount(m_config)))};
    return slot.second;
}

double LinkTiming::brakeWireBytes(std::int64_t value) const
{
    auto &slot = m_brakeMemo[static_cast<std::size_t>(value) % kBrakeMemo];
    if (slot.first != value)
        slot = {value, wireBytes(protocol::cmd::brake(value))};
    return slot.second;
}

double LinkTiming::wireBytes(const protocol::Command &command) const
{
    return static_cast<double>(protocol::encode(command, m_config.link.checksums).size());
}

double LinkTiming::speedWireBytes() const
{
    return wireBytes(protocol::cmd::speed(m_config.unit.maxPulseRate));
}

} // namespace frezka::machine::detail
