// MachineCore: scheduling, polling, state publication. See machinecore.h for the design.

#include "machinecore.h"

#include "driver/link/machinecore_internal.h"

#include <algorithm>
#include <cmath>
#include <variant>

namespace frezka::driver {

using namespace frezka::protocol;

namespace {
// The unit's address: the caller's (a shared line), else the profile's; so the adapter's latency
// for the reply allowance (LinkOptions::latencyS).
LinkOptions linkOptionsFor(LinkOptions link, const machine::MachineConfig &config)
{
    if (link.unitAddress == 0)
        link.unitAddress = config.unit.address;
    if (link.latencyS < 0)
        link.latencyS = config.link.latencyMs / 1000.0;
    return link;
}
} // namespace

MachineCore::MachineCore(machine::MachineConfig config, CoreOptions options)
    : m_config(std::move(config))
    , m_options(options)
    , m_engine(linkOptionsFor(options.link, m_config))
{
    if (m_options.link.baud <= 0)
        m_engine.setBaud(m_config.link.baud);
    m_engine.onOutcome = [this](const Outcome &o) { onOutcome(o); };
    m_engine.onLog = [this](LinkLogKind kind, const std::string &text) {
        static constexpr const char *kPrefix[] = {"> ", "< ", "? ", "! ", "!! "};
        log(kPrefix[static_cast<int>(kind)] + text);
    };
    m_state.variant = m_config.unit.variant;
    m_state.axisCount = machine::wireAxisCount(m_config);
}

void MachineCore::log(const std::string &text)
{
    if (onLog)
        onLog(text);
}

void MachineCore::setMode(MachineMode mode)
{
    if (m_state.mode == mode)
        return;
    log("mode: " + std::string(machineModeName(m_state.mode)) + " -> " + machineModeName(mode));
    m_state.mode = mode;
    m_dirty = true;
    if (mode == MachineMode::Idle)
        m_inputHoming.park();
}

MachineActivity MachineCore::currentActivity() const
{
    switch (m_state.mode) {
    case MachineMode::Connecting:
        return MachineActivity::Connecting;
    case MachineMode::Homing:
        return MachineActivity::Homing;
    case MachineMode::Jogging:
        return MachineActivity::Jogging;
    default:
        break;
    }
    if (!m_job.active())
        return MachineActivity::None;
    if (m_toolLift.active())
        return MachineActivity::ToolLift;
    if (m_job.offPath())
        return m_state.mode == MachineMode::Running ? MachineActivity::ReturnToPath
                                                    : MachineActivity::PathFault;
    if (m_job.verifying())
        return MachineActivity::CheckingProgress;
    if (m_job.probing())
        return MachineActivity::Probing;
    return MachineActivity::Job;
}

void MachineCore::publish()
{
    m_live.settle();
    if (const MachineActivity a = currentActivity(); a != m_state.activity) {
        m_state.activity = a;
        m_dirty = true;
    }
    m_state.link = m_engine.stats();
    m_state.checksums = m_engine.checksums();
    if (m_job.active()) {
        m_state.commandsAcked = static_cast<std::int64_t>(m_job.cursor().next);
        m_state.vectorsAcked = m_job.cursor().vectorsAcked;
    }
    if (!m_dirty)
        return;
    m_dirty = false;
    if (onStateChanged)
        onStateChanged(m_state);
}

void MachineCore::fail(const DriverMessage &reason, const Outcome *o, MachineMode mode)
{
    const MachineError e = detail::failure(reason, o);
    const std::string &message = e.message;
    m_state.lastError = e;
    m_dirty = true;
    log("error: " + message + (e.command.empty() ? "" : " [" + e.command + "]") +
        (e.reply.empty() ? "" : " -> '" + e.reply + "'"));
    if (onError)
        onError(e);
    setMode(mode);
}

bool MachineCore::unitError(const Outcome &o, const std::string &what, MachineMode mode)
{
    if (o.status == OutcomeStatus::Ok && o.reply.ok())
        return false;
    if (o.status == OutcomeStatus::Failed) {
        fail(detail::linkFailure(what, o), &o, MachineMode::LinkLost);
        m_steps.clear();
        return true;
    }
    fail({DriverCode::UnitAnswered, {what, std::string(replyCodeText(o.reply.code))}}, &o, mode);
    return true;
}

// ---- scheduling ------------------------------------------------------------------------------

void MachineCore::send(const Command &c, Then then)
{
    m_steps.push_back({c, std::move(then)});
}

void MachineCore::sendFront(const Command &c, Then then)
{
    m_steps.push_front({c, std::move(then)});
}

void MachineCore::onOutcome(const Outcome &o)
{
    if (!o.commands.empty() &&
        (o.commands.front().op == Op::Halt || o.commands.front().op == Op::Home))
        m_haltPending = false;
    // What the unit drives now, whoever sent it (job, buttons, console, holds): issue 14.
    if (o.status == OutcomeStatus::Ok && o.reply.ok() && !o.packet && !o.commands.empty())
        m_dirty = noteOutputsAccepted(m_state, o.commands.front(), m_config) || m_dirty;
    Then then = std::move(m_inFlight);
    m_inFlight = nullptr;
    if (then)
        then(o);
    // Every reply carries INTA: an input interrupt is seen at the next reply, whatever it was.
    if (o.status == OutcomeStatus::Ok && o.reply.inta && !m_haltPending && !m_haltExpected &&
        m_state.mode == MachineMode::Running && !m_state.inta) {
        m_state.inta = true;
        m_hold.interrupted();
    }
}

double MachineCore::deadline() const
{
    double d = m_engine.deadline();
    if (!m_open)
        return d;
    d = std::min(m_waits.nextTime(d), m_live.nextTime());
    if (m_engine.idle()) {
        d = std::min(d, m_haltPending ? kNoDeadline : m_poller.nextTime());
        if (m_job.waitUntil() > m_now)
            d = std::min(d, m_job.waitUntil());
    }
    return d;
}

void MachineCore::receive(std::string_view bytes, double now)
{
    m_now = now;
    m_engine.receive(bytes, now);
    pump(now);
}

void MachineCore::onTime(double now)
{
    m_now = now;
    m_engine.onTime(now);
    pump(now);
}

void MachineCore::afterDelay(double seconds, std::function<void()> then)
{
    m_waits.addTimer(m_now + std::max(0.0, seconds), std::move(then));
}

void MachineCore::heldAtOperatorStop(machine::StopReason reason)
{
    m_spindle.atOperatorStop(reason);
}

void MachineCore::pump(double now)
{
    m_now = now;
    if (m_open)
        m_waits.runDue(m_now);
    if (m_open && now >= m_live.nextTime())
        m_live.update(now);
    while (m_open && m_engine.idle()) {
        if (!m_steps.empty()) {
            Step s = std::move(m_steps.front());
            m_steps.pop_front();
            m_inFlight = std::move(s.then);
            if (s.command.op == Op::Halt || s.command.op == Op::Home)
                m_haltPending = true;
            m_engine.start(s.command, now);
            break;
        }
        if (!m_haltPending && now >= m_poller.nextTime()) {
            m_poller.start(now);
            break;
        }
        if (m_job.mayStream(now)) {
            m_job.streamStep(now);
            if (!m_engine.idle() || !m_steps.empty())
                continue;
        }
        break;
    }
    publish();
}

void MachineCore::applyPosition(const Reply &r)
{
    const auto v = r.decimals();
    if (!v)
        return;
    for (std::size_t i = 0; i < v->size() && i < 4; ++i) {
        m_state.positionSteps[i] = (*v)[i];
        m_state.positionMm[i] = mmFromSteps(static_cast<int>(i), (*v)[i]);
    }
    m_dirty = true;
    m_poller.positionRead(m_now);
    if (m_job.active())
        m_job.positionRead();
    m_live.positionRead();
}

void MachineCore::applyFlags(std::uint8_t flags)
{
    const bool wasInta = m_state.inta;
    detail::setFlags(m_state, flags);
    m_dirty = true;
    // A running unit that stands has run everything accepted; one held by H, an interrupt or a
    // tool lift (INTA set, or not Running) stands with its queue kept.
    if (m_job.active() && !m_state.run && !m_state.inta && m_state.mode == MachineMode::Running)
        m_job.unitStands();
    if (m_state.inta && !wasInta && m_state.mode == MachineMode::Running && !m_haltExpected)
        m_hold.interrupted();
    if (m_state.inta && !wasInta &&
        (m_state.mode == MachineMode::Jogging || m_state.mode == MachineMode::Idle))
        m_hold.interrupted();
    checkIdleWaiters();
}

void MachineCore::afterIdle(std::function<void()> then)
{
    m_waits.addIdle(std::move(then));
    send(cmd::flag(), [this](const Outcome &o) {
        if (o.status != OutcomeStatus::Ok || !o.reply.ok())
            return (void)unitError(o, "status", MachineMode::Alarm);
        applyFlags(*o.reply.hexValue());
    });
}

void MachineCore::afterJobIdle(std::function<void()> then)
{
    m_waits.addJobIdle(std::move(then));
    afterIdle(nullptr);
}

bool MachineCore::waitingForJobStand() const
{
    return m_waits.jobIdlePending() && m_job.active() && m_state.mode == MachineMode::Running &&
           !m_toolLift.kept();
}

void MachineCore::afterStopOrInterrupt(std::function<void()> then)
{
    m_waits.addStop(std::move(then));
    afterIdle(nullptr);
}

void MachineCore::checkIdleWaiters()
{
    if (m_state.inta || !m_state.run)
        m_waits.stopped();
    if (m_state.run)
        return;
    // The job's own waits (WaitIdle, M0, ProgramEnd, ...) count only while it runs: a queue
    // kept by K or a pause is not the job's end.
    m_waits.idle(m_state.mode == MachineMode::Running && !m_toolLift.kept());
}

// ---- CoreHost ---------------------------------------------------------------------------

void MachineCore::start(const Command &c, Then then)
{
    m_inFlight = std::move(then);
    m_engine.start(c, m_now);
}

void MachineCore::startPacket(std::vector<Command> packet, Then then)
{
    m_inFlight = std::move(then);
    m_engine.startPacket(std::move(packet), m_now);
}

void MachineCore::dropPending()
{
    m_waits.clearTimers();
    m_steps.clear();
    m_waits.clearIdle();
    m_waits.clearJobIdle();
}

void MachineCore::jobFinished(bool ok)
{
    if (onJobFinished)
        onJobFinished(ok);
}

Command MachineCore::positionCommand() const
{
    return m_state.axisCount == 4 ? cmd::positionXYZA() : cmd::positionXYZ();
}

// Two position reads that agree: the machine stands (after RUN = 0 or an interrupt's brake).
void MachineCore::whenStill(std::function<void()> then)
{
    const Command pos = positionCommand();
    send(pos, [this, pos, then](const Outcome &first) {
        if (unitError(first, "reading the position", MachineMode::Alarm))
            return;
        send(pos, [this, then, a = first.reply.values](const Outcome &second) {
            if (unitError(second, "reading the position", MachineMode::Alarm))
                return;
            applyPosition(second.reply);
            if (second.reply.values == a)
                then();
            else
                whenStill(then);
        });
    });
}

void MachineCore::readPositionAndStatus(std::function<void()> then)
{
    send(positionCommand(), [this](const Outcome &o) {
        if (unitError(o, "reading the position", MachineMode::Alarm))
            return;
        applyPosition(o.reply);
    });
    send(cmd::flag(), [this, then = std::move(then)](const Outcome &o) {
        if (unitError(o, "reading the status", MachineMode::Alarm))
            return;
        detail::setFlags(m_state, *o.reply.hexValue());
        m_poller.restartAt(m_now);
        if (then)
            then();
    });
}

// ---- operations ----------------------------------------------------------------------------

MachineCore::Result MachineCore::execute(MachineCommand command, double now)
{
    return std::visit(
        detail::Overloaded{
            [&](op::Run &c) {
                return moving([&] { return runJob(std::move(c.program), now); }, now);
            },
            // Homing stops at Pause (Stop, Esc) and Abort alike: no job to hold or drop.
            [&](op::Pause &c) {
                return accepted(m_homing.active() ? m_homing.stop() : m_hold.pause(c.stopSpindle),
                                now);
            },
            [&](op::HoldSpindle &c) { return accepted(m_hold.holdSpindle(c.stop), now); },
            [&](op::Resume &) { return accepted(m_hold.resume(), now); },
            [&](op::Abort &) {
                return accepted(m_homing.active() ? m_homing.stop() : m_hold.abort(), now);
            },
            [&](op::ToolLift &c) { return accepted(m_toolLift.lift(c.stopSpindle), now); },
            [&](op::ToolLower &c) { return accepted(m_toolLift.lower(c.speedPulsesPerS), now); },
            [&](op::Home &c) { return moving([&] { return startHoming(c.axisMask, now); }, now); },
            [&](op::JogStep &c) {
                if (m_state.mode == MachineMode::ToolLifted) // away from the work and back
                    return accepted(m_toolLift.jog(c.axis, c.distanceMm, c.speedMmPerMin), now);
                return moving([&] { return m_jog.step(c.axis, c.distanceMm, c.speedMmPerMin); },
                              now);
            },
            [&](op::JogContinuous &c) {
                return moving(
                    [&] { return m_jog.continuous(c.axis, c.direction, c.speedMmPerMin); }, now);
            },
            [&](op::JogStop &) { return accepted(m_jog.stop(), now); },
            [&](op::SetMpg &c) { return accepted(m_controls.setMpg(c.on), now); },
            [&](op::SetSpindleRpm &c) { return accepted(m_controls.setSpindleRpm(c.rpm), now); },
            [&](op::SetOutput &c) { return accepted(m_controls.setOutput(c.output, c.on), now); },
            [&](op::SetOverride &c) { return accepted(m_controls.setOverride(c.percent), now); },
            [&](op::SetSpindleOverride &c) {
                return accepted(m_controls.setSpindleOverride(c.percent), now);
            },
            [&](op::OverrideStep &c) { return accepted(m_controls.overrideStep(c.up), now); },
            [&](op::SendRaw &c) { return accepted(m_controls.sendRaw(c.text), now); },
            [&](op::WriteEeprom &) { return accepted(m_eeprom.write(), now); },
        },
        command);
}

MachineCore::Result MachineCore::accepted(Result refused, double now)
{
    if (!refused)
        pump(now);
    return refused;
}

// An operation that moves the machine: a unit parked in Y& for homing from its input gets Y-
// first (only while idle: a held job's moves already run with the MPG off).
MachineCore::Result MachineCore::moving(const std::function<Result()> &operation, double now)
{
    const bool unparked = m_inputHoming.unpark(); // parked only while idle (or in an alarm)
    Result refused = operation();
    if (refused && unparked)
        m_inputHoming.park();
    return accepted(refused, now);
}

MachineCore::Result MachineCore::runJob(machine::UnitProgram program, double now)
{
    if (auto refused = m_job.start(std::move(program), now))
        return refused;
    m_toolLift.reset();
    pump(now);
    return std::nullopt;
}

// Pumps only when something was queued (a W the variant refuses leaves nothing to send).
MachineCore::Result MachineCore::startHoming(unsigned axisMask, double now)
{
    bool queued = false;
    if (auto refused = m_homing.start(axisMask, &queued))
        return refused;
    if (queued)
        pump(now);
    return std::nullopt;
}

double MachineCore::mmFromSteps(int axis, std::int64_t steps) const
{
    return static_cast<double>(steps) / m_config.axes[static_cast<std::size_t>(axis)].stepsPerMm;
}

// ---- transport events --------------------------------------------------------------------

void MachineCore::linkOpened(double now)
{
    m_now = now;
    m_open = true;
    m_engine.reset();
    m_steps.clear();
    m_waits.clearIdle();
    m_inFlight = nullptr;
    m_haltPending = false;
    m_waits.clearJobIdle();
    m_waits.clearStop();
    m_waits.clearTimers();
    m_job.linkOpened();
    m_inputHoming.linkOpened();
    setMode(MachineMode::Connecting);
    m_connect.start();
    pump(now);
}

void MachineCore::linkClosed(const std::string &why, double now)
{
    m_now = now;
    const bool wasOpen = m_open;
    m_open = false;
    m_engine.reset();
    m_steps.clear();
    m_waits.clearIdle();
    m_waits.clearTimers();
    m_inFlight = nullptr;
    m_haltPending = false;
    if (m_job.active()) {
        m_job.linkLost();
        fail({DriverCode::LinkLostJobKept, {why}}, nullptr, MachineMode::LinkLost);
    } else if (why.empty()) {
        log("link closed");
        setMode(MachineMode::Disconnected);
    } else {
        // A port that failed to open or went away: the user must see why.
        fail({wasOpen ? DriverCode::LinkLost : DriverCode::CannotConnect, {why}}, nullptr,
             wasOpen ? MachineMode::LinkLost : MachineMode::Disconnected);
    }
    publish();
}

} // namespace frezka::driver
