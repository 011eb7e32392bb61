// MainWindow, the machine side: the controller facade, snapshots to widgets, operator actions.
#include "mainwindow.h"

#include "consolewidget.h"
#include "drowidget.h"
#include "holdbanner.h"
#include "iopanel.h"
#include "jogpanel.h"
#include "outputspanel.h"
#include "planneradapter.h"
#include "programlisting.h"
#include "runpanel.h"
#include "speedplot.h"
#include "toolpathview.h"

#include "driver/link/machinecontroller.h"
#include "gcode/interpreter.h"

#include <QFileInfo>
#include <QLabel>
#include <QSettings>
#include <QStatusBar>
#include <QVBoxLayout>

#include <cmath>

namespace frezka::gui {
namespace {

using driver::MachineMode;

// Output n (OUT0..OUT3) is on in port 0 (active low; bit0 OUT0, bit1 OUT3, bit2 OUT1, bit3 OUT2).
std::uint8_t logicalOutputs(std::uint8_t port)
{
    const std::uint8_t on = std::uint8_t(~port);
    return std::uint8_t((on & 0x01) | ((on & 0x04) ? 0x02 : 0) | ((on & 0x08) ? 0x04 : 0) |
                        ((on & 0x02) ? 0x08 : 0));
}

bool isConnected(MachineMode m)
{
    return m != MachineMode::Disconnected && m != MachineMode::Connecting &&
           m != MachineMode::LinkLost;
}

} // namespace

QString machineModeText(MachineMode mode)
{
    switch (mode) {
    case MachineMode::Disconnected:
        return MainWindow::tr("Not connected");
    case MachineMode::Connecting:
        return MainWindow::tr("Connecting…");
    case MachineMode::Idle:
        return MainWindow::tr("Ready");
    case MachineMode::Homing:
        return MainWindow::tr("Homing");
    case MachineMode::Jogging:
        return MainWindow::tr("Jogging");
    case MachineMode::Running:
        return MainWindow::tr("Running");
    case MachineMode::Stopping:
        return MainWindow::tr("Stopping");
    case MachineMode::Paused:
        return MainWindow::tr("Paused");
    case MachineMode::ToolLifted:
        return MainWindow::tr("Tool lifted");
    case MachineMode::Alarm:
        return MainWindow::tr("Alarm");
    case MachineMode::LinkLost:
        return MainWindow::tr("Link lost");
    }
    return {};
}

void MainWindow::buildCentral()
{
    auto *central = new QWidget(this);
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_hold = new HoldBanner(central);
    layout->addWidget(m_hold);
    layout->addWidget(m_view, 1);
    setCentralWidget(central);
}

void MainWindow::connectMachine()
{
    m_controller = new driver::MachineController(this);
    connect(m_controller, &driver::MachineController::stateChanged, this, &MainWindow::onState);
    connect(m_controller, &driver::MachineController::errorOccurred, this,
            &MainWindow::onMachineError);
    connect(m_controller, &driver::MachineController::logLine, this, &MainWindow::onLogLine);
    connect(m_controller, &driver::MachineController::jobFinished, this, [this](bool ok) {
        m_jobElapsedS = m_jobClock.isValid() ? m_jobClock.elapsed() / 1000.0 : 0;
        m_jobClock.invalidate();
        if (ok) {
            m_run->setProgress(1.0, m_jobElapsedS, 0);
            m_view->model()->setCutEntry(std::uint32_t(
                std::max<std::size_t>(
                    1, m_program->program().toolpath ? m_program->program().toolpath->size() : 1) -
                1));
            statusBar()->showMessage(
                tr("Program finished in %1.").arg(RunPanel::formatDuration(m_jobElapsedS)), 15000);
            m_console->appendInfo(tr("Program finished."));
        }
        updateRunPhase();
    });

    connectControls();

    // Run or report once a (re-)load triggered by Run / Check has finished.
    connect(m_program, &ProgramSession::loaded, this, [this] {
        const bool run = std::exchange(m_runAfterLoad, false);
        const bool check = std::exchange(m_checkAfterLoad, false);
        const LoadedProgram &p = m_program->program();
        if (check && p.runnable()) {
            m_console->appendInfo(
                tr("Check passed: %n move(s), estimated time %1, within the soft limits.", nullptr,
                   int(p.planStats.vectors))
                    .arg(RunPanel::formatDuration(p.estimatedS)));
            statusBar()->showMessage(tr("Check passed."), 10000);
        }
        if (check)
            emit programChecked(p.runnable());
        if (run && p.runnable())
            startPlannedRun();
    });

    m_reconnectTimer.setSingleShot(true);
    m_reconnectTimer.setInterval(2000);
    connect(&m_reconnectTimer, &QTimer::timeout, this, [this] {
        if (!m_userDisconnected && m_controller->state().mode == MachineMode::LinkLost)
            connectToUnit();
    });
    connect(m_offsets, &session::WorkOffsets::changed, this, &MainWindow::onOffsetsChanged);
    m_offsets->load();
    // The built-in emulator (or the profile's port) is connected as soon as the loop runs.
    QMetaObject::invokeMethod(
        this, [this] { connectToUnit(); }, Qt::QueuedConnection);
}

void MainWindow::connectControls()
{
    // Operator controls.
    connect(m_run, &RunPanel::runRequested, this, &MainWindow::runProgram);
    connect(m_run, &RunPanel::checkRequested, this, &MainWindow::checkProgram);
    connect(m_run, &RunPanel::pauseRequested, m_controller, &driver::MachineController::pause);
    connect(m_run, &RunPanel::resumeRequested, m_controller, &driver::MachineController::resume);
    connect(m_run, &RunPanel::stopRequested, m_controller, &driver::MachineController::abort);
    connect(m_run, &RunPanel::abortRequested, m_controller, &driver::MachineController::abort);
    connect(m_run, &RunPanel::toolLiftRequested, this, [this] {
        m_savedSpindleRpm = m_controller->state().spindleRpm;
        m_controller->toolLift(m_hold->stopSpindleOnLift());
    });
    connect(m_hold, &HoldBanner::continueRequested, m_controller,
            &driver::MachineController::resume);
    connect(m_hold, &HoldBanner::abortRequested, m_controller, &driver::MachineController::abort);
    connect(m_hold, &HoldBanner::liftRequested, this, [this](bool stopSpindle) {
        m_savedSpindleRpm = m_controller->state().spindleRpm;
        m_controller->toolLift(stopSpindle);
    });
    connect(m_hold, &HoldBanner::lowerRequested, this, &MainWindow::lowerTool);

    connect(m_jog, &JogPanel::jogStepRequested, this, &MainWindow::jogStep);
    connect(m_jog, &JogPanel::jogContinuousStarted, m_controller,
            &driver::MachineController::jogContinuous);
    connect(m_jog, &JogPanel::jogContinuousStopped, m_controller,
            &driver::MachineController::jogStop);
    // axis -1: every axis the profile homes, in its order; otherwise that axis alone.
    connect(m_jog, &JogPanel::homeRequested, m_controller,
            [this](int axis) { m_controller->home(axis < 0 ? 0xFu : 1u << axis); });
    connect(m_jog, &JogPanel::mpgToggled, m_controller, &driver::MachineController::setMpg);

    connect(m_outputs, &OutputsPanel::spindleRequested, this,
            [this](bool on, double rpm) { m_controller->setSpindleRpm(on ? rpm : 0.0); });
    auto outputFunction = [this](machine::OutputFunction f, bool on) {
        const std::uint8_t bit = machine::outputBit(m_profile, f);
        if (!bit) {
            showError(tr("No output of this machine is set up for that function; assign one in "
                         "Settings › Machine profile › Outputs."));
            return;
        }
        m_controller->setOutputs(bit, on ? bit : 0);
    };
    connect(m_outputs, &OutputsPanel::coolantRequested, this,
            [outputFunction](bool on) { outputFunction(machine::OutputFunction::Coolant, on); });
    connect(m_outputs, &OutputsPanel::airRequested, this,
            [outputFunction](bool on) { outputFunction(machine::OutputFunction::AirBlow, on); });
    connect(m_outputs, &OutputsPanel::outputRequested, this,
            [this](std::uint8_t bit, bool on) { m_controller->setOutputs(bit, on ? bit : 0); });
    connect(m_outputs, &OutputsPanel::feedOverrideRequested, m_controller,
            &driver::MachineController::setOverride);
    connect(m_outputs, &OutputsPanel::feedStepRequested, this, [this](int direction) {
        if (direction > 0)
            m_controller->overrideUp();
        else
            m_controller->overrideDown();
    });

    connect(m_dro, &DroWidget::zeroAxisRequested, this, &MainWindow::setWorkZero);
    connect(m_dro, &DroWidget::zeroAllRequested, this, [this] { setWorkZero(-1); });
    connect(m_dro, &DroWidget::offsetSelected, this, &MainWindow::selectWorkOffset);
    connect(m_console, &ConsoleWidget::manualLineEntered, this, &MainWindow::executeManualLine);
}

void MainWindow::connectToUnit()
{
    m_userDisconnected = false;
    m_controller->setMachineConfig(m_profile);
    driver::ConnectionSettings settings;
    const QString port = QString::fromStdString(m_profile.link.port);
    if (port.isEmpty() || port == QLatin1String("emulator")) {
        settings.kind = driver::ConnectionSettings::Kind::Emulator;
    } else {
        settings.kind = driver::ConnectionSettings::Kind::SerialPort;
        settings.portName = port;
    }
    settings.baud = m_profile.link.baud;
    QSettings().setValue(QStringLiteral("link/port"), port);
    m_console->appendInfo(tr("Connecting to %1 at %2 Bd…")
                              .arg(settings.kind == driver::ConnectionSettings::Kind::Emulator
                                       ? tr("the built-in emulator")
                                       : port)
                              .arg(settings.baud));
    m_controller->connectTo(settings);
}

void MainWindow::disconnectFromUnit()
{
    m_userDisconnected = true;
    m_controller->disconnectFromUnit();
}

void MainWindow::onState(const driver::MachineState &state)
{
    m_dro->setPositions(state.positionMm, m_offsets->workPosition(state.positionMm));
    const auto homed = [&state](int axis) { return ((state.homedAxes >> axis) & 1) != 0; };
    m_dro->setHomed({homed(0), homed(1), homed(2), homed(3)});
    m_view->model()->setToolPosition(QVector3D(
        float(state.positionMm[0]), float(state.positionMm[1]), float(state.positionMm[2])));
    const std::uint16_t inputs = std::uint16_t(state.inputs1 | ((state.inputs2 & 0xC0) << 8));
    // !7V1..1000 switches OUT0 on in the unit as well (docs/gve-protocol.md §9).
    const std::uint8_t outputs =
        std::uint8_t(logicalOutputs(state.outputs) | (state.spindlePermille > 0 ? 0x01 : 0));
    m_io->setIo(inputs, outputs, state.run, state.inta);
    auto on = [&](machine::OutputFunction f) {
        const std::uint8_t bit = machine::outputBit(m_profile, f);
        return bit && !(state.outputs & bit);
    };
    m_outputs->showState(state.spindlePermille > 0, on(machine::OutputFunction::Coolant),
                         on(machine::OutputFunction::AirBlow), std::uint8_t(~state.outputs));
    m_outputs->showFeedOverride(state.overridePercent);
    m_jog->setMpgOn(state.mpgOn);
    m_connection->setText(machineModeText(state.mode));
    m_connection->setStyleSheet(isConnected(state.mode) ? QString()
                                                        : QStringLiteral("color: #c00;"));
    const auto &info = protocol::variantInfo(state.variant);
    m_unit->setText(
        state.firmware.empty()
            ? QString::fromUtf8(info.displayName.data(), qsizetype(info.displayName.size()))
            : QStringLiteral("%1 · %2").arg(
                  QString::fromUtf8(info.displayName.data(), qsizetype(info.displayName.size())),
                  QString::fromStdString(state.firmware)));
    m_state->setText(state.jobActive && state.sourceLine > 0 ? tr("Line %1").arg(state.sourceLine)
                                                             : QString());
    if (state.jobActive && state.sourceLine > 0) {
        m_listing->showCurrentLine(int(state.sourceLine));
        m_view->model()->setCutEntry(m_program->program().entryOfLine(state.sourceLine));
    }
    updateProgress(state);
    updateHold(state);
    if (state.mode == MachineMode::LinkLost && m_lastMode != MachineMode::LinkLost) {
        showError(tr("The link to the unit was lost. The job position is kept: reconnect, then "
                     "Resume."));
        if (QSettings().value(QStringLiteral("link/autoReconnect"), true).toBool())
            m_reconnectTimer.start();
    }
    if (state.mode == MachineMode::Idle && m_lastMode == MachineMode::Connecting) {
        for (const auto &d : state.eepromDifferences)
            m_console->appendInfo(
                tr("Unit EEPROM differs from the profile: %1").arg(QString::fromStdString(d)));
    }
    m_lastMode = state.mode;
    updateRunPhase();
}

void MainWindow::updateProgress(const driver::MachineState &state)
{
    if (!state.jobActive)
        return;
    if (!m_jobClock.isValid())
        m_jobClock.start();
    const double elapsed = m_jobClock.elapsed() / 1000.0;
    // ETA from the planner's model at the line being cut; the driver's own figure otherwise.
    const LoadedProgram &p = m_program->program();
    const double planned = p.remainingS(state.sourceLine);
    if (planned >= 0 && p.estimatedS > 0)
        m_run->setProgress(1.0 - planned / p.estimatedS, elapsed, planned);
    else
        m_run->setProgress(state.progress, elapsed, state.etaS);
    // Actual speed from the live position (mm/min along the travelled path).
    const qint64 now = m_jobClock.elapsed();
    if (m_lastPosMs >= 0 && now > m_lastPosMs) {
        double d2 = 0;
        for (std::size_t i = 0; i < 3; ++i)
            d2 += (state.positionMm[i] - m_lastPos[i]) * (state.positionMm[i] - m_lastPos[i]);
        const double d = std::sqrt(d2);
        m_actualDistanceMm += d;
        m_plot->addActual(
            {m_actualDistanceMm, d / (double(now - m_lastPosMs) / 60000.0), state.sourceLine});
        m_plot->setCursorDistance(m_actualDistanceMm);
    }
    m_lastPos = state.positionMm;
    m_lastPosMs = now;
}

void MainWindow::updateHold(const driver::MachineState &state)
{
    using K = HoldBanner::Kind;
    K kind = K::None;
    if (state.mode == MachineMode::ToolLifted) {
        kind = K::ToolLifted;
    } else if (state.mode == MachineMode::Paused) {
        switch (state.hold) {
        case driver::HoldReason::OperatorStop:
            kind = K::OperatorStop;
            break;
        case driver::HoldReason::Interrupt:
            kind = K::Interrupt;
            break;
        case driver::HoldReason::ProbeFailed:
            kind = K::ProbeFailed;
            break;
        case driver::HoldReason::PathFault:
            kind = K::PathFault;
            break;
        default:
            kind = K::Paused;
        }
        if (m_continueAfterLower) {
            // The tool is back down after "Lower and continue".
            m_continueAfterLower = false;
            m_controller->resume();
        }
    }
    if (kind != m_hold->kind())
        m_hold->showHold(kind, int(state.sourceLine), QString::fromStdString(state.holdText));
}

void MainWindow::lowerTool(double newFeedMmPerMin, bool thenContinue)
{
    // Spindle back on first when the lift stopped it, then lower (K/R and the new speed are the
    // driver's), then continue once the machine is held again with the tool down.
    if (m_savedSpindleRpm > 0 && m_controller->state().spindlePermille == 0)
        m_controller->setSpindleRpm(m_savedSpindleRpm);
    int pulses = 0;
    if (newFeedMmPerMin > 0)
        pulses = int(std::lround(newFeedMmPerMin / 60.0 * m_profile.axes[0].stepsPerMm));
    m_continueAfterLower = thenContinue;
    m_controller->toolLower(pulses);
}

void MainWindow::onMachineError(const driver::MachineError &error)
{
    QString text = tr("The unit reported a problem: %1").arg(QString::fromStdString(error.message));
    if (!error.command.empty())
        text += QLatin1Char('\n') + tr("Command: %1").arg(QString::fromStdString(error.command));
    if (!error.reply.empty())
        text += QLatin1Char('\n') + tr("Reply: %1").arg(QString::fromStdString(error.reply));
    const std::uint32_t line = m_controller->state().sourceLine;
    if (m_controller->state().jobActive && line > 0)
        text += QLatin1Char('\n') + tr("Program line: %1").arg(line);
    showError(text);
}

void MainWindow::onLogLine(const QString &line)
{
    LogDirection dir = LogDirection::Info;
    QString body = line;
    if (line.startsWith(QLatin1String("> "))) {
        dir = LogDirection::Sent;
        body = line.mid(2);
    } else if (line.startsWith(QLatin1String("< "))) {
        dir = LogDirection::Received;
        body = line.mid(2);
    } else if (line.startsWith(QLatin1String("! "))) {
        dir = LogDirection::Error;
        body = line.mid(2);
    }
    m_console->append(dir, body.toUtf8());
}

void MainWindow::updateRunPhase()
{
    const auto &st = m_controller ? m_controller->state() : driver::MachineState{};
    const bool connected = isConnected(st.mode);
    RunPhase phase = m_program->program().runnable() ? RunPhase::Ready : RunPhase::NoProgram;
    if (m_program->program().ok() && !m_program->program().runnable())
        phase = RunPhase::NoProgram;
    switch (st.mode) {
    case MachineMode::Running:
    case MachineMode::Stopping:
        phase = RunPhase::Running;
        break;
    case MachineMode::Paused:
        phase = RunPhase::Paused;
        break;
    case MachineMode::ToolLifted:
        phase = RunPhase::Lifted;
        break;
    default:
        break;
    }
    m_run->setPhase(phase, connected && (st.mode == MachineMode::Idle || phase != RunPhase::Ready));
    const bool idle = st.mode == MachineMode::Idle;
    m_jog->setEnabled(idle || st.mode == MachineMode::Jogging);
    m_dro->setEnabled(true);
    m_connectAction->setEnabled(!connected);
    m_disconnectAction->setEnabled(st.mode != MachineMode::Disconnected);
}

} // namespace frezka::gui
