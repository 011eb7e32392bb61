// The serial link's timing for the link's pace (docs/planner.md §4).
#include "machine/chainparts.h"

#include "machine/unitwire.h"
#include "protocol/variant.h"

namespace frezka::machine::detail {

std::size_t LinkTiming::queueVectors() const
{
    return static_cast<std::size_t>(protocol::variantInfo(m_config.unit.variant).queueCapacity);
}

// A packet of half the queue costs one round trip (twice the adapter's latency, and the reply's
// few bytes), shared by its vectors.
double LinkTiming::vectorWireS(double bytes) const
{
    if (!m_config.link.packets) // every command waits for its own reply
        return nonPacketS(bytes) * m_options.wireMargin;
    return bytes * 10.0 / m_config.link.baud * m_options.wireMargin +
           2 * roundTripS() / static_cast<double>(queueVectors());
}

double LinkTiming::nonPacketS(double bytes) const
{
    if (m_config.link.baud <= 0)
        return 0;
    return bytes * 10.0 / m_config.link.baud + roundTripS();
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
    UnitCommand c;
    c.op = UnitOp::Vector;
    c.d = d;
    return wireBytes(*wireCommand(c, wireAxisCount(m_config)));
}

double LinkTiming::brakeWireBytes(std::int64_t value) const
{
    return wireBytes(protocol::cmd::brake(value));
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
