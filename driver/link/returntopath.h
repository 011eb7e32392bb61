#pragma once
// ReturnToPath: takes the machine back to the last verified point of a job's path.
//
// Contract: start() (after PathGuard stopped the unit off the path and dropped its queue) sets
// the speed to the slowest axis's maximum feed, then moves from rest to rest with L commands:
// Z up to the tool-lift height above both ends (never beyond its upper soft limit), across to
// the start of the last verified command, Z down to it. Where the counters then equal the plan,
// everything sent from that command on is counted as not sent, the modal settings in force
// there are sent again, and the job's stream runs on from it; otherwise it tries again, and
// after three attempts it is an alarm. The mode is Running meanwhile, with the path fault kept
// so that neither the stream nor the guard act. The moves and the speed are computed in
// machine/manualmoves.h (returnToPathMoves, slowestAxisPulseRate).

#include "machine/unitprogram.h"

#include <cstddef>
#include <vector>

namespace frezka::driver {

class CoreHost;
class Job;
class PathGuard;

class ReturnToPath
{
public:
    ReturnToPath(CoreHost &host, Job &job, PathGuard &guard)
        : m_host(host)
        , m_job(job)
        , m_guard(guard)
    {}

    void start(int attempt);

private:
    std::vector<machine::Steps4> planMoves() const;
    void step(std::size_t k);
    void arrived();

    CoreHost &m_host;
    Job &m_job;
    PathGuard &m_guard;
    std::vector<machine::Steps4> m_moves; // L moves back to the path, in order
    int m_attempt = 0;
};

} // namespace frezka::driver
