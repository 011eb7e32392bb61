#pragma once
// The machine's tool table as the program session uses it: the file the profile names
// (machine::toolTablePath), read with its errors in the user's language.

#include "gcode/tooltable.h"
#include "machine/machineconfig.h"

#include <QString>

#include <optional>

namespace frezka::session {

struct ToolTableFile
{
    QString path;                          // empty: the profile names no table
    std::optional<gcode::ToolTable> table; // nullopt: no table (no file, none named, or error)
    QString error; // "tool.tbl:3:7: ..." when the file is there but cannot be read
};

// Reads the table of a profile loaded from profilePath. A file that does not exist yet is no
// table (every tool of length 0, as without one) until the first save creates it.
ToolTableFile readProfileToolTable(const machine::MachineConfig &config,
                                   const QString &profilePath);

} // namespace frezka::session
