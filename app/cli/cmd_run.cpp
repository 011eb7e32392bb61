// frezka-cli run FILE [--machine PROFILE] [--offset G54:X,Y,Z[,A]]... [--work-zero X,Y,Z[,A]]
//                     [--port PATH|sim] [--baud N] [--latency-ms N]
//                     [--faults RATE --seed N] [--clock virtual|real] [--home]
//                     [--return-to-path] [--feed-override PCT] [--hold-at-line N [--lift]]
//                     [--continue-at-stops] [--from-line N] [--trace FILE]
//
// Interprets FILE from its work offsets (programoptions.h) and plans it for the machine
// profile, then the session's run workflow (the one
// the GUI drives) connects (a serial port / pty, or the in-process emulator), optionally homes,
// and runs the job with a progress bar on a terminal
// (line, %, ETA) and ends with one JSON line of figures on stdout. Exit code 0 when the job ran
// to its end, 1 on any error (on stderr), 2 on bad usage.
//
// --port sim (default) uses the in-process emulator of the profile's variant; with
// --clock virtual (default for sim) it runs on a virtual clock as fast as the computer allows,
// with --clock real in real time. --faults RATE injects byte errors (corrupted, dropped,
// duplicated) and lost replies at RATE each (sim only), seeded by --seed.
//
// When the unit's position leaves the planned path (a command damaged on the line in a way its
// checksum cannot show; see driver/link/pathguard.h) the job stops and the run
// ends with the error, unless --return-to-path lets the driver return to the last verified
// point of the path and run on without an operator.
//
// --feed-override PCT sets the unit's feed override (XM, the driver's override path) once the job
// runs. --hold-at-line N (in-process emulator on the virtual clock) plays an operator: when the
// job reaches line N it pauses with "stop the spindle", with --lift lifts the tool, waits 5 s,
// lowers it and continues (without --lift: waits and continues). The report then carries the
// emulator's safety counters (axis_over_max, cut_without_spindle, spindle_on_while_held) with
// the program's highest feed level as the top of the work (docs/emulator.md).
//
// --from-line N runs the program from line N (session/runfromline.h): the program's state at
// the line (printed on stderr), the spindle and coolant as there with the spin-up waited, the
// safe approach from the machine's zero, then the program's rest; a line that cannot be a start
// (inside a loop or a subroutine, never run, no feed in force) is refused with the line to
// choose (exit 1). Such a run prints one more JSON line before the report: the line, the safe
// height and the start point in steps, and where the emulator's counters first went below the
// safe height (unit_first_below_safe_z: straight above the start when the approach came first).
//
// --cut-depth (with --surface) samples the emulator's counters while the job runs and reports
// the tool's depth below the simulated surface while it cuts (runjob.h, CutDepth): cut_depth
// with the samples, the least and the greatest depth and where they were.
//
// --trace FILE saves the serial line of the run both ways, whether the job ended or not, in the
// format of docs/serial-trace.md (the session's record, driver/link/tracerecorder.h).
#include "cli.h"

#include "programoptions.h"
#include "runjob.h"

#include "driver/link/tracerecorder.h"
#include "machine/planner.h"
#include "machine/steps.h"
#include "session/plannedspeed.h"
#include "session/probefollow.h"
#include "session/programplanner.h"
#include "session/runfromline.h"

#include <QCoreApplication>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>

#include <optional>

