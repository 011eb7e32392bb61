#pragma once
// ToolLift: lifting the tool out of a held job, moving it by hand, lowering it back (KEEP/RESTORE).
//
// Contract: lift() is accepted only while a job is held (Paused) with the unit's queue intact
// (not after a path fault, whose queue was dropped). It reads the interrupt cause (ST4), keeps
// the unit's queue (K) and lifts Z by the profile's toolLiftMm, never beyond Z's upper soft limit
// (L); once the machine stands the spindle and coolant go off (SpindleHold, whatever the
// operator's box said), the position there is the lift point, and the mode is ToolLifted. While
// lifted, jog() moves one axis by a distance within its soft limits (V, L) so that the operator
// can change, measure or inspect the tool away from the work. lower() switches the spindle and
// coolant on again as they were and waits their spin-up, then returns to the lift point exactly
// (Z up to the higher of the two, across, Z down: L from rest to rest, checked against the
// counters), sends the job's own speed settings again when a jog changed them, moves Z back down
// by exactly the lift, restores the queue (R), optionally sets a new speed (V + XA), reads F and
// leaves the job Paused, to be resumed with G. abandon() (abort) ends it where it is. active()
// from the accepted lift() to the end of lower(): the core's activity is ToolLift meanwhile;
// kept() while the unit holds the job's queue aside, when neither the job's idle waits nor the
// path guard's polls apply. The moves and their speeds are computed in machine/manualmoves.h
// (toolLiftSteps, liftedJogMove, backToLiftPoint); this class sequences them with the unit.
//
// The vendor's example switches the interrupt masks for this manual phase (!0SW0,1A !0SW1,3F,
// then !0SW0,A2 !0SW1,78). Those values are its machine's: which inputs may stop a move is this
// machine's EEPROM setting (profile eeprom.interruptEnable, 0x08/0x09), and the STOP button and
// limit switches must brake a hand move as much as a job, so the masks stay as the profile set
// them (docs/emulator.md, "Tool lift").

#include "driver/link/machinestate.h"
#include "machine/unitprogram.h"

#include <cstdint>
#include <optional>
#include <vector>

namespace frezka::driver {

class CoreHost;
class Job;
class SpindleHold;

class ToolLift
{
public:
    ToolLift(CoreHost &host, Job &job, SpindleHold &spindle)
        : m_host(host)
        , m_job(job)
        , m_spindle(spindle)
    {}

    // nullopt when accepted, else why not. stopSpindle is the operator's box; the spindle and
    // coolant go off for a lifted tool in any case.
    std::optional<MachineError> lift(bool stopSpindle);
    std::optional<MachineError> jog(int axis, double distanceMm, double speedMmPerMin);
    // speedPulsesPerS > 0: the operator's new feed, applied as the override for the rest of the
    // job.
    std::optional<MachineError> lower(int speedPulsesPerS);
    bool active() const { return m_active; }
    bool kept() const { return m_kept; }
    void reset() { m_active = false; } // a new job
    void abandon();                    // abort: whatever is under way ends here

private:
    MachineState &state();
    void lifted();
    // overridePercent > 0: the operator's new feed, as the override from here on.
    void moveBack(std::size_t k, int overridePercent);
    void down(int overridePercent);
    void restored(int overridePercent);
    int handSpeed(double mmPerMin) const; // pulses/s, at most the slowest axis's maximum

    CoreHost &m_host;
    Job &m_job;
    SpindleHold &m_spindle;
    std::int64_t m_liftSteps = 0;
    machine::Steps4 m_liftPoint{};          // where the lift ended: lowering starts from here
    std::vector<machine::Steps4> m_moves{}; // L moves back to the lift point
    bool m_jogged = false;                  // a hand move changed V: the job's is sent again
    bool m_moving = false;                  // a hand move runs
    bool m_kept = false;
    bool m_active = false;
};

} // namespace frezka::driver
