// ToolLift: K, L up, spindle off, [hand moves], spindle on, back, L down, R, [XM] in a held
// job. See toollift.h.

#include "toollift.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/machinecore_internal.h"
#include "driver/link/spindlehold.h"
#include "machine/manualmoves.h"
#include "machine/pathcheck.h"
#include "machine/steps.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::notNow;
using detail::refusal;
using detail::stepsText;

MachineState &ToolLift::state()
{
    return m_host.liveState();
}

namespace {
Command lineFor(const machine::Steps4 &d, int axes)
{
    return axes == 4 ? cmd::line(d[0], d[1], d[2], d[3]) : cmd::line(d[0], d[1], d[2]);
}
} // namespace

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
    m_liftSteps = machine::toolLiftSteps(config, state().positionSteps[2]);
    if (m_liftSteps == 0)
        return refusal(DriverCode::LiftAtLimit);
    if (!stopSpindle && state().spindleOn)
        m_host.log("the spindle and coolant go off for the lifted tool all the same");
    m_active = true;
    m_jogged = m_moving = false;
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
    const Command up = lineFor({0, 0, m_liftSteps, 0}, state().axisCount);
    m_host.send(up, [this](const Outcome &o) {
        if (!m_active || m_host.unitError(o, "lifting the tool", MachineMode::Alarm))
            return;
        m_host.afterIdle([this] { lifted(); });
    });
    return std::nullopt;
}

// Up and standing: the spindle and coolant off, the lift point read from the counters.
void ToolLift::lifted()
{
    if (!m_active)
        return;
    m_spindle.stop("the tool is lifted");
    m_host.whenStill([this] {
        if (!m_active)
            return;
        m_liftPoint = state().positionSteps;
        detail::setHold(state(), HoldReason::User, {DriverCode::HoldToolLifted}, state().holdLine);
        m_host.setMode(MachineMode::ToolLifted);
    });
}

int ToolLift::handSpeed(double mmPerMin) const
{
    const machine::MachineConfig &config = m_host.config();
    return static_cast<int>(machine::speedPulsesAtMost(
        machine::slowestAxisPulseRate(config, m_host.liveState().axisCount, mmPerMin),
        config.unit.maxPulseRate));
}

std::optional<MachineError> ToolLift::jog(int axis, double distanceMm, double speedMmPerMin)
{
    if (state().mode != MachineMode::ToolLifted || !m_active)
        return notNow("Moving the lifted tool", state().mode);
    if (m_moving)
        return refusal(DriverCode::ToolStillMoving);
    if (axis < 0 || axis >= state().axisCount)
        return refusal(DriverCode::NoSuchAxis);
    const machine::Steps4 d = machine::liftedJogMove(
        m_host.config(), axis, state().positionSteps[static_cast<std::size_t>(axis)], distanceMm);
    if (d[static_cast<std::size_t>(axis)] == 0)
        return refusal(DriverCode::JogAtLimit);
    m_moving = m_jogged = true;
    m_host.markDirty();
    m_host.send(cmd::speed(handSpeed(speedMmPerMin)), [this](const Outcome &o) {
        m_host.unitError(o, "setting the speed of the hand move", MachineMode::Alarm);
    });
    m_host.send(lineFor(d, state().axisCount), [this](const Outcome &o) {
        if (!m_active || m_host.unitError(o, "moving the lifted tool", MachineMode::Alarm))
            return;
        m_host.afterIdle([this] {
            m_host.whenStill([this] {
                m_moving = false;
                m_host.markDirty();
            });
        });
    });
    return std::nullopt;
}

