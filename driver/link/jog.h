#pragma once
// Jog: the jogging activity: one axis moved by hand, within its soft limits.
//
// Contract: step() and continuous() are accepted only while the machine is Idle. What they may
// do is the soft-limit policy's (machine/softlimits.h, one place): before the axis is homed no
// limits and at most the homing speed; once homed a step that would pass a limit is refused
// and a continuous jog runs to the limit. The move goes out as V (the speed) and one L, with the
// mode Jogging until F shows the machine standing again (a step) or until stop() (continuous:
// H, then D drops the rest of the move). A refusal of the unit is an alarm and drops what is
// left.

#include "driver/link/machinestate.h"
#include "machine/softlimits.h"

#include <cstdint>
#include <optional>

namespace frezka::driver {

class CoreHost;

class Jog
{
public:
    explicit Jog(CoreHost &host)
        : m_host(host)
    {}

    // Each: nullopt when accepted, else why not.
    std::optional<MachineError> step(int axis, double distanceMm, double speedMmPerMin);
    std::optional<MachineError> continuous(int axis, int direction, double speedMmPerMin);
    std::optional<MachineError> stop();

private:
    std::optional<MachineError> send(int axis, const machine::JogMove &move);
    static bool homed(const MachineState &state, int axis);

    CoreHost &m_host;
    bool m_continuous = false; // runs until stop()
};

} // namespace frezka::driver
