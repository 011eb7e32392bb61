// MachineCore: machine operations (issue 5 item 4): pause/resume/abort, tool lift with
// KEEP/RESTORE, homing, jog, MPG, spindle, outputs, feed override, raw commands, interrupts.

#include "machinecore.h"

#include "driver/link/machinecore_internal.h"
#include "machine/homing.h"

#include "protocol/commandparser.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::notNow;
using detail::refusal;

std::int64_t MachineCore::stepsFromMm(int axis, double mm) const
{
    return std::llround(mm * m_config.axes[static_cast<std::size_t>(axis)].stepsPerMm);
}

double MachineCore::mmFromSteps(int axis, std::int64_t steps) const
{
    return static_cast<double>(steps) / m_config.axes[static_cast<std::size_t>(axis)].stepsPerMm;
}

// ---- run / pause / resume / abort ----

MachineCore::Result MachineCore::run(machine::UnitProgram program, double now)
{
    if (auto refused = m_job.start(std::move(program), now))
        return refused;
    m_toolLift.reset();
    pump(now);
    return std::nullopt;
}

// ---- pause / resume / abort ----------------------------------------------------------------

MachineCore::Result MachineCore::pause(double now)
{
    if (m_state.mode != MachineMode::Running)
        return notNow("Pause", m_state.mode);
    setMode(MachineMode::Stopping);
    sendFront(cmd::halt(), [this](const Outcome &o) {
        if (unitError(o, "pausing (H)", MachineMode::Alarm))
            return;
        m_holdNeedsGo = true;
        m_state.inta = true;
        m_state.hold = HoldReason::User;
        m_state.holdText = "paused";
        setMode(MachineMode::Paused);
    });
    pump(now);
    return std::nullopt;
}

MachineCore::Result MachineCore::resume(double now)
{
    if (m_state.mode != MachineMode::Paused)
        return notNow("Resume", m_state.mode);
    if (m_job.verifying())
        return refusal("the job's progress is still being checked against the unit's counters");
    if (m_state.hold == HoldReason::PathFault && m_job.active()) {
        m_job.returnToPath();
        pump(now);
        return std::nullopt;
    }
    auto running = [this] {
        m_state.hold = HoldReason::None;
        m_state.holdText.clear();
        m_state.interruptInputs = 0;
        setMode(m_job.active() ? MachineMode::Running : MachineMode::Idle);
    };
    if (!m_holdNeedsGo) {
        running();
        pump(now);
        return std::nullopt;
    }
    send(cmd::go(), [this, running](const Outcome &o) {
        // 6 = nothing to continue: the queue ran out while braking; the job streams on.
        if (o.status == OutcomeStatus::Ok && o.reply.code == ReplyCode::NothingToContinue) {
            m_holdNeedsGo = false;
            running();
            return;
        }
        if (unitError(o, "continuing (G)", MachineMode::Alarm))
            return;
        m_holdNeedsGo = false;
        m_state.inta = false;
        running();
    });
    pump(now);
    return std::nullopt;
}

MachineCore::Result MachineCore::abort(double now)
{
    switch (m_state.mode) {
    case MachineMode::Running:
    case MachineMode::Paused:
    case MachineMode::Stopping:
    case MachineMode::Jogging:
    case MachineMode::Alarm:
    case MachineMode::Homing:
        break;
    default:
        if (!m_job.active())
            return notNow("Abort", m_state.mode);
    }
    if (m_state.mode == MachineMode::ToolLifted)
        return refusal("lower the tool first: the job's queue is kept in the unit (K)");
    m_steps.clear();
    m_idleWaiters.clear();
    m_jobIdleWaiters.clear();
    const bool wasJob = m_job.active();
    m_job.abandon();
    setMode(MachineMode::Stopping);
    send(cmd::halt(),
         [this](const Outcome &o) { unitError(o, "stopping (H)", MachineMode::Alarm); });
    send(cmd::deleteQueue(), [this, wasJob](const Outcome &o) {
        if (unitError(o, "dropping the queue (D)", MachineMode::Alarm))
            return;
        m_holdNeedsGo = false;
        m_state.hold = HoldReason::None;
        m_state.holdText.clear();
        setMode(MachineMode::Idle);
        if (wasJob) {
            m_job.report().endS = m_now;
            publish();
            if (onJobFinished)
                onJobFinished(false);
        }
    });
    pump(now);
    return std::nullopt;
}

