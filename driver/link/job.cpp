// Job: streaming a unit program (packets, back-pressure, PC-side waits) and its end. See job.h.

#include "job.h"

#include "driver/link/corehost.h"
#include "driver/link/machinecore_internal.h"
#include "driver/link/programcheck.h"
#include "driver/link/unitcontrols.h"
#include "gcode/toolpath.h"
#include "machine/steps.h"
#include "machine/unitwire.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using machine::UnitOp;

using detail::isMotion;
using detail::refusal;

namespace {
// Motion kept in the unit beyond two round trips when a packet is sized to what it holds, s.
constexpr double kDryReserveS = 0.02;
// ... and this share of what it holds: the estimate of a second and more of queued motion is off
// by a percent or two (a 1.5 s packet after a spin-up arrived 11 ms after the unit ran dry).
constexpr double kHeldDriftShare = 0.05;
} // namespace

Job::Job(CoreHost &host)
    : m_host(host)
    , m_pace(host, m_program, m_cursor)
    , m_check(host, *this)
    , m_guard(host, *this)
    , m_probe(host, *this)
{}

// The one mapping of machine/unitwire.h (shared with the plan CLI). PC-side ops are never sent.
Command Job::toCommand(const machine::UnitCommand &c) const
{
    if (c.op == machine::UnitOp::Speed && m_override.speedScale() != 1.0) {
        machine::UnitCommand scaled = c;
        scaled.value = machine::speedPulses(static_cast<double>(c.value) * m_override.speedScale(),
                                            m_host.config().unit.maxPulseRate);
        return machine::wireCommand(scaled, m_program.axisCount).value_or(cmd::flag());
    }
    return machine::wireCommand(c, m_program.axisCount).value_or(cmd::flag());
}

std::optional<MachineError> Job::start(machine::UnitProgram program, double now)
{
    MachineState &state = m_host.liveState();
    if (state.mode != MachineMode::Idle)
        return refusal(DriverCode::JobNeedsIdle, {machineModeName(state.mode)});
    std::string note;
    auto bad = checkProgram(program, state, m_host.config(), &note);
    if (!note.empty())
        m_host.log(note);
    if (bad) {
        m_program = {};
        return bad;
    }
    m_program = std::move(program);
    m_active = true;
    ++m_serial;
    m_cursor = {};
    m_streamBlocked = m_queueFullSeen = m_afterRest = false;
    m_check.reset();
    m_guard.reset();
    m_lead.reset();
    m_sync.begin();
    m_waitUntil = -1;
    m_pace.build();
    m_packetLimit = m_pace.maxPacket();
    m_lineErrors.reset();
    m_cursor.execAt = now;
    m_host.restartPollCount();
    m_figures.start(now, m_host.link().stats());
    state.jobActive = true;
    state.commandsTotal = static_cast<std::int64_t>(m_program.commands.size());
    detail::setHold(state, HoldReason::None, {}, 0);
    state.lastError.reset();
    m_host.setMode(MachineMode::Running);
    m_override.resetLinkMin();
    m_override.follow(true);
    return std::nullopt;
}

bool Job::mayStream(double now) const
{
    return m_active && m_host.liveState().mode == MachineMode::Running && !m_streamBlocked &&
           now >= m_waitUntil;
}

bool Job::streaming(double now) const
{
    return mayStream(now) && m_cursor.next < m_program.commands.size();
}

bool Job::feeding() const
{
    return m_active && m_host.liveState().mode == MachineMode::Running && !m_streamBlocked &&
           m_cursor.next < m_program.commands.size();
}

bool Job::probing() const
{
    return m_streamBlocked && m_cursor.next < m_program.commands.size() &&
           m_program.commands[m_cursor.next].op == UnitOp::Probe;
}

void Job::streamStep(double now)
{
    if (m_check.pending())
        return;
    if (m_afterRest) {
        // The dwell is over and nothing was sent during it: the unit holds nothing, and the
        // estimate's clock starts now (it counted the dwell, a spin-up of seconds, as motion run
        // and took the unit for empty while the chain after it began, so its first packet was
        // as long as the queue and came too late).
        m_afterRest = false;
        m_cursor.exec = m_cursor.next;
        m_cursor.execAt = now;
    }
    if (m_sync.step(now) || (!m_sync.busy() && m_lead.step(now)))
        return;
    if (m_cursor.next >= m_program.commands.size()) {
        m_streamBlocked = true;
        m_host.afterJobIdle([this] { finishWithPosition(); });
        return;
    }
    const machine::UnitCommand &c = m_program.commands[m_cursor.next];
    if ((c.op == UnitOp::Vector || c.op == UnitOp::Brake) && m_host.options().packets) {
        sendPacket(now);
        return;
    }
    if (c.op > UnitOp::Spindle) {
        handlePcOp(c);
        return;
    }
    Command wire = toCommand(c);
    if (c.op == UnitOp::Spindle && !variantInfo(m_host.config().unit.variant).hasSpindleAddress7)
        wire = cmd::output((m_host.liveState().outputs & 0xFE) | (c.value ? 0 : 1));
    else if (c.op == UnitOp::Spindle) // the program's S at the spindle override
        wire = spindleSpeedCommand(m_host, static_cast<int>(c.value));
    const std::size_t index = m_cursor.next;
    m_cursor.inflightEnd = index + 1;
    m_host.start(wire,
                 [this, index](const Outcome &o) { onCommandOutcome(o, index, m_host.now()); });
}

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
    const double budget =
        held - std::min(2 * m_host.rttS() + kDryReserveS + kHeldDriftShare * held, 0.5 * held);
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

