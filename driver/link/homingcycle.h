#pragma once
// HomingCycle: the homing activity: the switch of each axis sought in short legs of W, in the
// profile's order, then the counters.
//
// Contract: start() is accepted only while the machine is Idle or in Alarm, for the axes of
// axisMask that the profile homes (machine::homingSequence gives the moves). It clears those
// axes' homed bits and sets the mode Homing. The unit answers W only when the W has ended, and
// answers nothing else meanwhile (the link is half-duplex, docs/gve-protocol.md §2, §6), so one
// long W would freeze the position display and leave nothing able to stop it. The search is
// therefore sent in legs of at most kLegS of travel each: W with the leg's length; code 5 at
// the leg's end means "not here yet", and after each leg the position and F are read (the
// display follows the axis) and the next leg goes out, until the switch is found (code 0: the
// unit has backed off it) or the profile's travel is used up (alarm: switch not found). Then
// the counter is set to the axis's home position (N<axis>); a firmware before v19 knows only
// N, which zeroes every counter, so there every axis must be homed together to 0 and one N
// follows the last W. stop() (the operator's Stop, Abort, Esc) is accepted at any moment of
// the cycle: no further leg is sent, the axis stops at the end of the leg running (at most
// kLegS later), stays not homed with every axis after it, and the mode is Idle. A leg that ends
// short of its length (an input interrupt, a switch that does not release within the back-off)
// or any refusal is an alarm.

#include "driver/link/machinestate.h"
#include "machine/homing.h"

#include <optional>
#include <vector>

namespace frezka::driver {

class CoreHost;

class HomingCycle
{
public:
    // Longest leg of the switch search, seconds of travel at the homing speed.
    static constexpr double kLegS = 0.25;

    explicit HomingCycle(CoreHost &host)
        : m_host(host)
    {}

    // nullopt when accepted (then *queued says whether anything went on the wire: a W the
    // variant refuses is reported as an alarm at once), else why not.
    std::optional<MachineError> start(unsigned axisMask, bool *queued);
    // The operator's stop: nullopt when homing was running (it ends after the current leg).
    std::optional<MachineError> stop();
    // Homing runs now (the mode is Homing and the cycle has not ended).
    bool active() const;

    // Steps of one leg toward the switch at `pulsesPerS` (at least 1).
    static std::int64_t legSteps(std::int64_t pulsesPerS);

private:
    struct Plan
    {
        std::vector<machine::HomingMove> moves;
        unsigned homedByProfile = 0; // the axes the profile homes
        unsigned homing = 0;         // the axes homed now
        bool zeroAll = false;        // one N after the last W (firmware before v19)
    };
    std::optional<MachineError> plan(unsigned axisMask, Plan &p) const;
    bool validMoves() const;
    void nextLeg();
    void legEnded(const machine::HomingMove &m, std::int64_t leg, std::int64_t from,
                  const Outcome &o);
    void axisHomed(const machine::HomingMove &m);
    void finish();
    void alarm(const DriverMessage &message, const Outcome *o);

    CoreHost &m_host;
    Plan m_plan;
    std::size_t m_axis = 0;    // index into m_plan.moves of the axis being homed
    std::int64_t m_sought = 0; // steps of its search travel used so far
    bool m_active = false;
    bool m_stopRequested = false;
};

} // namespace frezka::driver
