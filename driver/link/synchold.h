#pragma once
// SyncHold: the job waits at the sync points of its program (machine/rotarysplit.h) until every
// unit of the line has reached the same one, so that a block runs on several units together.
//
// Contract: before the job sends the command at a sync point the unit has run everything
// before it (a WaitIdle or the job's start precedes every sync point). When the unit's block
// there moves it (SyncPoint::held), the job sends H first: the standing unit sets INTA and
// queues the block without running it; the job streams the block in full packets until it is
// all queued (the next command rests) or the queue is full. Then the unit is ready: onReady
// tells the line's coordinator (LineSync), and the job sends nothing more until release()
// comes for this sync point. Released, a held unit has its interrupt causes read (ST4/ST5: an
// input that fired meanwhile holds the job, as LeadInHold does) and G starts the block; a unit
// that only waited goes on at once. The G's of all units follow each other on the line (each
// a round robin turn of SharedLine), so the block starts on them within an exchange or two.
// A pause, an abort or a lost link takes the hold over, as for LeadInHold.

#include <cstddef>
#include <functional>
#include <vector>

#include "machine/rotarysplit.h"

namespace frezka::driver {

class CoreHost;
class Job;

class SyncHold
{
public:
    SyncHold(CoreHost &host, Job &job)
        : m_host(host)
        , m_job(job)
    {}

    // The sync points of the next job (taken by begin(); a job started without them has none).
    void setPoints(std::vector<machine::SyncPoint> points) { m_pending = std::move(points); }
    void begin(); // the job starts
    void reset(); // the job ended or the link was lost: the points left are dropped
    // Before the job sends the command at its cursor: true when the hold took the step.
    bool step(double now);
    // Every unit has reached sync point `index` (0-based, in the program's order).
    void release(std::size_t index);
    // The unit stands held (H) with its block being queued (valid while true: start()).
    bool held() const { return m_state == State::Held || m_state == State::Ready; }
    bool busy() const { return m_state != State::Off; }
    std::size_t start() const { return m_start; }
    std::size_t reached() const { return m_next; } // sync points passed

    std::function<void(std::size_t index, double now)> onReady;

private:
    enum class State { Off, Halting, Held, Ready, Waiting, Releasing };
    bool fed() const;
    void ready(double now);
    void readCause(int n);
    void go();
    void passed();

    CoreHost &m_host;
    Job &m_job;
    std::vector<machine::SyncPoint> m_pending;
    std::vector<machine::SyncPoint> m_points;
    std::size_t m_next = 0;     // the sync point the job is at or before
    std::size_t m_released = 0; // sync points released by the coordinator
    State m_state = State::Off;
    std::size_t m_start = 0;
};

} // namespace frezka::driver
