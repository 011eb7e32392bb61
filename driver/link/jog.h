#pragma once
// Jog: the jogging activity: one axis moved by hand, within its soft limits.
//
// Contract: step() and continuous() are accepted only while the machine is Idle and the axis
// stands within its soft limits (otherwise it must be homed first). A step moves the axis by a
// distance, a continuous jog toward its soft limit in the given direction; both are clipped to
// the limits and sent as V (the speed, at most the axis's maximum feed) and one L, with the mode
// Jogging until F shows the machine standing again (a step) or until stop() (continuous: H,
// then D drops the rest of the move). A refusal of the unit is an alarm and drops what is left.

#include "driver/link/machinestate.h"

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
    std::optional<MachineError> moveTo(int axis, std::int64_t target, double speedMmPerMin);

    CoreHost &m_host;
    bool m_continuous = false; // runs until stop()
};

} // namespace frezka::driver
