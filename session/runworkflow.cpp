#include "runworkflow.h"

#include "machine/steps.h"

#include <cmath>
#include <utility>

namespace frezka::session {

using driver::MachineMode;

RunWorkflow::RunWorkflow(MachineLink &link, QObject *parent)
    : QObject(parent)
    , m_link(link)
{
    connect(&m_link, &MachineLink::stateChanged, this, &RunWorkflow::onState);
    connect(&m_link, &MachineLink::errorOccurred, this, &RunWorkflow::onError);
    connect(&m_link, &MachineLink::jobFinished, this, &RunWorkflow::onJobFinished);
    m_reconnect.setSingleShot(true);
    connect(&m_reconnect, &QTimer::timeout, this, [this] {
        if (!m_userDisconnected && state().mode == MachineMode::LinkLost)
            connectToUnit(m_settings);
    });
}

QString RunWorkflow::modeText(MachineMode mode)
{
    switch (mode) {
    case MachineMode::Disconnected:
        return tr("Not connected");
    case MachineMode::Connecting:
        return tr("Connecting…");
    case MachineMode::Idle:
        return tr("Ready");
    case MachineMode::Homing:
        return tr("Homing");
    case MachineMode::Jogging:
        return tr("Jogging");
    case MachineMode::Running:
        return tr("Running");
    case MachineMode::Stopping:
        return tr("Stopping");
    case MachineMode::Paused:
        return tr("Paused");
    case MachineMode::ToolLifted:
        return tr("Tool lifted");
    case MachineMode::Alarm:
        return tr("Alarm");
    case MachineMode::LinkLost:
        return tr("Link lost");
    }
    return {};
}

driver::ConnectionSettings RunWorkflow::connectionFor(const machine::MachineConfig &config)
{
    driver::ConnectionSettings settings;
    const QString port = QString::fromStdString(config.link.port);
    if (port.isEmpty() || port == QLatin1String("emulator")) {
        settings.kind = driver::ConnectionSettings::Kind::Emulator;
        // A simulated work top to probe on (README, "Height map"), without hardware.
        settings.surface = qEnvironmentVariable("FREZKA_EMULATOR_SURFACE");
    } else {
        settings.kind = driver::ConnectionSettings::Kind::SerialPort;
        settings.portName = port;
    }
    settings.baud = config.link.baud;
    return settings;
}

void RunWorkflow::setProfile(const machine::MachineConfig &config)
{
    m_profile = config;
    m_link.setMachineConfig(config);
}

// ---- connection

void RunWorkflow::connectToUnit(const driver::ConnectionSettings &settings)
{
    m_userDisconnected = false;
    m_connectionAsked = true;
    m_settings = settings;
    m_link.setMachineConfig(m_profile);
    const bool emulator = settings.kind == driver::ConnectionSettings::Kind::Emulator;
    emit message(tr("Connecting to %1 at %2 Bd…")
                     .arg(emulator ? tr("the built-in emulator") : settings.portName)
                     .arg(settings.baud));
    m_link.connectTo(settings);
}

void RunWorkflow::disconnectFromUnit()
{
    m_userDisconnected = true;
    m_reconnect.stop();
    m_link.disconnectFromUnit();
}

void RunWorkflow::setAutoReconnect(bool on, int delayMs)
{
    m_autoReconnect = on;
    m_reconnect.setInterval(delayMs);
    if (!on)
        m_reconnect.stop();
}

// ---- the program

void RunWorkflow::setProgram(std::shared_ptr<const machine::UnitProgram> plan,
                             const Position &startMm, const QString &name,
                             const QString &notRunnable)
{
    m_plan = std::move(plan);
    m_planStart = startMm;
    m_name = name;
    m_notRunnable = notRunnable;
    m_planEndsAtProbe = false;
    const Pending pending = std::exchange(m_pending, Pending::None);
    if (pending == Pending::Check)
        emit checked(m_plan != nullptr);
    if (pending == Pending::Run && m_plan)
        startJob();
    else if (pending == Pending::Run && m_step == Step::Running)
        end(false, m_notRunnable);
}

bool RunWorkflow::planStartsHere() const
{
    const auto &st = state();
    return m_planStart == st.positionMm && m_plan->startSteps == st.positionSteps;
}

void RunWorkflow::runProgram()
{
    if (!m_plan && !m_follow) {
        const QString why =
            m_notRunnable.isEmpty()
                ? tr("Open a program first.")
                : tr("The program has errors and cannot run:\n%1").arg(m_notRunnable);
        emit failed(why);
        if (m_step == Step::Running)
            end(false, why);
        return;
    }
    if (state().mode != MachineMode::Idle) {
        const QString why = tr("The machine is not ready (%1); wait until it is, then Run.")
                                .arg(modeText(state().mode));
        emit failed(why);
        if (m_step == Step::Running)
            end(false, why);
        return;
    }
    // The headless sequence (frezka-cli run) homes when told to (--home) and warns otherwise.
    if (!state().homed) {
        if (!m_profile.motion.runBeforeHoming && m_step != Step::Running) {
            emit message(tr("The machine is not homed: home it first, then Run."));
            emit homingNeeded();
            return;
        }
        emit message(tr("Warning: the machine is not homed; the program runs from counters "
                        "that were not set by homing (motion.runBeforeHoming)."));
    }
    if (m_follow) { // the whole program from here, up to its first probe
        ProbeFollow::Next next = m_follow->start(state().positionMm);
        if (!next.plan) {
            emit failed(next.error);
            if (m_step == Step::Running)
                end(false, next.error);
            return;
        }
        m_plan = next.plan;
        m_planStart = state().positionMm;
        m_planEndsAtProbe = next.endsAtProbe;
        m_probesFollowed = 0;
        startJob();
        return;
    }
    // The plan is relative to where it starts: re-plan from the machine's actual position.
    if (m_replan && !planStartsHere()) {
        m_pending = Pending::Run;
        emit message(tr("Planning from the current position…"));
        m_replan(state().positionMm);
        return;
    }
    startJob();
}

void RunWorkflow::startJobClock()
{
    m_jobClock.start();
    m_jobStartS = m_link.clockS();
}

double RunWorkflow::jobElapsedS() const
{
    if (!m_jobClock.isValid())
        return m_lastJobS;
    if (const std::optional<double> now = m_link.clockS(); now && m_jobStartS)
        return *now - *m_jobStartS;
    return double(m_jobClock.elapsed()) / 1000.0;
}

void RunWorkflow::startJob()
{
    emit message(tr("Running %1.").arg(m_name));
    startJobClock();
    emit jobStarted();
    m_plannedRestarts = machine::plannedRestarts(*m_plan);
    m_link.run(*m_plan);
}

void RunWorkflow::stop()
{
    // Stop: a controlled halt along the ramp, the job resumable; the spindle and coolant go off
    // once the machine stands and come back on (after the spin-up) when the job resumes.
    const MachineMode mode = state().mode;
    if (mode == MachineMode::Running)
        m_link.execute(driver::op::Pause{true});
    else if (mode == MachineMode::Homing)
        m_link.pause();
}

void RunWorkflow::homeThenRun()
{
    m_runAfterHoming = true;
    emit message(tr("Homing, then running the program…"));
    m_link.home(0xF);
}

void RunWorkflow::checkProgram()
{
    if (!m_replan) {
        emit checked(m_plan != nullptr);
        return;
    }
    m_pending = Pending::Check;
    m_replan(state().positionMm);
}

void RunWorkflow::start(const driver::ConnectionSettings &settings, bool homeFirst)
{
    m_homeFirst = homeFirst;
    m_error.clear();
    m_step = Step::Connecting;
    if (state().mode == MachineMode::Idle)
        advance(state(), MachineMode::Idle); // already connected
    else
        connectToUnit(settings);
}

void RunWorkflow::end(bool ok, const QString &why)
{
    if (m_step == Step::Ended || m_step == Step::None)
        return;
    m_step = Step::Ended;
    if (!ok)
        m_error = why; // what ended the run (an earlier error may have been survived)
    emit runEnded(ok);
}

// ---- during a job

void RunWorkflow::toolLift(bool stopSpindle)
{
    m_link.toolLift(stopSpindle);
}

void RunWorkflow::lowerTool(double newFeedMmPerMin, bool thenContinue)
{
    // The driver switches the spindle and coolant on again and waits their spin-up before the
    // tool goes down (K/R and the new speed are its too); continue once it is held again, down.
    int pulses = 0;
    if (newFeedMmPerMin > 0)
        pulses =
            int(std::llround(machine::pulseRateOf(newFeedMmPerMin, m_profile.axes[0].stepsPerMm)));
    m_continueAfterLower = thenContinue;
    m_link.toolLower(pulses);
}

// ---- what the machine reports

void RunWorkflow::onState(const driver::MachineState &s)
{
    const MachineMode last = std::exchange(m_lastMode, s.mode);
    if (s.jobActive && !m_jobClock.isValid())
        startJobClock(); // a job not started here (a console line, one kept over a lost link)
    if (s.mode == MachineMode::LinkLost && last != MachineMode::LinkLost) {
        emit linkLost();
        if (m_autoReconnect && !m_userDisconnected)
            m_reconnect.start();
    }
    if (s.mode == MachineMode::Idle && last == MachineMode::Connecting)
        emit connected();
    if (s.mode == MachineMode::Paused && m_continueAfterLower) {
        m_continueAfterLower = false; // the tool is back down after "Lower and continue"
        m_link.resume();
    }
    if (m_runAfterHoming && s.mode == MachineMode::Idle && last == MachineMode::Homing) {
        m_runAfterHoming = false;
        if (s.homed)
            runProgram();
        else
            emit failed(tr("Homing did not finish; the program was not started."));
    }
    watchStartInput(s);
    if (m_step != Step::None && m_step != Step::Ended)
        advance(s, last);
}

// The START button: its press (the edge to the active level of unit.startInput, at the
// polarity of eeprom.polarity) while connected. Forgotten over a new connection, so that a
// button held while connecting does nothing.
void RunWorkflow::watchStartInput(const driver::MachineState &s)
{
    const int input = m_profile.unit.startInput;
    if (input < 3 || input > 7 || s.mode == MachineMode::Connecting ||
        s.mode == MachineMode::Disconnected || s.mode == MachineMode::LinkLost) {
        m_startActive = -1;
        return;
    }
    const int active = s.inputActive(m_profile, input) ? 1 : 0;
    const int was = std::exchange(m_startActive, active);
    if (was == 0 && active == 1)
        startPressed();
}

void RunWorkflow::startPressed()
{
    const MachineMode mode = state().mode;
    if (mode == MachineMode::Paused) {
        emit message(tr("START button: resuming the job."));
        m_link.resume();
    } else if (mode == MachineMode::Idle && m_plan && !state().jobActive) {
        emit message(tr("START button: running %1.").arg(m_name));
        runProgram();
    } else {
        emit message(
            tr("START button ignored: nothing to start or resume (%1).").arg(modeText(mode)));
    }
}

// The headless sequence: connecting -> (homing) -> running -> ended.
void RunWorkflow::advance(const driver::MachineState &s, MachineMode last)
{
    if (s.mode == MachineMode::Alarm || s.mode == MachineMode::LinkLost ||
        (s.mode == MachineMode::Disconnected && last != MachineMode::Disconnected)) {
        QString why = tr("the machine stopped: %1").arg(modeText(s.mode));
        if (s.lastError) // the driver's words in the user's language
            why += QStringLiteral(" (%1)").arg(driver::translatedText(s.lastError->reason, true));
        end(false, why);
        return;
    }
    if (m_step == Step::Running && answerProgramStop(s))
        return;
    if (m_step == Step::Running && m_endOnHold && s.mode == MachineMode::Paused) {
        end(false, tr("the job stopped: %1").arg(driver::translatedText(s.holdMessage)));
        return;
    }
    if (s.mode != MachineMode::Idle)
        return;
    if (m_step == Step::Connecting && m_homeFirst) {
        m_step = Step::Homing;
        m_link.home(0xF);
    } else if (m_step == Step::Connecting || (m_step == Step::Homing && s.homed)) {
        m_step = Step::Running;
        runProgram();
    } else if (m_step == Step::Homing && last == MachineMode::Homing) {
        end(false, tr("homing did not finish"));
    }
}

// An M0 / M1 / M6 hold of the headless run, answered once as setProgramStops() says: true when
// the state is such a hold (answered now or before), false for everything else.
bool RunWorkflow::answerProgramStop(const driver::MachineState &s)
{
    const bool atStop = s.mode == MachineMode::Paused && s.hold == driver::HoldReason::OperatorStop;
    const bool first = atStop && (!m_atProgramStop || s.holdLine != m_programStopLine);
    m_atProgramStop = atStop;
    m_programStopLine = atStop ? s.holdLine : 0;
    if (!atStop || m_programStops == ProgramStops::End)
        return false;
    if (!first)
        return true;
    ++m_programStopsSeen;
    const QString text = driver::translatedText(s.holdMessage);
    if (m_programStops == ProgramStops::Ask) {
        emit programStopped(s.holdLine, text);
        return true;
    }
    emit message(tr("%1: continuing without an operator.").arg(text));
    m_link.resume();
    return true;
}

void RunWorkflow::onError(const driver::MachineError &e)
{
    if (m_step == Step::None || m_step == Step::Ended)
        return;
    m_error = driver::translatedText(e.reason, true);
    if (!e.command.empty())
        m_error += tr(" [command %1]").arg(QString::fromStdString(e.command));
    if (!e.reply.empty())
        m_error += tr(" [reply '%1']").arg(QString::fromStdString(e.reply));
    // An operation refused or a port that did not open ends the sequence; while the machine
    // is busy (connecting, homing, a job) it ends by the state or the job's end instead.
    const auto &st = state();
    const bool busy =
        st.mode == MachineMode::Connecting || st.mode == MachineMode::Homing || st.jobActive;
    if (!busy)
        end(false, m_error);
}

// The job ended with its probe move (ProbeFollow plans each job up to the next probe): the
// rest of the program, interpreted again with the probe's result, runs on from where the
// machine stands. False when it cannot (the reason is the run's error).
bool RunWorkflow::followProbe()
{
    const driver::MachineState &s = state();
    const gcode::Point4 at{s.positionMm[0], s.positionMm[1], s.positionMm[2], s.positionMm[3]};
    const std::uint32_t line = m_plan->commands.empty() ? 0 : m_plan->commands.back().sourceLine;
    ProbeFollow::Next next = m_follow->afterProbe(at, s.probeTripped);
    if (!next.plan) {
        m_error = next.error;
        emit failed(next.error);
        return false;
    }
    ++m_probesFollowed;
    const QString text =
        s.probeTripped ? tr("Line %1: the probe touched at X %2 Y %3 Z %4 (machine); the rest of "
                            "the program runs as interpreted with that result.")
                       : tr("Line %1: the probe stopped at X %2 Y %3 Z %4 (machine) without "
                            "touching; the rest of the program runs as interpreted with that "
                            "result.");
    emit message(text.arg(line)
                     .arg(s.positionMm[0], 0, 'f', 3)
                     .arg(s.positionMm[1], 0, 'f', 3)
                     .arg(s.positionMm[2], 0, 'f', 3));
    m_plan = next.plan;
    m_planStart = s.positionMm;
    m_planEndsAtProbe = next.endsAtProbe;
    emit probeFollowed(line, next);
    m_plannedRestarts += machine::plannedRestarts(*m_plan);
    m_link.run(*m_plan);
    return true;
}

void RunWorkflow::onJobFinished(bool ok)
{
    if (ok && m_follow && m_planEndsAtProbe && followProbe())
        return; // the same run goes on
    m_lastJobS = jobElapsedS();
    m_jobClock.invalidate();
    emit jobFinished(ok);
    if (m_step == Step::Running)
        end(ok, m_error.isEmpty() ? tr("the job did not finish") : m_error);
}

} // namespace frezka::session
