#pragma once
// ToolLift: lifting the tool out of a held job and lowering it back (KEEP / RESTORE).
//
// Contract: lift() is accepted only while a job is held (Paused) with the unit's queue intact
// (not after a path fault, whose queue was dropped). It reads the interrupt cause (ST4), keeps
// the unit's queue (K), optionally stops the spindle, and lifts Z by the profile's toolLiftMm,
// never beyond Z's upper soft limit (L); once the machine stands the mode is ToolLifted.
// lower() restarts the spindle if lift() stopped it, moves Z back down by exactly the lift,
// restores the queue (R), optionally sets a new speed (V + XA), reads F and leaves the job
// Paused, to be resumed with G. active() from the accepted lift() to the end of lower(): the
// core's activity is ToolLift meanwhile; kept() while the unit holds the job's queue aside, when
// neither the job's idle waits nor the path guard's polls apply.

#include "driver/link/machinestate.h"

#include <cstdint>
#include <optional>

namespace frezka::driver {

class CoreHost;
class Job;

class ToolLift
{
public:
    ToolLift(CoreHost &host, const Job &job)
        : m_host(host)
        , m_job(job)
    {}

    // nullopt when accepted, else why not.
    std::optional<MachineError> lift(bool stopSpindle);
    std::optional<MachineError> lower(int speedPulsesPerS);
    bool active() const { return m_active; }
    bool kept() const { return m_kept; }
    void reset() { m_active = false; } // a new job

private:
    MachineState &state();

    CoreHost &m_host;
    const Job &m_job;
    std::int64_t m_liftSteps = 0;
    bool m_spindleStopped = false;
    int m_liftSpindle = 0;
    bool m_kept = false;
    bool m_active = false;
};

} // namespace frezka::driver
