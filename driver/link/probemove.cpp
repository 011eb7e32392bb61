// ProbeMove: a G38 probe move of a job. See probemove.h.

#include "probemove.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/machinecore_internal.h"
#include "gcode/toolpath.h"
#include "machine/manualmoves.h"

namespace frezka::driver {

using namespace frezka::protocol;

void ProbeMove::start(std::size_t index)
{
    const machine::UnitCommand c = m_job.program().commands[index];
    const machine::ProbeArming arming =
        machine::probeArming(m_host.config().eeprom, static_cast<gcode::ProbeKind>(c.aux));
    const bool mustTrip = arming.mustTrip;
    m_host.send(cmd::input2(), [this, index, arming](const Outcome &o) {
        if (m_host.unitError(o, "reading the probe input", MachineMode::Alarm))
            return;
        if (machine::probeAlreadyTripped(arming, *o.reply.hexValue())) {
            m_host.clearSteps();
            m_host.fail({DriverCode::ProbeAlreadyTripped,
                         {detail::lineArg(m_job.program().commands[index])}},
                        &o, MachineMode::Alarm);
            m_job.finish(false);
        }
    });
    auto armed = [this](const Outcome &o) {
        m_host.unitError(o, "arming the probe input", MachineMode::Alarm);
    };
    m_host.send(cmd::statusWrite(1, arming.interruptEnableHigh), armed);
    m_host.send(cmd::statusWrite(3, arming.polarityHigh), armed);
    m_host.send(m_job.toCommand({machine::UnitOp::Line, c.d}),
                [this, index, mustTrip](const Outcome &o) {
                    if (m_host.unitError(o, "probe move", MachineMode::Alarm))
                        return;
                    m_host.setHaltExpected(true);
                    m_host.afterStopOrInterrupt([this, index, mustTrip, serial = m_job.serial()] {
                        if (!m_job.active() || m_job.serial() != serial) {
                            disarm(); // the job aborted meanwhile: not evaluated
                            return;
                        }
                        // The unit brakes after the input fires; H answers only once it stands
                        // (two equal position reads alone can come from the last, slow steps of
                        // the ramp).
                        m_host.send(cmd::halt(), [this](const Outcome &h) {
                            m_host.unitError(h, "stopping the probe move (H)", MachineMode::Alarm);
                        });
                        m_host.whenStill([this, index, mustTrip] { end(index, mustTrip); });
                    });
                });
}

// The probe input back to the profile's interrupt mask and polarity.
void ProbeMove::disarm()
{
    const machine::EepromConfig &ee = m_host.config().eeprom;
    m_host.send(cmd::statusWrite(1, ee.interruptEnableHigh), [](const Outcome &) {});
    m_host.send(cmd::statusWrite(3, ee.polarityHigh), [this](const Outcome &o) {
        m_host.setHaltExpected(false);
        m_host.unitError(o, "disarming the probe input", MachineMode::Alarm);
    });
}

// The probe read back, the move dropped and disarmed, then the outcome (machine::probeOutcome).
void ProbeMove::end(std::size_t index, bool mustTrip)
{
    m_host.send(cmd::statusRead(5), [this](const Outcome &o) {
        if (!m_host.unitError(o, "reading the probe result", MachineMode::Alarm))
            m_host.liveState().probeTripped = (*o.reply.hexValue() & 0x80) != 0;
    });
    m_host.send(m_host.positionCommand(), [this](const Outcome &o) {
        if (!m_host.unitError(o, "reading the probe position", MachineMode::Alarm)) {
            m_host.applyPosition(o.reply);
            m_host.liveState().probeSteps = m_host.liveState().positionSteps;
        }
    });
    // D drops what is left of the probe move and clears INTA and the cause bits.
    m_host.send(cmd::deleteQueue(),
                [this](const Outcome &o) { m_host.unitError(o, "D", MachineMode::Alarm); });
    const machine::EepromConfig &ee = m_host.config().eeprom;
    m_host.send(cmd::statusWrite(1, ee.interruptEnableHigh), [](const Outcome &) {});
    m_host.send(cmd::statusWrite(3, ee.polarityHigh), [this, index, mustTrip](const Outcome &o) {
        m_host.setHaltExpected(false);
        MachineState &state = m_host.liveState();
        if (m_host.unitError(o, "disarming the probe input", MachineMode::Alarm))
            return;
        state.inta = false;
        const auto &program = m_job.program();
        const machine::UnitCommand &c = program.commands[index];
        using machine::ProbeOutcome;
        const ProbeOutcome outcome = machine::probeOutcome(program, index, state.positionSteps,
                                                           state.probeTripped, mustTrip);
        if (outcome == ProbeOutcome::NotTripped) {
            state.hold = HoldReason::ProbeFailed;
            m_host.fail({DriverCode::ProbeNotTripped, {detail::lineArg(c)}}, nullptr,
                        MachineMode::Alarm);
            m_job.finish(false);
            return;
        }
        if (outcome != ProbeOutcome::AtEnd)
            m_job.guard().switchOff(); // the rest was planned from the probe's programmed end
        if (outcome == ProbeOutcome::StoppedShortMotion) {
            m_host.fail({DriverCode::ProbeTrippedElsewhere,
                         {detail::lineArg(c), detail::stepsText(state.probeSteps, 3)}},
                        nullptr, MachineMode::Alarm);
            m_job.finish(false);
            return;
        }
        m_job.acceptUpTo(index + 1);
        m_job.setStreamBlocked(false);
    });
}

} // namespace frezka::driver
