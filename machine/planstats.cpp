// The plan's figures: the estimate and the time-optimal bound with the link's part of each
// rest (docs/planner.md §7), and the one warning for capped feeds. Part of Planner
// (planner_internal.h).
#include "machine/planner_internal.h"

#include "machine/chainparts.h"
#include "machine/leadin.h"
#include "machine/unitmodel.h"
#include "machine/unitwire.h"
#include "protocol/command.h"
#include "protocol/variant.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace frezka::machine::detail {

// One warning for the whole program: where the feed is first above what the axes allow, the
// feed asked for, the feed the machine will run there, and how many lines are capped.
void Planner::feedCapWarning()
{
    if (m_feedCapLines == 0)
        return;
    const detail::FeedCap &c = m_firstFeedCap;
    auto mmPerMin = [](double mmPerS) { return std::to_string(std::llround(mmPerS * 60)); };
    const std::string limit =
        c.limit == 'P' ? "the unit's " + std::to_string(m_config.unit.maxPulseRate) + " pulses/s"
                       : std::string(1, c.limit) + "'s maximum speed of " +
                             mmPerMin(c.limitMmPerS) + " mm/min";
    std::string what = "F" + mmPerMin(c.askedMmPerS) +
                       " mm/min is above what the axes allow along this move; the machine runs "
                       "it at " +
                       mmPerMin(c.runMmPerS) + " mm/min (" + limit + ")";
    if (m_feedCapLines == 2)
        what += "; 1 more line is capped the same way";
    else if (m_feedCapLines > 2)
        what += "; " + std::to_string(m_feedCapLines - 1) + " more lines are capped the same way";
    what += ". Lower the F word, or raise the axis maxima in the machine profile if the machine "
            "can go faster";
    m_result.warnings.push_back(
        {PlanErrorCode::FeedCapped, c.line, "line " + std::to_string(c.line) + ": " + what});
}

