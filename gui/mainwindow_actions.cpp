// MainWindow, the operator's actions: run, check, jog, work zero, manual line.
#include "mainwindow.h"

#include "consolewidget.h"
#include "drowidget.h"
#include "speedplot.h"
#include "toolpathview.h"

#include "driver/link/machinecontroller.h"
#include "machine/softlimits.h"

#include <QFileInfo>

namespace frezka::gui {

using driver::MachineMode;

// ---- operator actions ----

void MainWindow::runProgram()
{
    m_workflow->runProgram();
}

void MainWindow::onJobStarted()
{
    m_view->model()->setCutEntry(ToolpathViewModel::kNoneCut);
    m_plot->clearActual();
    m_speed.reset();
    m_panelSpeed.reset();
    const LoadedProgram &p = m_program->program();
    m_remaining = session::RemainingTime(p.lineEndS, p.estimatedS);
}

void MainWindow::checkProgram()
{
    if (m_program->program().path.isEmpty()) {
        showError(tr("Open a program first."));
        return;
    }
    m_workflow->checkProgram();
}

// The loaded (or re-planned) program goes to the run workflow.
void MainWindow::offerProgram()
{
    const LoadedProgram &p = m_program->program();
    const gcode::Point4 o = p.toolpath ? p.toolpath->origin() : gcode::Point4{};
    m_workflow->setProgram(p.runnable() ? p.unitProgram : nullptr, {o.x, o.y, o.z, o.a},
                           QFileInfo(p.path).fileName(),
                           p.errors.empty() ? QString() : p.errors.front().text);
}

// The soft-limit policy (machine/softlimits.h) decides; the driver applies the same function,
// this only puts its refusal into the operator's words at once.
void MainWindow::jogStep(int axis, double deltaMm, double feedMmPerMin)
{
    const auto &st = m_controller->state();
    const auto &a = profile().axes[std::size_t(axis)];
    const bool homed = st.axisHomed(axis);
    const machine::JogMove move = machine::jogStep(
        profile(), axis, st.positionSteps[std::size_t(axis)], deltaMm, feedMmPerMin, homed);
    static const char kAxes[] = "XYZA";
    if (move.verdict == machine::JogVerdict::BeyondLimit) {
        showError(tr("Jog refused: %1 would go to %2 mm, outside the soft limits %3 … %4 mm.")
                      .arg(QLatin1Char(kAxes[axis]))
                      .arg(move.targetMm, 0, 'f', 3)
                      .arg(a.softMinMm, 0, 'f', 3)
                      .arg(a.softMaxMm, 0, 'f', 3));
        return;
    }
    m_controller->jogStep(axis, deltaMm, feedMmPerMin);
}

void MainWindow::onOffsetsChanged()
{
    const auto &st = m_controller->state();
    m_program->setWorkOffsets(m_offsets->state());
    m_dro->setActiveOffset(m_offsets->active());
    m_dro->setPositions(st.shownMm(), m_offsets->workPosition(st.shownMm()));
    m_program->setStartPosition(st.positionMm);
    m_program->reload(); // offsets apply by re-interpreting the program
}

void MainWindow::setWorkZero(int axis)
{
    const auto &st = m_controller->state();
    if (st.mode != MachineMode::Idle) {
        showError(tr("Set the work zero while the machine is ready and still."));
        return;
    }
    m_offsets->setZero(axis, st.positionMm);
}

void MainWindow::selectWorkOffset(int index)
{
    m_offsets->select(index);
}

void MainWindow::executeManualLine(const QString &line)
{
    m_consoleSession->execute(line);
}

} // namespace frezka::gui
