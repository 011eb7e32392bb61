// frezka-cli probe tool-length --tool N [--table FILE] [--port PATH|sim] [--surface SPEC]
//                             [--machine PROFILE]
// measures a tool on the profile's tool length sensor (session/toollength.h) and writes its
// length into the tool table (--table, else the profile's tools.tableFile); one JSON line (tool,
// trip point, length, table, the emulator's counters). Exit 0 measured, 1 error, 2 usage.
//
// frezka-cli probe z-plate --plate MM [--feed MM/MIN] [--slow-feed MM/MIN] [--depth MM]
//                         [--retract MM] [--port PATH|sim] [--surface SPEC]
//                         [--machine PROFILE] [--offset G54:X,Y,Z]...
//
// Work zero by probing (issue 19 item 2), Z from a touch plate of known thickness lying on the
// work under the tool: from where the tool stands, G38.2 down at --feed (at most --depth below
// the start), back off by --retract, G38.2 again at --slow-feed (session/heightprobe.h:
// HeightProbe::startAt; the probe input is read before each probe move and a probe already in
// contact refuses to move; a probe that reaches the depth without touching is an error and the
// tool goes back up to the start), then up to --retract above the plate. The active work
// offset's Z (G54 unless --offset chose another) is set so that the work's top, the plate's
// thickness below the trip point, is Z 0 (session::touchPlateZero): the result names the
// system and its new value and gives it as an --offset argument for the next commands. Ends
// with one JSON line (trip point, offsets, on the emulator its counters and the lowest Z
// counter reached). Exit 0 when the plate was touched, 1 on an error (on stderr), 2 on usage.

#include "cli.h"

#include "proberun.h"
#include "programoptions.h"

#include "driver/link/emulatorport.h"
#include "driver/link/machinestate.h"
#include "session/heightprobe.h"
#include "session/toollength.h"
#include "session/tooltablefile.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <optional>

