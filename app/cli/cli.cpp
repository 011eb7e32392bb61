#include "cli.h"

#include <QCoreApplication>

#include <cstdio>

namespace frezka::cli {

std::map<std::string, Command> &commands()
{
    static std::map<std::string, Command> table;
    return table;
}

bool registerCommand(const std::string &name, Command command)
{
    return commands().emplace(name, std::move(command)).second;
}

void out(const QString &text)
{
    const QByteArray bytes = text.toUtf8();
    std::fwrite(bytes.constData(), 1, static_cast<std::size_t>(bytes.size()), stdout);
    std::fflush(stdout);
}

void err(const QString &text)
{
    const QByteArray bytes = text.toUtf8();
    std::fwrite(bytes.constData(), 1, static_cast<std::size_t>(bytes.size()), stderr);
    std::fflush(stderr);
}

QString planMessage(const QString &file, const machine::PlanError &error, const QString &kind)
{
    std::string what = error.message;
    const std::string prefix = "line " + std::to_string(error.line) + ": ";
    if (what.rfind(prefix, 0) == 0)
        what.erase(0, prefix.size());
    return file + QLatin1Char(':') + QString::number(error.line) + QStringLiteral(": ") + kind +
           QString::fromStdString(what) + QLatin1Char('\n');
}

void printGcodeWarnings(const QString &file, const gcode::Result &result)
{
    for (const gcode::Error &w : result.warnings)
        err(gcode::formatError(file, w) + QLatin1Char('\n'));
    if (result.warningsNotShown > 0) {
        err(QCoreApplication::translate("frezka::gcode", "%1: %n more warning(s) not shown", "",
                                        static_cast<int>(result.warningsNotShown))
                .arg(file) +
            QLatin1Char('\n'));
    }
}

void printConfigNotes(const machine::ConfigResult &result)
{
    const QString note = QCoreApplication::translate("frezka::cli", "note: ");
    for (const machine::ConfigError &n : result.notes)
        err(note + QString::fromStdString(n.message) + QLatin1Char('\n'));
}

} // namespace frezka::cli
