// MainWindow, run from a line (issue 16 item 2): the listing's "Run from this line…" and
// Machine › Run from line… load the program again as the job from that line (the program
// session does it, session/runfromline.h); the preview, the listing and the plot show that job,
// Run runs it through the run workflow as any program (pause, stop, abort, the tool lift), and
// once it has ended the program is whole again.
#include "mainwindow.h"

#include "consolewidget.h"
#include "programlisting.h"

#include "driver/link/machinecontroller.h"

#include <QAction>
#include <QInputDialog>
#include <QMenu>
#include <QStatusBar>

namespace frezka::gui {

void MainWindow::buildFromLineActions()
{
    m_machineMenu->addSeparator();
    m_runFromLineAction = m_machineMenu->addAction(QString(), this, [this] { askRunFromLine(); });
    m_runFromLineAction->setObjectName(QStringLiteral("runFromLine"));
    m_wholeProgramAction = m_machineMenu->addAction(QString(), this, [this] { runWholeProgram(); });
    m_wholeProgramAction->setObjectName(QStringLiteral("wholeProgram"));
    m_wholeProgramAction->setEnabled(false);
}

void MainWindow::runFromLine(int line)
{
    const LoadedProgram &p = m_program->program();
    if (p.path.isEmpty() || !p.text) {
        showError(tr("Open a program first, then choose the line to run from."));
        return;
    }
    if (line < 1 || line > p.text->lineCount()) {
        showError(tr("Line %1 is not in the program (lines 1 to %2): choose one of its lines.")
                      .arg(line)
                      .arg(p.text->lineCount()));
        return;
    }
    const auto &st = m_link->state();
    if (st.mode != driver::MachineMode::Idle && st.mode != driver::MachineMode::Disconnected) {
        showError(tr("The machine is busy (%1): run from a line once it is ready.")
                      .arg(machineModeText(st.mode)));
        return;
    }
    m_program->setStartLine(std::uint32_t(line));
    m_program->setStartPosition(st.positionMm); // the approach starts where the machine stands
    m_program->reload();
}

void MainWindow::runWholeProgram()
{
    if (m_program->startLine() == 0)
        return;
    m_program->setStartLine(0);
    m_program->setStartPosition(m_link->state().positionMm);
    m_program->reload();
}

void MainWindow::askRunFromLine()
{
    const LoadedProgram &p = m_program->program();
    if (p.path.isEmpty() || !p.text) {
        showError(tr("Open a program first, then choose the line to run from."));
        return;
    }
    const int suggested =
        m_listing->selectedLine() > 0 ? m_listing->selectedLine() : m_listing->firstVisibleLine();
    bool ok = false;
    const int line =
        QInputDialog::getInt(this, tr("Run from line"),
                             tr("Start the program at line (1 to %1):").arg(p.text->lineCount()),
                             std::max(1, suggested), 1, p.text->lineCount(), 1, &ok);
    if (ok)
        runFromLine(line);
}

// After a load: say what a job from a line will do (or nothing for the whole program).
void MainWindow::onFromLineLoaded()
{
    const LoadedProgram &p = m_program->program();
    m_wholeProgramAction->setEnabled(m_program->startLine() != 0);
    if (!p.fromLine)
        return;
    const QString text =
        tr("Run from line %1 is ready: the view shows the approach. Run starts it; Machine › Run "
           "the whole program goes back.")
            .arg(p.fromLine->askedLine);
    m_console->appendInfo(text + QLatin1Char(' ') + session::fromLineSummary(*p.fromLine));
    statusBar()->showMessage(text);
    m_listing->showCurrentLine(int(p.fromLine->line));
}

} // namespace frezka::gui
