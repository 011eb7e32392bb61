// SyncHold: the job held at its sync points until every unit of the line is there. See
// synchold.h.

#include "synchold.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/machinecore_internal.h"
#include "machine/leadin.h"

#include <string>

namespace frezka::driver {

using namespace frezka::protocol;

void SyncHold::begin()
{
    reset();
    m_points = std::move(m_pending);
    m_pending.clear();
}

void SyncHold::reset()
{
    if (m_state == State::Halting)
        m_host.setHaltExpected(false);
    if (m_state == State::Ready || m_state == State::Waiting)
        m_job.setStreamBlocked(false);
    m_state = State::Off;
    m_points.clear();
    m_next = m_released = 0;
}

void SyncHold::release(std::size_t index)
{
    m_released = std::max(m_released, index + 1);
    if ((m_state == State::Ready || m_state == State::Waiting) && m_next < m_released) {
        m_job.setStreamBlocked(false);
        m_host.markDirty();
    }
}

bool SyncHold::step(double now)
{
    JobCursor &cursor = m_job.cursor();
    switch (m_state) {
    case State::Halting:
    case State::Releasing:
        return true;
    case State::Held:
        if (!m_host.liveState().inta) { // a pause was resumed meanwhile: its G started the block
            m_state = State::Off;       // the block runs alone: the others are not held up
            ready(now);
            passed();
            return false;
        }
        cursor.exec = m_start; // the unit stands: the estimate's clock starts when it goes
        cursor.execAt = now;
        cursor.paceKey = static_cast<std::size_t>(-1);
        if (!fed())
            return false;
        m_state = State::Ready;
        ready(now);
        return step(now); // released at once when the others were there first
    case State::Ready:
        if (m_next >= m_released) {
            m_job.setStreamBlocked(true);
            return true;
        }
        m_state = State::Releasing;
        readCause(4);
        return true;
    case State::Waiting:
        if (m_next >= m_released) {
            m_job.setStreamBlocked(true);
            return true;
        }
        m_state = State::Off;
        passed();
        return step(now); // another sync point at the same command
    case State::Off:
        break;
    }
    if (m_next >= m_points.size() || m_points[m_next].at != cursor.next)
        return false;
    if (!m_points[m_next].held) {
        m_state = State::Waiting;
        ready(now);
        return step(now);
    }
    m_state = State::Halting;
    m_start = cursor.next;
    m_host.setHaltExpected(true); // its INTA is no input's interrupt
    m_host.send(cmd::halt(), [this](const Outcome &o) {
        if (m_state != State::Halting)
            return; // the job ended meanwhile
        m_host.setHaltExpected(false);
        m_state = State::Off;
        if (m_host.unitError(o, "holding the unit at a sync point with the other units (H)",
                             MachineMode::Alarm))
            return;
        m_state = State::Held;
        m_host.liveState().inta = true;
    });
    return true;
}

void SyncHold::ready(double now)
{
    if (onReady)
        onReady(m_next, now); // may release this very sync point at once
}

void SyncHold::passed()
{
    ++m_next;
}

// The block is all queued (the next command rests), or the unit's queue is full.
bool SyncHold::fed() const
{
    const auto &cmds = m_job.program().commands;
    const std::size_t next = m_job.cursor().next;
    if (next >= cmds.size() || machine::restsAt(cmds.op(next)))
        return true;
    const std::int64_t capacity = variantInfo(m_host.config().unit.variant).queueCapacity - 1;
    const JobPace &pace = m_job.pace();
    return pace.vectorsBefore(next) - pace.vectorsBefore(m_start) >= capacity;
}

// ST4 then ST5 before G, which clears them: an input that fired while the unit was held holds
// the job for the operator (LeadInHold::readCause).
void SyncHold::readCause(int n)
{
    m_host.send(cmd::statusRead(n), [this, n](const Outcome &o) {
        if (m_state != State::Releasing)
            return;
        m_state = State::Off;
        if (m_host.unitError(o,
                             "reading the interrupt causes before a synchronised block starts "
                             "(SR" +
                                 std::to_string(n) + ")",
                             MachineMode::Alarm))
            return;
        if (o.reply.hexValue().value_or(0) != 0) {
            passed();
            m_host.liveState().inta = false; // taken for an interrupt at this reply
            m_host.markDirty();
            return;
        }
        m_state = State::Releasing;
        if (n == 4 && m_host.config().unit.variant != Variant::Gve84)
            readCause(5);
        else
            go();
    });
}

void SyncHold::go()
{
    m_host.send(cmd::go(), [this](const Outcome &o) {
        if (m_state != State::Releasing)
            return;
        m_state = State::Off;
        passed();
        const bool nothing =
            o.status == OutcomeStatus::Ok && o.reply.code == ReplyCode::NothingToContinue;
        if (!nothing &&
            m_host.unitError(o, "starting a synchronised block (G)", MachineMode::Alarm))
            return;
        m_host.liveState().inta = false;
        JobCursor &cursor = m_job.cursor();
        cursor.exec = m_start;
        cursor.execAt = m_host.now() - m_host.rttS() / 2;
        cursor.paceKey = static_cast<std::size_t>(-1);
    });
}

} // namespace frezka::driver
