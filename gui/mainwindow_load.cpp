// MainWindow: a program load cancelled from the status bar's Cancel (issue 17 item 4). The
// program session stops the load at once; the program loaded before stays (its listing, view,
// plan), or the window stays empty, and the status bar and the console say which.
#include "mainwindow.h"

#include "consolewidget.h"
#include "loadprogress.h"

#include <QFileInfo>
#include <QLabel>
#include <QStatusBar>

namespace frezka::gui {

void MainWindow::connectLoadCancel()
{
    connect(m_loadProgress, &LoadProgress::cancelRequested, m_program, &ProgramSession::cancel);
    connect(m_program, &ProgramSession::loadCancelled, this, [this](const QString &path) {
        m_loadProgress->setVisible(false);
        const LoadedProgram &kept = m_program->program();
        const QString name = QFileInfo(path).fileName();
        QString message;
        if (kept.path.isEmpty()) {
            m_file->setText(tr("No program"));
            message = tr("Loading %1 was cancelled; no program is loaded.").arg(name);
        } else {
            m_file->setText(programFileText());
            message = tr("Loading %1 was cancelled; %2 stays loaded.")
                          .arg(name, QFileInfo(kept.path).fileName());
        }
        m_console->appendInfo(message);
        statusBar()->showMessage(message, 15000);
    });
}

QString MainWindow::programFileText() const
{
    const LoadedProgram &p = m_program->program();
    return tr("%1 — %n line(s)", nullptr, p.text ? p.text->lineCount() : 0)
               .arg(QFileInfo(p.path).fileName()) +
           QStringLiteral(" · ") + programUnitsText();
}

} // namespace frezka::gui