// The link's part of each rest (docs/planner.md §7): where the queue drains (the program's start,
// a wait for it to drain, a dwell, an operator stop, a probe) the driver learns that the unit
// stands from F read back to back (one F exchange after the stop on average: half an exchange to
// the unit's next reading, then the reply), reads the position (the path guard), sends the
// commands that cannot travel in a packet one round trip each, and the unit starts again when
// the first packet has arrived whole (it runs a packet at its *E; a lone command at its CR).
Planner::RestCosts Planner::restCosts(std::span<const std::pair<std::size_t, double>> holds,
                                      const ModelResult &model) const
{
    const LinkConfig &link = m_config.link;
    if (!m_options.wireLimited || link.baud <= 0)
        return {};
    const detail::LinkTiming timing(m_config, m_options);
    // The position read (the path guard's; its reply is the long one), and F read back to back:
    // on average half an exchange to the unit's next reading after the stop, then the reply.
    const double positionS = timing.nonPacketS(kExchangeBytes);
    const double flagReplyBytes = link.checksums ? kFlagReplyBytes : kFlagReplyBytes - 3;
    const double flagS =
        timing.nonPacketS(timing.wireBytes(protocol::cmd::flag()) + flagReplyBytes);
    // At the least (the bound's part): an F already on its way when the unit stops is answered
    // at once, so only its reply is sure to follow the stop.
    const double flagLeastS = flagReplyBytes * 10.0 / link.baud + link.latencyMs / 1000.0;
    const double okReplyBytes = link.checksums ? kOkReplyBytes : kOkReplyBytes - 3;
    const auto &cmds = m_result.program.commands;
    const std::size_t maxPacket =
        static_cast<std::size_t>(protocol::variantInfo(m_config.unit.variant).queueCapacity - 1);
    auto packetable = [&](UnitOp op) {
        return link.packets && (op == UnitOp::Vector || op == UnitOp::Brake);
    };
    // The first packet after a rest, from command k, as the driver sends it from an empty queue
    // (Job::sendPacket: as many C/B as the queue takes; a single command goes without framing):
    // its bytes on the wire and the latency to the unit, which starts on it at its end.
    // Held (leadinhold.h), the unit starts at the G after the packet's reply, which counts.
    // Where the motion is slow a free start's packet is cut so that polls keep their rate
    // (JobPace::slowMotionPacketEnd, at rest: margin 2, the poll's round trip), vec: the motion
    // commands before k (the model's vectorTimes).
    const double pollRttS = timing.nonPacketS(kExchangeBytes);
    auto firstPacketS = [&](std::size_t k, bool held, std::size_t vec) {
        const std::size_t start = k;
        std::vector<double> bytesTo{0.0}, motionTo{0.0};
        const bool packet = packetable(cmds.op(k)); // else an L or a C alone
        for (std::size_t n = 0;
             k < cmds.size() && n < maxPacket && (n == 0 || (packet && packetable(cmds.op(k))));
             ++k, ++n) {
            bytesTo.push_back(bytesTo.back() +
                              timing.wireBytes(*wireCommand(cmds[k], m_result.program.axisCount)));
            const bool motion = cmds.op(k) == UnitOp::Vector || cmds.op(k) == UnitOp::Line;
            motionTo.push_back(motionTo.back() + (motion && vec < model.vectorTimes.size()
                                                      ? model.vectorTimes[vec++]
                                                      : 0.0));
        }
        std::size_t n = bytesTo.size() - 1;
        for (const double wire : {kStatusPollS - 2 * pollRttS, kSlowPacketWireS}) {
            if (held || !packet || wire < 0.005)
                continue;
            std::size_t e = 0;
            while (e < n && bytesTo[e + 1] * 10.0 / link.baud <= wire)
                ++e;
            if (e > 0 && e < n && start + e < cmds.size() &&
                motionTo[e] >= 2 * (wire + 2.75 * pollRttS)) {
                n = e;
                break;
            }
        }
        double bytes = bytesTo[n] + (n > 1 ? kPacketFramingBytes : 0);
        return bytes * 10.0 / link.baud + (held ? timing.roundTripS() : link.latencyMs / 1000.0);
    };
    RestCosts costs;
    bool atRest = true;
    bool moved = false;             // a chain ran before this rest: the unit pauses T after it
    double pauseS = kInitialPauseS; // T, as the unit model starts
    double dwellS = 0;              // PC-side dwell since the rest began
    double commandsS = 0;        // the commands after the rest that travel alone, a round trip each
    std::size_t chainStart = 0;  // the first command after the last rest
    std::size_t firstSent = 0;   // the first command of the first packet after the rest
    bool packetStarted = false;  // ... seen
    std::size_t firstVector = 0; // motion commands before it
    std::size_t vectors = 0;     // motion commands before i
    auto hold = holds.begin();   // the chains the driver holds at their start (leadInHolds)
    for (std::size_t i = 0; i < cmds.size(); ++i) {
        const UnitCommand &c = cmds[i];
        double holdS = 0;
        if (c.op == UnitOp::Vector) {
            while (hold != holds.end() && hold->first < chainStart)
                ++hold;
            if (hold != holds.end() && hold->first == chainStart) {
                holdS = hold->second;
                ++hold;
            }
        }
        if (c.op == UnitOp::Vector || c.op == UnitOp::Line) {
            if (atRest) {
                // The unit's own T pause after the rest (what a dwell has not covered) runs
                // while the link does its part, a hold at the chain's start included: the
                // estimate counts the longer of the two (seed 45, packets off: 50 holds charged
                // beside the pause put the estimate 9 % above the job).
                const double unitS = moved ? std::max(0.0, pauseS - dwellS) : 0.0;
                const double firstS = firstPacketS(packetStarted ? firstSent : i, holdS > 0,
                                                   packetStarted ? firstVector : vectors);
                // The job's start reads neither F nor the position (the link did while it
                // connected): it begins with its first command.
                const double restS = (moved ? positionS : 0.0) + commandsS + firstS + holdS - unitS;
                costs.linkS += std::max(0.0, (moved ? flagS : 0.0) + restS);
                costs.boundLinkS += std::max(0.0, (moved ? flagLeastS : 0.0) + restS);
                costs.unitPauseS += unitS;
            } else {
                costs.linkS += holdS; // after an L: nothing to overlap
                costs.boundLinkS += holdS;
            }
            atRest = false;
            moved = true;
            commandsS = 0;
            dwellS = 0;
            packetStarted = false;
        } else if (c.op == UnitOp::Brake && link.packets) {
            // travels in the first packet
            if (atRest && !packetStarted) {
                firstSent = i;
                firstVector = vectors;
                packetStarted = true;
            }
        } else if (wireCommand(c, m_result.program.axisCount)) {
            pauseS = c.op == UnitOp::Pause ? static_cast<double>(c.value) / 1000.0 : pauseS;
            commandsS += atRest
                             ? timing.nonPacketS(
                                   timing.wireBytes(*wireCommand(c, m_result.program.axisCount)) +
                                   okReplyBytes)
                             : 0.0;
        } else {
            atRest = true; // a PC-side wait: the queue drains
            dwellS += c.op == UnitOp::Dwell ? static_cast<double>(c.value) / 1000.0 : 0.0;
        }
        if (restsAt(c.op))
            chainStart = i + 1;
        vectors += c.op == UnitOp::Vector || c.op == UnitOp::Line ? 1 : 0;
    }
    // The program's end is a rest too, with nothing after it: the job learns that the unit
    // stands and reads the position there (the path guard's last check) before it ends. Left
    // out until 2026-11-27, it put every short job 1-10 % over its estimate (property seeds 29,
    // 36, 88, 158, 167: 2 or 3 rests, 0.07-0.17 s over). F's exchange and the position's.
    if (moved && atRest) {
        costs.linkS += flagS + positionS;
        costs.boundLinkS += flagLeastS + positionS;
    }
    return costs;
}

