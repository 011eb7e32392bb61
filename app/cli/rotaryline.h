#pragma once
// frezka-cli run-line --rotary-a: one program for a machine's unit (X Y Z) and a rotary table
// on a second GVE114 on the same line (A), split at the blocks that move A into two unit
// programs with sync points (machine/rotarysplit.h).

#include "programoptions.h"

#include "machine/rotarysplit.h"

#include <QString>

#include <optional>

namespace frezka::cli {

struct RotaryLinePlan
{
    machine::MachineConfig machine; // the --machine profile, at its unit.address
    machine::MachineConfig rotary;  // the rotary unit's profile, at its address
    machine::RotarySplit split;
};

// Loads both profiles (the rotary's: `rotaryProfile`, else --machine; it must have an A axis),
// plans `file` for the machine with the rotary unit's A axis (A's soft limits, scale, speeds
// and acceleration are the rotary unit's) and splits it. nullopt with the reasons on stderr.
std::optional<RotaryLinePlan> planRotaryLine(const QString &file, const ProgramOptions &options,
                                             int rotaryAddress, const QString &rotaryProfile);

} // namespace frezka::cli
