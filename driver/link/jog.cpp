// Jog: one axis moved by hand within its soft limits. See jog.h.

#include "jog.h"

#include "driver/link/corehost.h"
#include "driver/link/machinecore_internal.h"
#include "machine/softlimits.h"
#include "machine/steps.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::notNow;
using detail::refusal;

// Sends what the soft-limit policy (machine/softlimits.h) made of the request: V (the speed)
// and one L, or the policy's refusal.
std::optional<MachineError> Jog::send(int axis, const machine::JogMove &m)
{
    const machine::MachineConfig &config = m_host.config();
    MachineState &state = m_host.liveState();
    const auto &ax = config.axes[static_cast<std::size_t>(axis)];
    switch (m.verdict) {
    case machine::JogVerdict::Move:
        break;
    case machine::JogVerdict::BeyondLimit:
        return refusal(
            DriverCode::JogBeyondLimits,
            {numberText(m.targetMm), numberText(ax.softMinMm), numberText(ax.softMaxMm)});
    case machine::JogVerdict::AtLimit:
        return refusal(DriverCode::JogAtLimit);
    case machine::JogVerdict::NoMove:
        return refusal(DriverCode::JogTooShort);
    }
    const std::int64_t pulses = machine::speedPulses(
        machine::pulseRateOf(m.speedMmPerMin, ax.stepsPerMm), config.unit.maxPulseRate);
    std::array<std::int64_t, 4> d{};
    d[static_cast<std::size_t>(axis)] = m.deltaSteps;
    const Command l =
        state.axisCount == 4 ? cmd::line(d[0], d[1], d[2], d[3]) : cmd::line(d[0], d[1], d[2]);
    m_host.setMode(MachineMode::Jogging);
    m_host.send(cmd::speed(pulses), [this](const Outcome &o) {
        if (m_host.unitError(o, "setting the jog speed", MachineMode::Alarm))
            m_host.clearSteps();
    });
    m_host.send(l, [this](const Outcome &o) {
        if (m_host.unitError(o, "jogging", MachineMode::Alarm)) {
            m_host.clearSteps();
            return;
        }
        m_host.afterIdle([this] {
            if (m_host.liveState().mode == MachineMode::Jogging && !m_continuous)
                m_host.setMode(MachineMode::Idle);
        });
    });
    return std::nullopt;
}

bool Jog::homed(const MachineState &state, int axis)
{
    return ((state.homedAxes >> axis) & 1) != 0;
}

std::optional<MachineError> Jog::step(int axis, double distanceMm, double speedMmPerMin)
{
    const MachineState &state = m_host.liveState();
    if (state.mode != MachineMode::Idle)
        return notNow("Jogging", state.mode);
    if (axis < 0 || axis >= state.axisCount)
        return refusal(DriverCode::NoSuchAxis);
    m_continuous = false;
    const auto from = state.positionSteps[static_cast<std::size_t>(axis)];
    return send(axis, machine::jogStep(m_host.config(), axis, from, distanceMm, speedMmPerMin,
                                       homed(state, axis)));
}

std::optional<MachineError> Jog::continuous(int axis, int direction, double speedMmPerMin)
{
    const MachineState &state = m_host.liveState();
    if (state.mode == MachineMode::ToolLifted)
        return refusal(DriverCode::ContinuousJogWhileLifted); // docs/gui.md, the tool lift
    if (state.mode != MachineMode::Idle)
        return notNow("Jogging", state.mode);
    if (axis < 0 || axis >= state.axisCount || direction == 0)
        return refusal(DriverCode::NoSuchAxisOrDirection);
    m_continuous = true;
    const auto from = state.positionSteps[static_cast<std::size_t>(axis)];
    auto r = send(axis, machine::jogContinuous(m_host.config(), axis, from, direction,
                                               speedMmPerMin, homed(state, axis)));
    if (r)
        m_continuous = false;
    return r;
}

std::optional<MachineError> Jog::stop()
{
    if (m_host.liveState().mode != MachineMode::Jogging)
        return notNow("Stopping the jog", m_host.liveState().mode);
    m_continuous = false;
    m_host.sendFront(cmd::halt(), [this](const Outcome &o) {
        m_host.unitError(o, "stopping the jog (H)", MachineMode::Alarm);
    });
    m_host.send(cmd::deleteQueue(), [this](const Outcome &o) {
        if (m_host.unitError(o, "ending the jog (D)", MachineMode::Alarm))
            return;
        m_host.liveState().inta = false;
        m_host.setMode(MachineMode::Idle);
    });
    return std::nullopt;
}

} // namespace frezka::driver
