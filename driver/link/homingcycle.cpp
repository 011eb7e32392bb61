// HomingCycle: W per axis, then the counters. See homingcycle.h.

#include "homingcycle.h"

#include "driver/link/corehost.h"
#include "driver/link/machinecore_internal.h"

#include <algorithm>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::notNow;
using detail::refusal;

std::optional<MachineError> HomingCycle::plan(unsigned axisMask, Plan &p) const
{
    const MachineState &state = m_host.liveState();
    const machine::MachineConfig &config = m_host.config();
    if (!state.features.switchHoming)
        return refusal(DriverCode::HomingNeedsFirmware, {std::to_string(state.firmwareVersion)});
    const std::vector<machine::HomingMove> all = machine::homingSequence(config);
    for (const auto &m : all) {
        const int a = static_cast<int>(m.axis);
        if (a >= state.axisCount)
            continue;
        p.homedByProfile |= 1u << a;
        if (axisMask & (1u << a))
            p.moves.push_back(m);
    }
    if (p.moves.empty()) {
        return refusal(all.empty() ? DriverCode::NoHomedAxis : DriverCode::AxisNotHomed);
    }
    for (const auto &m : p.moves)
        p.homing |= 1u << static_cast<int>(m.axis);
    // Before v19 a GVE64 cannot set one axis's counter (N<axis>): only N, which zeroes them all,
    // and only when every axis is homed to 0 together.
    p.zeroAll = !state.features.vlVkXmNa;
    if (p.zeroAll) {
        unsigned every = 0; // the axes the machine has (an absent one's counter means nothing)
        for (int a = 0; a < state.axisCount; ++a)
            every |= config.axes[static_cast<std::size_t>(a)].present ? 1u << a : 0u;
        const bool allZero =
            std::all_of(p.moves.begin(), p.moves.end(),
                        [](const machine::HomingMove &m) { return m.homeSteps == 0; });
        if (p.homing != every || !allZero)
            return refusal(DriverCode::HomeAllTogether, {std::to_string(state.firmwareVersion)});
    }
    return std::nullopt;
}

std::optional<MachineError> HomingCycle::start(unsigned axisMask, bool *queued)
{
    *queued = false;
    MachineState &state = m_host.liveState();
    if (state.mode != MachineMode::Idle && state.mode != MachineMode::Alarm)
        return notNow("Homing", state.mode);
    Plan p;
    if (auto refused = plan(axisMask, p))
        return refused;
    state.homedAxes = static_cast<std::uint8_t>(state.homedAxes & ~p.homing);
    state.homed = false;
    m_host.setMode(MachineMode::Homing);
    for (const auto &m : p.moves) {
        if (!queueAxis(m, p.zeroAll))
            return std::nullopt;
    }
    if (p.zeroAll) {
        m_host.send(cmd::zeroAll(), [this, homing = p.homing](const Outcome &o) {
            if (m_host.unitError(o, "zeroing the counters (N)", MachineMode::Alarm)) {
                m_host.clearSteps();
                return;
            }
            MachineState &s = m_host.liveState();
            s.homedAxes = static_cast<std::uint8_t>(s.homedAxes | homing);
        });
    }
    m_host.readPositionAndStatus(nullptr);
    m_host.send(cmd::flag(), [this, homedByProfile = p.homedByProfile](const Outcome &o) {
        if (m_host.unitError(o, "status", MachineMode::Alarm))
            return;
        MachineState &s = m_host.liveState();
        s.homed = (s.homedAxes & homedByProfile) == homedByProfile;
        m_host.setMode(MachineMode::Idle);
    });
    *queued = true;
    return std::nullopt;
}

// W for one axis, then (unless one N follows the last) its counter. False when the variant
// refuses the W: then nothing stays queued and the alarm is reported.
bool HomingCycle::queueAxis(const machine::HomingMove &m, bool zeroAll)
{
    const machine::MachineConfig &config = m_host.config();
    const auto axis = static_cast<Axis>(m.axis);
    const Command w =
        cmd::home(axis, m.travelSteps, m.towardPulsesPerS, m.backOffSteps, m.offPulsesPerS);
    if (auto bad = validate(w, config.unit.variant, config.unit.maxPulseRate)) {
        m_host.clearSteps();
        m_host.fail({DriverCode::HomingInvalid, {std::string(1, axisLetter(axis)), bad.message}},
                    nullptr, MachineMode::Alarm);
        return false;
    }
    m_host.send(w, [this, axis](const Outcome &o) {
        if (o.status == OutcomeStatus::Ok && o.reply.code == ReplyCode::OutOfRange) {
            m_host.clearSteps();
            m_host.fail({DriverCode::HomeSwitchNotFound, {std::string(1, axisLetter(axis))}}, &o,
                        MachineMode::Alarm);
            return;
        }
        if (m_host.unitError(o, std::string("homing axis ") + axisLetter(axis), MachineMode::Alarm))
            m_host.clearSteps();
    });
    if (zeroAll)
        return true; // N after the last axis
    m_host.send(cmd::setCounter(axis, m.homeSteps), [this, axis](const Outcome &o) {
        if (m_host.unitError(o, std::string("setting the counter of ") + axisLetter(axis),
                             MachineMode::Alarm)) {
            m_host.clearSteps();
            return;
        }
        MachineState &s = m_host.liveState();
        s.homedAxes = static_cast<std::uint8_t>(s.homedAxes | (1u << static_cast<int>(axis)));
    });
    return true;
}

} // namespace frezka::driver
