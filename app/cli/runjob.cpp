// frezka-cli run: the job run by the session's run workflow, on the emulator's virtual clock
// (SimLink, with the scripted operator of --hold-at-line) or on a real link (LinkWorker), with
// the progress bar on a terminal.
#include "runjob.h"

#include "cli.h"

#include "driver/link/emulatortransport.h"
#include "driver/link/linkworker.h"
#include "machine/steps.h"
#include "session/qtmachinelink.h"
#include "session/runworkflow.h"
#include "session/simlink.h"

#include <QElapsedTimer>
#include <QEventLoop>
#include <QTimer>

#include <cmath>
#include <functional>
#include <unistd.h>

namespace frezka::cli {

namespace {

// The scripted operator's wait while the job is held (--hold-at-line).
constexpr double kScriptedHoldS = 5.0;

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

} // namespace

RunOutcome runVirtual(const RunArgs &a, const machine::MachineConfig &config,
                      const machine::UnitProgram &program, std::optional<double> workTopMm)
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

RunOutcome runReal(const RunArgs &a, const machine::MachineConfig &config,
                   const machine::UnitProgram &program)
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
    const driver::ConnectionSettings settings = connectionSettings(a, options.link.baud);
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

} // namespace frezka::cli
