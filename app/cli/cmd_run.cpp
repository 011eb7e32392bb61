// frezka-cli run FILE [--machine PROFILE] [--port PATH|sim] [--baud N] [--latency-ms N]
//                     [--faults RATE --seed N] [--clock virtual|real] [--home]
//                     [--return-to-path] [--feed-override PCT] [--hold-at-line N [--lift]]
//
// Interprets and plans FILE for the machine profile, then the session's run workflow (the one
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
#include "cli.h"

#include "driver/link/emulatorport.h"
#include "driver/link/emulatortransport.h"
#include "driver/link/linkworker.h"
#include "gcode/interpreter.h"
#include "machine/planner.h"
#include "session/programplanner.h"
#include "session/qtmachinelink.h"
#include "session/runworkflow.h"
#include "session/simlink.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QFile>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <cmath>
#include <optional>
#include <unistd.h>

namespace {

using namespace frezka;

// The run command's messages (Czech and English in translations/).
struct RunCli
{
    Q_DECLARE_TR_FUNCTIONS(RunCli)
};

struct RunArgs
{
    QString file;
    QString machine;
    QString port = QStringLiteral("sim");
    int baud = 0; // 0 = the profile's
    double latencyMs = 0;
    double faults = 0;
    quint32 seed = 1;
    bool virtualClock = true;
    bool clockGiven = false;
    bool home = false;
    bool returnToPath = false;
    int feedOverride = 0; // 0 = unchanged
    int holdAtLine = 0;   // 0 = no scripted hold
    bool lift = false;
};

// The scripted operator's wait while the job is held (--hold-at-line).
constexpr double kScriptedHoldS = 5.0;

int usage()
{
    cli::err(
        RunCli::tr("usage: frezka-cli run FILE [--machine PROFILE] [--port PATH|sim] [--baud N] "
                   "[--latency-ms N] [--faults RATE --seed N] [--clock virtual|real] [--home] "
                   "[--return-to-path] [--feed-override PCT] [--hold-at-line N [--lift]]\n"));
    return 2;
}

std::optional<RunArgs> parseArgs(const QStringList &args)
{
    RunArgs a;
    for (int i = 0; i < args.size(); ++i) {
        const QString &k = args[i];
        const bool hasValue = i + 1 < args.size();
        bool ok = true;
        if (k == QLatin1String("--machine") && hasValue) {
            a.machine = args[++i];
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
    if ((a.lift && a.holdAtLine == 0) || (a.holdAtLine > 0 && !(sim && a.virtualClock)))
        return std::nullopt; // the scripted operator plays on the virtual clock only
    return a;
}

// Profile, then the program checked and planned as the GUI does it (the session layer; no work
// offsets, from the machine zero). Prints every error; nullopt on failure.
struct Prepared
{
    machine::MachineConfig config;
    machine::UnitProgram program;
    machine::PlanStats stats;
    std::optional<double> workTopMm; // the highest Z a feed move reaches: the top of the work
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

std::optional<Prepared> prepare(const RunArgs &a)
{
    machine::MachineConfig config = machine::defaultMachineConfig(protocol::Variant::Gve64);
    if (!a.machine.isEmpty()) {
        const machine::ConfigResult r = machine::loadMachineConfig(a.machine.toStdString());
        cli::printConfigNotes(r);
        if (!r.config) {
            for (const machine::ConfigError &e : r.errors)
                cli::err(QStringLiteral("%1: %2%3\n")
                             .arg(a.machine,
                                  e.key.empty() ? QString() : QString::fromStdString(e.key) + ": ",
                                  QString::fromStdString(e.message)));
            return std::nullopt;
        }
        config = *r.config;
    }
    // The in-process emulator's link has the latency given here: the plan keeps its pace.
    if (a.port == QLatin1String("sim"))
        config.link.latencyMs = a.latencyMs;
    QFile file(a.file);
    if (!file.open(QIODevice::ReadOnly)) {
        cli::err(gcode::formatError(
                     a.file, {gcode::ErrorCode::FileOpenFailed, 0, 0, a.file.toStdString()}) +
                 QLatin1Char('\n'));
        return std::nullopt;
    }
    session::InterpretRequest request;
    request.text = file.readAll();
    request.fileName = a.file;
    const session::InterpretOutcome g = session::interpretProgram(request);
    if (!g.errors.empty()) {
        for (const session::ProgramMessage &e : g.errors)
            cli::err(e.text + QLatin1Char('\n'));
        return std::nullopt;
    }
    session::PlanOutcome p = session::planProgram(*g.toolpath, config, a.file);
    for (const session::ProgramMessage &w : p.warnings)
        cli::err(RunCli::tr("warning: %1\n").arg(w.text));
    if (!p.ok()) {
        for (const session::ProgramMessage &e : p.errors)
            cli::err(e.text + QLatin1Char('\n'));
        return std::nullopt;
    }
    return Prepared{config, std::move(*p.program), p.stats, workTop(*g.toolpath)};
}

// Progress bar on a terminal (stderr), at most every 0.2 s of wall time.
class Progress
{
public:
    Progress()
        : m_tty(isatty(2) != 0)
    {
        m_wall.start();
    }
    void show(const driver::MachineState &s, bool force = false)
    {
        if (!m_tty || (!force && m_wall.elapsed() < 200))
            return;
        m_wall.restart();
        const int width = 30;
        const int filled = static_cast<int>(std::lround(s.progress * width));
        QString bar = QString(filled, QLatin1Char('#')) + QString(width - filled, QLatin1Char('.'));
        QString eta = s.etaS < 0 ? QStringLiteral("--:--")
                                 : QStringLiteral("%1:%2")
                                       .arg(static_cast<int>(s.etaS) / 60)
                                       .arg(static_cast<int>(s.etaS) % 60, 2, 10, QLatin1Char('0'));
        cli::err(RunCli::tr("\r[%1] %2% line %3 ETA %4 ")
                     .arg(bar)
                     .arg(s.progress * 100, 5, 'f', 1)
                     .arg(s.sourceLine)
                     .arg(eta));
    }
    void done()
    {
        if (m_tty)
            cli::err(QStringLiteral("\n"));
    }

private:
    bool m_tty;
    QElapsedTimer m_wall;
};

struct Outcome
{
    bool ok = false;
    driver::JobReport report;
    std::array<std::int64_t, 4> finalSteps{};
    std::optional<emulator::Stats> unitStats;
    std::optional<bool> spindleOnAtEnd; // the emulator's spindle when the job ended
    QString error;
};

// The scripted operator of --hold-at-line: pause with the spindle stop at line N, (lift), wait,
// (lower), continue. The workflow would end the run at a hold: it waits meanwhile. Empty when
// all went as asked, else why not.
QString scriptedHold(const RunArgs &a, session::SimLink &link, session::RunWorkflow &workflow)
{
    using driver::MachineMode;
    const driver::MachineState &s = link.liveState();
    auto until = [&](const std::function<bool()> &done, const char *what) {
        return link.runUntil([&] { return done() || workflow.hasEnded(); }, 3600) &&
                       !workflow.hasEnded()
                   ? QString()
                   : RunCli::tr("the scripted hold at line %1 failed %2: %3")
                         .arg(a.holdAtLine)
                         .arg(QString::fromLatin1(what),
                              QString::fromStdString(s.lastError ? s.lastError->message
                                                                 : std::string("(no error)")));
    };
    if (QString e = until(
            [&] {
                return s.mode == MachineMode::Running &&
                       s.sourceLine >= std::uint32_t(a.holdAtLine);
            },
            "reaching the line");
        !e.isEmpty())
        return e;
    workflow.setEndOnHold(false);
    link.execute(driver::op::Pause{true});
    if (QString e = until([&] { return s.mode == MachineMode::Paused && !s.spindleOn; }, "pausing");
        !e.isEmpty())
        return e;
    if (a.lift) {
        link.execute(driver::op::ToolLift{true});
        if (QString e = until([&] { return s.mode == MachineMode::ToolLifted; }, "lifting");
            !e.isEmpty())
            return e;
    }
    link.runFor(kScriptedHoldS);
    if (a.lift) {
        link.execute(driver::op::ToolLower{0});
        if (QString e = until(
                [&] {
                    return s.mode == MachineMode::Paused &&
                           s.activity != driver::MachineActivity::ToolLift;
                },
                "lowering");
            !e.isEmpty())
            return e;
    }
    link.execute(driver::op::Resume{});
    if (QString e = until([&] { return s.mode == MachineMode::Running; }, "continuing");
        !e.isEmpty())
        return e;
    workflow.setEndOnHold(true);
    return {};
}

// The in-process emulator on a virtual clock (SimLink), the run workflow turning it.
Outcome runVirtual(const RunArgs &a, const machine::MachineConfig &config,
                   const machine::UnitProgram &program, std::optional<double> workTopMm)
{
    Outcome out;
    driver::WireOptions wire;
    wire.baud = a.baud > 0 ? a.baud : config.link.baud;
    wire.latencyS = a.latencyMs / 1000.0;
    wire.byteErrorRate = a.faults;
    wire.replyLossRate = a.faults;
    wire.seed = a.seed;
    driver::CoreOptions options;
    options.returnToPathAutomatically = a.returnToPath;
    options.link.baud = wire.baud;
    emulator::UnitOptions unit = driver::unitOptionsFor(config);
    if (workTopMm) { // the program starts at the machine's zero: its Z is the counter's
        unit.machine.hasWorkSurface = true;
        unit.machine.workSurfaceZSteps = std::llround(*workTopMm * config.axes[2].stepsPerMm);
    }
    session::SimLink link(config, unit, wire, options);
    session::RunWorkflow workflow(link);
    workflow.setProfile(config);
    workflow.setEndOnHold(true); // nobody at the machine to answer a hold
    workflow.setProgram(std::make_shared<const machine::UnitProgram>(program), {}, a.file);
    bool ended = false;
    QObject::connect(&workflow, &session::RunWorkflow::runEnded, [&](bool ok) { ended = ok; });
    Progress progress;
    workflow.start(session::RunWorkflow::connectionFor(config), a.home);
    if (a.feedOverride > 0) {
        link.runUntil([&] { return link.liveState().jobActive || workflow.hasEnded(); }, 600);
        link.execute(driver::op::SetOverride{a.feedOverride});
    }
    if (a.holdAtLine > 0) {
        if (QString e = scriptedHold(a, link, workflow); !e.isEmpty()) {
            out.error = e;
            out.unitStats = link.port().unit().stats();
            return out;
        }
    }
    while (!workflow.hasEnded()) {
        link.runFor(0.25);
        if (link.liveState().jobActive)
            progress.show(link.liveState());
        if (link.liveState().mode == driver::MachineMode::Connecting && link.now() > 120) {
            out.error = RunCli::tr("could not connect to the emulator");
            return out;
        }
    }
    progress.show(link.liveState(), true);
    progress.done();
    out.ok = ended;
    out.error = workflow.error();
    out.report = link.jobReport();
    out.finalSteps = link.liveState().positionSteps;
    out.unitStats = link.port().unit().stats();
    out.spindleOnAtEnd = link.port().unit().spindleTurning();
    return out;
}

// A serial port / pty, or the emulator in real time: the link worker on this thread's event
// loop, exactly as the GUI drives it (without the extra thread), the run workflow driving it.
Outcome runReal(const RunArgs &a, const machine::MachineConfig &config,
                const machine::UnitProgram &program)
{
    Outcome out;
    driver::LinkWorker worker;
    driver::CoreOptions options;
    options.returnToPathAutomatically = a.returnToPath;
    options.link.baud = a.baud > 0 ? a.baud : config.link.baud;
    worker.setCoreOptions(options);
    driver::EmulatorTransport *emulated = nullptr;
    worker.setTransportFactory([&](const driver::ConnectionSettings &s,
                                   const machine::MachineConfig &c, QObject *parent,
                                   QString *error) -> driver::Transport * {
        driver::Transport *t = driver::createTransport(s, c, parent, error);
        emulated = qobject_cast<driver::EmulatorTransport *>(t);
        return t;
    });
    session::QtMachineLink<driver::LinkWorker> link(worker);
    session::RunWorkflow workflow(link);
    workflow.setProfile(config);
    workflow.setEndOnHold(true);
    workflow.setProgram(std::make_shared<const machine::UnitProgram>(program), {}, a.file);
    std::optional<bool> finished;
    QEventLoop loop;
    Progress progress;
    QObject::connect(&workflow, &session::RunWorkflow::runEnded, &loop, [&](bool ok) {
        finished = ok;
        loop.quit();
    });
    bool overrideSent = a.feedOverride == 0;
    QObject::connect(&link, &session::MachineLink::stateChanged, &loop,
                     [&](const driver::MachineState &s) {
                         if (s.jobActive && !overrideSent) {
                             overrideSent = true;
                             link.execute(driver::op::SetOverride{a.feedOverride});
                         }
                         if (s.jobActive)
                             progress.show(s);
                     });
    driver::ConnectionSettings settings;
    const bool sim = a.port == QLatin1String("sim");
    settings.kind = sim ? driver::ConnectionSettings::Kind::Emulator
                        : driver::ConnectionSettings::Kind::SerialPort;
    settings.portName = a.port;
    settings.baud = options.link.baud;
    settings.latencyMs = a.latencyMs;
    settings.faultRate = a.faults;
    settings.seed = a.seed;
    QTimer::singleShot(0, &worker, [&] { workflow.start(settings, a.home); });
    loop.exec();
    progress.show(link.state(), true);
    progress.done();
    out.ok = finished.value_or(false);
    out.error = workflow.error();
    out.report = worker.jobReport();
    out.finalSteps = link.state().positionSteps;
    if (emulated) {
        out.unitStats = emulated->unit().stats();
        out.spindleOnAtEnd = emulated->unit().spindleTurning();
    }
    worker.disconnectFromUnit();
    return out;
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

void printReport(const Outcome &o, const machine::UnitProgram &program,
                 const machine::PlanStats &stats, int baud)
{
    const int axes = program.axisCount;
    const machine::Steps4 expected =
        program.commands.empty() ? program.startSteps : program.commands.back().endSteps;
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
        j[QStringLiteral("starvation_stops")] =
            static_cast<qint64>(o.unitStats->motion.starvationStops);
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
    j[QStringLiteral("spindle_on_at_end")] =
        o.spindleOnAtEnd ? QJsonValue(*o.spindleOnAtEnd) : QJsonValue(QJsonValue::Null);
    // The feed override the link could not feed was held down to this (null: never).
    j[QStringLiteral("override_link_min")] = r.overrideLinkMinPercent
                                                 ? QJsonValue(r.overrideLinkMinPercent)
                                                 : QJsonValue(QJsonValue::Null);
    j[QStringLiteral("resent")] = static_cast<qint64>(r.resent);
    j[QStringLiteral("recovered")] = static_cast<qint64>(r.recovered);
    j[QStringLiteral("path_faults")] = static_cast<qint64>(r.pathFaults);
    cli::out(QString::fromUtf8(QJsonDocument(j).toJson(QJsonDocument::Compact)) +
             QLatin1Char('\n'));
}

int runRun(const QStringList &args)
{
    const auto a = parseArgs(args);
    if (!a)
        return usage();
    auto prepared = prepare(*a);
    if (!prepared)
        return 1;
    const auto &[config, program, stats, top] = *prepared;
    const Outcome o =
        a->virtualClock ? runVirtual(*a, config, program, top) : runReal(*a, config, program);
    const int baud = a->baud > 0 ? a->baud : config.link.baud;
    if (!o.ok) {
        cli::err(
            RunCli::tr("%1: %2\n")
                .arg(a->file, o.error.isEmpty() ? RunCli::tr("the job did not finish") : o.error));
        return 1;
    }
    printReport(o, program, stats, baud);
    const machine::Steps4 expected =
        program.commands.empty() ? program.startSteps : program.commands.back().endSteps;
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
    "run FILE [--machine PROFILE] [--port PATH|sim] [--baud N] [--latency-ms N] "
    "[--faults RATE --seed N] [--clock virtual|real] [--home] [--return-to-path] "
    "[--feed-override PCT] [--hold-at-line N [--lift]]",
    "Run a G-code job on a GVE unit or the emulator, with progress and a JSON report", runRun);
