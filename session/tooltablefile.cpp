#include "tooltablefile.h"

#include <QFileInfo>

namespace frezka::session {

ToolTableFile readProfileToolTable(const machine::MachineConfig &config, const QString &profilePath)
{
    ToolTableFile out;
    out.path = QString::fromStdString(machine::toolTablePath(config, profilePath.toStdString()));
    if (out.path.isEmpty() || !QFileInfo::exists(out.path))
        return out;
    gcode::ToolTable table;
    gcode::Error error;
    if (!gcode::readToolTableFile(out.path.toStdString(), &table, &error, false)) {
        out.error = gcode::formatError(out.path, error);
        return out;
    }
    out.table = std::move(table);
    return out;
}

} // namespace frezka::session
