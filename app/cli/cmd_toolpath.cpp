// frezka-cli toolpath FILE [--events]: the interpreted toolpath as JSON Lines on stdout
// (format in gcode/trace.h). On a G-code error nothing is written to stdout, the error goes to
// stderr as FILE:LINE:COL: message, and the exit code is 1.
#include "cli.h"

#include "gcode/interpreter.h"
#include "gcode/trace.h"

#include <QCoreApplication>

#include <cstdio>

namespace {

int usage()
{
    frezka::cli::err(
        QCoreApplication::translate("frezka::gcode", "usage: frezka-cli toolpath FILE [--events]") +
        QLatin1Char('\n'));
    return 2;
}

int runToolpath(const QStringList &args)
{
    using namespace frezka;
    QString file;
    bool events = false;
    for (const QString &a : args) {
        if (a == QLatin1String("--events"))
            events = true;
        else if (file.isEmpty() && !a.startsWith(QLatin1String("--")))
            file = a;
        else {
            return usage();
        }
    }
    if (file.isEmpty()) {
        return usage();
    }
    const gcode::Result result = gcode::interpretFile(file.toStdString());
    cli::printGcodeWarnings(file, result);
    if (!result.ok()) {
        for (const gcode::Error &e : result.errors)
            cli::err(gcode::formatError(file, e) + QLatin1Char('\n'));
        return 1;
    }
    if (!gcode::writeJsonLines(result.toolpath, stdout, events)) {
        cli::err(
            QCoreApplication::translate("frezka::gcode", "frezka-cli: cannot write the toolpath") +
            QLatin1Char('\n'));
        return 1;
    }
    return 0;
}

} // namespace

FREZKA_CLI_COMMAND(
    toolpath, "toolpath FILE [--events]",
    QT_TRANSLATE_NOOP("frezka::cli",
                      "Interpret a G-code program and print its moves as JSON Lines"),
    runToolpath);
