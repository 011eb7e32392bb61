#pragma once
// Hold: stopping and going on: pause, resume, abort, and the unit's input interrupts.
//
// Contract: pause() (a running job only) brakes the machine along its ramp with H, the unit
// keeping its queue (INTA set), and holds the job (Paused, HoldReason::User); with stopSpindle the
// spindle and coolant then go off (SpindleHold), as holdSpindle() does while the job is held. An
// enabled input that fires (STOP button, limit) is seen at the next reply or F: a running job is
// held (HoldReason::Interrupt), anything else is an alarm, and ST4/ST5 name the inputs. resume()
// continues a held job: the spindle and coolant on again as they were and their spin-up waited
// first, then G when the unit holds (nothing when the job waited on its own, such as M0); it
// returns to the path after a path fault (ReturnToPath) and is refused while the job's progress
// is being checked or the spindle is still starting. abort() stops whatever moves (H), gives a
// lifted tool's kept queue back (R) to drop it, drops the unit's queue (D), switches the spindle
// and coolant off and ends the job (unsuccessfully) where it is. needsGo() is the one fact this
// class keeps besides a resume in progress: whether the unit holds (INTA) so that going on needs G.

#include "driver/link/machinestate.h"

#include <optional>

namespace frezka::driver {

class CoreHost;
class Job;
class SpindleHold;
class ToolLift;

class Hold
{
public:
    Hold(CoreHost &host, Job &job, SpindleHold &spindle, ToolLift &lift)
        : m_host(host)
        , m_job(job)
        , m_spindle(spindle)
        , m_lift(lift)
    {}

    // Each: nullopt when accepted, else why not.
    std::optional<MachineError> pause(bool stopSpindle = false);
    std::optional<MachineError> holdSpindle(bool stop);
    std::optional<MachineError> resume();
    std::optional<MachineError> abort();
    // An input interrupt stopped the machine (INTA rose outside an expected stop).
    void interrupted();
    void setNeedsGo(bool on) { m_needsGo = on; }

private:
    MachineState &state();

    void goOn();

    CoreHost &m_host;
    Job &m_job;
    SpindleHold &m_spindle;
    ToolLift &m_lift;
    bool m_needsGo = false;  // the unit holds (INTA set by H or an interrupt): resume with G
    bool m_resuming = false; // resume() accepted, the spindle still starting
};

} // namespace frezka::driver
