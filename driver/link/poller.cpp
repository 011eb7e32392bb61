// Poller: when to poll the unit and what to read. See poller.h.

#include "poller.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/toollift.h"

#include <algorithm>
#include <utility>

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
    // The job waits for the unit to stand: one read after the other (standPoll).
    if (standWait())
        return m_lastPoll;
    // A chain held at its start: the unit stands, the display's position once a second.
    if (m_job.leadInHeld())
        return m_lastPoll + std::max(m_host.options().pollIntervalS, kSlowPositionGapS);
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
    if (standWait()) {
        standPoll(now);
        return;
    }
    schedule(now);
    m_standWait = false;
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
    if (inputs)
        sendInputs(true);
    if (flags)
        m_host.sendFront(cmd::flag(), [this](const Outcome &o) { onFlags(o); });
    m_pollSentAt = now;
    readPosition();
}

// While the job waits for the unit to stand, one read a turn, back to back: F, and the position
// once a second (any position read counts: the path guard reads it at every rest) and the inputs
// at the streaming interval. Those two go while the model has the unit run for longer than they
// take, so that they do not delay the F that sees the stop (seed 20: the position and both inputs
// in one wait once a second cost 90 ms each time), or, the model wrong, at twice their interval.
// At 19 200 Bd and 10 ms a rest is seen 29 ms after it on average, not 67-124 ms as with the
// position, F and the inputs read at 20 Hz (docs/benchmarks.md, issue 12, eleventh session).
void Poller::standPoll(double now)
{
    schedule(now);
    m_lastPoll = now; // back to back: the schedule is the last read
    m_lastPollTransactions = 1;
    m_pollSentAt = now;
    const double runsS = m_job.pace().bufferedS();
    const bool first = !std::exchange(m_standWait, true); // the unit has just started its last
    auto due = [&](double last, double gap, int reads) {
        return (now - last >= 2 * gap && first) ||
               (now - last >= gap && runsS > (reads + 1) * m_rttS);
    };
    if (due(m_lastPositionPoll, kSlowPositionGapS, 1)) {
        readPosition();
        return;
    }
    const bool gve84 = m_host.config().unit.variant == Variant::Gve84;
    if (due(m_lastInputsPoll, 4 * m_host.options().inputsPollIntervalS, gve84 ? 1 : 2)) {
        m_lastInputsPoll = now;
        sendInputs(false);
        return;
    }
    m_host.start(cmd::flag(), [this](const Outcome &o) { onFlags(o); });
}

// Only near the stop by the job's model: while the unit still runs for a while the polls go on at
// their rate (the path guard sees a damaged vector within a poll interval, not a second: a job
// waiting at its end for a long slow chain re-ran 7 vectors after the return, not 5).
bool Poller::standWait() const
{
    return m_host.waitingForJobStand() && m_job.pace().bufferedS() < kStandAheadS + 2 * m_rttS;
}

void Poller::readPosition()
{
    m_host.start(m_host.positionCommand(), [this](const Outcome &o) {
        if (o.status != OutcomeStatus::Ok || !o.reply.ok())
            return (void)m_host.unitError(o, "position poll", MachineMode::Alarm);
        m_rttS = 0.8 * m_rttS + 0.2 * (m_host.now() - m_pollSentAt);
        m_host.applyPosition(o.reply);
        if (m_job.active())
            m_job.checkPolledPosition(m_toolLift.kept());
    });
}

void Poller::onFlags(const Outcome &o)
{
    if (o.status != OutcomeStatus::Ok || !o.reply.ok())
        return (void)m_host.unitError(o, "status poll", MachineMode::Alarm);
    m_host.applyFlags(*o.reply.hexValue());
}

// front: ahead of the steps queued (after the poll's position read); else I1 now.
void Poller::sendInputs(bool front)
{
    auto byte = [this](std::uint8_t &field) {
        return [this, &field](const Outcome &o) {
            if (o.status == OutcomeStatus::Ok && o.reply.ok()) {
                field = *o.reply.hexValue();
                m_host.markDirty();
            }
        };
    };
    MachineState &state = m_host.liveState();
    if (m_host.config().unit.variant != Variant::Gve84)
        m_host.sendFront(cmd::input2(), byte(state.inputs2));
    if (front)
        m_host.sendFront(cmd::input1(), byte(state.inputs1));
    else
        m_host.start(cmd::input1(), byte(state.inputs1));
}

} // namespace frezka::driver
