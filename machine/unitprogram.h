#pragma once
// UnitProgram: the planner's output and the driver's input (docs/architecture): the unit
// commands in the order they go to the unit (unitcommand.h says what each is and what the
// planner promises about them), stored compactly (unitcommands.h: 24-26 bytes a command).

#include "machine/unitcommands.h"

#include <cstdint>

namespace frezka::machine {

struct UnitProgram
{
    int axisCount = 3;     // 3 or 4: how many components L/C carry on the wire
    Steps4 startSteps{};   // absolute steps the program assumes at its start
    UnitCommands commands; // reads as a std::vector<UnitCommand> of values
    friend bool operator==(const UnitProgram &, const UnitProgram &) = default;
};

// The C commands the unit starts from rest because the program drains its queue before them:
// a C after a C with a PC-side command between (a wait for the queue, a dwell, an operator
// stop, the end; UnitOp::WaitIdle and after), an L or a probe (an L on the wire) between
// leaving none. The emulator counts each of them as a starvation stop (driver/emulator/
// motion.h: it cannot tell a planned rest from a queue that ran dry), so a report of the unit
// running dry subtracts them.
inline std::int64_t plannedRestarts(const UnitProgram &program)
{
    std::int64_t n = 0;
    bool afterC = false, drained = false;
    for (const UnitCommand &c : program.commands) {
        if (c.op == UnitOp::Vector || c.op == UnitOp::Line || c.op == UnitOp::Probe) {
            n += c.op == UnitOp::Vector && afterC && drained ? 1 : 0;
            afterC = c.op == UnitOp::Vector;
            drained = false;
        } else if (c.op >= UnitOp::WaitIdle) {
            drained = true;
        }
    }
    return n;
}

} // namespace frezka::machine
