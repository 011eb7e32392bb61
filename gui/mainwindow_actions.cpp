// MainWindow, the operator's actions: run, check, jog, work zero, manual line.
#include "mainwindow.h"

#include "consolewidget.h"
#include "drowidget.h"
#include "jogpanel.h"
#include "placementbar.h"
#include "programinfodialog.h"
#include "speedplot.h"
#include "statuspanel.h"
#include "toolpathview.h"

#include "driver/link/machinecontroller.h"
#include "machine/softlimits.h"
#include "session/programinfo.h"
#include "session/programmodes.h"
#include "session/travelcheck.h"
#include "session/workoffsets.h"

#include <QFileInfo>
#include <QFileSystemWatcher>
#include <QMessageBox>
#include <QPushButton>

namespace frezka::gui {

using driver::MachineMode;

// ---- operator actions ----

void MainWindow::runProgram()
{
    // A program that probes for itself runs from its start again: shown as before its probes.
    if (!m_link->state().jobActive)
        m_program->restoreAsLoaded();
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

void MainWindow::reloadProgram()
{
    const QString path = m_program->program().path;
    if (path.isEmpty()) {
        showError(tr("Open a program first."));
        return;
    }
    if (m_link->state().jobActive) {
        showError(tr("The program cannot be reloaded while its job runs: let it finish or "
                     "abort it, then reload."));
        return;
    }
    m_reloadAfterJob = false;
    openProgram(path);
}

void MainWindow::onProgramFileChanged(const QString &path)
{
    // An editor that saves by writing a new file and renaming it ends the watch: watch again.
    if (QFileInfo::exists(path) && !m_watcher->files().contains(path))
        m_watcher->addPath(path);
    if (path != m_program->program().path || !QFileInfo::exists(path) ||
        QFileInfo(path).lastModified() == m_programModified)
        return; // another file, removed, or the version read last (a reload came first)
    if (m_link->state().jobActive) {
        m_reloadAfterJob = true; // the running job keeps the plan it has; ask when it ends
        return;
    }
    promptReload();
}

// "The file changed on disk: reload it?" — not modal (the machine window stays usable); one at a
// time, however many times the file is written.
void MainWindow::promptReload()
{
    m_reloadAfterJob = false;
    if (findChild<QMessageBox *>(QStringLiteral("reloadPrompt")))
        return;
    auto *box = new QMessageBox(
        QMessageBox::Question, tr("Frezka"),
        tr("%1 has changed on disk. Reload it? Until then the listing, the preview and the job "
           "are of the version read before.")
            .arg(QFileInfo(m_program->program().path).fileName()),
        QMessageBox::NoButton, this);
    box->setObjectName(QStringLiteral("reloadPrompt"));
    box->setWindowModality(Qt::NonModal);
    box->setAttribute(Qt::WA_DeleteOnClose);
    QPushButton *reload = box->addButton(tr("Reload"), QMessageBox::AcceptRole);
    reload->setObjectName(QStringLiteral("reloadYes"));
    box->addButton(tr("Keep the version read before"), QMessageBox::RejectRole)
        ->setObjectName(QStringLiteral("reloadNo"));
    connect(reload, &QPushButton::clicked, this, &MainWindow::reloadProgram);
    box->show();
}

void MainWindow::applyDisplayUnits()
{
    const LengthUnit unit = displayUnit();
    m_dro->setUnit(unit);
    m_jog->setUnit(unit);
    m_status->setUnit(unit);
    m_plot->setUnit(unit);
}

QString MainWindow::programUnitsText() const
{
    const LoadedProgram &p = m_program->program();
    if (!p.text)
        return {};
    // Units are set in a program's preamble: its first lines say it without reading it all.
    session::ModalScanner scanner(p.text, m_offsets->active());
    const int g = scanner.at(std::uint32_t(std::min(p.text->lineCount(), 2000))).g[gcode::kGUnits];
    return g == 200 ? tr("G20: the program is in inches") : tr("G21: the program is in mm");
}

ProgramInfoDialog *MainWindow::openProgramInfo()
{
    if (!m_programInfo) {
        m_programInfo = new ProgramInfoDialog(this);
        m_programInfo->setAttribute(Qt::WA_DeleteOnClose);
        updateProgramInfo();
    }
    m_programInfo->show();
    m_programInfo->raise();
    return m_programInfo;
}

void MainWindow::updateProgramInfo()
{
    if (!m_programInfo)
        return;
    const LoadedProgram &p = m_program->program();
    m_programInfo->setInfo(session::programInfo(p, m_offsets->state(), profile()),
                           QFileInfo(p.path).fileName());
}

void MainWindow::updatePlacement()
{
    const LoadedProgram &p = m_program->program();
    m_placement->setProgram(p.toolpath ? session::checkTravel(*p.toolpath, profile())
                                       : session::TravelFit{},
                            m_offsets->state(), profile());
    const auto &st = m_link->state();
    m_placement->setPosition(st.positionMm, st.mode == MachineMode::Idle);
}

// The placement bar's work zero: the active system takes the offset, the program is read again
// at it (onOffsetsChanged) and the bar hides once it is inside the travel.
void MainWindow::placeWorkOffset(const session::Axes4 &offsetMm)
{
    if (m_link->state().mode != MachineMode::Idle) {
        showError(tr("Set the work zero while the machine is ready and still."));
        return;
    }
    m_offsets->setSystem(m_offsets->active(), offsetMm);
    m_console->appendInfo(tr("Work offset %1 set to X %2, Y %3, Z %4 mm.")
                              .arg(session::workSystemName(m_offsets->active()))
                              .arg(offsetMm[0], 0, 'f', 3)
                              .arg(offsetMm[1], 0, 'f', 3)
                              .arg(offsetMm[2], 0, 'f', 3));
}

// The loaded (or re-planned) program goes to the run workflow.
void MainWindow::offerProgram()
{
    const LoadedProgram &p = m_program->program();
    const gcode::Point4 o = p.toolpath ? p.toolpath->origin() : gcode::Point4{};
    m_workflow->setProgram(p.runnable() ? p.unitProgram : nullptr, {o.x, o.y, o.z, o.a},
                           QFileInfo(p.path).fileName(),
                           p.errors.empty() ? QString() : p.errors.front().text);
    offerProbeFollow();
}

// The soft-limit policy (machine/softlimits.h) decides; the driver applies the same function,
// this only puts its refusal into the operator's words at once.
void MainWindow::jogStep(int axis, double deltaMm, double feedMmPerMin)
{
    const auto &st = m_link->state();
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
    m_link->execute(driver::op::JogStep{axis, deltaMm, feedMmPerMin});
}

void MainWindow::onOffsetsChanged()
{
    const auto &st = m_link->state();
    m_program->setWorkOffsets(m_offsets->state());
    m_dro->setActiveOffset(m_offsets->active());
    m_dro->setPositions(st.shownMm(), m_offsets->workPosition(st.shownMm()));
    m_program->setStartPosition(st.positionMm);
    m_program->reload(); // offsets apply by re-interpreting the program
}

void MainWindow::keepWorkOffsets()
{
    const auto &changed = m_program->program().changedWorkOffsets;
    if (!changed)
        return;
    session::OffsetState next = m_offsets->state();
    QStringList said;
    for (int s = 0; s < session::kWorkSystems; ++s) {
        const session::Axes4 &now = next.systems[std::size_t(s)];
        const session::Axes4 &set = (*changed)[std::size_t(s)];
        if (set == now)
            continue;
        said += tr("%1 X%2 Y%3 Z%4 A%5")
                    .arg(session::workSystemName(s))
                    .arg(set[0], 0, 'f', 3)
                    .arg(set[1], 0, 'f', 3)
                    .arg(set[2], 0, 'f', 3)
                    .arg(set[3], 0, 'f', 3);
        next.systems[std::size_t(s)] = set;
    }
    if (said.isEmpty())
        return;
    // As LinuxCNC keeps #5221.. in its parameter file: the next program (and this one run
    // again) starts from the offsets this one set, e.g. the Z zero of a touch-off.
    m_console->appendInfo(tr("The program set work offsets (G10 L2/L20), kept: %1 (machine mm).")
                              .arg(said.join(QStringLiteral("; "))));
    m_offsets->setState(next);
}

void MainWindow::setWorkZero(int axis)
{
    const auto &st = m_link->state();
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
