// LeadInHold: the unit held at a chain's start until the wire can feed it. See leadinhold.h.

#include "leadinhold.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/machinecore_internal.h"

#include <string>

namespace frezka::driver {

using namespace frezka::protocol;

namespace {
constexpr std::size_t kNone = static_cast<std::size_t>(-1);
} // namespace

void LeadInHold::reset()
{
    if (m_state == State::Halting)
        m_host.setHaltExpected(false);
    m_state = State::Off;
    m_decided = kNone;
    m_afterDamage = false;
}

bool LeadInHold::step(double now)
{
    JobCursor &cursor = m_job.cursor();
    switch (m_state) {
    case State::Halting:
    case State::Releasing:
        return true;
    case State::Held:
        if (!m_host.liveState().inta) { // a pause was resumed meanwhile: its G started the chain
            m_state = State::Off;
            return false;
        }
        // The unit stands: the estimate's clock starts when it goes.
        cursor.exec = m_start;
        cursor.execAt = now;
        cursor.paceKey = kNone;
        if (!fed())
            return false;
        m_state = State::Releasing;
        readCause(4);
        return true;
    case State::Off:
        break;
    }
    const std::size_t next = cursor.next;
    const JobPace &pace = m_job.pace();
    if (next == m_decided || !m_host.options().leadInHold)
        return false;
    if (!pace.chainStartsAt(next))
        return m_job.chainDamaged() && haltBeforeDry();
    m_decided = next;
    m_job.setChainDamaged(false);
    const std::size_t firstEnd = pace.firstPacketEnd(next);
    if (pace.leadInSlackS(next, firstEnd) >= pace.leadInLink().reserveS() &&
        pace.leadInFeeds(next, firstEnd))
        return false;
    ++m_job.report().leadInHolds;
    halt(next);
    return true;
}

// In the middle of a chain after a damaged packet or a recovered reply: where the job's own
// packets from here would come after the unit began braking to rest at the end of its queue,
// and its last queued vector is too short to brake in from its V (property seeds 90 and 132),
// H now, while the queue still holds the ramp, then the lead-in hold from where the unit stands.
// Only after damage: on clean links the same play halted 58 chains of the 100 soak cases from
// seed 1 that ran on without a violation (the play sizes packets as the job would, not as it
// does), and their jobs took longer (docs/benchmarks.md, issue 12, ninth session).
bool LeadInHold::haltBeforeDry()
{
    const JobPace &pace = m_job.pace();
    // After damage the next exchange may need a recovery of its own: a lost reply costs its
    // allowance, the settle pause and the '@' and '>' (or the resend's) round trips before the
    // packets go on. The unit must hold that too (property seed 132: a packet cut short waited
    // for the unit's watchdog while its queue ran out at speed).
    const std::size_t dry = pace.dryAhead(recoveryS());
    if (dry == JobPace::kFeeds || pace.brakesWithin(dry))
        return false;
    // The H must reach the unit before its last queued vector begins to brake (what leadS
    // counts): then the stop, which needs at most that braking, fits in what it holds.
    const double arrives =
        m_host.link().wireTime(encode(cmd::halt(), m_host.link().checksums()).size()) +
        m_host.rttS() / 2;
    if (pace.leadS() <= arrives)
        return false; // too late to brake on the ramp: the next packet is the better chance
    m_decided = m_job.cursor().next;
    ++m_job.report().dryHolds;
    halt(pace.stopEstimate(arrives));
    m_afterDamage = true;
    return true;
}

double LeadInHold::recoveryS() const
{
    const LinkEngine &link = m_host.link();
    return link.replyAllowanceS() + link.options().settleS + 2 * m_host.rttS();
}

void LeadInHold::halt(std::size_t start)
{
    m_state = State::Halting;
    m_afterDamage = false;
    m_start = start;
    m_host.setHaltExpected(true); // its INTA is no input's interrupt
    m_host.send(cmd::halt(), [this](const Outcome &o) {
        if (m_state != State::Halting)
            return; // the job ended meanwhile
        m_host.setHaltExpected(false);
        m_state = State::Off;
        if (m_host.unitError(o, "holding the unit until the chain's start is queued (H)",
                             MachineMode::Alarm))
            return;
        m_state = State::Held;
        m_host.liveState().inta = true;
        if (m_job.verifying()) // the check began while the H was on its way
            releaseForCheck();
    });
}

void LeadInHold::releaseForCheck()
{
    // Not while the operator holds the job: the resume starts it (Hold::goOn).
    if (m_state != State::Held || m_host.liveState().mode != MachineMode::Running)
        return;
    m_host.log("starting the held chain: the job's progress is checked from where the unit "
               "stops");
    m_state = State::Releasing;
    readCause(4);
}

// The whole chain is queued, the queue is full, or the queued motion covers the wire's part.
bool LeadInHold::fed()
{
    const JobPace &pace = m_job.pace();
    const auto &cmds = m_job.program().commands;
    const std::size_t next = m_job.cursor().next;
    if (next >= cmds.size() || machine::restsAt(cmds.op(next)))
        return true;
    const std::int64_t capacity = variantInfo(m_host.config().unit.variant).queueCapacity - 1;
    if (pace.vectorsBefore(next) - pace.vectorsBefore(m_start) >= capacity)
        return true;
    // The held unit refused a vector for a full queue: nothing more fits until it runs. (Held
    // after a damaged packet, the unit may have stopped short of stopEstimate's guess, holding
    // more than the count above; waiting for room would wait for ever: a faulty link at 115 200
    // Bd, the overfeed raster, stood polling for hours.)
    if (m_job.queueFullSeen())
        return true;
    // Halted after damage: the queue also covers one more recovery, or the next command after
    // the G finds the unit short of it and halts it again (property seed 81: 90 halts).
    return pace.leadInSlackS(m_start, next) >= pace.leadInLink().reserveS() &&
           pace.leadInFeeds(m_start, next, m_afterDamage ? recoveryS() : 0.0);
}

// ST4 then ST5: an enabled input that fired while the unit was held (the STOP button, a limit)
// must not be released by G, which clears the causes: the job is held as for any interrupt.
void LeadInHold::readCause(int n)
{
    m_host.send(cmd::statusRead(n), [this, n](const Outcome &o) {
        if (m_state != State::Releasing)
            return;
        m_state = State::Off;
        if (m_host.unitError(o,
                             "reading the interrupt causes before a held chain starts (SR" +
                                 std::to_string(n) + ")",
                             MachineMode::Alarm))
            return;
        if (o.reply.hexValue().value_or(0) != 0) {
            // Taken for an interrupt at this very reply (it carries INTA): Hold::interrupted.
            m_host.liveState().inta = false;
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

void LeadInHold::go()
{
    m_host.send(cmd::go(), [this](const Outcome &o) {
        if (m_state != State::Releasing)
            return;
        m_state = State::Off;
        const bool nothing =
            o.status == OutcomeStatus::Ok && o.reply.code == ReplyCode::NothingToContinue;
        if (!nothing && m_host.unitError(o, "starting the held chain (G)", MachineMode::Alarm))
            return;
        m_host.liveState().inta = false;
        JobCursor &cursor = m_job.cursor();
        cursor.exec = m_start;
        cursor.execAt = m_host.now() - m_host.rttS() / 2;
        cursor.paceKey = kNone;
    });
}

} // namespace frezka::driver