namespace {

using namespace frezka;

struct ProbeCli
{
    Q_DECLARE_TR_FUNCTIONS(ProbeCli)
};

struct Args
{
    cli::ProgramOptions program;
    QString port = QStringLiteral("sim");
    QString surface;
    std::optional<double> plateMm;
    double feedMmPerMin = 100, depthMm = 10, retractMm = 1;
    std::optional<double> slowFeedMmPerMin; // default: a fifth of the feed
};

int usage()
{
    cli::err(ProbeCli::tr("usage: frezka-cli probe z-plate --plate MM [--feed MM/MIN] "
                          "[--slow-feed MM/MIN] [--depth MM] [--retract MM] [--port PATH|sim] "
                          "[--surface SPEC] %1\n")
                 .arg(cli::programOptionsUsage()));
    return 2;
}

bool number(const QStringList &args, int &i, double *value)
{
    if (i + 1 >= args.size())
        return false;
    bool ok = false;
    *value = args[++i].toDouble(&ok);
    return ok;
}

bool takeOption(const QStringList &args, int &i, Args *a)
{
    const QString &k = args[i];
    double v = 0;
    bool ok = true;
    if (cli::takeProgramOption(args, i, &a->program, &ok))
        return ok;
    if (k == QLatin1String("--port") && i + 1 < args.size()) {
        a->port = args[++i];
    } else if (k == QLatin1String("--surface") && i + 1 < args.size()) {
        a->surface = args[++i];
        emulator::ProbeSurface surface;
        if (!emulator::parseProbeSurface(a->surface.toStdString(), &surface)) {
            cli::err(ProbeCli::tr("frezka-cli probe: --surface %1: expected plane:Z0,DZDX,DZDY, "
                                  "sine:AMP,PERIOD[,Z0], warp:Z0,DZDX,DZDY,AMP,PERIOD or "
                                  "block:X0,Y0,X1,Y1,TOP "
                                  "(machine mm)\n")
                         .arg(a->surface));
            return false;
        }
    } else if (!number(args, i, &v)) {
        return false;
    } else if (k == QLatin1String("--plate")) {
        a->plateMm = v;
    } else if (k == QLatin1String("--feed")) {
        a->feedMmPerMin = v;
    } else if (k == QLatin1String("--slow-feed")) {
        a->slowFeedMmPerMin = v;
    } else if (k == QLatin1String("--depth")) {
        a->depthMm = v;
    } else if (k == QLatin1String("--retract")) {
        a->retractMm = v;
    } else {
        return false;
    }
    return true;
}

std::optional<Args> parseArgs(const QStringList &args)
{
    Args a;
    for (int i = 0; i < args.size(); ++i)
        if (!takeOption(args, i, &a))
            return std::nullopt;
    if (!a.plateMm || (!a.surface.isEmpty() && a.port != QLatin1String("sim")))
        return std::nullopt; // the simulated surface is the in-process emulator's
    return a;
}

// The values a probe cannot start with, named with what to do; empty when they are fine.
QString badValue(const Args &a)
{
    if (!(*a.plateMm >= 0))
        return ProbeCli::tr("--plate %1: the plate's thickness must be 0 mm or more (0: the "
                            "tool touches the work itself).")
            .arg(*a.plateMm);
    if (!(a.depthMm > 0))
        return ProbeCli::tr("--depth %1: how far below the start the probe may go must be above "
                            "0 mm.")
            .arg(a.depthMm);
    if (!(a.retractMm > 0))
        return ProbeCli::tr("--retract %1: the back-off above the plate must be above 0 mm.")
            .arg(a.retractMm);
    if (!(a.slowFeedMmPerMin.value_or(1) > 0))
        return ProbeCli::tr("--slow-feed %1: the slow probe's feed must be above 0 mm/min.")
            .arg(*a.slowFeedMmPerMin);
    return {};
}

QJsonArray axes(const session::Axes4 &v)
{
    return QJsonArray{v[0], v[1], v[2], v[3]};
}

// The JSON line on stdout: the trip point, the offsets after, the emulator's counters.
void printReport(const session::OffsetState &after, std::optional<double> tripZ, double plateMm,
                 const cli::ProbeRunOutcome &run)
{
    QJsonObject j;
    j[QStringLiteral("trip_z_mm")] = tripZ ? QJsonValue(*tripZ) : QJsonValue();
    j[QStringLiteral("plate_mm")] = plateMm;
    j[QStringLiteral("work_offset")] = session::workSystemName(after.active);
    j[QStringLiteral("offset_mm")] = axes(after.systems[static_cast<std::size_t>(after.active)]);
    j[QStringLiteral("g92_mm")] = axes(after.g92);
    j[QStringLiteral("offset_arg")] = tripZ ? QJsonValue(cli::offsetArgument(after)) : QJsonValue();
    j[QStringLiteral("unit_steps")] = cli::stepsJson(run.unitSteps);
    j[QStringLiteral("unit_lowest_z_steps")] =
        run.unitLowestZSteps ? QJsonValue(qint64(*run.unitLowestZSteps)) : QJsonValue();
    cli::out(QString::fromUtf8(QJsonDocument(j).toJson(QJsonDocument::Compact)) +
             QLatin1Char('\n'));
}

int runZPlate(const QStringList &args)
{
    const auto a = parseArgs(args);
    if (!a)
        return usage();
    if (const QString bad = badValue(*a); !bad.isEmpty()) {
        cli::err(QStringLiteral("frezka-cli probe z-plate: %1\n").arg(bad));
        return 2;
    }
    std::optional<machine::MachineConfig> config = cli::loadProfile(a->program.machine);
    if (!config)
        return 1;
    std::optional<double> tripZ;
    const cli::ProbeRunOutcome run = cli::runProbe(
        a->port, a->surface, *config,
        [&](session::HeightProbe &probe, const driver::MachineState &s) {
            session::HeightProbeSettings settings;
            settings.clearanceZMm = s.positionMm[2]; // the start: back here after a failure
            settings.bottomZMm = s.positionMm[2] - a->depthMm;
            settings.feedMmPerMin = a->feedMmPerMin;
            settings.slowFeedMmPerMin = a->slowFeedMmPerMin.value_or(a->feedMmPerMin / 5);
            settings.retractMm = a->retractMm;
            return probe.startAt(s.positionMm[0], s.positionMm[1], settings);
        },
        [&](const session::HeightProbe &probe, bool ok) {
            if (ok)
                tripZ = probe.pointZMm();
        });
    const session::OffsetState before = a->program.offsets;
    const session::OffsetState after =
        tripZ ? session::touchPlateZero(before, *tripZ, *a->plateMm) : before;
    printReport(after, tripZ, *a->plateMm, run);
    if (!run.ok || !tripZ) {
        cli::err(ProbeCli::tr("frezka-cli probe z-plate: %1\n").arg(run.error));
        return 1;
    }
    cli::err(ProbeCli::tr("The plate's top touched at machine Z %1; %2 Z is now %3 (was %4), so "
                          "the work's top under the %5 mm plate is Z 0 and the tool stands at "
                          "Z %6. Give the next commands --offset %7.\n")
                 .arg(*tripZ, 0, 'f', 3)
                 .arg(session::workSystemName(after.active))
                 .arg(after.systems[static_cast<std::size_t>(after.active)][2], 0, 'f', 3)
                 .arg(before.systems[static_cast<std::size_t>(before.active)][2], 0, 'f', 3)
                 .arg(*a->plateMm, 0, 'f', 3)
                 .arg(*a->plateMm + a->retractMm, 0, 'f', 3)
                 .arg(cli::offsetArgument(after)));
    return 0;
}

// ---- probe tool-length (issue 19 item 1) ----

struct ToolArgs
{
    cli::ProgramOptions program;
    QString port = QStringLiteral("sim");
    QString surface;
    QString table; // the tool table file; empty: the profile's
    int tool = 0;
};

int toolUsage()
{
    cli::err(ProbeCli::tr("usage: frezka-cli probe tool-length --tool N [--table FILE] "
                          "[--port PATH|sim] [--surface SPEC] [--machine PROFILE]\n"));
    return 2;
}

std::optional<ToolArgs> parseToolArgs(const QStringList &args)
{
    ToolArgs a;
    for (int i = 0; i < args.size(); ++i) {
        const QString &k = args[i];
        bool ok = true;
        if (cli::takeProgramOption(args, i, &a.program, &ok)) {
            if (!ok)
                return std::nullopt;
        } else if (i + 1 >= args.size()) {
            return std::nullopt;
        } else if (k == QLatin1String("--tool")) {
            a.tool = args[++i].toInt(&ok);
            if (!ok || a.tool < 1)
                return std::nullopt;
        } else if (k == QLatin1String("--table")) {
            a.table = args[++i];
        } else if (k == QLatin1String("--port")) {
            a.port = args[++i];
        } else if (k == QLatin1String("--surface")) {
            a.surface = args[++i];
            emulator::ProbeSurface surface;
            if (!emulator::parseProbeSurface(a.surface.toStdString(), &surface))
                return std::nullopt;
        } else {
            return std::nullopt;
        }
    }
    if (a.tool < 1 || (!a.surface.isEmpty() && a.port != QLatin1String("sim")))
        return std::nullopt;
    return a;
}

// The table the length goes into: --table, else the profile's (an empty path: none).
session::ToolTableFile toolTableFor(const ToolArgs &a, const machine::MachineConfig &config)
{
    if (a.table.isEmpty())
        return session::readProfileToolTable(config, a.program.machine);
    session::ToolTableFile t;
    t.path = a.table;
    gcode::ToolTable table;
    gcode::Error error;
    if (gcode::readToolTableFile(a.table.toStdString(), &table, &error))
        t.table = table;
    else
        t.error = gcode::formatError(a.table, error);
    return t;
}

// Writes the length into the table file; false with the reason on stderr.
bool storeToolLength(const session::ToolTableFile &file, int tool, double lengthMm)
{
    gcode::ToolTable table = file.table.value_or(gcode::ToolTable{});
    session::setToolLength(&table, tool, lengthMm);
    gcode::Error error;
    if (gcode::writeToolTableFile(file.path.toStdString(), table, &error))
        return true;
    cli::err(QStringLiteral("frezka-cli probe tool-length: %1\n")
                 .arg(gcode::formatError(file.path, error)));
    return false;
}

int runToolLength(const QStringList &args)
{
    const auto a = parseToolArgs(args);
    if (!a)
        return toolUsage();
    std::optional<machine::MachineConfig> config = cli::loadProfile(a->program.machine);
    if (!config)
        return 1;
    if (const QString problem = session::toolSensorProblem(*config); !problem.isEmpty()) {
        cli::err(QStringLiteral("frezka-cli probe tool-length: %1\n").arg(problem));
        return 1;
    }
    const session::ToolTableFile file = toolTableFor(*a, *config);
    if (!file.error.isEmpty()) { // a table that cannot be read is not overwritten
        cli::err(QStringLiteral("frezka-cli probe tool-length: %1\n").arg(file.error));
        return 1;
    }
    const machine::ToolSensorConfig &sensor = config->tools.sensor;
    std::optional<double> tripZ;
    const cli::ProbeRunOutcome run = cli::runProbe(
        a->port, a->surface, *config,
        [&](session::HeightProbe &probe, const driver::MachineState &) {
            return probe.startAt(sensor.xMm, sensor.yMm, session::toolSensorSettings(sensor));
        },
        [&](const session::HeightProbe &probe, bool ok) {
            if (ok)
                tripZ = probe.pointZMm();
        });
    const bool tripped = tripZ.has_value();
    const double tripMm = tripZ.value_or(0);
    const double lengthMm = tripped ? session::toolLengthFromTrip(sensor, tripMm) : 0;
    QJsonObject j;
    j[QStringLiteral("tool")] = a->tool;
    j[QStringLiteral("trip_z_mm")] = tripped ? QJsonValue(tripMm) : QJsonValue();
    j[QStringLiteral("length_mm")] = tripped ? QJsonValue(lengthMm) : QJsonValue();
    j[QStringLiteral("table")] = file.path.isEmpty() ? QJsonValue() : QJsonValue(file.path);
    j[QStringLiteral("unit_steps")] = cli::stepsJson(run.unitSteps);
    cli::out(QString::fromUtf8(QJsonDocument(j).toJson(QJsonDocument::Compact)) +
             QLatin1Char('\n'));
    if (!run.ok || !tripped) {
        cli::err(ProbeCli::tr("frezka-cli probe tool-length: %1\n").arg(run.error));
        return 1;
    }
    if (file.path.isEmpty()) {
        cli::err(ProbeCli::tr("Tool %1 is %2 mm long (tripped at machine Z %3). The profile "
                              "names no tool table: set tools.tableFile to keep it, or apply it "
                              "with G43.1 Z%2.\n")
                     .arg(a->tool)
                     .arg(lengthMm, 0, 'f', 4)
                     .arg(tripMm, 0, 'f', 4));
        return 0;
    }
    if (!storeToolLength(file, a->tool, lengthMm))
        return 1;
    cli::err(ProbeCli::tr("Tool %1 is %2 mm long (tripped at machine Z %3); written to %4.\n")
                 .arg(a->tool)
                 .arg(lengthMm, 0, 'f', 4)
                 .arg(tripMm, 0, 'f', 4)
                 .arg(file.path));
    return 0;
}

int runProbe(const QStringList &args)
{
    if (!args.isEmpty() && args.front() == QLatin1String("z-plate"))
        return runZPlate(args.mid(1));
    if (!args.isEmpty() && args.front() == QLatin1String("tool-length"))
        return runToolLength(args.mid(1));
    if (!args.isEmpty() &&
        (args.front() == QLatin1String("edge") || args.front() == QLatin1String("corner")))
        return cli::runProbeEdge(args.mid(1), args.front() == QLatin1String("corner"));
    return usage();
}

} // namespace

FREZKA_CLI_COMMAND(probe,
                   "probe z-plate --plate MM [--feed MM/MIN] [--slow-feed MM/MIN] [--depth MM] "
                   "[--retract MM] [--port PATH|sim] [--surface SPEC] [--machine PROFILE] "
                   "[--offset G54:X,Y,Z[,A]]... | probe edge --axis x|y --direction +|- "
                   "--tool-diameter MM [--travel MM] ... | probe corner --x-direction +|- "
                   "--y-direction +|- --tool-diameter MM [--reach MM] ... | probe tool-length "
                   "--tool N [--table FILE] [--port PATH|sim] [--surface SPEC] "
                   "[--machine PROFILE]",
                   QT_TRANSLATE_NOOP("frezka::cli",
                                     "Probe the work's zero (Z from a touch plate, X/Y from an "
                                     "edge or a corner) or a tool's length on the tool sensor "
                                     "(fast then slow G38.2)"),
                   runProbe);
