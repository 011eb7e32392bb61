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
    void restartAt(double now) { m_lastPoll = now; }
    void restartCount() { m_pollCount = 0; } // a job starts: F and inputs in its rhythm
    double rttS() const { return m_rttS; }

private:
    void schedule(double now); // the poll's place in the schedule, counted

    CoreHost &m_host;
    Job &m_job;
    const ToolLift &m_toolLift;
    double m_lastPoll = -1e9;
    double m_lastInputsPoll = -1e9;
    std::deque<double> m_pollTimes; // for pollHz
    double m_rttS = 0.01;           // round trip of a poll, smoothed
    int m_lastPollTransactions = 1; // transactions of the last poll (position, F, inputs)
    double m_pollSentAt = 0;
    std::int64_t m_pollCount = 0;
};

} // namespace frezka::driver