void Job::acceptUpTo(std::size_t end, bool arrivedJustNow)
{
    if (arrivedJustNow && end > m_cursor.next &&
        m_pace.vectorsBefore(end) > m_pace.vectorsBefore(m_cursor.next))
        m_pace.noteArrival(m_cursor.next, m_host.now() - m_host.rttS() / 2);
    for (; m_cursor.next < end; ++m_cursor.next) {
        const bool motion = isMotion(m_program.commands[m_cursor.next].op);
        if (motion)
            ++m_cursor.vectorsAcked;
        m_figures.accepted(motion, m_host.now());
    }
    MachineState &state = m_host.liveState();
    state.commandsAcked = static_cast<std::int64_t>(m_cursor.next);
    state.vectorsAcked = m_cursor.vectorsAcked;
    m_host.markDirty();
}

void Job::onPacketOutcome(const Outcome &o, std::size_t first, std::size_t n, double now)
{
    (void)now;
    if (m_cursor.next != first || m_guard.faulted())
        return; // superseded (abort, link loss, the path guard dropped the queue)
    if (o.status == OutcomeStatus::Failed) {
        m_lineErrors.note(static_cast<int>(n), 1);
        m_packetLimit = std::max(4, m_packetLimit / 2);
        m_check.verify("packet outcome unknown: " + o.error);
        return;
    }
    const std::size_t accepted = std::min<std::size_t>(static_cast<std::size_t>(o.accepted), n);
    const bool damaged = o.reply.code == ReplyCode::Syntax || o.reply.code == ReplyCode::Watchdog;
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

void Job::onCommandOutcome(const Outcome &o, std::size_t index, double now)
{
    if (m_cursor.next != index || m_guard.faulted())
        return;
    const machine::UnitCommand &c = m_program.commands[index];
    if (o.status == OutcomeStatus::Failed) {
        if (isMotion(c.op)) {
            m_check.verify("outcome unknown: " + o.error);
        } else {
            m_check.require();
            m_host.fail(detail::linkFailure(detail::lineText(c), o), &o, MachineMode::LinkLost);
        }
        return;
    }
    switch (o.reply.code) {
    case ReplyCode::Ok:
        if (c.op == UnitOp::Vector)
            m_queueFullSeen = false;
        acceptUpTo(index + 1, o.recovered == 0);
        return;
    case ReplyCode::QueueFull: // C: queue full; L: queue not yet empty. Not accepted: again.
        m_queueFullSeen = c.op == UnitOp::Vector;
        m_waitUntil = now + m_host.options().pollIntervalS;
        return;
    default:
        m_host.fail({DriverCode::UnitRefused,
                     {detail::lineArg(c), encodeBody(o.commands.front()),
                      std::string(replyCodeText(o.reply.code))}},
                    &o, MachineMode::Alarm);
        return;
    }
}

// A wait of the job for the machine to stand before command `index`, then the path guard's
// exact check of the counters there, then `then` (unless the job moved on meanwhile).
void Job::atRest(std::size_t index, std::function<void()> then)
{
    m_host.afterJobIdle([this, index, then = std::move(then)]() mutable {
        if (m_cursor.next != index)
            return;
        m_guard.checkAtRest(index, [this, index, then = std::move(then)] {
            if (m_cursor.next != index)
                return;
            // The machine stands here: everything before ran, and the clock of the estimate
            // starts again now (it counted the rest, a spin-up of seconds, as motion run, and
            // took the unit for empty when the chain after it began).
            m_cursor.exec = index;
            m_cursor.execAt = m_host.now();
            then();
        });
    });
}

void Job::handlePcOp(const machine::UnitCommand &c)
{
    const std::size_t index = m_cursor.next;
    m_streamBlocked = true;
    switch (c.op) {
    case UnitOp::WaitIdle:
        atRest(index, [this, index] {
            acceptUpTo(index + 1);
            m_streamBlocked = false;
        });
        return;
    case UnitOp::Dwell:
        atRest(index, [this, index, ms = c.value] {
            acceptUpTo(index + 1);
            m_waitUntil = m_host.now() + static_cast<double>(ms) / 1000.0;
            m_afterRest = true;
            m_streamBlocked = false;
        });
        return;
    case UnitOp::OperatorStop:
        operatorStop(c, index);
        return;
    case UnitOp::ProgramEnd:
        atRest(index, [this, index] {
            acceptUpTo(index + 1);
            finishWithPosition();
        });
        return;
    case UnitOp::Probe:
        atRest(index, [this, index] { m_probe.start(index); });
        return;
    default:
        m_streamBlocked = false;
        m_host.fail({DriverCode::UnknownOperation, {detail::lineArg(c)}}, nullptr,
                    MachineMode::Alarm);
        return;
    }
}

// M0 / M1 / M6: the job holds where the machine stands (M1 only with optional stops on).
void Job::operatorStop(const machine::UnitCommand &c, std::size_t index)
{
    // The planner's StopReason (machine/unitprogram.h), not the G-code event kind.
    const auto kind = static_cast<machine::StopReason>(c.value);
    if (kind == machine::StopReason::OptionalPause && !m_host.options().optionalStops) {
        acceptUpTo(index + 1);
        m_streamBlocked = false;
        return;
    }
    const std::string line = detail::lineArg(c);
    const DriverMessage text =
        kind == machine::StopReason::ToolChange
            ? DriverMessage{DriverCode::HoldToolChange, {line, std::to_string(c.aux)}}
        : kind == machine::StopReason::OptionalPause
            ? DriverMessage{DriverCode::HoldOptionalStop, {line}}
            : DriverMessage{DriverCode::HoldProgramStop, {line}};
    atRest(index, [this, index, text] {
        acceptUpTo(index + 1);
        m_streamBlocked = false;
        m_host.setHoldNeedsGo(false);
        MachineState &state = m_host.liveState();
        detail::setHold(state, HoldReason::OperatorStop, text,
                        m_program.commands[index].sourceLine);
        m_host.setMode(MachineMode::Paused);
        m_host.heldAtOperatorStop(
            static_cast<machine::StopReason>(m_program.commands[index].value));
    });
}

// The job ran to its end: read the counters once more so that the report and the last state
// show where the machine really is.
void Job::finishWithPosition()
{
    m_host.send(m_host.positionCommand(), [this](const Outcome &o) {
        if (m_host.unitError(o, "reading the final position", MachineMode::LinkLost))
            return;
        m_host.applyPosition(o.reply);
        const auto &at = m_host.liveState().positionSteps;
        const machine::Steps4 &end = m_guard.plannedBefore(m_program.commands.size());
        for (int a = 0; a < m_program.axisCount && !m_guard.off(); ++a) {
            if (at[a] != end[a]) {
                m_guard.fault("the job ended with the counters at " +
                              detail::stepsText(at, m_program.axisCount) +
                              " steps where the program ends at " +
                              detail::stepsText(end, m_program.axisCount));
                return;
            }
        }
        finish(true);
    });
}

void Job::finish(bool ok)
{
    if (!m_active)
        return;
    m_active = false;
    m_streamBlocked = false;
    m_figures.finish(ok, m_host.now(), m_host.link().stats());
    MachineState &state = m_host.liveState();
    state.jobActive = false;
    state.progress = ok ? 1.0 : state.progress;
    state.etaS = ok ? 0 : -1;
    m_host.markDirty();
    if (state.mode == MachineMode::Running)
        m_host.setMode(MachineMode::Idle);
    m_figures.report().overrideLinkMinPercent = m_override.linkMinPercent();
    m_override.follow(false); // the operator's override again
    m_host.log(ok ? "job finished" : "job ended");
    m_host.publish(); // the final state before the news that the job ended
    m_host.jobFinished(ok);
}

void Job::abandon()
{
    m_active = false;
    m_host.liveState().jobActive = false;
    m_streamBlocked = false;
    m_check.cancel();
    m_guard.clearFault();
    m_lead.reset();
    m_sync.reset();
    m_override.follow(false);
}

void Job::pollStarted(double now)
{
    m_figures.pollStarted(now, m_cursor.next < m_program.commands.size() &&
                                   m_pace.vectorsBefore(m_pace.size() - 1) >
                                       m_pace.vectorsBefore(m_cursor.next));
}

// While progress is re-established from the counters a position on the path still verifies
// it; one off the path is left to that check.
void Job::checkPolledPosition(bool kept)
{
    if (m_host.liveState().mode != MachineMode::Running || m_guard.faulted() || kept ||
        m_guard.off() || m_guard.onPlannedPath() || m_check.pending())
        return;
    m_guard.fault("the unit's counters read " +
                  detail::stepsText(m_host.liveState().positionSteps, m_program.axisCount) +
                  " steps, on no segment of the path "
                  "sent to it");
}

void Job::linkOpened()
{
    if (m_active)
        m_streamBlocked = false; // a wait in progress is taken up again from the program
}

void Job::linkLost()
{
    m_check.linkLost();
    m_guard.clearFault(); // the check of the counters after reconnecting takes over
    m_lead.reset();       // a unit still held reports INTA when the link is back: the job is held
    m_sync.reset();       // ... and runs on without the other units
}

bool Job::resumeAfterReconnect()
{
    if (!m_active || !m_check.pending())
        return false;
    MachineState &state = m_host.liveState();
    m_host.setMode(MachineMode::Paused);
    detail::setHold(state, HoldReason::User, {DriverCode::HoldLinkRestored}, state.sourceLine);
    m_check.verify("reconnected");
    return true;
}

} // namespace frezka::driver
