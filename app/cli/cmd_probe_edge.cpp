// frezka-cli probe edge --axis x|y --direction +|- --tool-diameter MM [--travel MM] [--feed MM/MIN]
//                      [--slow-feed MM/MIN] [--retract MM] [--port PATH|sim] [--surface SPEC]
//                      [--machine PROFILE] [--offset G54:X,Y,Z]...
// frezka-cli probe corner --x-direction +|- --y-direction +|- --tool-diameter MM [--reach MM]
//                      (the same options)
//
// Work zero by probing (issue 19 item 2), X or Y from an edge, or both from a corner. The tool
// stands beside the edge, below the work's top (jogged there). From there G38.2 along the axis
// in the direction at --feed, at most --travel, back off by --retract, G38.2 again at
// --slow-feed, back to the start (session::HeightProbe::startEdge). The edge is the tool's
// radius beyond the trip point; the active work offset's X or Y is set so that the edge is 0
// (session::edgeZero; G92 kept). A corner is X then Y: from the same start for an inside corner
// (a pocket's), or, with --reach R, each probe first moves R along the other axis (toward the
// other probe's direction) to get beside its face of an outside corner, and back after.
// One JSON line (trip points, edges, offsets, the emulator's counters); exit 0 found, 1 error,
// 2 usage.

#include "cli.h"

#include "proberun.h"
#include "programoptions.h"

#include "driver/link/emulatorport.h"
#include "driver/link/machinestate.h"
#include "session/heightprobe.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <optional>

