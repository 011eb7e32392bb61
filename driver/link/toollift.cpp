// ToolLift: K, L up, [operator], L down, R, [V, XA] in a held job. See toollift.h.

#include "toollift.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/machinecore_internal.h"

#include <algorithm>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::notNow;
using detail::refusal;

MachineState &ToolLift::state()
{
    return m_host.liveState();
}

std::optional<MachineError> ToolLift::lift(bool stopSpindle)
{
    const machine::MachineConfig &config = m_host.config();
    if (state().mode != MachineMode::Paused || !m_job.active())
        return notNow("Lifting the tool", state().mode);
    if (state().hold == HoldReason::PathFault)
        return refusal(DriverCode::LiftOffPath);
    const double liftMm = config.motion.toolLiftMm;
    if (liftMm <= 0)
        return refusal(DriverCode::NoLiftHeight);
    // Up is toward the upper soft limit of Z, never beyond it.
    const machine::AxisConfig &z = config.axes[2];
    const std::int64_t now_z = state().positionSteps[2];
    const std::int64_t top = m_host.stepsFromMm(2, z.softMaxMm);
    m_liftSteps = std::min(m_host.stepsFromMm(2, liftMm), std::max<std::int64_t>(0, top - now_z));
    if (m_liftSteps == 0)
        return refusal(DriverCode::LiftAtLimit);
    m_spindleStopped = stopSpindle && state().spindlePermille > 0;
    const int permille = state().spindlePermille;
    m_liftSpindle = permille;
    m_active = true;
    m_host.setMode(MachineMode::Stopping);
    m_host.send(cmd::statusRead(4), [this](const Outcome &o) {
        if (o.status == OutcomeStatus::Ok && o.reply.ok())
            state().interruptInputs = (state().interruptInputs & 0xFF00) | *o.reply.hexValue();
    });
    m_host.send(cmd::keep(), [this](const Outcome &o) {
        if (m_host.unitError(o, "keeping the queue (K)", MachineMode::Alarm))
            return;
        m_kept = true;
    });
    if (m_spindleStopped)
        m_host.send(cmd::spindle(0), [this](const Outcome &o) {
            if (!m_host.unitError(o, "stopping the spindle", MachineMode::Alarm))
                state().spindlePermille = 0;
        });
    const int axes = state().axisCount;
    const Command up = axes == 4 ? cmd::line(0, 0, m_liftSteps, 0) : cmd::line(0, 0, m_liftSteps);
    m_host.send(up, [this](const Outcome &o) {
        if (m_host.unitError(o, "lifting the tool", MachineMode::Alarm))
            return;
        m_host.afterIdle([this] {
            detail::setHold(state(), HoldReason::User, {DriverCode::HoldToolLifted},
                            state().holdLine);
            m_host.setMode(MachineMode::ToolLifted);
        });
    });
    return std::nullopt;
}

std::optional<MachineError> ToolLift::lower(int speedPulsesPerS)
{
    const machine::MachineConfig &config = m_host.config();
    if (state().mode != MachineMode::ToolLifted)
        return notNow("Lowering the tool", state().mode);
    if (speedPulsesPerS > 0) {
        if (auto bad = validate(cmd::speed(speedPulsesPerS), config.unit.variant,
                                config.unit.maxPulseRate))
            return refusal(DriverCode::SpeedInvalid, {bad.message});
    }
    m_host.setMode(MachineMode::Stopping);
    if (m_spindleStopped) {
        m_host.send(cmd::spindle(m_liftSpindle), [this](const Outcome &o) {
            if (!m_host.unitError(o, "starting the spindle", MachineMode::Alarm))
                state().spindlePermille = m_liftSpindle;
        });
    }
    const int axes = state().axisCount;
    const Command down =
        axes == 4 ? cmd::line(0, 0, -m_liftSteps, 0) : cmd::line(0, 0, -m_liftSteps);
    m_host.send(down, [this, speedPulsesPerS](const Outcome &o) {
        if (m_host.unitError(o, "lowering the tool", MachineMode::Alarm))
            return;
        m_host.afterIdle([this, speedPulsesPerS] {
            m_host.sendFront(cmd::restore(), [this, speedPulsesPerS](const Outcome &r) {
                if (m_host.unitError(r, "restoring the queue (R)", MachineMode::Alarm))
                    return;
                m_kept = false;
                if (speedPulsesPerS > 0) {
                    m_host.send(cmd::speed(speedPulsesPerS), [this](const Outcome &v) {
                        m_host.unitError(v, "setting the new speed", MachineMode::Alarm);
                    });
                    m_host.send(cmd::exchangeAll(), [this](const Outcome &x) {
                        m_host.unitError(x, "applying the new speed (XA)", MachineMode::Alarm);
                    });
                }
                m_host.send(cmd::flag(), [this](const Outcome &f) {
                    if (m_host.unitError(f, "status", MachineMode::Alarm))
                        return;
                    m_host.applyFlags(*f.reply.hexValue());
                    m_host.setHoldNeedsGo(state().inta);
                    m_active = false;
                    detail::setHold(state(), state().hold, {DriverCode::HoldToolLowered},
                                    state().holdLine);
                    m_host.setMode(MachineMode::Paused);
                });
            });
        });
    });
    return std::nullopt;
}

} // namespace frezka::driver
