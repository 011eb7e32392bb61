#pragma once
// Hold: stopping and going on: pause, resume, abort, and the unit's input interrupts.
//
// Contract: pause() (a running job only) brakes the machine along its ramp with H, the unit
// keeping its queue (INTA set), and holds the job (Paused, HoldReason::User). An enabled input
// that fires (STOP button, limit) is seen at the next reply or F: a running job is held
// (HoldReason::Interrupt), anything else is an alarm, and ST4/ST5 name the inputs. resume()
// continues a held job (G when the unit holds, nothing when the job waited on its own, such as
// M0), returns to the path after a path fault (ReturnToPath), and is refused while the job's
// progress is being checked. abort() stops whatever moves (H), drops the unit's queue (D) and
// ends the job (unsuccessfully), except while the tool is lifted (the queue is kept aside: lower
// it first). needsGo() is the one fact this class keeps: whether the unit holds (INTA) so that
// going on needs G.

#include "driver/link/machinestate.h"

#include <optional>

namespace frezka::driver {

class CoreHost;
class Job;

class Hold
{
public:
    Hold(CoreHost &host, Job &job)
        : m_host(host)
        , m_job(job)
    {}

    // Each: nullopt when accepted, else why not.
    std::optional<MachineError> pause();
    std::optional<MachineError> resume();
    std::optional<MachineError> abort();
    // An input interrupt stopped the machine (INTA rose outside an expected stop).
    void interrupted();
    void setNeedsGo(bool on) { m_needsGo = on; }

private:
    MachineState &state();

    CoreHost &m_host;
    Job &m_job;
    bool m_needsGo = false; // the unit holds (INTA set by H or an interrupt): resume with G
};

} // namespace frezka::driver
