#pragma once
// The plan errors in the user's words: a planner error (soft limits, an absent axis, no feed,
// ...) as one translated line with the file name and the source line, for the program
// session's messages and the console's manual lines.

#include "machine/planner.h"

#include <QString>

namespace frezka::session {

// "file:12: the move leaves the machine's travel ... (detail)"; no line: "file: ...".
QString planErrorText(const QString &fileName, const machine::PlanError &error);

} // namespace frezka::session