namespace {

using namespace frezka;
using cli::RunArgs;
using cli::RunCli;
using cli::RunOutcome;

int usage()
{
    cli::err(RunCli::tr("usage: frezka-cli run FILE %1 [--port PATH|sim] [--baud N] "
                        "[--latency-ms N] [--faults RATE --seed N] [--clock virtual|real] [--home] "
                        "[--return-to-path] [--feed-override PCT] [--hold-at-line N [--lift]] "
                        "[--continue-at-stops] [--from-line N] [--trace FILE] [--surface SPEC "
                        "[--cut-depth]]\n")
                 .arg(cli::programOptionsUsage()));
    return 2;
}

std::optional<RunArgs> parseArgs(const QStringList &args)
{
    RunArgs a;
    for (int i = 0; i < args.size(); ++i) {
        const QString &k = args[i];
        const bool hasValue = i + 1 < args.size();
        bool ok = true;
        if (cli::takeProgramOption(args, i, &a.program, &ok)) {
            // --machine, --offset, --work-zero: taken (ok is false when malformed)
        } else if (k == QLatin1String("--port") && hasValue) {
            a.port = args[++i];
        } else if (k == QLatin1String("--baud") && hasValue) {
            a.baud = args[++i].toInt(&ok);
            ok = ok && a.baud > 0;
        } else if (k == QLatin1String("--latency-ms") && hasValue) {
            a.latencyMs = args[++i].toDouble(&ok);
            ok = ok && a.latencyMs >= 0 && a.latencyMs <= 1000;
        } else if (k == QLatin1String("--faults") && hasValue) {
            a.faults = args[++i].toDouble(&ok);
            ok = ok && a.faults >= 0 && a.faults < 0.5;
        } else if (k == QLatin1String("--seed") && hasValue) {
            a.seed = args[++i].toUInt(&ok);
        } else if (k == QLatin1String("--clock") && hasValue) {
            const QString c = args[++i];
            ok = c == QLatin1String("virtual") || c == QLatin1String("real");
            a.virtualClock = c == QLatin1String("virtual");
            a.clockGiven = true;
        } else if (k == QLatin1String("--home")) {
            a.home = true;
        } else if (k == QLatin1String("--return-to-path")) {
            a.returnToPath = true;
        } else if (k == QLatin1String("--feed-override") && hasValue) {
            a.feedOverride = args[++i].toInt(&ok);
            ok = ok && a.feedOverride >= 1 && a.feedOverride <= 1000;
        } else if (k == QLatin1String("--hold-at-line") && hasValue) {
            a.holdAtLine = args[++i].toInt(&ok);
            ok = ok && a.holdAtLine >= 1;
        } else if (k == QLatin1String("--lift")) {
            a.lift = true;
        } else if (k == QLatin1String("--continue-at-stops")) {
            a.continueAtStops = true;
        } else if (k == QLatin1String("--from-line") && hasValue) {
            a.fromLine = args[++i].toInt(&ok);
            ok = ok && a.fromLine >= 1;
        } else if (k == QLatin1String("--trace") && hasValue) {
            a.traceFile = args[++i];
        } else if (k == QLatin1String("--surface") && hasValue) {
            a.surface = args[++i];
            emulator::ProbeSurface surface;
            ok = emulator::parseProbeSurface(a.surface.toStdString(), &surface);
            if (!ok)
                cli::err(RunCli::tr("frezka-cli run: --surface %1: expected plane:Z0,DZDX,DZDY, "
                                    "sine:AMP,PERIOD[,Z0] or warp:Z0,DZDX,DZDY,AMP,PERIOD "
                                    "(machine mm), such as plane:-5,0.001,0\n")
                             .arg(a.surface));
        } else if (k == QLatin1String("--cut-depth")) {
            a.cutDepth = true;
        } else if (a.file.isEmpty() && !k.startsWith(QLatin1String("--"))) {
            a.file = k;
        } else {
            ok = false;
        }
        if (!ok)
            return std::nullopt;
    }
    if (a.file.isEmpty())
        return std::nullopt;
    const bool sim = a.port == QLatin1String("sim");
    if (!sim && !a.clockGiven)
        a.virtualClock = false;
    if (!sim && (a.virtualClock || a.faults > 0 || a.latencyMs > 0))
        return std::nullopt; // a real port runs in real time, with its own faults and latency
    if (!a.surface.isEmpty() && !(sim && a.virtualClock))
        return std::nullopt; // the simulated surface is the in-process emulator's
    if (a.cutDepth && a.surface.isEmpty())
        return std::nullopt; // the depth is measured below the simulated surface
    if ((a.lift && a.holdAtLine == 0) || (a.holdAtLine > 0 && !(sim && a.virtualClock)))
        return std::nullopt; // the scripted operator plays on the virtual clock only
    return a;
}

// Profile, then the program checked from its work offsets and planned as the GUI does it (the
// session layer), from the machine's zero. Prints every error; nullopt on failure.
struct Prepared
{
    machine::MachineConfig config;
    machine::UnitProgram program;
    machine::PlanStats stats;
    std::optional<double> workTopMm;       // the highest Z a feed move reaches: the top of the work
    std::vector<float> lineEndS;           // planned seconds to the end of each line
    std::optional<session::FromLine> from; // run from a line: the state and the approach
    std::shared_ptr<session::ProbeFollow> follow; // the program probes for itself
};

std::optional<double> workTop(const gcode::Toolpath &path)
{
    std::optional<double> top;
    for (std::size_t i = 0; i < path.size(); ++i) {
        const gcode::MotionKind k = path.kind(i);
        if (k == gcode::MotionKind::Feed || k == gcode::MotionKind::Arc)
            top = std::max(top.value_or(path.end(i).z), path.end(i).z);
    }
    return top;
}

// A program that probes for itself (its path after a probe depends on the probe's result): the
// first job up to its first probe, the rest planned by the run workflow after each probe
// (session/probefollow.h).
std::optional<Prepared> prepareFollow(const RunArgs &a, const machine::MachineConfig &config,
                                      session::InterpretRequest request,
                                      const session::InterpretOutcome &whole)
{
    cli::err(RunCli::tr("%1:%2: the path after this probe depends on where it stops: each part is "
                        "planned when the probe before it has run\n")
                 .arg(a.file)
                 .arg(whole.provisionalLine));
    auto follow = std::make_shared<session::ProbeFollow>(std::move(request), config);
    const session::ProbeFollow::Next first = follow->start({});
    for (const session::ProgramMessage &w : first.planned.warnings)
        cli::err(RunCli::tr("warning: %1\n").arg(w.text));
    if (!first.plan) {
        cli::err(first.error + QLatin1Char('\n'));
        return std::nullopt;
    }
    std::vector<float> lineEndS = session::plannedLineTimes(
        *first.plan, first.planned.stats.speedModeVk, first.planned.stats.estimatedS);
    // No work top from the path: its Z after the probe is not known before it runs.
    return Prepared{config, *first.plan, first.planned.stats, std::nullopt, std::move(lineEndS),
                    {},     follow};
}

std::optional<Prepared> prepare(const RunArgs &a)
{
    std::optional<machine::MachineConfig> config = cli::loadProfile(a.program.machine);
    if (!config)
        return std::nullopt;
    // The in-process emulator's link has the latency given here: the plan keeps its pace.
    if (a.port == QLatin1String("sim"))
        config->link.latencyMs = a.latencyMs;
    session::InterpretRequest request;
    const auto g =
        cli::interpretFile(a.file, a.program, nullptr, std::uint32_t(a.fromLine), &request);
    if (!g)
        return std::nullopt;
    std::shared_ptr<const gcode::Toolpath> job = g->toolpath;
    if (session::dependsOnProbe(*g->toolpath, g->provisionalEntry)) {
        // Never the provisional path: run whole, each part planned after its probe, or not.
        const QString refusal = session::selfProbingRefusal(
            g->provisionalLine, std::uint32_t(a.fromLine), !a.program.heightMap.isEmpty());
        if (!refusal.isEmpty()) {
            cli::err(QStringLiteral("%1: %2\n").arg(a.file, refusal));
            return std::nullopt;
        }
        return prepareFollow(a, *config, std::move(request), *g);
    }
    std::optional<session::FromLine> approach;
    if (a.fromLine > 0) {
        // The machine stands at its zero when the run starts (the plan's start, as for a whole
        // program): the approach starts there.
        const session::FromLineOutcome from =
            session::runFromLine(*g->toolpath, g->mark, *config, {}, a.file);
        if (!from.ok()) {
            cli::err(from.refusal + QLatin1Char('\n'));
            return std::nullopt;
        }
        cli::err(RunCli::tr("Run from line %1. %2\n")
                     .arg(a.fromLine)
                     .arg(session::fromLineSummary(from.from)));
        job = from.toolpath;
        approach = from.from;
    }
    session::PlanOutcome p = session::planProgram(*job, *config, a.file);
    for (const session::ProgramMessage &w : p.warnings)
        cli::err(RunCli::tr("warning: %1\n").arg(w.text));
    if (!p.ok()) {
        for (const session::ProgramMessage &e : p.errors)
            cli::err(e.text + QLatin1Char('\n'));
        return std::nullopt;
    }
    std::vector<float> lineEndS =
        session::plannedLineTimes(*p.program, p.stats.speedModeVk, p.stats.estimatedS);
    return Prepared{*config,
                    std::move(*p.program),
                    p.stats,
                    workTop(*g->toolpath),
                    std::move(lineEndS),
                    approach,
                    nullptr};
}

double bytesPerVector(const machine::UnitProgram &program, bool checksums)
{
    double bytes = 0;
    int n = 0;
    for (const machine::UnitCommand &c : program.commands) {
        if (c.op != machine::UnitOp::Vector)
            continue;
        const auto cmd = program.axisCount == 4
                             ? protocol::cmd::vector(c.d[0], c.d[1], c.d[2], c.d[3])
                             : protocol::cmd::vector(c.d[0], c.d[1], c.d[2]);
        bytes += static_cast<double>(protocol::encode(cmd, checksums).size());
        ++n;
    }
    return n ? bytes / n : 0;
}

QJsonArray steps(const std::array<std::int64_t, 4> &s, int axes)
{
    QJsonArray a;
    for (int i = 0; i < axes; ++i)
        a.append(static_cast<qint64>(s[static_cast<std::size_t>(i)]));
    return a;
}

void printReport(const RunOutcome &o, const machine::UnitProgram &program,
                 const machine::PlanStats &stats, int baud)
{
    const int axes = program.axisCount;
    const machine::Steps4 expected = o.lastPlanEnd              ? *o.lastPlanEnd
                                     : program.commands.empty() ? program.startSteps
                                                                : program.commands.back().endSteps;
    const driver::JobReport &r = o.report;
    const double streamS = r.lastVectorAckS - r.startS;
    const double bpv = bytesPerVector(program, true);
    QJsonObject j;
    j[QStringLiteral("vectors")] = static_cast<qint64>(r.vectors);
    j[QStringLiteral("final_steps")] = steps(o.finalSteps, axes);
    j[QStringLiteral("expected_steps")] = steps(expected, axes);
    j[QStringLiteral("job_s")] = r.endS - r.startS;
    j[QStringLiteral("estimated_s")] = stats.estimatedS;
    j[QStringLiteral("bound_s")] = stats.boundS;
    j[QStringLiteral("link_bytes")] = static_cast<qint64>(r.linkBytes);
    j[QStringLiteral("wire_limit_vectors_per_s")] = bpv > 0 ? baud / 10.0 / bpv : 0.0;
    j[QStringLiteral("vectors_per_s")] = streamS > 0 ? r.vectors / streamS : 0.0;
    if (o.unitStats) {
        // The unit running dry: the emulator's count less the restarts the plans ask for.
        j[QStringLiteral("starvation_stops")] =
            static_cast<qint64>(o.unitStats->motion.starvationStops - o.plannedRestarts);
        j[QStringLiteral("brake_violations")] =
            static_cast<qint64>(o.unitStats->motion.brakeViolations);
        j[QStringLiteral("axis_over_max")] = static_cast<qint64>(o.unitStats->motion.axisOverMax);
        j[QStringLiteral("cut_without_spindle")] =
            static_cast<qint64>(o.unitStats->safety.cutWithoutSpindle);
        j[QStringLiteral("spindle_on_while_held")] =
            static_cast<qint64>(o.unitStats->safety.spindleOnWhileHeld);
    } else { // a real unit does not count them
        for (const char *key : {"starvation_stops", "brake_violations", "axis_over_max",
                                "cut_without_spindle", "spindle_on_while_held"})
            j[QLatin1String(key)] = QJsonValue::Null;
    }
    // The emulator's own counters (null on a real port: only the polled ones are known).
    j[QStringLiteral("unit_steps")] =
        o.unitSteps ? QJsonValue(steps(*o.unitSteps, axes)) : QJsonValue(QJsonValue::Null);
    // Where the last probe move (G38.x) tripped (null: none did).
    j[QStringLiteral("probe_steps")] =
        o.probeSteps ? QJsonValue(steps(*o.probeSteps, axes)) : QJsonValue(QJsonValue::Null);
    j[QStringLiteral("spindle_on_at_end")] =
        o.spindleOnAtEnd ? QJsonValue(*o.spindleOnAtEnd) : QJsonValue(QJsonValue::Null);
    // The feed override the link could not feed was held down to this (null: never).
    j[QStringLiteral("override_link_min")] = r.overrideLinkMinPercent
                                                 ? QJsonValue(r.overrideLinkMinPercent)
                                                 : QJsonValue(QJsonValue::Null);
    j[QStringLiteral("resent")] = static_cast<qint64>(r.resent);
    j[QStringLiteral("recovered")] = static_cast<qint64>(r.recovered);
    j[QStringLiteral("path_faults")] = static_cast<qint64>(r.pathFaults);
    j[QStringLiteral("program_stops")] = o.programStops;
    // Probe moves after which the rest of a program that probes for itself was planned again.
    j[QStringLiteral("probes_followed")] = o.probesFollowed;
    if (o.cutDepth) { // --cut-depth: the tool's depth below the simulated surface while cutting
        const cli::CutDepth &d = *o.cutDepth;
        auto at = [](const std::array<double, 3> &p) { return QJsonArray{p[0], p[1], p[2]}; };
        j[QStringLiteral("cut_depth")] = QJsonObject{{QStringLiteral("samples"), d.samples},
                                                     {QStringLiteral("min_mm"), d.minMm},
                                                     {QStringLiteral("max_mm"), d.maxMm},
                                                     {QStringLiteral("min_at_mm"), at(d.minAtMm)},
                                                     {QStringLiteral("max_at_mm"), at(d.maxAtMm)}};
    }
    cli::out(QString::fromUtf8(QJsonDocument(j).toJson(QJsonDocument::Compact)) +
             QLatin1Char('\n'));
}

// Run from a line: one more JSON line before the report: the line, the approach's safe height and
// start point (steps) and where the emulator's counters first went below that height (null: a real
// port).
void printFromLine(const RunOutcome &o, const session::FromLine &from,
                   const machine::MachineConfig &config, int axes)
{
    const machine::Steps4 start = machine::stepsOf(from.state.machineMm, config);
    QJsonObject j;
    j[QStringLiteral("from_line")] = static_cast<qint64>(from.line);
    j[QStringLiteral("safe_z_steps")] =
        static_cast<qint64>(machine::stepsOf(from.safeZMm, config.axes[2].stepsPerMm));
    j[QStringLiteral("start_steps")] = steps(start, axes);
    j[QStringLiteral("unit_first_below_safe_z")] = o.firstBelowSteps
                                                       ? QJsonValue(steps(*o.firstBelowSteps, axes))
                                                       : QJsonValue(QJsonValue::Null);
    cli::out(QString::fromUtf8(QJsonDocument(j).toJson(QJsonDocument::Compact)) +
             QLatin1Char('\n'));
}

// Saves the session's serial trace to --trace FILE, naming the run in its header.
bool saveTrace(const RunArgs &a)
{
    driver::TraceRecorder &recorder = driver::TraceRecorder::session();
    recorder.setValue("operation", a.home ? "home, job" : "job");
    recorder.setValue("program", a.file.toStdString());
    QString error;
    if (!recorder.save(a.traceFile, &error)) {
        cli::err(error + QLatin1Char('\n'));
        return false;
    }
    cli::err(RunCli::tr("serial trace saved to %1\n").arg(a.traceFile));
    return true;
}

int runRun(const QStringList &args)
{
    const auto a = parseArgs(args);
    if (!a)
        return usage();
    auto prepared = prepare(*a);
    if (!prepared)
        return 1;
    const auto &[config, program, stats, top, lineEndS, from, follow] = *prepared;
    const session::RemainingTime remaining(lineEndS, stats.estimatedS);
    RunArgs run = *a;
    run.follow = follow;
    if (from && run.virtualClock)
        run.watchBelowZMm = from->safeZMm;
    const RunOutcome o = run.virtualClock ? cli::runVirtual(run, config, program, top, remaining)
                                          : cli::runReal(run, config, program, remaining);
    const int baud = a->baud > 0 ? a->baud : config.link.baud;
    if (!a->traceFile.isEmpty() && !saveTrace(*a))
        return 1;
    if (!o.ok) {
        cli::err(
            RunCli::tr("%1: %2\n")
                .arg(a->file, o.error.isEmpty() ? RunCli::tr("the job did not finish") : o.error));
        return 1;
    }
    if (from) // before the report, which stays the last line
        printFromLine(o, *from, config, program.axisCount);
    printReport(o, program, stats, baud);
    // A program that ends with a probe that tripped ends where it tripped, not at its
    // programmed end (the job stops short there, driver/link/probemove.h).
    // A program that probes for itself ends where its last part was planned to.
    const machine::Steps4 expected = o.probeSteps && *o.probeSteps == o.finalSteps ? *o.probeSteps
                                     : o.lastPlanEnd                               ? *o.lastPlanEnd
                                     : program.commands.empty() ? program.startSteps
                                                                : program.commands.back().endSteps;
    for (int i = 0; i < program.axisCount; ++i) {
        if (o.finalSteps[static_cast<std::size_t>(i)] != expected[static_cast<std::size_t>(i)]) {
            cli::err(RunCli::tr("%1: the unit's counters differ from the planned end position\n")
                         .arg(a->file));
            return 1;
        }
    }
    return 0;
}

} // namespace

FREZKA_CLI_COMMAND(
    run,
    "run FILE [--machine PROFILE] [--offset G54:X,Y,Z[,A]]... [--work-zero X,Y,Z[,A]] "
    "[--port PATH|sim] [--baud N] [--latency-ms N] [--faults RATE --seed N] "
    "[--clock virtual|real] [--home] [--return-to-path] [--feed-override PCT] "
    "[--hold-at-line N [--lift]] [--continue-at-stops] [--from-line N] [--trace FILE] "
    "[--surface SPEC [--cut-depth]]",
    QT_TRANSLATE_NOOP(
        "frezka::cli",
        "Run a G-code job on a GVE unit or the emulator, with progress and a JSON report"),
    runRun);
