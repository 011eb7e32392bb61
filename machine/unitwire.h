#pragma once
// A UnitCommand as the codec's typed command (protocol/command.h): one mapping for the
// plan CLI and the driver, so that only the codec formats bytes.

#include "machine/machineconfig.h"
#include "machine/unitprogram.h"
#include "protocol/command.h"

#include <optional>
#include <string>

namespace frezka::machine {

// The wire command of a unit op; nullopt for the PC-side ops (WaitIdle, Dwell, OperatorStop,
// Probe, ProgramEnd), which the driver carries out itself. L/C carry a fourth (A) component
// only when it is non-zero and the unit has four axes (axisCount 4): the A component may be
// left out (docs/gve-protocol.md §4), which saves bytes on the wire.
std::optional<protocol::Command> wireCommand(const UnitCommand &command, int axisCount);

// One line of text for a command: the wire text without checksum ("!0C697,30,0"), or for a
// PC-side op a comment starting with '#' ("# wait-idle", "# dwell 500 ms").
std::string commandText(const UnitCommand &command, int axisCount);

// The per-axis speed limits for VL (pulses/s, docs/gve-protocol.md §4): each present axis's
// maxSpeedMmPerMin in its steps, at least the unit's minimum 10 and at most its pulse rate; an
// absent axis gets the pulse rate (it never moves). With these set, an XM above 100 % never
// drives an axis over its maximum.
std::array<std::int64_t, 4> axisSpeedLimits(const MachineConfig &config);

} // namespace frezka::machine
