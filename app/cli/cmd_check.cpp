// frezka-cli check FILE [--rapid MM_PER_MIN] [--machine PROFILE.json]: reports every error of a
// G-code program as FILE:LINE:COL: message (exit 1), or a summary: moves, arcs, bounds per axis
// in machine coordinates, rapid and feed length and a naive time (exit 0). With --machine the
// program is also planned for that machine: plan errors (soft limits, ...) fail the check, plan
// warnings (a feed above what the axes allow, ...) are reported as FILE:LINE: warning: ...
#include "cli.h"

#include "gcode/interpreter.h"
#include "gcode/trace.h"
#include "machine/machineconfig.h"
#include "machine/planner.h"

#include <QCoreApplication>

namespace {

QString mm(double v)
{
    return QString::number(v, 'f', 4);
}

int usage()
{
    frezka::cli::err(QCoreApplication::translate(
                         "frezka::gcode",
                         "usage: frezka-cli check FILE [--rapid MM_PER_MIN] [--machine PROFILE]") +
                     QLatin1Char('\n'));
    return 2;
}

// Plans the program for the machine profile: errors and warnings to stderr; false on errors.
bool planFor(const QString &file, const QString &machinePath, const frezka::gcode::Toolpath &path)
{
    using namespace frezka;
    const machine::ConfigResult loaded = machine::loadMachineConfig(machinePath.toStdString());
    cli::printConfigNotes(loaded);
    if (!loaded.config) {
        for (const machine::ConfigError &e : loaded.errors)
            cli::err(machinePath + QStringLiteral(": ") + QString::fromStdString(e.message) +
                     QLatin1Char('\n'));
        return false;
    }
    const machine::PlanResult plan = machine::plan(path, *loaded.config);
    const QString warning = QCoreApplication::translate("frezka::cli", "warning: ");
    for (const machine::PlanError &w : plan.warnings)
        cli::err(cli::planMessage(file, w, warning));
    for (const machine::PlanError &e : plan.errors)
        cli::err(cli::planMessage(file, e, QString()));
    return plan.ok();
}

// The summary `check` prints for a good program: lines, moves, bounds, lengths, naive time.
QString summaryText(const QString &file, const frezka::gcode::Result &result, double rapid)
{
    using namespace frezka;
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
    return text;
}

int runCheck(const QStringList &args)
{
    using namespace frezka;
    QString file, machinePath;
    double rapid = 3000.0;
    for (int i = 0; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--machine") && i + 1 < args.size()) {
            machinePath = args[++i];
        } else if (args[i] == QLatin1String("--rapid") && i + 1 < args.size()) {
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
    cli::printGcodeWarnings(file, result);
    if (!result.ok()) {
        for (const gcode::Error &e : result.errors)
            cli::err(gcode::formatError(file, e) + QLatin1Char('\n'));
        if (result.errorsNotShown > 0)
            cli::err(QCoreApplication::translate("frezka::gcode", "%1: %n more error(s) not shown",
                                                 "", static_cast<int>(result.errorsNotShown))
                         .arg(file) +
                     QLatin1Char('\n'));
        const int count = static_cast<int>(result.errors.size() + result.errorsNotShown);
        cli::err(
            QCoreApplication::translate("frezka::gcode", "%1: %n error(s)", "", count).arg(file) +
            QLatin1Char('\n'));
        return 1;
    }
    if (!machinePath.isEmpty() && !planFor(file, machinePath, result.toolpath))
        return 1;
    cli::out(summaryText(file, result, rapid));
    return 0;
}

} // namespace

FREZKA_CLI_COMMAND(check, "check FILE [--rapid MM_PER_MIN] [--machine PROFILE]",
                   "Check a G-code program: every error, or a summary", runCheck);
