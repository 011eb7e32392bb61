// MainWindow, what the screen says about the machine: the connection in the status bar, the
// line, progress and ETA of the running job, the actual-speed plot, the hold banner and the
// driver's errors, all in the user's language (the driver reports codes, drivererror.h).
#include "mainwindow.h"

#include "consolewidget.h"
#include "holdbanner.h"
#include "programlisting.h"
#include "programview.h"
#include "runpanel.h"
#include "speedplot.h"
#include "toolpathview.h"

#include "driver/link/drivererror.h"
#include "driver/link/machinecontroller.h"

#include <QLabel>
#include <QStatusBar>

#include <cmath>

namespace frezka::gui {

using driver::MachineMode;

namespace {

bool held(MachineMode m)
{
    return m == MachineMode::Paused || m == MachineMode::ToolLifted;
}

} // namespace

// "Ready · built-in emulator", "Running · /dev/ttyUSB0, 115200 Bd".
QString MainWindow::connectionText(const driver::MachineState &state) const
{
    const driver::ConnectionSettings &c = m_workflow->connection();
    const QString where = c.kind == driver::ConnectionSettings::Kind::Emulator
                              ? tr("built-in emulator")
                              : tr("%1, %2 Bd").arg(c.portName).arg(c.baud);
    return tr("%1 · %2").arg(machineModeText(state.mode), where);
}

// The program line the operator should look at: the hold's own line while held (an M0/M6
// names its line, a pause the line it stopped in), else the line executing now.
std::uint32_t MainWindow::shownLine(const driver::MachineState &state) const
{
    if (held(state.mode) && state.holdLine > 0)
        return state.holdLine;
    // The line of the modelled position between polls: never past what the unit was sent.
    return state.live.modelled && state.live.sourceLine > 0 ? state.live.sourceLine
                                                            : state.sourceLine;
}

// The job's line, listing, cut drawing, progress and speed; a console line's job leaves the
// loaded program's display alone.
void MainWindow::showJob(const driver::MachineState &state)
{
    const bool programJob = state.jobActive && !m_consoleSession->ranLastJob();
    const std::uint32_t line = shownLine(state);
    m_state->setText(programJob && line > 0 ? tr("Line %1").arg(line) : QString());
    if (!programJob)
        return;
    if (line > 0)
        m_listing->showCurrentLine(int(line));
    if (line > 0)
        m_view->model()->setCutEntry(m_program->program().entryOfLine(line));
    updateProgress(state);
}

void MainWindow::updateProgress(const driver::MachineState &state)
{
    const double elapsed = m_workflow->jobElapsedS();
    // ETA from the planner's model at the line being cut (counting down through the line, a
    // dwell too); the driver's own figure otherwise.
    const LoadedProgram &p = m_program->program();
    const double planned =
        m_remaining.at(state.sourceLine, elapsed, state.mode == driver::MachineMode::Running);
    if (planned >= 0 && p.estimatedS > 0)
        m_run->setProgress(1.0 - planned / p.estimatedS, elapsed, planned);
    else
        m_run->setProgress(state.progress, elapsed, state.etaS);
    // Actual speed along the travelled path, over a window of polls, never above what the
    // machine can reach (its axes together, at the feed override).
    double ceiling = 0;
    for (std::size_t a = 0; a < 3; ++a)
        ceiling += profile().axes[a].present
                       ? profile().axes[a].maxSpeedMmPerMin * profile().axes[a].maxSpeedMmPerMin
                       : 0.0;
    m_speed.setCeiling(std::sqrt(ceiling) * std::max(100, state.overridePercent) / 100.0);
    m_panelSpeed.setCeiling(m_speed.ceiling());
    m_panelSpeed.add(elapsed, state.positionMm);
    if (m_speed.add(elapsed, state.positionMm) || state.mode == MachineMode::Running) {
        m_plot->addActual({m_speed.distanceMm(), m_speed.speed(), state.sourceLine});
        m_plot->setCursorDistance(m_speed.distanceMm());
    }
}

QString MainWindow::holdDetail(const driver::MachineState &state) const
{
    QString text = driver::translatedText(state.holdMessage);
    const auto &p = m_program->program();
    const QString comment =
        state.hold == driver::HoldReason::OperatorStop && p.text && !m_consoleSession->ranLastJob()
            ? p.text->comment(int(state.holdLine))
            : QString();
    if (!comment.isEmpty())
        text += QLatin1Char('\n') + tr("Program comment: %1").arg(comment);
    if (const QString tool = toolChangeText(state); !tool.isEmpty())
        text += QLatin1Char('\n') + tool;
    return text;
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
    }
    m_hold->setOutputs(state.spindleOn, state.outputsHeld, profile().spindle.spinUpMs / 1000.0);
    m_hold->setNewFeedAvailable(state.features.vlVkXmNa);
    const int line = kind == K::None ? 0 : int(shownLine(state));
    const QString detail = kind == K::None ? QString() : holdDetail(state);
    if (kind == m_hold->kind() && line == m_holdLine && detail == m_holdDetail)
        return;
    const bool newKind = kind != m_hold->kind();
    m_holdLine = line;
    m_holdDetail = detail;
    m_hold->showHold(kind, line, detail);
    if (!newKind)
        return;
    // The operator's word on the spindle for a hold: ticked, a pause or an input's stop switches
    // it off once the machine stands; at M0/M1/M6 the profile decides and the box shows it.
    if (kind == K::OperatorStop)
        m_hold->setStopSpindle(state.outputsHeld || !state.spindleOn);
    else if ((kind == K::Paused || kind == K::Interrupt) && m_hold->stopSpindleOnLift() &&
             state.spindleOn && !state.outputsHeld)
        m_link->execute(driver::op::HoldSpindle{true});
}

void MainWindow::onMachineError(const driver::MachineError &error)
{
    QString text =
        tr("The unit reported a problem: %1").arg(driver::translatedText(error.reason, true));
    if (!error.command.empty())
        text += QLatin1Char('\n') + tr("Command: %1").arg(QString::fromStdString(error.command));
    if (!error.reply.empty())
        text += QLatin1Char('\n') + tr("Reply: %1").arg(QString::fromStdString(error.reply));
    const std::uint32_t line = m_link->state().sourceLine;
    if (m_link->state().jobActive && line > 0 && !m_consoleSession->ranLastJob())
        text += QLatin1Char('\n') + tr("Program line: %1").arg(line);
    showError(text);
}

// The driver's log line of a mode change ("mode: Idle -> Jogging") in the user's words; any
// other line as it is.
QString MainWindow::logLineText(const QString &line) const
{
    static const QLatin1String kMode("mode: ");
    const qsizetype arrow = line.indexOf(QLatin1String(" -> "));
    if (!line.startsWith(kMode) || arrow < 0)
        return line;
    const QString from = line.mid(kMode.size(), arrow - kMode.size());
    const QString to = line.mid(arrow + 4);
    return tr("State: %1 → %2")
        .arg(driver::translatedPhrase(from.toStdString()),
             driver::translatedPhrase(to.toStdString()));
}

} // namespace frezka::gui
