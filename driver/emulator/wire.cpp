#include "wire.h"

#include <algorithm>

namespace frezka::emulator {

std::uint64_t SplitMix64::next()
{
    std::uint64_t z = (m_state += 0x9E3779B97F4A7C15ULL);
    z = (z ^ (z >> 30)) * 0xBF58476D1CE4E5B9ULL;
    z = (z ^ (z >> 27)) * 0x94D049BB133111EBULL;
    return z ^ (z >> 31);
}

double SplitMix64::uniform()
{
    return static_cast<double>(next() >> 11) * 0x1.0p-53;
}

ByteChannel::ByteChannel(int baud, double latencyS, DirectionFaults faults, SplitMix64 *rng)
    : m_byteTimeS(10.0 / std::max(1, baud))
    , m_latencyS(std::max(0.0, latencyS))
    , m_faults(faults)
    , m_rng(rng)
{}

void ByteChannel::put(double nowS, char c)
{
    const double start = std::max(nowS, m_lineFreeAtS);
    m_lineFreeAtS = start + m_byteTimeS;
    m_inFlight.push_back({m_lineFreeAtS + m_latencyS, c});
}

void ByteChannel::send(double nowS, std::string_view bytes)
{
    // A draw happens only for a fault whose rate is set, so a fault-free channel consumes no
    // random numbers and adding one kind of fault does not reshuffle another direction.
    auto draw = [this](double rate) { return rate > 0 && m_rng->uniform() < rate; };
    for (char c : bytes) {
        ++m_stats.bytesSent;
        if (m_atMessageStart) {
            m_losingMessage = draw(m_faults.loseMessageRate);
            if (m_losingMessage)
                ++m_stats.messagesLost;
        }
        m_atMessageStart = c == '\r';
        if (m_losingMessage)
            continue;
        if (draw(m_faults.dropByteRate)) {
            ++m_stats.bytesDropped;
            m_lineFreeAtS = std::max(nowS, m_lineFreeAtS) + m_byteTimeS; // it used the line
            continue;
        }
        if (draw(m_faults.corruptByteRate)) {
            ++m_stats.bytesCorrupted;
            c = static_cast<char>(c ^ (1 << (m_rng->next() % 8)));
        }
        put(nowS, c);
        if (draw(m_faults.duplicateByteRate)) {
            ++m_stats.bytesDuplicated;
            put(nowS, c);
        }
    }
}

double ByteChannel::nextArrivalS() const
{
    return m_inFlight.empty() ? std::numeric_limits<double>::infinity()
                              : m_inFlight.front().arrivalS;
}

std::string ByteChannel::takeArrived(double timeS)
{
    std::string out;
    while (!m_inFlight.empty() && m_inFlight.front().arrivalS <= timeS) {
        out += m_inFlight.front().byte;
        m_inFlight.pop_front();
    }
    return out;
}

Wire::Wire(WireOptions options)
    : m_options(options)
    , m_rng(options.seed)
    , m_toUnit(options.baud, options.latencyPcToUnitS, options.pcToUnit, &m_rng)
    , m_toPc(options.baud, options.latencyUnitToPcS, options.unitToPc, &m_rng)
{}

} // namespace frezka::emulator
