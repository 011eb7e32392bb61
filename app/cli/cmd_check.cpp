// frezka-cli check FILE [--rapid MM_PER_MIN] [--machine PROFILE] [--offset G54:X,Y,Z[,A]]...
//                       [--work-zero X,Y,Z[,A]]
//
// Reports every error of a G-code program as FILE:LINE:COL: message (exit 1), or a summary:
// moves, arcs, bounds per axis in machine coordinates, rapid and feed length and a naive time
// (exit 0). The program is checked from its work offsets (--offset, --work-zero) and planned
// for the machine (--machine, or the shipped GVE64 profile, as plan and run do): plan errors fail
// the check, plan warnings (a feed above what the axes allow, ...) are reported as
// FILE:LINE: warning: ... . The machine's travel (soft limits): each side of an axis the program
// leaves is named with its first line and how far beyond the limit it goes (exit 1). Without a
// profile or an offset the program's place on the machine is not known yet: a program that would
// fit the travel at another work zero is then told as a warning with the offset that puts it
// inside (exit 0), one too large for the travel at any work zero fails.
#include "cli.h"
#include "programoptions.h"

#include "gcode/interpreter.h"
#include "gcode/trace.h"
#include "machine/machineconfig.h"
#include "machine/planner.h"
#include "session/probefollow.h"
#include "session/travelcheck.h"

#include <QCoreApplication>
#include <QFile>

