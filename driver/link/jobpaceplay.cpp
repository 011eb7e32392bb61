// JobPace: the packet play, the job's packets replayed ahead of the wire to tell whether they
// keep the unit fed (a chain's lead-in, the middle of a chain after damage), and where a halted
// unit stands. Part of JobPace (jobpace.h), apart so that jobpace.cpp stays readable.

#include "jobpace.h"

#include "driver/link/corehost.h"
#include "driver/link/coretypes.h"
#include "driver/link/machinecore_internal.h"
#include "machine/leadin.h"

#include <algorithm>

namespace frezka::driver {

using machine::UnitOp;

namespace {
// Motion kept in the unit beyond two round trips when a packet is sized to what it holds, s.
constexpr double kDryReserveS = 0.02;
// ... and this share of what it holds: the estimate of a second and more of queued motion is off
// by a percent or two (a 1.5 s packet after a spin-up arrived 11 ms after the unit ran dry).
constexpr double kHeldDriftShare = 0.05;
// Bytes of a packet's frame (*S *S *E).
constexpr std::size_t kPacketFrameBytes = 24;
} // namespace

double JobPace::packetBudgetS(double heldS, double rttS)
{
    return heldS - std::min(2 * rttS + kDryReserveS + kHeldDriftShare * heldS, 0.5 * heldS);
}

bool JobPace::leadInFeeds(std::size_t start, std::size_t queuedEnd, double delayS) const
{
    // The unit starts when G's (or the first packet's) reply is on its way back: the next
    // command leaves half a round trip later (and `delayS` more).
    return playPackets(m_timePrefix[start], start, queuedEnd, m_host.rttS() / 2 + delayS) == kFeeds;
}

std::size_t JobPace::dryAhead(double delayS) const
{
    const auto &cmds = m_program.commands;
    const std::size_t next = m_cursor.next;
    if (next >= cmds.size() || m_lastMotion[next] == 0 ||
        cmds[m_lastMotion[next] - 1].op != UnitOp::Vector)
        return kFeeds;
    for (std::size_t k = m_lastMotion[next]; k < next; ++k) {
        if (machine::restsAt(cmds[k].op))
            return kFeeds; // the unit rests before the cursor: a chain's start (LeadInHold)
    }
    // Where the model has the unit now, in program seconds: the commands sent from here on go
    // as the job sends them, the first one `delayS` from now.
    const std::size_t from = std::min(exec(), next);
    const double origin = std::min(m_timePrefix[from] + elapsedS() * rate(), m_timePrefix[next]);
    return playPackets(origin, 0, next, delayS);
}

bool JobPace::brakesWithin(std::size_t vectorEnd) const
{
    if (vectorEnd == 0 || vectorEnd > m_lastMotion.size())
        return true;
    const std::size_t last = vectorEnd - 1;
    return m_brakeS[last + 1] <= m_timePrefix[last + 1] - m_timePrefix[last];
}

std::size_t JobPace::stopEstimate(double aheadS) const
{
    const std::size_t next = m_cursor.next;
    if (next == 0 || m_lastMotion[next] == 0)
        return next;
    const std::size_t from = std::min(exec(), next);
    const std::size_t at = std::min(execEstimate() + 1, next);
    // Braking from V takes its whole time at most; counted as motion run (the unit is taken to
    // stand later than it does: it holds more than the hold reckons, never less).
    const double t = m_timePrefix[from] + (elapsedS() + aheadS) * rate() + m_brakeS[at];
    const auto it =
        std::upper_bound(m_timePrefix.begin() + static_cast<std::ptrdiff_t>(from),
                         m_timePrefix.begin() + static_cast<std::ptrdiff_t>(next) + 1, t);
    const auto k = static_cast<std::size_t>(it - m_timePrefix.begin()) - 1;
    return std::min(k, m_lastMotion[next] - 1);
}

std::size_t JobPace::playPackets(double originS, std::size_t floor, std::size_t queuedEnd,
                                 double t0) const
{
    const auto &cmds = m_program.commands;
    const double rtt = m_host.rttS();
    const bool packets = m_host.options().packets;
    const std::size_t maxCommands = static_cast<std::size_t>(maxPacket());
    const std::size_t last = std::min(cmds.size(), queuedEnd + 4 * maxCommands + 64);
    double t = t0;
    std::size_t next = queuedEnd;
    while (next < last && !machine::restsAt(cmds[next].op)) {
        const std::size_t lastMotion = m_lastMotion[next];
        if (lastMotion <= floor)
            return kFeeds; // nothing queued moves yet: the unit waits for its first vector
        // What the unit holds when the next command leaves: the queued motion from the origin
        // less the time run and the braking of the last queued vector.
        const std::size_t lastVector = lastMotion - 1;
        // At 100 %, as leadInSlackS: above, the override's ceiling keeps the wire ahead (judged
        // at the override, chains that ran without a stop at the ceiling were held, and
        // StreamPace.AFeedOverrideIsKeptWithinWhatTheLinkCanFeed took 2.7 % longer).
        const double reach = m_timePrefix[next] - originS -
                             std::min(m_brakeS[lastVector + 1],
                                      m_timePrefix[lastVector + 1] - m_timePrefix[lastVector]);
        const double held = reach - t;
        if (held > 1.0)
            return kFeeds; // well ahead: the steady pace holds from here
        const machine::UnitOp op = cmds[next].op;
        std::size_t bytes = 0;
        std::size_t end = next;
        if (packets && (op == UnitOp::Vector || op == UnitOp::Brake)) {
            const double budget = packetBudgetS(held, rtt);
            bytes = kPacketFrameBytes;
            bool vector = false;
            while (end < cmds.size() && end - next < maxCommands &&
                   (cmds[end].op == UnitOp::Vector || cmds[end].op == UnitOp::Brake)) {
                const auto size =
                    static_cast<std::size_t>(m_bytePrefix[end + 1] - m_bytePrefix[end]);
                if (vector && m_host.link().wireTime(bytes + size) > budget)
                    break;
                bytes += size;
                vector = vector || cmds[end].op == UnitOp::Vector;
                ++end;
            }
        } else {
            bytes = static_cast<std::size_t>(m_bytePrefix[next + 1] - m_bytePrefix[next]);
            end = next + 1;
        }
        t += m_host.link().wireTime(bytes) + rtt;
        if (t > reach && m_vectorPrefix[end] > m_vectorPrefix[next])
            return lastMotion; // its vectors come after the unit began braking to rest
        next = end;
    }
    return kFeeds;
}

} // namespace frezka::driver
