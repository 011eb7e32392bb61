// HomingCycle: the switch sought in legs of W per axis, then the counters. See homingcycle.h.

#include "homingcycle.h"

#include "driver/link/corehost.h"
#include "driver/link/machinecore_internal.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

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

std::int64_t HomingCycle::legSteps(std::int64_t pulsesPerS)
{
    return std::max<std::int64_t>(1, std::llround(static_cast<double>(pulsesPerS) * kLegS));
}

// Every W the cycle may send is checked against the variant before anything moves (the legs
// differ from these only in a shorter travel).
bool HomingCycle::validMoves() const
{
    const machine::MachineConfig &config = m_host.config();
    for (const auto &m : m_plan.moves) {
        const auto axis = static_cast<Axis>(m.axis);
        const Command w =
            cmd::home(axis, m.travelSteps, m.towardPulsesPerS, m.backOffSteps, m.offPulsesPerS);
        if (auto bad = validate(w, config.unit.variant, config.unit.maxPulseRate)) {
            m_host.clearSteps();
            m_host.fail({DriverCode::HomingInvalid,
                         {std::string(1, axisLetter(axis))},
                         commandCheckMessage(bad)},
                        nullptr, MachineMode::Alarm);
            return false;
        }
    }
    return true;
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
    m_plan = std::move(p);
    m_axis = 0;
    m_sought = 0;
    m_stopRequested = false;
    m_active = false;
    if (!validMoves())
        return std::nullopt;
    m_active = true;
    // Where the first leg starts from (each leg's length is checked against the counter).
    m_host.readPositionAndStatus([this] { nextLeg(); });
    *queued = true;
    return std::nullopt;
}

bool HomingCycle::active() const
{
    return m_active && m_host.liveState().mode == MachineMode::Homing;
}

std::optional<MachineError> HomingCycle::stop()
{
    const MachineState &state = m_host.liveState();
    if (!active())
        return notNow("Stopping homing", state.mode);
    m_stopRequested = true;
    m_host.log("homing: stop requested, the axis stops at the end of its current leg");
    return std::nullopt;
}

void HomingCycle::alarm(const DriverMessage &message, const Outcome *o)
{
    m_active = false;
    m_host.clearSteps();
    m_host.fail(message, o, MachineMode::Alarm);
}

// The next leg of the axis being sought, the next axis, or the end.
void HomingCycle::nextLeg()
{
    if (!m_active || m_host.liveState().mode != MachineMode::Homing)
        return;
    if (m_stopRequested) {
        m_active = false;
        m_host.log("homing stopped by the operator: the axes not homed yet stay not homed");
        m_host.setMode(MachineMode::Idle);
        return;
    }
    if (m_axis >= m_plan.moves.size()) {
        finish();
        return;
    }
    const machine::HomingMove &m = m_plan.moves[m_axis];
    const auto axis = static_cast<Axis>(m.axis);
    const std::int64_t travel = std::llabs(m.travelSteps);
    const std::int64_t leg = std::min(travel - m_sought, legSteps(m.towardPulsesPerS));
    const std::int64_t sign = m.travelSteps < 0 ? -1 : 1;
    const std::int64_t from = m_host.liveState().positionSteps[static_cast<std::size_t>(m.axis)];
    const Command w =
        cmd::home(axis, sign * leg, m.towardPulsesPerS, m.backOffSteps, m.offPulsesPerS);
    m_host.send(w, [this, m, leg, from](const Outcome &o) { legEnded(m, leg, from, o); });
}

void HomingCycle::legEnded(const machine::HomingMove &m, std::int64_t leg, std::int64_t from,
                           const Outcome &o)
{
    const auto axis = static_cast<Axis>(m.axis);
    const std::string name = std::string("homing axis ") + axisLetter(axis);
    if (o.status == OutcomeStatus::Ok && o.reply.code == ReplyCode::Ok) {
        axisHomed(m);
        return;
    }
    if (o.status != OutcomeStatus::Ok || o.reply.code != ReplyCode::OutOfRange) {
        m_active = false;
        if (m_host.unitError(o, name, MachineMode::Alarm))
            m_host.clearSteps();
        return;
    }
    // Code 5: the leg's travel ended without the switch - or something stopped it early.
    m_sought += leg;
    const std::int64_t sign = m.travelSteps < 0 ? -1 : 1;
    const bool inta = o.reply.inta;
    m_host.readPositionAndStatus([this, m, leg, from, sign, inta, axis, o] {
        const std::int64_t at = m_host.liveState().positionSteps[static_cast<std::size_t>(m.axis)];
        if (inta || at != from + sign * leg) {
            alarm({DriverCode::HomingLegStopped, {std::string(1, axisLetter(axis))}}, &o);
            return;
        }
        if (m_sought >= std::llabs(m.travelSteps) && !m_stopRequested) {
            alarm({DriverCode::HomeSwitchNotFound, {std::string(1, axisLetter(axis))}}, &o);
            return;
        }
        nextLeg();
    });
}

// The switch found and left: the counter set (unless one N follows the last axis).
void HomingCycle::axisHomed(const machine::HomingMove &m)
{
    const auto axis = static_cast<Axis>(m.axis);
    ++m_axis;
    m_sought = 0;
    if (m_plan.zeroAll) {
        m_host.readPositionAndStatus([this] { nextLeg(); });
        return;
    }
    m_host.send(cmd::setCounter(axis, m.homeSteps), [this, axis](const Outcome &o) {
        if (m_host.unitError(o, std::string("setting the counter of ") + axisLetter(axis),
                             MachineMode::Alarm)) {
            m_active = false;
            m_host.clearSteps();
            return;
        }
        MachineState &s = m_host.liveState();
        s.homedAxes = static_cast<std::uint8_t>(s.homedAxes | (1u << static_cast<int>(axis)));
        m_host.markDirty();
        m_host.readPositionAndStatus([this] { nextLeg(); });
    });
}

void HomingCycle::finish()
{
    if (m_plan.zeroAll) {
        m_host.send(cmd::zeroAll(), [this](const Outcome &o) {
            if (m_host.unitError(o, "zeroing the counters (N)", MachineMode::Alarm)) {
                m_active = false;
                m_host.clearSteps();
                return;
            }
            MachineState &s = m_host.liveState();
            s.homedAxes = static_cast<std::uint8_t>(s.homedAxes | m_plan.homing);
        });
    }
    m_host.readPositionAndStatus(nullptr);
    m_host.send(cmd::flag(), [this](const Outcome &o) {
        m_active = false;
        if (m_host.unitError(o, "status", MachineMode::Alarm))
            return;
        MachineState &s = m_host.liveState();
        s.homed = (s.homedAxes & m_plan.homedByProfile) == m_plan.homedByProfile;
        m_host.setMode(MachineMode::Idle);
    });
}

} // namespace frezka::driver
