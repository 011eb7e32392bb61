#pragma once
// Poller: the status polls of a connected unit: when the next one is due and what it reads.
//
// Contract: a poll reads the position (PF/P4), F (RUN, INTA, queue full) and now and then the
// inputs (I1/I2), queued ahead of every other step; nothing is polled while the link is down or
// connecting (the core also holds polls while an H or W is in flight). While a job streams,
// every poll is a round trip the stream cannot use: where the motion ahead is slower than the
// wire and the unit holds plenty of it, polls are free and run at pollIntervalS; where the wire
// is the bottleneck or the unit holds little, polls read the position only (F and the inputs
// every 8th time) and take at most wireBoundPollShare of the link's time, yet come at least
// every maxPollGapS. Polls keep their schedule: one that had to wait for a packet's reply does
// not push the next one back. Each position read of a running job goes to the path guard. The
// poller owns the schedule, the achieved rate (MachineState::pollHz) and the smoothed round
// trip of a poll, which the job's estimates use.
//
// Two phases of a job poll otherwise (issue 12, docs/planner.md §7). While the job waits for the
// unit to stand (a wait for the queue to drain, a dwell, M0, a probe, the end) and the job's model
// has the unit stop within kStandAheadS and two round trips: F alone, back to back, so that the
// stop is seen one F exchange after it whatever the link (position, F and the inputs back to back
// took 67-124 ms at 19 200-38 400 Bd, and the stop fell at a phase of that cycle that repeats with
// repeating chains); the position there once a second (the display, the path guard), the inputs at
// the streaming interval. While a chain is held at its start (INTA set, nothing runs: leadinhold.h)
// the position once a second and nothing else: the unit stands, and an input that fires is read in
// the interrupt causes before G. Limits and the probe need no poll: an enabled input interrupts the
// unit, and every reply carries INTA; the inputs are polled for the display and the START button.

#include "driver/link/linkengine.h"

#include <cstdint>
#include <deque>

namespace frezka::driver {

class CoreHost;
class Job;
class ToolLift;

class Poller
{
public:
    Poller(CoreHost &host, Job &job, const ToolLift &toolLift)
        : m_host(host)
        , m_job(job)
        , m_toolLift(toolLift)
    {}

    // When the next poll is due (kNoDeadline: none while the link is down or connecting).
    double nextTime() const;
    // Queues a poll ahead of everything and starts its position read (the link is idle).
    void start(double now);
    // Position and status were just read by someone else: the schedule starts again at `now`.
    void restartAt(double now)
    {
        m_lastPoll = now;
        m_standWait = false;
    }
    void restartCount() { m_pollCount = 0; } // a job starts: F and inputs in its rhythm
    void positionRead(double now) { m_lastPositionPoll = now; } // by anyone (the display's)
    double rttS() const { return m_rttS; }

    // The position at least this often while the job waits for the unit to stand or holds a
    // chain at its start (the operator's display), s.
    static constexpr double kSlowPositionGapS = 1.0;
    // F alone from this much motion before the stop by the job's model (and two round trips).
    static constexpr double kStandAheadS = 0.25;

private:
    void schedule(double now);  // the poll's place in the schedule, counted
    bool standWait() const;     // the job waits for the unit to stand, near the stop
    void standPoll(double now); // one read of the wait for the unit to stand
    void readPosition();        // in flight now
    void onFlags(const Outcome &o);
    void sendInputs(bool front); // I1 (and I2 but on a GVE84) ahead of other steps

    CoreHost &m_host;
    Job &m_job;
    const ToolLift &m_toolLift;
    double m_lastPoll = -1e9;
    double m_lastInputsPoll = -1e9;
    double m_lastPositionPoll = -1e9;
    bool m_standWait = false;       // standPoll's turns since the wait began
    std::deque<double> m_pollTimes; // for pollHz
    double m_rttS = 0.01;           // round trip of a poll, smoothed
    int m_lastPollTransactions = 1; // transactions of the last poll (position, F, inputs)
    double m_pollSentAt = 0;
    std::int64_t m_pollCount = 0;
};

} // namespace frezka::driver
