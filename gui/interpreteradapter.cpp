#include "interpreteradapter.h"

namespace frezka::gui {

InterpretFn gcodeInterpreter()
{
    return [](const InterpretRequest &req) { return session::interpretProgram(req); };
}

} // namespace frezka::gui
