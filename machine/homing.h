#pragma once
// Homing as the unit's W command needs it (docs/gve-protocol.md §6), from the machine profile:
// the same conversion to steps (machine/steps.h) as every position.

#include "machine/machineconfig.h"

#include <cstdint>
#include <vector>

namespace frezka::machine {

struct HomingMove
{
    Axis axis = Axis::X;
    int order = 1;                     // axes with the same order home together
    std::int64_t travelSteps = 0;      // n2: max travel toward the switch, signed (direction)
    std::int64_t towardPulsesPerS = 0; // n3
    std::int64_t backOffSteps = 0;     // n4: max travel back off the switch
    std::int64_t offPulsesPerS = 0;    // n5
    std::int64_t homeSteps = 0;        // counter value to set afterwards (NX..)
    friend bool operator==(const HomingMove &, const HomingMove &) = default;
};

// The homed axes in homing order (present axes with homing.order > 0; ties keep X, Y, Z, A
// order). Speeds are at least the unit's 10 pulses/s and at most its maximum pulse rate.
std::vector<HomingMove> homingSequence(const MachineConfig &config);

} // namespace frezka::machine