// ---- tool lift (toollift.h) ----------------------------------------------------------------

MachineCore::Result MachineCore::toolLift(bool stopSpindle, double now)
{
    return accepted(m_toolLift.lift(stopSpindle), now);
}

MachineCore::Result MachineCore::toolLower(int speedPulsesPerS, double now)
{
    return accepted(m_toolLift.lower(speedPulsesPerS), now);
}

// ---- interrupts ----------------------------------------------------------------------------

void MachineCore::interrupted()
{
    const bool job = m_state.mode == MachineMode::Running;
    setMode(job ? MachineMode::Paused : MachineMode::Alarm);
    m_holdNeedsGo = true;
    m_state.hold = HoldReason::Interrupt;
    m_state.holdText = "an input interrupt stopped the machine";
    auto cause = [this](int n) {
        return [this, n](const Outcome &o) {
            if (o.status != OutcomeStatus::Ok || !o.reply.ok())
                return;
            const int bits = *o.reply.hexValue();
            m_state.interruptInputs = static_cast<std::uint16_t>(
                n == 4 ? (m_state.interruptInputs & 0xFF00) | bits
                       : (m_state.interruptInputs & 0x00FF) | (bits << 8));
            std::string names;
            for (int b = 0; b < 16; ++b) {
                if (m_state.interruptInputs & (1 << b))
                    names += (names.empty() ? "IN" : ", IN") + std::to_string(b);
            }
            m_state.holdText = "stopped by input " + (names.empty() ? "?" : names) +
                               (m_state.interruptInputs & 0x80 ? " (STOP button)" : "");
            m_dirty = true;
        };
    };
    sendFront(cmd::statusRead(4), cause(4));
    if (m_config.unit.variant != Variant::Gve84)
        send(cmd::statusRead(5), cause(5));
}

// ---- homing (homingcycle.h), jog (jog.h) ----------------------------------------------------

MachineCore::Result MachineCore::home(double now, unsigned axisMask)
{
    bool queued = false;
    if (auto refused = m_homing.start(axisMask, &queued))
        return refused;
    if (queued)
        pump(now);
    return std::nullopt;
}

MachineCore::Result MachineCore::accepted(Result refused, double now)
{
    if (!refused)
        pump(now);
    return refused;
}

MachineCore::Result MachineCore::jogStep(int axis, double distanceMm, double speedMmPerMin,
                                         double now)
{
    return accepted(m_jog.step(axis, distanceMm, speedMmPerMin), now);
}

MachineCore::Result MachineCore::jogContinuous(int axis, int direction, double speedMmPerMin,
                                               double now)
{
    return accepted(m_jog.continuous(axis, direction, speedMmPerMin), now);
}

MachineCore::Result MachineCore::writeEeprom(double now)
{
    return accepted(m_eeprom.write(), now);
}

MachineCore::Result MachineCore::jogStop(double now)
{
    return accepted(m_jog.stop(), now);
}

// ---- MPG, spindle, outputs, override, raw --------------------------------------------------

MachineCore::Result MachineCore::setMpg(bool on, double now)
{
    if (!m_state.features.mpg)
        return refusal(variantInfo(m_config.unit.variant).hasMpg
                           ? "this unit's firmware (v" + std::to_string(m_state.firmwareVersion) +
                                 ") has no MPG handwheel; it needs v10"
                           : std::string("this unit has no MPG handwheel"));
    if (m_state.mode != MachineMode::Idle)
        return notNow("Switching the MPG", m_state.mode);
    send(on ? cmd::mpgSilent() : cmd::mpgOff(), [this, on](const Outcome &o) {
        if (!unitError(o, "switching the MPG", MachineMode::Alarm)) {
            m_state.mpgOn = on;
            m_dirty = true;
        }
    });
    pump(now);
    return std::nullopt;
}

