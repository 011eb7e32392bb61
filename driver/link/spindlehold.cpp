// SpindleHold: spindle and coolant off for a hold, on again before the work. See spindlehold.h.

#include "spindlehold.h"

#include "driver/link/corehost.h"

#include <string>

namespace frezka::driver {

using namespace frezka::protocol;

std::uint8_t SpindleHold::coolantBits() const
{
    const machine::MachineConfig &c = m_host.config();
    return static_cast<std::uint8_t>(machine::outputBit(c, machine::OutputFunction::Coolant) |
                                     machine::outputBit(c, c.outputs.mist) |
                                     machine::outputBit(c, machine::OutputFunction::AirBlow));
}

std::uint8_t SpindleHold::relayBit() const
{
    const machine::MachineConfig &c = m_host.config();
    if (variantInfo(c.unit.variant).hasSpindleAddress7)
        return 0;
    return machine::outputBit(c, machine::OutputFunction::Spindle);
}

double SpindleHold::spinUpS() const
{
    const bool spindle = relayBit() ? !(m_port & relayBit()) : m_permille > 0;
    return m_stopped && spindle ? m_host.config().spindle.spinUpMs / 1000.0 : 0.0;
}

void SpindleHold::stop(const char *why)
{
    MachineState &state = m_host.liveState();
    const std::uint8_t relay = relayBit();
    const auto offPort = static_cast<std::uint8_t>(state.outputs | coolantBits() | relay |
                                                   (relay ? 0 : machine::kSpindleOutputBit));
    const bool spindleOn = relay ? !(state.outputs & relay) : state.spindlePermille > 0;
    if (!spindleOn && offPort == state.outputs)
        return; // nothing turns: nothing to stop, nothing to restore
    if (!m_stopped) {
        m_stopped = true;
        m_permille = relay ? 0 : state.spindlePermille;
        m_port = state.outputs;
    }
    state.outputsHeld = true;
    m_host.markDirty();
    const std::string what = std::string("switching the spindle and coolant off (") + why + ")";
    if (!relay && spindleOn) {
        m_host.send(cmd::spindle(0), [this, what](const Outcome &o) {
            m_host.unitError(o, what, MachineMode::Alarm);
        });
    }
    // After !7V0 the unit has OUT0 off already; coolant (and the GVE84's relay) by port 0.
    const auto afterSpindle = static_cast<std::uint8_t>(
        relay ? state.outputs : state.outputs | machine::kSpindleOutputBit);
    if (offPort != afterSpindle) {
        m_host.send(cmd::output(offPort), [this, what](const Outcome &o) {
            m_host.unitError(o, what, MachineMode::Alarm);
        });
    }
}

void SpindleHold::atOperatorStop(machine::StopReason reason)
{
    const machine::SpindleConfig &c = m_host.config().spindle;
    const bool toolChange = reason == machine::StopReason::ToolChange;
    if (toolChange ? c.stopAtToolChange : c.stopAtProgramStop)
        stop(toolChange ? "M6: tool change" : "M0/M1: program stop");
}

void SpindleHold::restore(std::function<void()> then)
{
    if (!m_stopped) {
        if (then)
            then();
        return;
    }
    const double wait = spinUpS();
    // The speed asked, at the spindle override as it is now (it may have changed meanwhile).
    const MachineState &state = m_host.liveState();
    const int permille =
        m_permille > 0 && state.spindleAskedPermille > 0
            ? spindlePermilleAt(state.spindleAskedPermille, state.spindleOverridePercent)
            : m_permille;
    const std::uint8_t port = m_port;
    m_stopped = false;
    m_starting = true;
    const std::string what = "switching the spindle and coolant on again";
    if (permille > 0) {
        m_host.send(cmd::spindle(permille), [this, what](const Outcome &o) {
            m_host.unitError(o, what, MachineMode::Alarm);
        });
    }
    const std::uint8_t now = m_host.liveState().outputs;
    const auto afterSpindle =
        static_cast<std::uint8_t>(permille > 0 ? now & ~machine::kSpindleOutputBit : now);
    if (port != afterSpindle) {
        m_host.send(cmd::output(port), [this, what](const Outcome &o) {
            m_host.unitError(o, what, MachineMode::Alarm);
        });
    }
    // The wait starts when the unit has them: after the reply of the last one (F in between).
    m_host.send(cmd::flag(), [this, wait, then = std::move(then)](const Outcome &o) mutable {
        if (m_host.unitError(o, "status", MachineMode::Alarm))
            return;
        m_host.liveState().outputsHeld = false;
        m_host.markDirty();
        if (then)
            m_waiters.insert(m_waiters.begin(), std::move(then));
        if (wait > 0) {
            m_host.log("waiting " + std::to_string(static_cast<int>(wait * 1000)) +
                       " ms for the spindle to reach its speed (spindle.spinUpMs)");
            m_host.afterDelay(wait, [this] { atSpeed(); });
        } else {
            atSpeed();
        }
    });
}

void SpindleHold::atSpeed()
{
    m_starting = false;
    auto waiters = std::move(m_waiters);
    m_waiters.clear();
    for (auto &w : waiters)
        w();
}

void SpindleHold::whenAtSpeed(std::function<void()> then)
{
    if (m_starting)
        m_waiters.push_back(std::move(then));
    else if (then)
        then();
}

void SpindleHold::forget()
{
    m_stopped = m_starting = false;
    m_waiters.clear();
    m_host.liveState().outputsHeld = false;
    m_host.markDirty();
}

} // namespace frezka::driver
