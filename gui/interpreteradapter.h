#pragma once
// The G-code interpreter step of ProgramSession: the session layer's interpretProgram() (check
// mode, every error of the file with line, column and what to do), started from the persisted
// work offsets and the machine's position.

#include "programsession.h"

namespace frezka::gui {

InterpretFn gcodeInterpreter();

} // namespace frezka::gui
