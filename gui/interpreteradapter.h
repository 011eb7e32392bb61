#pragma once
// The G-code interpreter step of ProgramSession: frezka::gcode::Interpreter in check mode
// (every error of the file reported, each with line, column and what to do), started from the
// persisted work offsets and the machine's position.

#include "programsession.h"

namespace frezka::gui {

InterpretFn gcodeInterpreter();

} // namespace frezka::gui
