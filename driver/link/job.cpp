// Job: streaming a unit program (packets, back-pressure, PC-side waits) and its end. See job.h.

#include "job.h"

#include "driver/link/corehost.h"
#include "driver/link/machinecore_internal.h"
#include "driver/link/programcheck.h"
#include "driver/link/unitcontrols.h"
#include "gcode/toolpath.h"
#include "machine/pathcheck.h"
#include "machine/steps.h"
#include "machine/unitwire.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using machine::UnitOp;

using detail::isMotion;
using detail::refusal;

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
    m_streamBlocked = m_queueFullSeen = m_afterRest = m_chainDamaged = false;
    m_restVerified = kNoRest;
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

void Job::onCommandOutcome(const Outcome &o, std::size_t index, double now)
{
    if (m_cursor.next != index || m_guard.faulted())
        return;
    const machine::UnitCommand &c = m_program.commands[index];
    m_chainDamaged = m_chainDamaged || o.status == OutcomeStatus::Failed || o.recovered > 0;
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
            m_restVerified = index;
            // F and the position were just read: no poll between them and the restart (a
            // poll there, due 50 ms after the wait's last F, took another round trip or three).
            m_host.restartPolls();
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
        // Right after a wait for the queue to drain, checked at rest, nothing was sent: the unit
        // stands where the program ends (F and the position again took two round trips).
        if (!m_guard.off() && index > 0 && m_restVerified == index - 1 &&
            index + 1 == m_program.commands.size() &&
            machine::sameSteps(m_host.liveState().positionSteps, m_guard.plannedBefore(index + 1),
                               m_program.axisCount)) {
            acceptUpTo(index + 1);
            finish(true);
            return;
        }
        atRest(index, [this, index] {
            acceptUpTo(index + 1);
            // The path guard's read at rest was the program's end: read again only without it.
            if (!m_guard.off() && index + 1 == m_program.commands.size())
                finish(true);
            else
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
