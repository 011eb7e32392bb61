// Job: its packets of C/B commands, sized to what the unit's queue holds and to the wire, and
// what their replies say. Part of Job (job.h), apart so that job.cpp stays readable.

#include "job.h"

#include "driver/link/corehost.h"
#include "driver/link/machinecore_internal.h"

#include <algorithm>

namespace frezka::driver {

using namespace frezka::protocol;
using machine::UnitOp;

// As many C/B commands as fit: the unit takes a packet at its *E, by when it has run part of
// its queue for as long as the packet takes on the wire. Where the motion ahead keeps pace with
// the wire, a packet must take no longer than that (each packet then brings more motion than it
// costs, so the unit holds more after it), or the unit runs dry mid-chain and stops without
// braking. Where the unit holds too little for any budget, the packet is one vector: the
// smallest is the one that may still come in time. Kept in reserve: the reply's
// and the next packet's round trips and a little more (the estimate of what the unit holds
// drifts between polls), or half of what it holds when it holds little (a small queue, as the
// GVE84's 64 vectors: a short packet still comes in time). Long for the one decision it makes.
void Job::sendPacket(double now)
{
    const auto &cmds = m_program.commands;
    const std::int64_t capacity = variantInfo(m_host.config().unit.variant).queueCapacity - 1;
    LinkEngine &link = m_host.link();
    std::vector<Command> packet;
    std::int64_t vectors = 0;
    std::size_t bytes = 24; // *S *S *E
    std::size_t end = m_cursor.next;
    const std::size_t shortEnd = m_pace.slowMotionPacketEnd();
    const bool keepShort = shortEnd > m_cursor.next;
    const double held = m_pace.leadS(); // the packet must arrive before the last vector brakes
    const double budget = JobPace::packetBudgetS(held, m_host.rttS());
    // While the unit moves, a packet is no longer on the wire than the budget, and holds at
    // least one vector: where the unit holds too little for any budget, the smallest packet
    // is the one that may still arrive in time. A full packet there (30 commands, 40 ms on the
    // wire, where the unit held a few ms after a V) made it run dry (property seed 154).
    // A unit held at its chain's start runs nothing until the lead-in is queued: full packets,
    // as many vectors as its queue takes.
    const std::optional<std::size_t> heldAt = heldFrom();
    const bool paced = held > 0 && !heldAt;
    const std::int64_t heldQueued =
        heldAt ? m_pace.vectorsBefore(end) - m_pace.vectorsBefore(*heldAt) : 0;
    while (end < cmds.size() && static_cast<int>(packet.size()) < m_packetLimit) {
        const UnitOp op = cmds[end].op;
        if (op != UnitOp::Vector && op != UnitOp::Brake)
            break;
        if (keepShort && end >= shortEnd)
            break;
        Command c = toCommand(cmds[end]);
        const std::size_t size = encode(c, link.checksums()).size();
        // At least one vector whatever the budget: a packet of its B alone was taken for a full
        // queue, and the job waited a poll interval while the unit ran dry (property seed 100).
        if (paced && vectors > 0 && link.wireTime(bytes + size) > budget)
            break;
        const std::int64_t queued =
            heldAt ? heldQueued : m_pace.queuedAfter(link.wireTime(bytes + size));
        if (op == UnitOp::Vector && queued + vectors + 1 > capacity)
            break;
        bytes += size;
        vectors += op == UnitOp::Vector ? 1 : 0;
        packet.push_back(std::move(c));
        ++end;
    }
    if (packet.empty() ||
        (vectors == 0 && cmds[end < cmds.size() ? end : end - 1].op == UnitOp::Vector)) {
        // No room in the unit's queue by our estimate: wait until about 16 vectors have run.
        const std::size_t at = m_pace.execEstimate();
        const std::size_t later = std::min(at + 16, m_cursor.next);
        m_waitUntil =
            now + std::clamp(m_pace.runS(at, later), 0.002, m_host.options().pollIntervalS);
        m_queueFullSeen = true;
        return;
    }
    // The command index (mod 256) must tell a packet that arrived from one that did not: all its
    // lines (*S *S, the commands, *E) must not advance it by a multiple of 256.
    if ((packet.size() + 3) % 256 == 0) {
        packet.pop_back();
        --end;
    }
    const std::size_t first = m_cursor.next;
    m_cursor.inflightEnd = end;
    if (packet.size() == 1) {
        m_host.start(packet.front(),
                     [this, first](const Outcome &o) { onCommandOutcome(o, first, m_host.now()); });
        return;
    }
    const std::size_t n = packet.size();
    ++m_figures.report().packets;
    m_host.startPacket(std::move(packet), [this, first, n](const Outcome &o) {
        onPacketOutcome(o, first, n, m_host.now());
    });
}

std::optional<std::size_t> Job::heldFrom() const
{
    if (m_lead.held())
        return m_lead.start();
    if (m_sync.held())
        return m_sync.start();
    return std::nullopt;
}

void Job::onPacketOutcome(const Outcome &o, std::size_t first, std::size_t n, double now)
{
    (void)now;
    if (m_cursor.next != first || m_guard.faulted())
        return; // superseded (abort, link loss, the path guard dropped the queue)
    if (o.status == OutcomeStatus::Failed) {
        m_chainDamaged = true;
        m_lineErrors.note(static_cast<int>(n), 1);
        m_packetLimit = std::max(4, m_packetLimit / 2);
        m_check.verify("packet outcome unknown: " + o.error);
        return;
    }
    const std::size_t accepted = std::min<std::size_t>(static_cast<std::size_t>(o.accepted), n);
    const bool damaged = o.reply.code == ReplyCode::Syntax || o.reply.code == ReplyCode::Watchdog;
    m_chainDamaged = m_chainDamaged || damaged || o.recovered > 0;
    m_lineErrors.note(static_cast<int>(o.reply.ok() ? n : accepted + 1), damaged ? 1 : 0);
    acceptUpTo(first + accepted, o.recovered == 0);
    switch (o.reply.code) {
    case ReplyCode::Ok:
        m_queueFullSeen = false;
        m_packetLimit = std::min({m_pace.maxPacket(), m_packetLimit + m_packetLimit / 2 + 1,
                                  std::max(m_packetLimit, m_lineErrors.packetCap())});
        return;
    case ReplyCode::QueueFull:
        // The queue is full right now: that calibrates the estimate of where the unit is.
        m_queueFullSeen = true;
        m_cursor.exec = m_pace.executingAtFull();
        m_cursor.execAt = m_host.now();
        // Bytes beyond the free space are wasted wire time: start smaller next time.
        m_packetLimit = std::max(16, static_cast<int>(accepted));
        return;
    case ReplyCode::Syntax:   // a line damaged on the way (bad checksum) or lost
    case ReplyCode::Watchdog: // the packet came in too slowly: none of the rest ran
        m_packetLimit = std::max(4, m_packetLimit / 2);
        m_figures.report().resent += static_cast<std::int64_t>(n - accepted);
        return;
    default:
        m_host.fail({DriverCode::UnitRefused,
                     {detail::lineArg(m_program.commands[first + accepted]),
                      encodeBody(toCommand(m_program.commands[first + accepted])),
                      std::string(replyCodeText(o.reply.code))}},
                    &o, MachineMode::Alarm);
        return;
    }
}

} // namespace frezka::driver
