#pragma once
// checkProgram: whether a unit program can run on the connected unit from where the machine is.
//
// Refuses (returns the error, the program's commands untouched) a program for another number of
// axes than the unit has, one planned from another position than the counters show, one in VK
// for a firmware without speed modes, and one with a command the variant refuses (the error then
// names the command). For a firmware without speed modes it drops the VN commands (it always
// runs as VN) and says so in *note. Pure: no I/O, no state.

#include "driver/link/machinestate.h"
#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <optional>
#include <string>

namespace frezka::driver {

std::optional<MachineError> checkProgram(machine::UnitProgram &program, const MachineState &state,
                                         const machine::MachineConfig &config, std::string *note);

} // namespace frezka::driver
