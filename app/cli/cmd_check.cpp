// frezka-cli check FILE [--rapid MM_PER_MIN]: reports every error of a G-code program as
// FILE:LINE:COL: message (exit 1), or a summary: moves, arcs, bounds per axis in machine
// coordinates, rapid and feed length and a naive time (exit 0).
#include "cli.h"

#include "gcode/interpreter.h"
#include "gcode/trace.h"

#include <QCoreApplication>

namespace {

QString mm(double v)
{
    return QString::number(v, 'f', 4);
}

int usage()
{
    frezka::cli::err(QCoreApplication::translate(
                         "frezka::gcode", "usage: frezka-cli check FILE [--rapid MM_PER_MIN]") +
                     QLatin1Char('\n'));
    return 2;
}

int runCheck(const QStringList &args)
{
    using namespace frezka;
    QString file;
    double rapid = 3000.0;
    for (int i = 0; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--rapid") && i + 1 < args.size()) {
            bool ok = false;
            rapid = args[++i].toDouble(&ok);
            if (!ok || rapid <= 0)
                return usage();
        } else if (file.isEmpty() && !args[i].startsWith(QLatin1String("--"))) {
            file = args[i];
        } else {
            return usage();
        }
    }
    if (file.isEmpty())
        return usage();
    gcode::Options options;
    options.collectAllErrors = true;
    const gcode::Result result = gcode::interpretFile(file.toStdString(), options);
    if (!result.ok()) {
        for (const gcode::Error &e : result.errors)
            cli::err(gcode::formatError(file, e) + QLatin1Char('\n'));
        const int count = static_cast<int>(result.errors.size());
        cli::err(QCoreApplication::translate("frezka::gcode", "%1: %n error(s)", "", count)
                     .arg(file) +
                 QLatin1Char('\n'));
        return 1;
    }
    const gcode::Summary s = gcode::summarize(result.toolpath, rapid);
    QString text;
    const auto line = [&text](const QString &l) { text += l + QLatin1Char('\n'); };
    line(QCoreApplication::translate("frezka::gcode", "%1: OK, %2 lines")
             .arg(file)
             .arg(result.linesRead));
    line(QCoreApplication::translate("frezka::gcode",
                                     "moves: %1 (rapid %2, feed %3, arc %4, probe %5), dwells: %6")
             .arg(s.moves())
             .arg(s.rapids)
             .arg(s.feeds)
             .arg(s.arcs)
             .arg(s.probes)
             .arg(s.dwells));
    if (s.hasMotion) {
        line(QCoreApplication::translate(
                 "frezka::gcode",
                 "bounds (machine, mm): X %1 .. %2, Y %3 .. %4, Z %5 .. %6, A %7 .. %8")
                 .arg(mm(s.min.x), mm(s.max.x), mm(s.min.y), mm(s.max.y), mm(s.min.z), mm(s.max.z),
                      mm(s.min.a), mm(s.max.a)));
    }
    line(QCoreApplication::translate("frezka::gcode", "length: rapid %1 mm, feed %2 mm")
             .arg(mm(s.rapidLengthMm), mm(s.feedLengthMm)));
    const auto seconds = static_cast<long long>(std::llround(s.timeSeconds));
    line(QCoreApplication::translate("frezka::gcode",
                                     "naive time: %1:%2:%3 (rapid %4 mm/min, no acceleration)")
             .arg(seconds / 3600)
             .arg((seconds / 60) % 60, 2, 10, QLatin1Char('0'))
             .arg(seconds % 60, 2, 10, QLatin1Char('0'))
             .arg(rapid));
    cli::out(text);
    return 0;
}

} // namespace

FREZKA_CLI_COMMAND(check, "check FILE [--rapid MM_PER_MIN]",
                   "Check a G-code program: every error, or a summary", runCheck);
