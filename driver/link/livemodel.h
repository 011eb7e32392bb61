#pragma once
// LiveModel: where the unit is between position polls, from the driver's model of it (issue 16
// item 3; a part of MachineCore).
//
// Where the wire is the bottleneck a poll comes every few seconds (docs/benchmarks.md), so the
// polled counters alone leave the DRO, the tool marker and the line frozen on the dense jobs an
// operator watches most. While a job runs, every kIntervalS of the core's clock this model places
// the unit on the plan: from the command the last poll found executing (JobCursor::exec, which
// began at execAt), the unit model's time of each command (JobPace, machine/unitmodel.h, the
// planner's own and exact for the unit while its queue does not run dry) at the feed override the
// unit runs, interpolated along the vector by its share of time. It never passes the end of the
// last command the unit accepted (JobCursor::next), and each poll corrects it (the tracker moves
// the cursor). The figure goes to MachineState::live only: positionSteps / positionMm stay the
// polled counters, the only input of the path guard, the tracker and the ETA.
//
// The poll's position is the unit's at the moment it read its counters, about half a round trip
// before the reply arrived: the model counts that age in, else it would run that far behind.

#include "driver/link/machinestate.h"

#include <cstddef>
#include <optional>

namespace frezka::driver {

class CoreHost;
class Job;

class LiveModel
{
public:
    static constexpr double kIntervalS = 0.04; // 25 Hz: the issue asks for at least 20

    LiveModel(CoreHost &host, Job &job)
        : m_host(host)
        , m_job(job)
    {}

    // When the next figure is due (kNoDeadline while nothing is modelled).
    double nextTime() const;
    // At or after nextTime(): models the position now into MachineState::live.
    void update(double now);
    // A poll read the counters: live shows them (not modelled) until the next update.
    void positionRead();
    // Before each publication: a job that stopped running on its plan shows the counters at once.
    void settle();

    // The modelled position at `now` (public for tests): nullopt when the job does not run on
    // its plan (held, lifted, off the path, checking its progress, probing).
    std::optional<LivePosition> at(double now) const;

private:
    bool modelling() const;

    CoreHost &m_host;
    Job &m_job;
    double m_next = 0;
};

} // namespace frezka::driver
