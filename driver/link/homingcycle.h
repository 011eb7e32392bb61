#pragma once
// HomingCycle: the homing activity: W per axis in the profile's order, then the counters.
//
// Contract: start() is accepted only while the machine is Idle or in Alarm, for the axes of
// axisMask that the profile homes (machine::homingSequence gives the moves). It clears those
// axes' homed bits, sets the mode Homing and queues, per axis, W (switch search, back-off) and
// the counter set to the axis's home position (N<axis>); a firmware before v19 knows only N,
// which zeroes every counter, so there every axis must be homed together to 0 and one N follows
// the last W. A W that finds no switch within its travel (code 5) or any refusal drops the rest
// and is an alarm. At the end the position and F are read, MachineState::homed says whether
// every axis the profile homes is homed, and the mode is Idle again. No fields: the cycle lives
// in the queued steps.

#include "driver/link/machinestate.h"
#include "machine/homing.h"

#include <optional>
#include <vector>

namespace frezka::driver {

class CoreHost;

class HomingCycle
{
public:
    explicit HomingCycle(CoreHost &host)
        : m_host(host)
    {}

    // nullopt when accepted (then *queued says whether anything went on the wire: a W the
    // variant refuses is reported as an alarm at once), else why not.
    std::optional<MachineError> start(unsigned axisMask, bool *queued);

private:
    struct Plan
    {
        std::vector<machine::HomingMove> moves;
        unsigned homedByProfile = 0; // the axes the profile homes
        unsigned homing = 0;         // the axes homed now
        bool zeroAll = false;        // one N after the last W (firmware before v19)
    };
    std::optional<MachineError> plan(unsigned axisMask, Plan &p) const;
    bool queueAxis(const machine::HomingMove &m, bool zeroAll);

    CoreHost &m_host;
};

} // namespace frezka::driver
