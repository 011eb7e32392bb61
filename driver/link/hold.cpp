// Hold: pause, resume, abort and input interrupts. See hold.h.

#include "hold.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/machinecore_internal.h"
#include "driver/link/spindlehold.h"
#include "driver/link/toollift.h"

namespace frezka::driver {

using namespace frezka::protocol;
using detail::notNow;
using detail::refusal;

MachineState &Hold::state()
{
    return m_host.liveState();
}

std::optional<MachineError> Hold::pause(bool stopSpindle)
{
    if (state().mode != MachineMode::Running)
        return notNow("Pause", state().mode);
    m_host.setMode(MachineMode::Stopping);
    m_host.sendFront(cmd::halt(), [this, stopSpindle](const Outcome &o) {
        if (m_host.unitError(o, "pausing (H)", MachineMode::Alarm))
            return;
        m_needsGo = true;
        state().inta = true;
        detail::setHold(state(), HoldReason::User, {DriverCode::HoldPaused}, state().sourceLine);
        m_host.setMode(MachineMode::Paused);
        if (stopSpindle)
            m_spindle.stop("pausing"); // only once the machine stands: never mid-cut
    });
    return std::nullopt;
}

std::optional<MachineError> Hold::holdSpindle(bool stop)
{
    if (state().mode != MachineMode::Paused || !m_job.active())
        return notNow(stop ? "Stopping the spindle of a held job" : "Starting the spindle again",
                      state().mode);
    if (m_resuming)
        return refusal(DriverCode::SpindleStarting);
    if (stop)
        m_spindle.stop("the operator asked while the job is held");
    else
        m_spindle.restore(nullptr);
    return std::nullopt;
}

std::optional<MachineError> Hold::resume()
{
    if (state().mode != MachineMode::Paused)
        return notNow("Resume", state().mode);
    if (m_job.verifying())
        return refusal(DriverCode::ProgressBeingChecked);
    if (m_resuming)
        return refusal(DriverCode::SpindleStarting);
    auto proceed = [this] {
        m_resuming = false;
        if (state().mode != MachineMode::Paused)
            return; // aborted meanwhile
        if (state().hold == HoldReason::PathFault && m_job.active()) {
            m_job.returnToPath();
            return;
        }
        goOn();
    };
    // The spindle (and coolant) first, at speed before the tool moves in the work again.
    m_resuming = true;
    if (m_spindle.stopped()) {
        detail::setHold(state(), state().hold, {DriverCode::HoldSpindleStarting}, state().holdLine);
        m_host.markDirty();
        m_spindle.restore(proceed);
    } else {
        m_spindle.whenAtSpeed(proceed); // at once unless a spin-up is under way
    }
    return std::nullopt;
}

void Hold::goOn()
{
    auto running = [this] {
        detail::setHold(state(), HoldReason::None, {}, 0);
        state().interruptInputs = 0;
        m_host.setMode(m_job.active() ? MachineMode::Running : MachineMode::Idle);
    };
    if (!m_needsGo) {
        running();
        return;
    }
    if (m_job.leadInHeld() && state().hold == HoldReason::User) {
        // The operator paused a unit held at a chain's start: a G now would
        // start the chain with what little is queued, which the wire cannot feed (property seed
        // 235 with its spindle on: 4 brake violations). The unit stays held (INTA); the job
        // queues the lead-in and the hold reads the causes and sends its own G.
        m_needsGo = false;
        running();
        if (m_job.verifying()) // a check waits for the unit to run dry: the hold starts it
            m_job.releaseLeadIn();
        return;
    }
    m_host.send(cmd::go(), [this, running](const Outcome &o) {
        // 6 = nothing to continue: the queue ran out while braking; the job streams on.
        if (o.status == OutcomeStatus::Ok && o.reply.code == ReplyCode::NothingToContinue) {
            m_needsGo = false;
            running();
            return;
        }
        if (m_host.unitError(o, "continuing (G)", MachineMode::Alarm))
            return;
        m_needsGo = false;
        state().inta = false;
        running();
    });
}

std::optional<MachineError> Hold::abort()
{
    switch (state().mode) {
    case MachineMode::Running:
    case MachineMode::Paused:
    case MachineMode::Stopping:
    case MachineMode::Jogging:
    case MachineMode::Alarm:
    case MachineMode::Homing:
    case MachineMode::ToolLifted:
        break;
    default:
        if (!m_job.active())
            return notNow("Abort", state().mode);
    }
    m_host.dropPending();
    const bool wasJob = m_job.active();
    const bool kept = m_lift.kept(); // the job's queue aside in the unit (K): back, then dropped
    m_job.abandon();
    m_lift.abandon();
    m_resuming = false;
    m_host.setMode(MachineMode::Stopping);
    m_host.send(cmd::halt(), [this](const Outcome &o) {
        m_host.unitError(o, "stopping (H)", MachineMode::Alarm);
    });
    if (kept) {
        m_host.send(cmd::restore(), [this](const Outcome &o) {
            m_host.unitError(o, "taking the kept queue back to drop it (R)", MachineMode::Alarm);
        });
    }
    // The spindle and coolant off once the machine stands, whatever a hold had remembered.
    m_spindle.forget();
    m_spindle.stop("aborting");
    m_spindle.forget();
    m_host.send(cmd::deleteQueue(), [this, wasJob](const Outcome &o) {
        if (m_host.unitError(o, "dropping the queue (D)", MachineMode::Alarm))
            return;
        m_needsGo = false;
        state().inta = false;
        detail::setHold(state(), HoldReason::None, {}, 0);
        // Idle with the counters where the machine stopped: a console line planned right after
        // Abort started from the last poll's position, short of it, and the path guard held it.
        m_host.readPositionAndStatus([this, wasJob] {
            m_host.setMode(MachineMode::Idle);
            if (wasJob) {
                m_job.report().endS = m_host.now();
                m_host.publish();
                m_host.jobFinished(false);
            }
        });
    });
    return std::nullopt;
}

void Hold::interrupted()
{
    const bool job = state().mode == MachineMode::Running;
    m_host.setMode(job ? MachineMode::Paused : MachineMode::Alarm);
    m_needsGo = true;
    detail::setHold(state(), HoldReason::Interrupt, {DriverCode::HoldInterrupt},
                    state().sourceLine);
    auto cause = [this](int n) {
        return [this, n](const Outcome &o) {
            if (o.status != OutcomeStatus::Ok || !o.reply.ok())
                return;
            const int bits = *o.reply.hexValue();
            state().interruptInputs = static_cast<std::uint16_t>(
                n == 4 ? (state().interruptInputs & 0xFF00) | bits
                       : (state().interruptInputs & 0x00FF) | (bits << 8));
            std::string names;
            for (int b = 0; b < 16; ++b) {
                if (state().interruptInputs & (1 << b))
                    names += (names.empty() ? "IN" : ", IN") + std::to_string(b);
            }
            detail::setHold(state(), state().hold,
                            {state().interruptInputs & 0x80 ? DriverCode::HoldStopButton
                                                            : DriverCode::HoldInput,
                             {names.empty() ? "?" : names}},
                            state().holdLine);
            m_host.markDirty();
        };
    };
    m_host.sendFront(cmd::statusRead(4), cause(4));
    if (m_host.config().unit.variant != Variant::Gve84)
        m_host.send(cmd::statusRead(5), cause(5));
}

} // namespace frezka::driver