// The driver holds the unit at the start of a chain its wire cannot feed from an empty queue
// (machine/leadin.h, driver/link/leadinhold.h): the H, the reads of the interrupt causes and the
// G, and the wire time of what it queues beyond the first packet before the unit moves, are the
// link's part of that rest. Each chain's lead-in is judged over a window of the program: its first
// queue-full of vectors and the packets the slack looks ahead to.
std::vector<std::pair<std::size_t, double>> Planner::leadInHolds(const ModelResult &model) const
{
    std::vector<std::pair<std::size_t, double>> holds;
    const LinkConfig &linkConfig = m_config.link;
    if (!m_options.wireLimited || linkConfig.baud <= 0)
        return holds;
    const detail::LinkTiming timing(m_config, m_options);
    const auto &cmds = m_result.program.commands;
    const std::int64_t capacity = protocol::variantInfo(m_config.unit.variant).queueCapacity - 1;
    LeadInLink link;
    link.roundTripS = timing.roundTripS();
    link.secondsPerByte = 10.0 / linkConfig.baud;
    link.packets = linkConfig.packets;
    link.maxPacket = static_cast<std::size_t>(capacity);
    link.steadyHeldS = detail::LinkTiming::kSteadyHeldS;
    const int reads = m_config.unit.variant == protocol::Variant::Gve84 ? 1 : 2;
    // H, the reads of ST4/ST5 and G, each with its reply (a status digit, INTA set, and for the
    // reads a byte), one round trip each.
    const double replyBytes = linkConfig.checksums ? 5 : 2;
    // The unit starts at the G's arrival: its bytes and the latency, not its reply.
    double holdS = timing.nonPacketS(timing.wireBytes(protocol::cmd::halt()) + replyBytes) +
                   timing.wireBytes(protocol::cmd::go()) * 10.0 / linkConfig.baud +
                   linkConfig.latencyMs / 1000.0;
    for (int n = 4; n < 4 + reads; ++n)
        holdS += timing.nonPacketS(timing.wireBytes(protocol::cmd::statusRead(n)) + replyBytes + 3);
    std::vector<double> time, brake;
    std::vector<std::int64_t> bytes, trips;
    std::vector<std::size_t> lastMotion;
    std::int64_t speed = 0, accel = 0; // modal V and A
    std::size_t vector = 0;            // motion commands before i (the model's vectorTimes)
    for (std::size_t i = 0; i < cmds.size(); ++i) {
        if (chainStartsAt(cmds, i)) {
            time.assign(1, 0.0);
            brake.assign(1, 0.0);
            bytes.assign(1, 0);
            trips.assign(1, 0);
            lastMotion.assign(1, 0);
            std::int64_t v = speed, a = accel, vectors = 0;
            std::size_t vec = vector, beyond = 0;
            bool inRun = false;
            for (std::size_t k = i;
                 k < cmds.size() && !restsAt(cmds.op(k)) && beyond < 4 * link.maxPacket; ++k) {
                const UnitCommand &c = cmds[k];
                const bool motion = c.op == UnitOp::Vector || c.op == UnitOp::Line;
                const double t =
                    motion && vec < model.vectorTimes.size() ? model.vectorTimes[vec++] : 0.0;
                v = c.op == UnitOp::Speed ? c.value : v;
                a = c.op == UnitOp::Accel ? c.value : a;
                const bool packetable = c.op == UnitOp::Vector || c.op == UnitOp::Brake;
                const auto wire = wireCommand(c, m_result.program.axisCount);
                time.push_back(time.back() + t);
                brake.push_back(a > 0 ? static_cast<double>(v) / (1000.0 * a) : 0.0);
                bytes.push_back(bytes.back() +
                                static_cast<std::int64_t>(wire ? timing.wireBytes(*wire) : 0));
                trips.push_back(trips.back() + (wire && !(packetable && inRun) ? 1 : 0));
                lastMotion.push_back(motion ? k + 1 : lastMotion.back());
                inRun = packetable;
                vectors += c.op == UnitOp::Vector ? 1 : 0;
                beyond += vectors > capacity ? 1 : 0;
            }
            const LeadInPrefixes p{cmds, i, time, bytes, trips, brake, lastMotion};
            const std::size_t first = std::min(firstPacketEnd(cmds, i, link), p.end());
            if (leadInSlackS(p, link, i, first) < link.reserveS()) {
                const std::size_t release = std::max(first, leadInRelease(p, link, i, capacity));
                holds.emplace_back(i,
                                   holdS +
                                       static_cast<double>(bytes[release - i] - bytes[first - i]) *
                                           link.secondsPerByte +
                                       static_cast<double>(trips[release - i] - trips[first - i]) *
                                           link.roundTripS);
            }
        }
        const UnitCommand &c = cmds[i];
        speed = c.op == UnitOp::Speed ? c.value : speed;
        accel = c.op == UnitOp::Accel ? c.value : accel;
        vector += c.op == UnitOp::Vector || c.op == UnitOp::Line ? 1 : 0;
    }
    return holds;
}

void Planner::finishStats()
{
    PlanStats &s = m_result.stats;
    const ModelResult model = runUnitModel(m_result.program, m_vk);
    s.vectors = model.vectors;
    s.brakeViolations = model.brakeViolations;
    // The unit's T pause after each PC-side rest is the program's (a wait, a dwell, a stop) or
    // the machine's (a reversal its jump limits cannot pass moving), not the plan's: the bound
    // pays it as the estimate does (seed 30: 181 such rests, the estimate 2.9 % above a bound
    // that left them out). Rests the plan chooses (exact stop's L moves) stay out of it.
    const RestCosts rests = restCosts(leadInHolds(model), model);
    s.linkWaitS = rests.linkS;
    s.waitS = m_waitS;
    s.estimatedS = model.motionS + model.waitS + s.linkWaitS;
    s.boundS = m_bound + m_waitS + rests.unitPauseS + rests.boundLinkS;
}

} // namespace frezka::machine::detail