namespace frezka::cli {

namespace {

struct EdgeCli
{
    Q_DECLARE_TR_FUNCTIONS(EdgeCli)
};

struct EdgeArgs
{
    ProgramOptions program;
    QString port = QStringLiteral("sim");
    QString surface;
    int axis = -1;             // edge: 0 X, 1 Y
    int direction[2] = {0, 0}; // edge: direction[axis]; corner: X's and Y's
    std::optional<double> diameterMm;
    double travelMm = 10, feedMmPerMin = 100, retractMm = 1, reachMm = 0;
    std::optional<double> slowFeedMmPerMin;
};

int usage(bool corner)
{
    err(corner ? EdgeCli::tr("usage: frezka-cli probe corner --x-direction +|- --y-direction "
                             "+|- --tool-diameter MM [--reach MM] [--travel MM] [--feed MM/MIN] "
                             "[--slow-feed MM/MIN] [--retract MM] [--port PATH|sim] "
                             "[--surface SPEC] %1\n")
                     .arg(programOptionsUsage())
               : EdgeCli::tr("usage: frezka-cli probe edge --axis x|y --direction +|- "
                             "--tool-diameter MM [--travel MM] [--feed MM/MIN] "
                             "[--slow-feed MM/MIN] [--retract MM] [--port PATH|sim] "
                             "[--surface SPEC] %1\n")
                     .arg(programOptionsUsage()));
    return 2;
}

int sign(const QString &text)
{
    return text == QLatin1String("+") ? 1 : text == QLatin1String("-") ? -1 : 0;
}

// One option and its value; false when it is unknown or its value is malformed.
bool takeOption(const QStringList &args, int &i, EdgeArgs *a)
{
    bool ok = true;
    if (takeProgramOption(args, i, &a->program, &ok))
        return ok;
    if (i + 1 >= args.size())
        return false;
    const QString &k = args[i];
    const QString v = args[++i];
    if (k == QLatin1String("--port")) {
        a->port = v;
        return true;
    }
    if (k == QLatin1String("--surface")) {
        a->surface = v;
        emulator::ProbeSurface s;
        return emulator::parseProbeSurface(v.toStdString(), &s);
    }
    if (k == QLatin1String("--axis")) {
        a->axis = v == QLatin1String("x") ? 0 : v == QLatin1String("y") ? 1 : -2;
        return a->axis >= 0;
    }
    if (k == QLatin1String("--direction") || k == QLatin1String("--x-direction") ||
        k == QLatin1String("--y-direction")) {
        const int at = k == QLatin1String("--y-direction") ? 1 : 0;
        a->direction[k == QLatin1String("--direction") ? 0 : at] = sign(v);
        return sign(v) != 0;
    }
    const double n = v.toDouble(&ok);
    if (!ok)
        return false;
    if (k == QLatin1String("--tool-diameter"))
        a->diameterMm = n;
    else if (k == QLatin1String("--travel"))
        a->travelMm = n;
    else if (k == QLatin1String("--feed"))
        a->feedMmPerMin = n;
    else if (k == QLatin1String("--slow-feed"))
        a->slowFeedMmPerMin = n;
    else if (k == QLatin1String("--retract"))
        a->retractMm = n;
    else if (k == QLatin1String("--reach"))
        a->reachMm = n;
    else
        return false;
    return true;
}

std::optional<EdgeArgs> parseArgs(const QStringList &args, bool corner)
{
    EdgeArgs a;
    for (int i = 0; i < args.size(); ++i)
        if (!takeOption(args, i, &a))
            return std::nullopt;
    if (!corner && a.axis >= 0) { // --direction was read into [0]
        a.direction[a.axis] = a.direction[0];
        if (a.axis == 1)
            a.direction[0] = 0;
    }
    const bool directions = corner ? a.direction[0] != 0 && a.direction[1] != 0
                                   : a.axis >= 0 && a.direction[a.axis] != 0;
    if (!directions || !a.diameterMm || (!a.surface.isEmpty() && a.port != QLatin1String("sim")))
        return std::nullopt;
    return a;
}

QString badValue(const EdgeArgs &a)
{
    if (!(*a.diameterMm >= 0))
        return EdgeCli::tr("--tool-diameter %1: the diameter of the tool (or the probe's ball) "
                           "must be 0 mm or more.")
            .arg(*a.diameterMm);
    if (!(a.travelMm > 0))
        return EdgeCli::tr("--travel %1: how far the probe may move toward the edge must be "
                           "above 0 mm.")
            .arg(a.travelMm);
    if (!(a.retractMm > 0))
        return EdgeCli::tr("--retract %1: the back-off before the slow probe must be above 0 mm.")
            .arg(a.retractMm);
    if (!(a.reachMm >= 0))
        return EdgeCli::tr("--reach %1: the move beside an outside corner's face must be 0 mm "
                           "(an inside corner) or more.")
            .arg(a.reachMm);
    return {};
}

} // namespace

int runProbeEdge(const QStringList &args, bool corner)
{
    const auto a = parseArgs(args, corner);
    if (!a)
        return usage(corner);
    const QString name = corner ? QStringLiteral("corner") : QStringLiteral("edge");
    if (const QString bad = badValue(*a); !bad.isEmpty()) {
        err(QStringLiteral("frezka-cli probe %1: %2\n").arg(name, bad));
        return 2;
    }
    std::optional<machine::MachineConfig> config = loadProfile(a->program.machine);
    if (!config)
        return 1;
    // The axes in order (a corner: X, then Y) and their trips.
    const std::vector<int> axes = corner ? std::vector<int>{0, 1} : std::vector<int>{a->axis};
    std::vector<double> trips;
    auto settingsFor = [&](int axis) {
        session::HeightProbeSettings s;
        s.feedMmPerMin = a->feedMmPerMin;
        s.slowFeedMmPerMin = a->slowFeedMmPerMin.value_or(a->feedMmPerMin / 5);
        s.retractMm = a->retractMm;
        s.travelMm = a->travelMm;
        s.reachMm = corner ? a->direction[1 - axis] * a->reachMm : 0;
        return s;
    };
    auto startAxis = [&](session::HeightProbe &probe, int axis) {
        return probe.startEdge(axis, a->direction[axis], settingsFor(axis));
    };
    const ProbeRunOutcome run = runProbe(
        a->port, a->surface, *config,
        [&](session::HeightProbe &probe, const driver::MachineState &) {
            return startAxis(probe, axes.front());
        },
        [&](session::HeightProbe &probe, bool ok) {
            if (!ok || !probe.pointZMm())
                return;
            trips.push_back(*probe.pointZMm());
            if (trips.size() < axes.size())
                startAxis(probe, axes[trips.size()]);
        });
    session::OffsetState after = a->program.offsets;
    QJsonObject j;
    QJsonObject edges;
    for (std::size_t k = 0; k < trips.size(); ++k) {
        const int axis = axes[k];
        after = session::edgeZero(after, axis, a->direction[axis], trips[k], *a->diameterMm);
        const QString letter = axis == 0 ? QStringLiteral("x") : QStringLiteral("y");
        j[QStringLiteral("trip_%1_mm").arg(letter)] = trips[k];
        edges[letter] = trips[k] + a->direction[axis] * *a->diameterMm / 2;
    }
    const bool found = run.ok && trips.size() == axes.size();
    j[QStringLiteral("edge_mm")] = edges;
    j[QStringLiteral("work_offset")] = session::workSystemName(after.active);
    const session::Axes4 &v = after.systems[static_cast<std::size_t>(after.active)];
    j[QStringLiteral("offset_mm")] = QJsonArray{v[0], v[1], v[2], v[3]};
    j[QStringLiteral("offset_arg")] = found ? QJsonValue(offsetArgument(after)) : QJsonValue();
    j[QStringLiteral("unit_steps")] = stepsJson(run.unitSteps);
    out(QString::fromUtf8(QJsonDocument(j).toJson(QJsonDocument::Compact)) + QLatin1Char('\n'));
    if (!found) {
        err(EdgeCli::tr("frezka-cli probe %1: %2\n").arg(name, run.error));
        return 1;
    }
    err(EdgeCli::tr("%1 is now X %2, Y %3 (machine mm of its zero): the %4 is the work's zero, "
                    "with the tool's radius of %5 mm taken into account. Give the next commands "
                    "--offset %6.\n")
            .arg(session::workSystemName(after.active))
            .arg(v[0], 0, 'f', 3)
            .arg(v[1], 0, 'f', 3)
            .arg(corner ? EdgeCli::tr("corner") : EdgeCli::tr("edge"))
            .arg(*a->diameterMm / 2, 0, 'f', 3)
            .arg(offsetArgument(after)));
    return 0;
}

} // namespace frezka::cli