namespace {

QString mm(double v)
{
    return QString::number(v, 'f', 4);
}

int usage()
{
    frezka::cli::err(QCoreApplication::translate(
                         "frezka::gcode", "usage: frezka-cli check FILE [--rapid MM_PER_MIN] "
                                          "%1")
                         .arg(frezka::cli::programOptionsUsage()) +
                     QLatin1Char('\n'));
    return 2;
}

QString mm3(double v)
{
    return QString::number(v, 'f', 3);
}

const char *const kAxisNames[] = {"X", "Y", "Z", "A"};

// "FILE:LINE: Z 5.000 is 5.000 mm above the machine's travel (Z -120.000 .. 0.000 mm)", and the
// farthest point when another line goes farther.
QString excursionText(const QString &file, const frezka::session::TravelExcursion &e,
                      const frezka::machine::AxisConfig &axis, const QString &kind)
{
    QString text =
        (e.aboveMax ? QCoreApplication::translate(
                          "frezka::cli",
                          "%1:%2: %3%4 %5 is %6 mm above the machine's travel (%4 %7 .. %8 mm)")
                    : QCoreApplication::translate(
                          "frezka::cli",
                          "%1:%2: %3%4 %5 is %6 mm below the machine's travel (%4 %7 .. %8 mm)"))
            .arg(file)
            .arg(e.firstLine)
            .arg(kind, QLatin1String(kAxisNames[e.axis]), mm3(e.firstValueMm), mm3(e.firstBeyondMm),
                 mm3(axis.softMinMm), mm3(axis.softMaxMm));
    if (e.farthestLine != e.firstLine)
        text += QCoreApplication::translate("frezka::cli",
                                            "; the program goes %1 mm beyond it at line %2")
                    .arg(mm3(e.farthestBeyondMm))
                    .arg(e.farthestLine);
    return text + QLatin1Char('\n');
}

// The machine's travel: false when the program leaves it and its place is known (or it is too
// large for the travel); the excursions on stderr as errors, or as warnings with the offset
// that puts the program inside.
bool checkTravel(const QString &file, const frezka::gcode::Toolpath &path,
                 const frezka::machine::MachineConfig &config,
                 const frezka::cli::ProgramOptions &options)
{
    using namespace frezka;
    const session::TravelFit fit = session::checkTravel(path, config);
    if (fit.inside())
        return true;
    const bool placed = options.offsetsGiven || !options.machine.isEmpty();
    const bool fails = placed || !fit.fitsElsewhere;
    for (const session::TravelExcursion &e : fit.excursions)
        cli::err(excursionText(file, e, config.axes[std::size_t(e.axis)],
                               fails ? QString()
                                     : QCoreApplication::translate("frezka::cli", "warning: ")));
    if (!fails) {
        const session::Axes4 &o = options.offsets.systems[0];
        const session::Axes4 &d = fit.shiftMm;
        cli::err(QCoreApplication::translate(
                     "frezka::cli",
                     "%1: the program fits the machine's travel once its work zero is set: give it "
                     "with --offset G54:X,Y,Z (--offset G54:%2,%3,%4 puts it inside)\n")
                     .arg(file, mm3(o[0] + d[0]), mm3(o[1] + d[1]), mm3(o[2] + d[2])));
    } else if (!fit.fitsElsewhere) {
        cli::err(QCoreApplication::translate(
                     "frezka::cli", "%1: the program is larger than the machine's travel\n")
                     .arg(file));
    }
    return !fails;
}

// Plans the program for the machine profile: errors and warnings to stderr; false on errors.
// The soft limits are checkTravel's to word (with how far and what to do).
bool planFor(const QString &file, const frezka::gcode::Toolpath &path,
             const frezka::cli::ProgramOptions &options)
{
    using namespace frezka;
    const std::optional<machine::MachineConfig> config = cli::loadProfile(options.machine);
    if (!config)
        return false;
    const bool travelOk = checkTravel(file, path, *config, options);
    const machine::PlanResult plan = machine::plan(path, *config);
    for (const machine::PlanError &w : plan.warnings)
        cli::err(
            cli::planMessage(file, w, QCoreApplication::translate("frezka::cli", "warning: ")));
    bool ok = travelOk;
    for (const machine::PlanError &e : plan.errors) {
        if (e.code == machine::PlanErrorCode::SoftLimit)
            continue; // told by checkTravel, with how far beyond
        cli::err(cli::planMessage(file, e, QString()));
        ok = false;
    }
    return ok;
}

// The summary `check` prints for a good program: lines, moves, bounds, lengths, naive time.
QString summaryText(const QString &file, const frezka::gcode::Toolpath &path,
                    std::uint64_t linesRead, double rapid)
{
    using namespace frezka;
    const gcode::Summary s = gcode::summarize(path, rapid);
    QString text;
    const auto line = [&text](const QString &l) { text += l + QLatin1Char('\n'); };
    line(QCoreApplication::translate("frezka::gcode", "%1: OK, %2 lines").arg(file).arg(linesRead));
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
    QString file;
    cli::ProgramOptions options;
    double rapid = 3000.0;
    for (int i = 0; i < args.size(); ++i) {
        bool ok = true;
        if (cli::takeProgramOption(args, i, &options, &ok)) {
            if (!ok)
                return usage();
        } else if (args[i] == QLatin1String("--rapid") && i + 1 < args.size()) {
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
    int errors = 0;
    const auto program = cli::interpretFile(file, options, &errors);
    if (!program) {
        if (errors > 0 && QFile::exists(file))
            cli::err(QCoreApplication::translate("frezka::gcode", "%1: %n error(s)", "", errors)
                         .arg(file) +
                     QLatin1Char('\n'));
        return 1;
    }
    // A program that probes for itself: what follows its first probe is checked as if the probe
    // ended at its programmed end (docs/probing.md, "Programs that probe for themselves").
    if (session::dependsOnProbe(*program->toolpath, program->provisionalEntry)) {
        cli::err(QCoreApplication::translate("frezka::cli",
                                             "%1:%2: note: after this line the path depends on "
                                             "the probe's result; it is checked here as if the "
                                             "probe ended at its programmed end (run plans it "
                                             "once the probe has run)\n")
                     .arg(file)
                     .arg(program->provisionalLine));
    }
    if (!planFor(file, *program->toolpath, options))
        return 1;
    cli::out(summaryText(file, *program->toolpath, program->linesRead, rapid));
    return 0;
}

} // namespace

FREZKA_CLI_COMMAND(
    check,
    "check FILE [--rapid MM_PER_MIN] [--machine PROFILE] [--offset G54:X,Y,Z[,A]]... "
    "[--work-zero X,Y,Z[,A]]",
    QT_TRANSLATE_NOOP(
        "frezka::cli",
        "Check a G-code program against the machine's travel: every error, or a summary"),
    runCheck);
