// frezka-cli probe-grid --out MAP.csv (--area X0,Y0,X1,Y1 | --program FILE) --spacing MM
//                       --clearance MM --depth MM --feed MM/MIN [--port PATH|sim]
//                       [--machine PROFILE] [--offset G54:X,Y,Z]... [--surface SPEC]
//
// Probes a height map on the unit (session/heightprobe.h: a G38.2 per node in serpentine
// order, back up to the clearance between the nodes) and writes the map file
// (docs/height-map.md). The area, the clearance and the depth are in the work coordinates of
// the offsets (G54; machine coordinates without them): the clearance is the work Z of the
// moves between the nodes, the depth how far below the work's Z 0 the probe may go. --program
// takes the area from the program's cuts (interpreted from the same offsets). --port sim (the
// default) probes the in-process emulator on a virtual clock, with --surface its simulated work
// top. Ends with one JSON line (the points, the reference Z, the heights' range; on the
// emulator its counters at the end and the lowest Z counter it reached). Exit 0 when every
// node was probed and the file written, 1 on an error (on stderr, naming the node), 2 on usage.

#include "cli.h"

#include "proberun.h"
#include "programoptions.h"

#include "driver/link/emulatorport.h"
#include "session/heightprobe.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <algorithm>
#include <optional>

namespace {

using namespace frezka;

struct ProbeGridCli
{
    Q_DECLARE_TR_FUNCTIONS(ProbeGridCli)
};

struct Args
{
    cli::ProgramOptions program;
    QString port = QStringLiteral("sim");
    QString area, programFile, surface, out;
    double spacingMm = 0, clearanceMm = 0, depthMm = 0, feedMmPerMin = 0;
    bool spacingGiven = false, clearanceGiven = false, depthGiven = false, feedGiven = false;
};

struct Outcome
{
    bool ok = false;
    QString error;
    gcode::HeightMap map;
    int done = 0, total = 0;
    std::optional<machine::Steps4> unitSteps;     // the emulator's counters at the end
    std::optional<std::int64_t> unitLowestZSteps; // the lowest Z counter the emulator reached
};

int usage()
{
    cli::err(ProbeGridCli::tr("usage: frezka-cli probe-grid (--area X0,Y0,X1,Y1 | --program FILE) "
                              "--spacing MM --clearance MM --depth MM --feed MM/MIN --out MAP.csv "
                              "[--port PATH|sim] [--surface SPEC] %1\n")
                 .arg(cli::programOptionsUsage()));
    return 2;
}

bool takeNumber(const QStringList &args, int &i, double *value, bool *given)
{
    if (i + 1 >= args.size())
        return false;
    bool ok = false;
    *value = args[++i].toDouble(&ok);
    *given = true;
    return ok;
}

std::optional<Args> parseArgs(const QStringList &args)
{
    Args a;
    for (int i = 0; i < args.size(); ++i) {
        const QString &k = args[i];
        const bool hasValue = i + 1 < args.size();
        bool ok = true;
        if (cli::takeProgramOption(args, i, &a.program, &ok)) {
        } else if (k == QLatin1String("--port") && hasValue) {
            a.port = args[++i];
        } else if (k == QLatin1String("--area") && hasValue) {
            a.area = args[++i];
        } else if (k == QLatin1String("--program") && hasValue) {
            a.programFile = args[++i];
        } else if (k == QLatin1String("--out") && hasValue) {
            a.out = args[++i];
        } else if (k == QLatin1String("--spacing")) {
            ok = takeNumber(args, i, &a.spacingMm, &a.spacingGiven);
        } else if (k == QLatin1String("--clearance")) {
            ok = takeNumber(args, i, &a.clearanceMm, &a.clearanceGiven);
        } else if (k == QLatin1String("--depth")) {
            ok = takeNumber(args, i, &a.depthMm, &a.depthGiven);
        } else if (k == QLatin1String("--feed")) {
            ok = takeNumber(args, i, &a.feedMmPerMin, &a.feedGiven);
        } else if (k == QLatin1String("--surface") && hasValue) {
            a.surface = args[++i];
            emulator::ProbeSurface surface;
            ok = emulator::parseProbeSurface(a.surface.toStdString(), &surface);
            if (!ok)
                cli::err(ProbeGridCli::tr("frezka-cli probe-grid: --surface %1: expected "
                                          "plane:Z0,DZDX,DZDY, sine:AMP,PERIOD[,Z0] or "
                                          "warp:Z0,DZDX,DZDY,AMP,PERIOD (machine mm)\n")
                             .arg(a.surface));
        } else {
            ok = false;
        }
        if (!ok)
            return std::nullopt;
    }
    const bool oneArea = a.area.isEmpty() != a.programFile.isEmpty();
    if (!oneArea || a.out.isEmpty() || !a.spacingGiven || !a.clearanceGiven || !a.depthGiven ||
        !a.feedGiven)
        return std::nullopt;
    if (!a.surface.isEmpty() && a.port != QLatin1String("sim"))
        return std::nullopt; // the simulated surface is the in-process emulator's
    return a;
}

// The settings in machine coordinates: the area and heights given in work coordinates.
std::optional<session::HeightProbeSettings> settingsFor(const Args &a)
{
    const session::Axes4 zero = a.program.offsets.total();
    session::HeightProbeSettings s;
    if (!a.area.isEmpty()) {
        const QStringList parts = a.area.split(QLatin1Char(','));
        std::array<double, 4> v{};
        bool ok = parts.size() == 4;
        for (int i = 0; ok && i < 4; ++i)
            v[static_cast<std::size_t>(i)] = parts[i].trimmed().toDouble(&ok);
        if (!ok) {
            cli::err(ProbeGridCli::tr("frezka-cli probe-grid: --area %1: expected four numbers "
                                      "X0,Y0,X1,Y1 (mm), such as 0,0,80,60\n")
                         .arg(a.area));
            return std::nullopt;
        }
        s.x0Mm = std::min(v[0], v[2]) + zero[0];
        s.y0Mm = std::min(v[1], v[3]) + zero[1];
        s.x1Mm = std::max(v[0], v[2]) + zero[0];
        s.y1Mm = std::max(v[1], v[3]) + zero[1];
    } else {
        cli::ProgramOptions plain = a.program;
        plain.heightMap.clear(); // the area of the program as written
        const auto g = cli::interpretFile(a.programFile, plain);
        if (!g)
            return std::nullopt;
        const auto box = session::cutArea(*g->toolpath);
        if (!box) {
            cli::err(ProbeGridCli::tr("%1: the program cuts nothing (no feed move or arc): give "
                                      "the area with --area X0,Y0,X1,Y1\n")
                         .arg(a.programFile));
            return std::nullopt;
        }
        s.x0Mm = (*box)[0];
        s.y0Mm = (*box)[1];
        s.x1Mm = (*box)[2];
        s.y1Mm = (*box)[3];
    }
    s.spacingMm = a.spacingMm;
    s.clearanceZMm = zero[2] + a.clearanceMm;
    s.bottomZMm = zero[2] - a.depthMm;
    s.feedMmPerMin = a.feedMmPerMin;
    QString error;
    if (!session::heightProbeGrid(s, &error)) {
        cli::err(QStringLiteral("frezka-cli probe-grid: %1\n").arg(error));
        return std::nullopt;
    }
    return s;
}

void printReport(const Outcome &o)
{
    QJsonObject j;
    j[QStringLiteral("points")] = o.total;
    j[QStringLiteral("points_probed")] = o.done;
    j[QStringLiteral("reference_z_mm")] = o.map.probing().referenceZMm;
    j[QStringLiteral("min_height_mm")] = o.map.minZ();
    j[QStringLiteral("max_height_mm")] = o.map.maxZ();
    j[QStringLiteral("count_x")] = o.map.countX();
    j[QStringLiteral("count_y")] = o.map.countY();
    j[QStringLiteral("unit_steps")] = cli::stepsJson(o.unitSteps);
    j[QStringLiteral("unit_lowest_z_steps")] =
        o.unitLowestZSteps ? QJsonValue(qint64(*o.unitLowestZSteps)) : QJsonValue();
    cli::out(QString::fromUtf8(QJsonDocument(j).toJson(QJsonDocument::Compact)) +
             QLatin1Char('\n'));
}

int runProbeGrid(const QStringList &args)
{
    const auto a = parseArgs(args);
    if (!a)
        return usage();
    std::optional<machine::MachineConfig> config = cli::loadProfile(a->program.machine);
    if (!config)
        return 1;
    const auto settings = settingsFor(*a);
    if (!settings)
        return 1;
    Outcome o;
    const cli::ProbeRunOutcome run = cli::runProbe(
        a->port, a->surface, *config,
        [&](session::HeightProbe &probe, const driver::MachineState &) {
            return probe.start(*settings);
        },
        [&](const session::HeightProbe &probe, bool) {
            o.map = probe.map();
            o.done = probe.pointsDone();
            o.total = probe.pointsTotal();
        });
    o.ok = run.ok;
    o.error = run.error;
    o.unitSteps = run.unitSteps;
    o.unitLowestZSteps = run.unitLowestZSteps;
    printReport(o);
    if (!o.ok) {
        cli::err(ProbeGridCli::tr("frezka-cli probe-grid: %1\n").arg(o.error));
        return 1;
    }
    QString error;
    if (!o.map.save(a->out, &error)) {
        cli::err(QStringLiteral("%1: %2\n").arg(a->out, error));
        return 1;
    }
    cli::err(ProbeGridCli::tr("%1 points probed, heights %2 to %3 mm from the first point (machine "
                              "Z %4); the map is in %5. Set the work's Z zero on the surface at "
                              "the first point (X %6, Y %7) before running with --height-map.\n")
                 .arg(o.done)
                 .arg(o.map.minZ(), 0, 'f', 3)
                 .arg(o.map.maxZ(), 0, 'f', 3)
                 .arg(o.map.probing().referenceZMm, 0, 'f', 3)
                 .arg(a->out)
                 .arg(o.map.nodeX(0), 0, 'f', 3)
                 .arg(o.map.nodeY(0), 0, 'f', 3));
    return 0;
}

} // namespace

// Registered by hand: the macro takes the name as an identifier, and this one has a dash.
static const bool registeredProbeGrid = frezka::cli::registerCommand(
    "probe-grid",
    {"probe-grid (--area X0,Y0,X1,Y1 | --program FILE) --spacing MM --clearance MM "
     "--depth MM --feed MM/MIN --out MAP.csv [--port PATH|sim] [--surface SPEC] "
     "[--machine PROFILE] [--offset G54:X,Y,Z[,A]]...",
     QT_TRANSLATE_NOOP("frezka::cli", "Probe a height map on the unit (G38.2 on a grid) and write "
                                      "its file"),
     runProbeGrid});
