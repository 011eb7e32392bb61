#pragma once
// ProbeMove: a G38.2-.5 probe move of a job.
//
// Contract: with the machine standing at the probe command (the job checked it), start() reads
// the probe input (IN15) and refuses to move when it is already in the state the move waits for,
// arms it as an interrupt for contact (G38.2/.3) or for its loss (G38.4/.5), and sends the move
// as an L. The unit brakes when the input fires; once it stands, the counters give the trip
// point (MachineState::probeSteps, probeTripped), the rest of the move is dropped (D) and the
// input disarmed. A G38.2/.4 that did not trip fails the job (the error is reported before the
// job ends, so that a front end ending its run with the job names it). The planner planned the rest
// of the program from the probe's programmed end, so when the probe stops short the path guard is
// switched off, and when motion follows the job ends there (to be planned again from the trip
// point) rather than run displaced; otherwise the job's stream runs on. A front end that runs
// a program probing for itself (session/probefollow.h) plans each job only up to and including
// its next probe, so that nothing follows it: the job ends there (finished, the result in
// probeSteps / probeTripped) and the front end plans the rest from the trip point. A probe move
// aborted before it stops is not evaluated (no probe error after the abort): the input is disarmed
// only. The arming and the
// reading of the outcome are machine/manualmoves.h's (probeArming, probeOutcome).

#include <cstddef>

namespace frezka::driver {

class CoreHost;
class Job;

class ProbeMove
{
public:
    ProbeMove(CoreHost &host, Job &job)
        : m_host(host)
        , m_job(job)
    {}

    void start(std::size_t index);

private:
    void end(std::size_t index, bool mustTrip);
    void disarm();

    CoreHost &m_host;
    Job &m_job;
};

} // namespace frezka::driver