std::optional<MachineError> ToolLift::lower(int speedPulsesPerS)
{
    const machine::MachineConfig &config = m_host.config();
    if (state().mode != MachineMode::ToolLifted)
        return notNow("Lowering the tool", state().mode);
    if (m_moving)
        return refusal(DriverCode::ToolStillMoving);
    // A new feed is the feed override from here on (XM, for the rest of the job as the window
    // shows it): XA after V would change only the queued vectors, and set them all to one speed.
    int newPercent = 0;
    if (speedPulsesPerS > 0) {
        if (auto bad = validate(cmd::speed(speedPulsesPerS), config.unit.variant,
                                config.unit.maxPulseRate))
            return refusal(DriverCode::SpeedInvalid, {}, commandCheckMessage(bad));
        if (!state().features.vlVkXmNa)
            return refusal(DriverCode::NewFeedNeedsXm);
        const std::int64_t planned = m_job.pace().plannedSpeedNow();
        if (planned <= 0)
            return refusal(DriverCode::NoPlannedSpeed);
        newPercent = std::clamp(
            static_cast<int>(std::lround(100.0 * speedPulsesPerS / static_cast<double>(planned))),
            kOverrideMinPercent, kOverrideMaxPercent);
    }
    m_host.setMode(MachineMode::Stopping);
    detail::setHold(state(), state().hold, {DriverCode::HoldToolLowering}, state().holdLine);
    // The spindle at speed before anything moves toward the work again.
    m_spindle.restore([this, overridePercent = newPercent] {
        if (!m_active)
            return;
        const machine::Steps4 from = state().positionSteps;
        const machine::Steps4 &to = m_liftPoint;
        m_moves = machine::backToLiftPoint(from, to, state().axisCount);
        if (!m_moves.empty()) {
            m_host.log("back to the lift point: " + stepsText(from, state().axisCount) + " -> " +
                       stepsText(to, state().axisCount));
            m_host.send(cmd::speed(handSpeed(0)), [this](const Outcome &o) {
                m_host.unitError(o, "setting the speed back to the lift point", MachineMode::Alarm);
            });
            m_jogged = true;
        }
        moveBack(0, overridePercent);
    });
    return std::nullopt;
}

// Each L from rest to rest, then the counters must read the lift point exactly.
void ToolLift::moveBack(std::size_t k, int overridePercent)
{
    if (!m_active)
        return;
    if (k < m_moves.size()) {
        m_host.send(
            lineFor(m_moves[k], state().axisCount), [this, k, overridePercent](const Outcome &o) {
                if (!m_active ||
                    m_host.unitError(o, "moving back to the lift point", MachineMode::Alarm))
                    return;
                m_host.afterIdle([this, k, overridePercent] { moveBack(k + 1, overridePercent); });
            });
        return;
    }
    m_host.whenStill([this, overridePercent] {
        if (!m_active)
            return;
        if (!machine::sameSteps(state().positionSteps, m_liftPoint, state().axisCount)) {
            m_host.fail({DriverCode::LiftPointMissed,
                         {stepsText(state().positionSteps, state().axisCount),
                          stepsText(m_liftPoint, state().axisCount)}},
                        nullptr, MachineMode::Alarm);
            return;
        }
        if (!m_jogged) {
            down(overridePercent);
            return;
        }
        // A hand move set its own V: the job's speed settings again before its queue runs on.
        m_jogged = false;
        m_job.progress().resendModals([this, overridePercent] { down(overridePercent); });
    });
}

void ToolLift::down(int overridePercent)
{
    if (!m_active)
        return;
    const Command l = lineFor({0, 0, -m_liftSteps, 0}, state().axisCount);
    m_host.send(l, [this, overridePercent](const Outcome &o) {
        if (!m_active || m_host.unitError(o, "lowering the tool", MachineMode::Alarm))
            return;
        m_host.afterIdle([this, overridePercent] {
            if (!m_active)
                return;
            m_host.sendFront(cmd::restore(), [this, overridePercent](const Outcome &r) {
                if (m_host.unitError(r, "restoring the queue (R)", MachineMode::Alarm))
                    return;
                m_kept = false;
                restored(overridePercent);
            });
        });
    });
}

void ToolLift::restored(int overridePercent)
{
    if (overridePercent > 0) {
        state().overridePercent = overridePercent;
        m_job.feedOverride().follow(true); // XM, within what the link can feed
        m_host.markDirty();
    }
    m_host.send(cmd::flag(), [this](const Outcome &f) {
        if (m_host.unitError(f, "status", MachineMode::Alarm))
            return;
        m_host.applyFlags(*f.reply.hexValue());
        m_host.setHoldNeedsGo(state().inta);
        m_active = false;
        detail::setHold(state(), state().hold, {DriverCode::HoldToolLowered}, state().holdLine);
        m_host.setMode(MachineMode::Paused);
    });
}

void ToolLift::abandon()
{
    m_active = m_kept = m_moving = m_jogged = false;
    m_moves.clear();
}

} // namespace frezka::driver
