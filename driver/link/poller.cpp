// Poller: when to poll the unit and what to read. See poller.h.

#include "poller.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/toollift.h"

#include <algorithm>

namespace frezka::driver {

using namespace frezka::protocol;

double Poller::nextTime() const
{
    switch (m_host.liveState().mode) {
    case MachineMode::Disconnected:
    case MachineMode::Connecting:
    case MachineMode::LinkLost:
        return kNoDeadline;
    default:
        break;
    }
    // Waiting for room in the unit's full queue is part of the stream: polls at the full rate
    // with F and the inputs there (three round trips, 100 ms on a GVE84 at 16 ms) held back the
    // packet the draining queue needed, and the unit ran dry.
    if (!m_job.feeding())
        return m_lastPoll + m_host.options().pollIntervalS;
    // A poll costs a round trip of the link. Plenty of motion queued and the motion ahead slower
    // than the wire: the stream has time to spare, poll at the full rate, but never take more
    // than streamPollShare of the link's time on the position read (at 9 600 Bd it takes 47 ms
    // of the 50: the stream's next commands waited behind polls until the unit ran dry; the F
    // and inputs reads come every few polls). Otherwise every round
    // trip spent on polls is missing from the stream: keep them to wireBoundPollShare of the
    // link's time (the last poll's cost over that share), at least every maxPollGapS.
    const double buffered = m_job.pace().leadS();
    const double cost = m_lastPollTransactions * m_rttS;
    if (!m_job.pace().wireBoundAhead() && buffered >= std::max(0.25, 10 * m_rttS))
        return m_lastPoll + std::max(m_host.options().pollIntervalS,
                                     m_rttS / std::max(1e-3, m_host.options().streamPollShare));
    const double share = std::max(1e-3, m_host.options().wireBoundPollShare);
    // A poll that also read F and the inputs delays the next one by its extra cost.
    return m_lastPoll +
           std::clamp(cost / share, m_host.options().pollIntervalS,
                      std::max(m_host.options().pollIntervalS, m_host.options().maxPollGapS) *
                          m_lastPollTransactions);
}

// Polls keep their schedule: one that had to wait for a packet's reply does not push the next
// one back, so the rate stays at pollIntervalS where the link has room for it. Counts the poll
// (the rate shown, the job's figures).
void Poller::schedule(double now)
{
    const double due = nextTime();
    m_lastPoll = due <= now && now - due < m_host.options().pollIntervalS ? due : now;
    m_pollTimes.push_back(now);
    while (!m_pollTimes.empty() && m_pollTimes.front() < now - 1.0)
        m_pollTimes.pop_front();
    m_host.liveState().pollHz = static_cast<double>(m_pollTimes.size());
    if (m_job.active())
        m_job.pollStarted(now);
}

void Poller::start(double now)
{
    schedule(now);
    const Command pos = m_host.positionCommand();
    // While streaming, every reply carries INTA (interrupts) and packet replies carry queue
    // full: F and the inputs are read less often there, to leave the wire to the job.
    // Where the stream is wire-bound or the unit holds little, the position alone, F every 8th
    // time and the inputs at another (a poll of position, F and inputs is three or four round
    // trips, longer than a GVE84's short queue lasts on a dense raster: two stops there).
    // Waiting for room in a full queue counts as streaming: the room comes within the poll.
    const bool stream = m_job.feeding();
    const bool lean = stream && (m_job.pace().wireBoundAhead() ||
                                 m_job.pace().leadS() < std::max(0.25, 10 * m_rttS));
    const bool flags = !stream || m_pollCount % (lean ? 8 : 4) == (lean ? 7 : 0);
    const bool inputsTurn = !lean || m_pollCount % 8 == 3;
    ++m_pollCount;
    const bool inputs =
        inputsTurn && now - m_lastInputsPoll >= (stream ? 4 * m_host.options().inputsPollIntervalS
                                                        : m_host.options().inputsPollIntervalS);
    if (inputs)
        m_lastInputsPoll = now;
    m_lastPollTransactions =
        1 + (flags ? 1 : 0) +
        (inputs ? (m_host.config().unit.variant != Variant::Gve84 ? 2 : 1) : 0);
    // Position now, F right after it, inputs after that: one poll, ahead of other steps.
    auto byte = [this](std::uint8_t &field) {
        return [this, &field](const Outcome &o) {
            if (o.status == OutcomeStatus::Ok && o.reply.ok()) {
                field = *o.reply.hexValue();
                m_host.markDirty();
            }
        };
    };
    if (inputs && m_host.config().unit.variant != Variant::Gve84)
        m_host.sendFront(cmd::input2(), byte(m_host.liveState().inputs2));
    if (inputs)
        m_host.sendFront(cmd::input1(), byte(m_host.liveState().inputs1));
    if (flags) {
        m_host.sendFront(cmd::flag(), [this](const Outcome &o) {
            if (o.status != OutcomeStatus::Ok || !o.reply.ok())
                return (void)m_host.unitError(o, "status poll", MachineMode::Alarm);
            m_host.applyFlags(*o.reply.hexValue());
        });
    }
    m_pollSentAt = now;
    m_host.start(pos, [this](const Outcome &o) {
        if (o.status != OutcomeStatus::Ok || !o.reply.ok())
            return (void)m_host.unitError(o, "position poll", MachineMode::Alarm);
        m_rttS = 0.8 * m_rttS + 0.2 * (m_host.now() - m_pollSentAt);
        m_host.applyPosition(o.reply);
        if (m_job.active())
            m_job.checkPolledPosition(m_toolLift.kept());
    });
}

} // namespace frezka::driver
