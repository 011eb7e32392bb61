// MainWindow, the operator's actions: run, check, jog, work zero, manual line.
#include "mainwindow.h"

#include "consolewidget.h"
#include "drowidget.h"
#include "planneradapter.h"
#include "speedplot.h"
#include "toolpathview.h"

#include "driver/link/machinecontroller.h"
#include "gcode/interpreter.h"

#include <QFileInfo>

namespace frezka::gui {

using driver::MachineMode;

// ---- operator actions ----

void MainWindow::runProgram()
{
    const LoadedProgram &p = m_program->program();
    if (!p.runnable()) {
        showError(
            p.errors.empty()
                ? tr("Open a program first.")
                : tr("The program has errors and cannot run:\n%1").arg(p.errors.front().text));
        return;
    }
    const auto &st = m_controller->state();
    if (st.mode != MachineMode::Idle) {
        showError(tr("The machine is not ready (%1); wait until it is, then Run.")
                      .arg(machineModeText(st.mode)));
        return;
    }
    // The plan is relative to where it starts: re-plan from the machine's actual position.
    const gcode::Point4 o = p.toolpath->origin();
    const std::array<double, 4> start{o.x, o.y, o.z, o.a};
    if (start != st.positionMm || p.unitProgram->startSteps != st.positionSteps) {
        m_program->setStartPosition(st.positionMm);
        m_runAfterLoad = true;
        m_console->appendInfo(tr("Planning from the current position…"));
        m_program->reload();
        return;
    }
    startPlannedRun();
}

void MainWindow::startPlannedRun()
{
    const LoadedProgram &p = m_program->program();
    m_view->model()->setCutEntry(ToolpathViewModel::kNoneCut);
    m_plot->clearActual();
    m_actualDistanceMm = 0;
    m_lastPosMs = -1;
    m_jobClock.start();
    m_console->appendInfo(tr("Running %1.").arg(QFileInfo(p.path).fileName()));
    m_controller->run(*p.unitProgram);
}

void MainWindow::checkProgram()
{
    if (m_program->program().path.isEmpty()) {
        showError(tr("Open a program first."));
        return;
    }
    m_program->setStartPosition(m_controller->state().positionMm);
    m_checkAfterLoad = true;
    m_program->reload();
}

void MainWindow::jogStep(int axis, double deltaMm, double feedMmPerMin)
{
    const auto &st = m_controller->state();
    const auto &a = m_profile.axes[std::size_t(axis)];
    const double target = st.positionMm[std::size_t(axis)] + deltaMm;
    static const char kAxes[] = "XYZA";
    if (target < a.softMinMm - 1e-9 || target > a.softMaxMm + 1e-9) {
        showError(tr("Jog refused: %1 would go to %2 mm, outside the soft limits %3 … %4 mm.")
                      .arg(QLatin1Char(kAxes[axis]))
                      .arg(target, 0, 'f', 3)
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
    m_dro->setPositions(st.positionMm, m_offsets->workPosition(st.positionMm));
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
    if (line.startsWith(QLatin1Char('!'))) {
        m_controller->sendRaw(line);
        return;
    }
    const auto &st = m_controller->state();
    if (st.mode != MachineMode::Idle) {
        showError(tr("Manual G-code runs only while the machine is ready."));
        return;
    }
    const std::string text = line.toStdString();
    session::MdiSession::Outcome result = m_mdi->interpret(text, st.positionMm, m_offsets->state());
    if (!result.ok()) {
        showError(gcode::formatError(tr("manual line"), result.errors.front()));
        return;
    }
    if (result.offsetsChanged)
        m_offsets->setState(result.offsets);
    m_console->appendInfo(tr("Manual: %1 (%2)").arg(line, m_mdi->modal().text()));
    if (result.toolpath.empty())
        return; // modes only (G91, F100, G55 ...)
    const machine::PlanResult plan = machine::plan(result.toolpath, m_profile);
    if (!plan.ok()) {
        showError(planErrorText(tr("manual line"), plan.errors.front()));
        return;
    }
    m_controller->run(plan.program);
}

} // namespace frezka::gui
