#pragma once
// PathGuard: checks that the unit runs the path the job sent it.
//
// The protocol's checksum is a sum of the bytes mod 256, so two faults in one line can cancel
// out: a dropped '0' and a doubled '0' turn `C60,20,2` into `C6,200,2` with the same checksum,
// and the unit runs a vector nobody planned. Nothing in the protocol can catch that before the
// unit runs it, so the driver checks what the unit does:
//
// - every position poll of a running job must lie on the planned path, within one step of a
//   segment between the last verified command and the last one sent (the unit's counters step
//   along the straight line of each vector, each axis within one step of it);
// - where the machine stands (before I/O, dwells, operator stops, probes and at the end), its
//   counters must equal the planned position exactly.
//
// Contract: fault() stops the unit (H), drops its queue (D) and holds the job with the reason
// (HoldReason::PathFault); faulted() stays true, keeping the stream and the guard itself off,
// until ReturnToPath (on resume, or at once with CoreOptions::returnToPathAutomatically) has
// brought the machine back to the start of the last verified command and the job streams on
// from there, so that it ends at exactly the planned counters. A probe that stopped short
// switches the guard off for the rest of the job (the rest was planned from elsewhere). The
// geometry (the planned position, a position on a segment within a step) is machine/pathcheck.h.

#include "driver/link/returntopath.h"
#include "machine/unitprogram.h"

#include <cstddef>
#include <functional>
#include <string>

namespace frezka::driver {

class CoreHost;
class Job;

class PathGuard
{
public:
    PathGuard(CoreHost &host, Job &job);

    void reset();
    bool faulted() const { return m_pathFault; }
    void clearFault() { m_pathFault = false; }
    bool off() const { return m_off; }
    void switchOff() { m_off = true; }
    // Commands before it ran as planned (the unit was seen on the path at or after its start).
    std::size_t verified() const { return m_verified; }
    // The planned position before program command `index` (after the motion before it).
    machine::Steps4 plannedBefore(std::size_t index) const;
    // Whether the polled position lies on the planned path between the last verified command
    // and the last one sent; moves verified() to the first segment that holds it.
    bool onPlannedPath();
    // The machine stands before command `index`: its counters must be exactly where the plan
    // has it. Then `then`; otherwise the fault.
    void checkAtRest(std::size_t index, std::function<void()> then);
    void fault(const std::string &why);
    void returnToPath() { m_return.start(1); }

private:
    void holdOrReturn();

    CoreHost &m_host;
    Job &m_job;
    ReturnToPath m_return;
    std::size_t m_verified = 0;
    bool m_pathFault = false; // stopping, held, or returning
    bool m_off = false;       // a probe stopped short: the rest was planned from elsewhere
    std::string m_faultText;
};

} // namespace frezka::driver
