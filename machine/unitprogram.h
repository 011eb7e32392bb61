#pragma once
// UnitProgram: the planner's output and the driver's input (docs/architecture): the unit
// commands in the order they go to the unit (unitcommand.h says what each is and what the
// planner promises about them), stored compactly (unitcommands.h: 24-26 bytes a command).

#include "machine/unitcommands.h"

namespace frezka::machine {

struct UnitProgram
{
    int axisCount = 3;     // 3 or 4: how many components L/C carry on the wire
    Steps4 startSteps{};   // absolute steps the program assumes at its start
    UnitCommands commands; // reads as a std::vector<UnitCommand> of values
    friend bool operator==(const UnitProgram &, const UnitProgram &) = default;
};

} // namespace frezka::machine
