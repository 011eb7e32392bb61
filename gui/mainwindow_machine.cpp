// MainWindow, the machine side: the controller facade, snapshots to widgets, operator actions.
#include "mainwindow.h"

#include "consolewidget.h"
#include "drowidget.h"
#include "eepromdecode.h"
#include "holdbanner.h"
#include "iopanel.h"
#include "jogpanel.h"
#include "outputspanel.h"
#include "placementbar.h"
#include "programlisting.h"
#include "runpanel.h"
#include "speedplot.h"
#include "toolpathview.h"

#include "driver/link/machinecontroller.h"
#include "session/qtmachinelink.h"

#include <QAbstractButton>
#include <QFileInfo>
#include <QLabel>
#include <QMessageBox>
#include <QSettings>
#include <QStatusBar>
#include <QVBoxLayout>

#include <cmath>

namespace frezka::gui {
namespace {

using driver::MachineMode;

bool isConnected(MachineMode m)
{
    return m != MachineMode::Disconnected && m != MachineMode::Connecting &&
           m != MachineMode::LinkLost;
}

} // namespace

QString machineModeText(MachineMode mode)
{
    return session::RunWorkflow::modeText(mode);
}

void MainWindow::buildCentral()
{
    auto *central = new QWidget(this);
    auto *layout = new QVBoxLayout(central);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->setSpacing(0);
    m_hold = new HoldBanner(central);
    layout->addWidget(m_hold);
    m_placement = new PlacementBar(central);
    connect(m_placement, &PlacementBar::workOffsetRequested, this, &MainWindow::placeWorkOffset);
    layout->addWidget(m_placement);
    layout->addWidget(m_view, 1);
    setCentralWidget(central);
}

void MainWindow::connectMachine()
{
    m_controller = new driver::MachineController(this);
    if (m_clock == MainWindowOptions::Clock::Virtual) {
        // The built-in emulator on a virtual clock: the screen shows the state once per slice of
        // the clock (the workflow hears every one); the controller stays unconnected.
        m_virtualClock = new session::VirtualClockLink(this);
        m_link = m_virtualClock;
        connect(m_virtualClock, &session::VirtualClockLink::sliceEnded, this, &MainWindow::onState);
        connect(m_link, &session::MachineLink::errorOccurred, this, &MainWindow::onMachineError);
    } else {
        m_link = new session::QtMachineLink<driver::MachineController>(*m_controller, this);
        connect(m_controller, &driver::MachineController::stateChanged, this, &MainWindow::onState);
        connect(m_controller, &driver::MachineController::errorOccurred, this,
                &MainWindow::onMachineError);
    }
    m_workflow = new session::RunWorkflow(*m_link, this);
    m_consoleSession = new session::ConsoleSession(*m_workflow, *m_offsets, this);
    connect(m_controller, &driver::MachineController::logLine, this, &MainWindow::onLogLine);
    buildUnitsDock();

    using session::RunWorkflow;
    connect(m_workflow, &RunWorkflow::message, m_console, &ConsoleWidget::appendInfo);
    connect(m_workflow, &RunWorkflow::failed, this, &MainWindow::showError);
    connect(m_workflow, &RunWorkflow::jobStarted, this, &MainWindow::onJobStarted);
    connect(m_workflow, &RunWorkflow::jobFinished, this, &MainWindow::onJobFinished);
    connect(m_workflow, &RunWorkflow::checked, this, &MainWindow::onChecked);
    connect(m_workflow, &RunWorkflow::connected, this, &MainWindow::onConnected);
    connect(m_workflow, &RunWorkflow::linkLost, this, [this] {
        // The preference as it is now (the settings may have changed it since connecting); the
        // workflow reads it right after this signal.
        m_workflow->setAutoReconnect(
            QSettings().value(QStringLiteral("link/autoReconnect"), true).toBool());
        showError(tr("The link to the unit was lost. The job position is kept: reconnect, then "
                     "Resume."));
    });
    connect(m_consoleSession, &session::ConsoleSession::message, m_console,
            &ConsoleWidget::appendInfo);
    connect(m_consoleSession, &session::ConsoleSession::failed, this, &MainWindow::showError);

    // The program session plans; the workflow asks it to plan again from where the machine is.
    m_workflow->setReplanner([this](const RunWorkflow::Position &startMm) {
        m_program->setStartPosition(startMm);
        m_program->reload();
    });
    connect(m_program, &ProgramSession::loaded, this, &MainWindow::offerProgram);
    connect(m_program, &ProgramSession::loadFailed, this,
            [this](const QString &why) { m_workflow->setProgram(nullptr, {}, QString(), why); });

    connectControls();
    connect(m_offsets, &session::WorkOffsets::changed, this, &MainWindow::onOffsetsChanged);
    m_offsets->load();
    // The built-in emulator (or the profile's port) is connected as soon as the loop runs.
    QMetaObject::invokeMethod(
        this, [this] { connectToUnit(); }, Qt::QueuedConnection);
}

void MainWindow::onJobFinished(bool ok)
{
    const double elapsedS = m_workflow->jobElapsedS();
    if (m_consoleSession->ranLastJob()) {
        // A console line's own job: the loaded program's display stays as it was.
        if (ok)
            m_console->appendInfo(tr("Manual line done."));
        updateRunPhase();
        return;
    }
    if (!ok) {
        // Aborted or failed: nothing of the program is running, so no progress is left shown.
        m_run->setProgress(0, elapsedS, m_program->program().estimatedS);
        m_state->clear();
    }
    if (ok) {
        m_run->setProgress(1.0, elapsedS, 0);
        const auto &toolpath = m_program->program().toolpath;
        m_view->model()->setCutEntry(
            std::uint32_t(std::max<std::size_t>(1, toolpath ? toolpath->size() : 1) - 1));
        // The listing at the job's last line too: the states between the last one shown and
        // the end may not all have been shown (on the virtual clock, one a slice).
        if (const auto &unit = m_program->program().unitProgram;
            unit && !unit->commands.empty() && unit->commands.back().sourceLine > 0)
            m_listing->showCurrentLine(int(unit->commands.back().sourceLine));
        statusBar()->showMessage(
            tr("Program finished in %1.").arg(RunPanel::formatDuration(elapsedS)), 15000);
        m_console->appendInfo(tr("Program finished."));
        keepWorkOffsets();
        writeBackToolTable();
    }
    if (m_program->startLine() != 0)
        runWholeProgram(); // the job from a line is done (or dropped): the program is whole again
    updateRunPhase();
    if (m_reloadAfterJob)
        promptReload(); // the file changed on disk while the job ran
}

void MainWindow::onChecked(bool ok)
{
    const LoadedProgram &p = m_program->program();
    if (ok) {
        m_console->appendInfo(
            tr("Check passed: %n move(s), estimated time %1, within the soft limits.", nullptr,
               int(p.planStats.vectors))
                .arg(RunPanel::formatDuration(p.estimatedS)));
        statusBar()->showMessage(tr("Check passed."), 10000);
    }
    if (p.provisional()) {
        const QString note = tr("After line %1 the path depends on the probe's result: it is "
                                "checked and shown as if the probe ended at its programmed end "
                                "(provisional), and each part is planned once the probe before "
                                "it has run.")
                                 .arg(p.provisionalLine);
        m_console->appendInfo(note);
        statusBar()->showMessage(ok ? tr("Check passed.") + QLatin1Char(' ') + note : note, 15000);
    }
    emit programChecked(ok);
}

// One EEPROM difference in the user's words: the setting's caption and both values as the unit
// shows them (bytes in hex).
QString MainWindow::eepromDifferenceText(const driver::EepromDifference &d) const
{
    return tr("Unit EEPROM differs from the profile: %1 is %2 in the unit, %3 in the profile")
        .arg(eepromLabel(m_link->state().variant, d.entry.address),
             eepromValueText(d.entry.kind, d.unitValue),
             eepromValueText(d.entry.kind, d.entry.value));
}

void MainWindow::onConnected()
{
    // Once, in the user's words (the driver's own English log line of each is not shown).
    for (const auto &d : m_link->state().eepromDifferences)
        m_console->appendInfo(eepromDifferenceText(d));
}

// One connect per control, panel by panel: a wiring table, kept whole so that every control's
// path to the workflow or the driver reads in one place.
void MainWindow::connectControls()
{
    // Operator controls.
    connect(m_run, &RunPanel::runRequested, this, &MainWindow::runProgram);
    connect(m_run, &RunPanel::checkRequested, this, &MainWindow::checkProgram);
    connect(m_listing, &ProgramListing::runFromLineRequested, this, &MainWindow::runFromLine);
    using session::RunWorkflow;
    connect(m_run, &RunPanel::pauseRequested, m_workflow, &RunWorkflow::pause);
    connect(m_run, &RunPanel::resumeRequested, m_workflow, &RunWorkflow::resume);
    // Stop is the controlled stop (H: the job held, resumable; homing ended), Abort drops the
    // job; Esc is Stop from anywhere in the window (docs/gui.md, "Stopping"), and the other
    // operator keys act as their buttons do (gui/shortcuts.h).
    connect(m_run, &RunPanel::stopRequested, m_workflow, &RunWorkflow::stop);
    installShortcuts();
    connect(m_workflow, &RunWorkflow::homingNeeded, this, &MainWindow::askToHome);
    connect(m_run, &RunPanel::abortRequested, m_workflow, &RunWorkflow::abort);
    connect(m_run, &RunPanel::toolLiftRequested, this,
            [this] { m_workflow->toolLift(m_hold->stopSpindleOnLift()); });
    connect(m_hold, &HoldBanner::continueRequested, m_workflow, &RunWorkflow::resume);
    connect(m_hold, &HoldBanner::abortRequested, m_workflow, &RunWorkflow::abort);
    connect(m_hold, &HoldBanner::liftRequested, m_workflow, &RunWorkflow::toolLift);
    connect(m_hold, &HoldBanner::lowerRequested, m_workflow, &RunWorkflow::lowerTool);
    connect(m_hold, &HoldBanner::spindleHoldRequested, this,
            [this](bool stop) { m_link->execute(driver::op::HoldSpindle{stop}); });

    connect(m_jog, &JogPanel::jogStepRequested, this, &MainWindow::jogStep);
    // Through the link (the controller's, or the virtual clock's: MainWindowOptions::clock).
    connect(m_jog, &JogPanel::jogContinuousStarted, this,
            [this](int axis, int direction, double speed) {
                m_link->execute(driver::op::JogContinuous{axis, direction, speed});
            });
    connect(m_jog, &JogPanel::jogContinuousStopped, this,
            [this] { m_link->execute(driver::op::JogStop{}); });
    // axis -1: every axis the profile homes, in its order; otherwise that axis alone.
    connect(m_jog, &JogPanel::homeRequested, this,
            [this](int axis) { m_link->home(axis < 0 ? 0xFu : 1u << axis); });
    connect(m_jog, &JogPanel::mpgToggled, this,
            [this](bool on) { m_link->execute(driver::op::SetMpg{on}); });
    connect(m_jog, &JogPanel::wheelTurned, m_controller,
            &driver::MachineController::turnEmulatedWheel);

    connectOutputs();

    connect(m_dro, &DroWidget::zeroAxisRequested, this, &MainWindow::setWorkZero);
    connect(m_dro, &DroWidget::zeroAllRequested, this, [this] { setWorkZero(-1); });
    connect(m_dro, &DroWidget::offsetSelected, this, &MainWindow::selectWorkOffset);
    connect(m_console, &ConsoleWidget::manualLineEntered, m_consoleSession,
            &session::ConsoleSession::execute);
}

// The outputs panel: spindle, coolant and the other outputs, the feed and spindle overrides.
void MainWindow::connectOutputs()
{
    connect(m_outputs, &OutputsPanel::spindleRequested, this,
            [this](bool on, double rpm) { m_link->setSpindleRpm(on ? rpm : 0.0); });
    auto outputFunction = [this](machine::OutputFunction f, bool on) {
        const int output = machine::outputNumber(profile(), f);
        if (output < 0) {
            showError(tr("No output of this machine is set up for that function; assign one in "
                         "Settings › Machine profile › Outputs."));
            return;
        }
        m_link->execute(driver::op::SetOutput{output, on});
    };
    connect(m_outputs, &OutputsPanel::coolantRequested, this,
            [outputFunction](bool on) { outputFunction(machine::OutputFunction::Coolant, on); });
    connect(m_outputs, &OutputsPanel::airRequested, this,
            [outputFunction](bool on) { outputFunction(machine::OutputFunction::AirBlow, on); });
    connect(m_outputs, &OutputsPanel::outputRequested, this, outputFunction);
    connect(m_outputs, &OutputsPanel::feedOverrideRequested, this,
            [this](int percent) { m_link->execute(driver::op::SetOverride{percent}); });
    connect(m_outputs, &OutputsPanel::spindleOverrideRequested, this,
            [this](int percent) { m_link->execute(driver::op::SetSpindleOverride{percent}); });
    connect(m_outputs, &OutputsPanel::feedStepRequested, this,
            [this](int direction) { m_link->execute(driver::op::OverrideStep{direction > 0}); });
}

// A run asked before homing: home, then run - or not. The question is a window-modal box that
// does not block (open(), as the EEPROM dialog's), so tests answer it offscreen too.
void MainWindow::askToHome()
{
    const QString text = tr("The machine is not homed: its soft limits refer to nothing yet. "
                            "Home all axes now and then run the program?");
    m_console->appendInfo(text);
    statusBar()->showMessage(text, 15000);
    auto *box = new QMessageBox(QMessageBox::Question, tr("Frezka"), text,
                                QMessageBox::Yes | QMessageBox::Cancel, this);
    box->setObjectName(QStringLiteral("askToHome"));
    box->button(QMessageBox::Yes)->setText(tr("Home and run"));
    box->setAttribute(Qt::WA_DeleteOnClose);
    connect(box, &QMessageBox::accepted, m_workflow, &session::RunWorkflow::homeThenRun);
    box->open();
}

void MainWindow::connectToUnit()
{
    QSettings settings;
    machine::MachineConfig config = profile();
    // After a restart the port used last (set with Apply, perhaps never saved in the profile)
    // is used again, and the console says so.
    const QString last = settings.value(QStringLiteral("link/port")).toString();
    if (!m_workflow->connectionAsked() && !last.isEmpty() &&
        last.toStdString() != config.link.port) {
        m_console->appendInfo(tr("Using the port used last, %1 (the machine profile says %2).")
                                  .arg(last, QString::fromStdString(config.link.port)));
        config.link.port = last.toStdString();
        config.link.baud = settings.value(QStringLiteral("link/baud"), config.link.baud).toInt();
        // The window's profile names the port in use, so the settings show it and applying
        // another port (the saved profile's too) connects that one; the file is not changed.
        m_workflow->setProfile(config);
    }
    settings.setValue(QStringLiteral("link/port"), QString::fromStdString(config.link.port));
    settings.setValue(QStringLiteral("link/baud"), config.link.baud);
    m_workflow->setAutoReconnect(
        settings.value(QStringLiteral("link/autoReconnect"), true).toBool());
    const driver::ConnectionSettings connection = session::RunWorkflow::connectionFor(config);
    if (m_clock == MainWindowOptions::Clock::Virtual &&
        connection.kind != driver::ConnectionSettings::Kind::Emulator) {
        // A real machine moves in real time: only the built-in emulator runs on the virtual
        // clock, and nothing is opened.
        showError(tr("The port %1 is not opened: on the virtual clock (--clock virtual) only the "
                     "built-in emulator runs. Choose the emulator as the port, or start Frezka "
                     "without --clock virtual.")
                      .arg(connection.portName));
        return;
    }
    if (!prepareLine(config))
        return;
    m_workflow->connectToUnit(connection);
}

void MainWindow::disconnectFromUnit()
{
    m_workflow->disconnectFromUnit();
}

void MainWindow::onState(const driver::MachineState &state)
{
    // Between the polls of a running job: the driver's model of the unit (MachineState::live).
    const std::array<double, 4> &shown = state.shownMm();
    m_dro->setPositions(shown, m_offsets->workPosition(shown));
    m_dro->setModelled(state.live.modelled);
    m_placement->setPosition(state.positionMm, state.mode == MachineMode::Idle);
    const std::array<bool, 4> homed{state.axisHomed(0), state.axisHomed(1), state.axisHomed(2),
                                    state.axisHomed(3)};
    m_dro->setHomed(homed);
    m_view->model()->setToolPosition(QVector3D(float(shown[0]), float(shown[1]), float(shown[2])));
    // The driver decodes the ports (MachineState::inputHigh, outputIsOn, outputOn).
    m_io->setIo([&state](int n) { return state.inputHigh(n); },
                [&state](int n) { return state.outputIsOn(n); }, state.run, state.inta);
    m_outputs->showState(state.spindleOn, [&state, this](machine::OutputFunction f) {
        return state.outputOn(profile(), f);
    });
    m_outputs->showFeedOverride(state.overridePercent, state.overrideHeldPercent());
    m_outputs->showSpindleOverride(state.spindleOverridePercent);
    m_jog->setMpgOn(state.mpgOn);
    // The simulated wheel turns the real-time driver's emulator (not the virtual clock's).
    m_jog->setSimulatedWheelAvailable(isConnected(state.mode) && !m_virtualClock &&
                                      m_workflow->connection().kind ==
                                          driver::ConnectionSettings::Kind::Emulator);
    m_jog->setHomedAxes(homed, isConnected(state.mode));
    m_connection->setText(connectionText(state));
    m_connection->setStyleSheet(isConnected(state.mode) ? QString()
                                                        : QStringLiteral("color: #c00;"));
    const auto &info = protocol::variantInfo(state.variant);
    m_unit->setText(
        state.firmware.empty()
            ? QString::fromUtf8(info.displayName.data(), qsizetype(info.displayName.size()))
            : QStringLiteral("%1 · %2").arg(
                  QString::fromUtf8(info.displayName.data(), qsizetype(info.displayName.size())),
                  QString::fromStdString(state.firmware)));
    showJob(state);
    updateHold(state);
    updateRunPhase();
    updateStatus(state);
}

void MainWindow::onLogLine(const QString &line)
{
    if (line.startsWith(QLatin1String("EEPROM differs: ")))
        return; // onConnected() reports each difference in the user's language
    LogDirection dir = LogDirection::Info;
    QString body = logLineText(line);
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
    const auto &st = m_link ? m_link->state() : driver::MachineState{};
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
    case MachineMode::Homing: // Stop and Abort end homing
        phase = RunPhase::Homing;
        break;
    default:
        break;
    }
    m_run->setPhase(phase, connected && (st.mode == MachineMode::Idle || phase != RunPhase::Ready));
    const bool idle = st.mode == MachineMode::Idle;
    // While the tool is lifted the operator jogs it away and back (by steps, issue 14).
    m_jog->setEnabled(idle || st.mode == MachineMode::Jogging ||
                      st.mode == MachineMode::ToolLifted);
    m_dro->setEnabled(true);
    m_connectAction->setEnabled(!connected);
    m_disconnectAction->setEnabled(st.mode != MachineMode::Disconnected);
}

} // namespace frezka::gui