MachineCore::Result MachineCore::setSpindleRpm(double rpm, double now)
{
    if (m_state.mode == MachineMode::Disconnected || m_state.mode == MachineMode::Connecting ||
        m_state.mode == MachineMode::LinkLost)
        return notNow("Setting the spindle", m_state.mode);
    const double maxRpm = m_config.spindle.maxRpm;
    if (rpm < 0 || rpm > maxRpm)
        return refusal("spindle speed " + std::to_string(rpm) + " rpm is outside 0.." +
                       std::to_string(maxRpm));
    const int permille = static_cast<int>(std::lround(rpm / maxRpm * 1000.0));
    Command c = cmd::spindle(permille);
    if (!variantInfo(m_config.unit.variant).hasSpindleAddress7)
        c = cmd::output((m_state.outputs & 0xFE) | (permille > 0 ? 0 : 1));
    send(c, [this, permille, rpm](const Outcome &o) {
        if (unitError(o, "setting the spindle", MachineMode::Alarm))
            return;
        m_state.spindlePermille = permille;
        m_state.spindleRpm = rpm;
        m_dirty = true;
    });
    pump(now);
    return std::nullopt;
}

MachineCore::Result MachineCore::setOutputs(std::uint8_t mask, std::uint8_t activeHigh, double now)
{
    if (m_state.mode == MachineMode::Disconnected || m_state.mode == MachineMode::LinkLost)
        return notNow("Switching outputs", m_state.mode);
    const auto value = static_cast<std::uint8_t>((m_state.outputs & ~mask) | (~activeHigh & mask));
    send(cmd::output(value), [this, value](const Outcome &o) {
        if (unitError(o, "switching outputs", MachineMode::Alarm))
            return;
        m_state.outputs = value;
        m_dirty = true;
    });
    pump(now);
    return std::nullopt;
}

MachineCore::Result MachineCore::setOverride(int percent, double now)
{
    if (auto bad = validate(cmd::multiplier(percent), m_config.unit.variant))
        return refusal(bad.message);
    if (!m_state.features.vlVkXmNa)
        return refusal(variantInfo(m_config.unit.variant).hasVlVkXmNa
                           ? "this unit's firmware (v" + std::to_string(m_state.firmwareVersion) +
                                 ") has no XM feed override; it needs v19"
                           : std::string("this unit has no XM feed override"));
    send(cmd::multiplier(percent), [this, percent](const Outcome &o) {
        if (unitError(o, "setting the feed override (XM)", MachineMode::Alarm))
            return;
        m_state.overridePercent = percent;
        m_dirty = true;
    });
    pump(now);
    return std::nullopt;
}

MachineCore::Result MachineCore::overrideStep(bool up, double now)
{
    send(up ? cmd::exchangeUp() : cmd::exchangeDown(), [this, up](const Outcome &o) {
        if (unitError(o, up ? "raising queued speeds (XU)" : "lowering queued speeds (XD)",
                      MachineMode::Alarm))
            return;
        // XU/XD change the queued vectors by 1/16 of their speed; shown as an approximation.
        m_state.overridePercent =
            static_cast<int>(std::lround(m_state.overridePercent * (up ? 17.0 : 15.0) / 16.0));
        m_dirty = true;
    });
    pump(now);
    return std::nullopt;
}

MachineCore::Result MachineCore::sendRaw(const std::string &text, double now)
{
    std::string line = text;
    while (!line.empty() && (line.back() == '\r' || line.back() == '\n' || line.back() == ' '))
        line.pop_back();
    if (line.empty())
        return refusal("empty command");
    if (line.front() != '!')
        line = "!0" + line;
    const ParsedCommand p = parseCommand(line, false);
    if (p.status != ParseStatus::Ok)
        return refusal("'" + text + "': " + (p.message.empty() ? "not a command" : p.message));
    if (auto bad = validate(p.command, m_config.unit.variant, m_config.unit.maxPulseRate))
        return refusal(bad.message);
    const Op op = p.command.op;
    if (m_job.active() && (op == Op::Line || op == Op::Vector || op == Op::Delete ||
                           op == Op::Keep || op == Op::Restore || op == Op::Jump ||
                           op == Op::ZeroAll || op == Op::SetCounter || op == Op::Home))
        return refusal("'" + text + "' would disturb the running job");
    send(p.command, [this](const Outcome &o) {
        if (o.status != OutcomeStatus::Ok) {
            unitError(o, "raw command", MachineMode::LinkLost);
            return;
        }
        log("reply: " + o.raw);
    });
    pump(now);
    return std::nullopt;
}

} // namespace frezka::driver
