// frezka-cli run: the job run by the session's run workflow, on the emulator's virtual clock
// (SimLink, with the scripted operator of --hold-at-line) or on a real link (LinkWorker), with
// the progress bar on a terminal.
#include "runjob.h"

#include "cli.h"

#include "driver/link/emulatortransport.h"
#include "driver/link/linkworker.h"
#include "driver/link/tracingtransport.h"
#include "machine/steps.h"
#include "session/programtext.h"
#include "session/qtmachinelink.h"
#include "session/runworkflow.h"
#include "session/simlink.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QFile>
#include <QSocketNotifier>
#include <QTimer>

#include <cmath>
#include <cstdio>
#include <functional>
#include <unistd.h>

namespace frezka::cli {

namespace {

// The scripted operator's wait while the job is held (--hold-at-line).
constexpr double kScriptedHoldS = 5.0;

// Progress bar on a terminal (stderr), at most every 0.2 s of wall time; the time left from the
// planner's model at the line being cut (session::RemainingTime: it counts down through
// dwells), the driver's own estimate where nothing was planned.
class Progress
{
public:
    explicit Progress(session::RemainingTime remaining)
        : m_tty(isatty(2) != 0)
        , m_remaining(std::move(remaining))
    {
        m_wall.start();
    }
    // nowS: the job's clock (virtual or wall seconds).
    void show(const driver::MachineState &s, double nowS, bool force = false)
    {
        const double planned =
            m_remaining.at(s.sourceLine, nowS, s.mode == driver::MachineMode::Running);
        if (!m_tty || (!force && m_wall.elapsed() < 200))
            return;
        m_wall.restart();
        const int width = 30;
        const int filled = static_cast<int>(std::lround(s.progress * width));
        QString bar = QString(filled, QLatin1Char('#')) + QString(width - filled, QLatin1Char('.'));
        const double left = planned >= 0 ? planned : s.etaS;
        QString eta = left < 0 ? QStringLiteral("--:--")
                               : QStringLiteral("%1:%2")
                                     .arg(static_cast<int>(left) / 60)
                                     .arg(static_cast<int>(left) % 60, 2, 10, QLatin1Char('0'));
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
    // A line of its own (a prompt) while the bar is shown.
    void interrupt()
    {
        if (m_tty)
            cli::err(QStringLiteral("\n"));
    }

private:
    bool m_tty;
    session::RemainingTime m_remaining;
    QElapsedTimer m_wall;
};

// The program's own stops (M0, M1, M6) of an attended run: the prompt on stderr names the stop
// and its line's comment, Enter on standard input continues, the end of the input ends the run
// at the stop (nobody there to answer).
class StopPrompt
{
public:
    StopPrompt(const RunArgs &a, session::RunWorkflow &workflow, Progress &progress)
        : m_workflow(workflow)
        , m_progress(progress)
    {
        QFile file(a.file);
        if (file.open(QIODevice::ReadOnly))
            m_text = session::ProgramText(file.readAll());
    }
    void ask(std::uint32_t line, const QString &text)
    {
        m_progress.interrupt();
        const QString comment = m_text.comment(int(line));
        cli::err(
            RunCli::tr("%1%2. Press Enter to continue.\n")
                .arg(text, comment.isEmpty() ? QString() : QStringLiteral(" (%1)").arg(comment)));
    }
    // A line read (or the end of the input): continue, or end the run at the stop.
    void answer(bool gotLine)
    {
        if (gotLine) {
            m_workflow.resume();
            return;
        }
        cli::err(RunCli::tr("No answer on standard input: the job ends at the stop (use "
                            "--continue-at-stops for an unattended run).\n"));
        m_workflow.setProgramStops(session::RunWorkflow::ProgramStops::End);
        m_workflow.abort();
    }
    // Blocks until a line or the end of standard input (the virtual clock waits meanwhile).
    void readBlocking()
    {
        char buffer[256];
        answer(std::fgets(buffer, sizeof buffer, stdin) != nullptr);
    }

private:
    session::RunWorkflow &m_workflow;
    Progress &m_progress;
    session::ProgramText m_text;
};

// A program that probes for itself: the workflow follows its probes; each one's rest is counted
// and its plan's end kept for the final check.
void followProbes(const RunArgs &a, session::RunWorkflow &workflow, RunOutcome &out)
{
    if (!a.follow)
        return;
    workflow.setProbeFollow(a.follow.get());
    QObject::connect(&workflow, &session::RunWorkflow::probeFollowed,
                     [&out](std::uint32_t line, const session::ProbeFollow::Next &next) {
                         ++out.probesFollowed;
                         const machine::UnitProgram &p = *next.plan;
                         out.lastPlanEnd =
                             p.commands.empty() ? p.startSteps : p.commands.back().endSteps;
                         cli::err(RunCli::tr("line %1: the probe has run; the rest of the program "
                                             "runs as interpreted with its result\n")
                                      .arg(line));
                     });
}

void setProgramStops(const RunArgs &a, session::RunWorkflow &workflow)
{
    workflow.setProgramStops(a.continueAtStops ? session::RunWorkflow::ProgramStops::Continue
                                               : session::RunWorkflow::ProgramStops::Ask);
}

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

// The connection of --port: the in-process emulator in real time (sim), or a serial port / pty.
driver::ConnectionSettings connectionSettings(const RunArgs &a, int baud)
{
    driver::ConnectionSettings settings;
    const bool sim = a.port == QLatin1String("sim");
    settings.kind = sim ? driver::ConnectionSettings::Kind::Emulator
                        : driver::ConnectionSettings::Kind::SerialPort;
    settings.portName = a.port;
    settings.baud = baud;
    settings.latencyMs = a.latencyMs;
    settings.faultRate = a.faults;
    settings.seed = a.seed;
    return settings;
}

// Run from a line: the first of the emulator's traced positions below the approach's safe
// height (the trace is read and dropped as the job runs, so it never grows).
void watchBelow(const RunArgs &a, const machine::MachineConfig &config, emulator::Unit &unit,
                RunOutcome &out)
{
    if (!a.watchBelowZMm)
        return;
    const std::int64_t below = machine::stepsOf(*a.watchBelowZMm, config.axes[2].stepsPerMm);
    for (const emulator::TracePoint &p : unit.trace()) {
        if (out.firstBelowSteps || p.position[2] >= below)
            continue;
        out.firstBelowSteps =
            std::array<std::int64_t, 4>{p.position[0], p.position[1], p.position[2], p.position[3]};
    }
    unit.clearTrace();
}

// --cut-depth: one sample of the unit's counters (see CutDepth); *last: the previous sample.
void sampleCutDepth(const emulator::Unit &unit, const emulator::ProbeSurface &surface,
                    std::array<std::int64_t, 4> *last, CutDepth &depth)
{
    const std::array<std::int64_t, 4> at = unit.position();
    const bool movedXY = at[0] != (*last)[0] || at[1] != (*last)[1];
    *last = at;
    const std::array<double, 3> mm{double(at[0]) / surface.stepsPerMm[0],
                                   double(at[1]) / surface.stepsPerMm[1],
                                   double(at[2]) / surface.stepsPerMm[2]};
    const double below = surface.heightMm(mm[0], mm[1]) - mm[2];
    if (!movedXY || below < -CutDepth::kCutBandMm)
        return;
    if (depth.samples == 0 || below < depth.minMm) {
        depth.minMm = below;
        depth.minAtMm = mm;
    }
    if (depth.samples == 0 || below > depth.maxMm) {
        depth.maxMm = below;
        depth.maxAtMm = mm;
    }
    ++depth.samples;
}

} // namespace

RunOutcome runVirtual(const RunArgs &a, const machine::MachineConfig &config,
                      const machine::UnitProgram &program, std::optional<double> workTopMm,
                      session::RemainingTime remaining)
{
    RunOutcome out;
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
        unit.machine.workSurfaceZSteps = machine::stepsOf(*workTopMm, config.axes[2].stepsPerMm);
    }
    if (!a.surface.isEmpty()) // checked by parseArgs; the surface in machine mm
        driver::setProbeSurface(unit, a.surface.toStdString(), config);
    unit.trace = a.watchBelowZMm.has_value();
    driver::TraceRecorder &recorder = driver::TraceRecorder::session();
    const auto &variant = protocol::variantInfo(config.unit.variant);
    recorder.begin({{"variant", std::string(variant.id)},
                    {"baud", std::to_string(wire.baud)},
                    {"port", "built-in emulator"},
                    {"clock", "virtual"}},
                   0);
    session::SimLink link(config, unit, wire, options, nullptr,
                          a.traceFile.isEmpty() ? nullptr : &recorder);
    session::RunWorkflow workflow(link);
    workflow.setProfile(config);
    workflow.setEndOnHold(true); // nobody at the machine to answer a hold
    workflow.setProgram(std::make_shared<const machine::UnitProgram>(program), {}, a.file);
    followProbes(a, workflow, out);
    bool ended = false;
    QObject::connect(&workflow, &session::RunWorkflow::runEnded, [&](bool ok) { ended = ok; });
    Progress progress(std::move(remaining));
    setProgramStops(a, workflow);
    StopPrompt prompt(a, workflow, progress);
    QObject::connect(&workflow, &session::RunWorkflow::programStopped,
                     [&](std::uint32_t line, const QString &text) {
                         prompt.ask(line, text);
                         prompt.readBlocking();
                     });
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
    std::array<std::int64_t, 4> lastSample = link.port().unit().position();
    if (a.cutDepth)
        out.cutDepth = CutDepth{};
    while (!workflow.hasEnded()) {
        link.runFor(a.cutDepth ? CutDepth::kCutSampleS : 0.25);
        if (a.cutDepth)
            sampleCutDepth(link.port().unit(), unit.surface, &lastSample, *out.cutDepth);
        watchBelow(a, config, link.port().unit(), out);
        if (link.liveState().jobActive)
            progress.show(link.liveState(), link.now());
        if (link.liveState().mode == driver::MachineMode::Connecting && link.now() > 120) {
            out.error = RunCli::tr("could not connect to the emulator");
            return out;
        }
    }
    progress.show(link.liveState(), link.now(), true);
    progress.done();
    out.ok = ended;
    out.programStops = workflow.programStopsSeen();
    out.error = workflow.error();
    out.report = link.jobReport();
    out.plannedRestarts = workflow.plannedRestarts();
    out.finalSteps = link.liveState().positionSteps;
    out.unitStats = link.port().unit().stats();
    out.spindleOnAtEnd = link.port().unit().spindleTurning();
    out.unitSteps = link.port().unit().position();
    if (link.liveState().probeTripped)
        out.probeSteps = link.liveState().probeSteps;
    return out;
}

RunOutcome runReal(const RunArgs &a, const machine::MachineConfig &config,
                   const machine::UnitProgram &program, session::RemainingTime remaining)
{
    RunOutcome out;
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
        auto *traced = qobject_cast<driver::TracingTransport *>(t);
        emulated = qobject_cast<driver::EmulatorTransport *>(traced ? traced->inner() : t);
        return t;
    });
    session::QtMachineLink<driver::LinkWorker> link(worker);
    session::RunWorkflow workflow(link);
    workflow.setProfile(config);
    workflow.setEndOnHold(true);
    workflow.setProgram(std::make_shared<const machine::UnitProgram>(program), {}, a.file);
    followProbes(a, workflow, out);
    std::optional<bool> finished;
    QEventLoop loop;
    Progress progress(std::move(remaining));
    setProgramStops(a, workflow);
    StopPrompt prompt(a, workflow, progress);
    // Standard input is read when it has something, so that the link runs on meanwhile.
    QSocketNotifier input(STDIN_FILENO, QSocketNotifier::Read);
    input.setEnabled(false);
    QObject::connect(&workflow, &session::RunWorkflow::programStopped,
                     [&](std::uint32_t line, const QString &text) {
                         prompt.ask(line, text);
                         input.setEnabled(true);
                     });
    QObject::connect(&input, &QSocketNotifier::activated, &loop, [&] {
        input.setEnabled(false);
        prompt.readBlocking();
    });
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
                             progress.show(s, workflow.jobElapsedS());
                     });
    const driver::ConnectionSettings settings = connectionSettings(a, options.link.baud);
    QTimer::singleShot(0, &worker, [&] { workflow.start(settings, a.home); });
    loop.exec();
    progress.show(link.state(), workflow.jobElapsedS(), true);
    progress.done();
    out.ok = finished.value_or(false);
    out.programStops = workflow.programStopsSeen();
    out.error = workflow.error();
    out.report = worker.jobReport();
    out.plannedRestarts = workflow.plannedRestarts();
    out.finalSteps = link.state().positionSteps;
    if (emulated) {
        out.unitStats = emulated->unit().stats();
        out.spindleOnAtEnd = emulated->unit().spindleTurning();
        out.unitSteps = emulated->unit().position();
    }
    worker.disconnectFromUnit();
    return out;
}

} // namespace frezka::cli
