// MainWindow: Machine › Save serial trace… — the session's record of the serial line both ways
// (docs/serial-trace.md), to send with a report of what went wrong.

#include "mainwindow.h"

#include "driver/link/tracerecorder.h"

#include <QAction>
#include <QDateTime>
#include <QDir>
#include <QFileDialog>
#include <QMenu>
#include <QStatusBar>

namespace frezka::gui {

void MainWindow::buildTraceAction()
{
    m_machineMenu->addSeparator();
    m_saveTraceAction = m_machineMenu->addAction(QString(), this, [this] {
        const QString suggested =
            QDir::homePath() +
            QStringLiteral("/frezka-%1.trace")
                .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss")));
        const QString path = QFileDialog::getSaveFileName(this, tr("Save serial trace"), suggested,
                                                          tr("Serial traces (*.trace *.txt)"));
        if (path.isEmpty())
            return;
        QString error;
        if (!saveSerialTrace(path, &error))
            showError(error);
        else
            statusBar()->showMessage(tr("Serial trace saved to %1").arg(path), 10000);
    });
    m_saveTraceAction->setObjectName(QStringLiteral("saveSerialTrace"));
}

bool MainWindow::saveSerialTrace(const QString &path, QString *error) const
{
    driver::TraceRecorder &recorder = driver::TraceRecorder::session();
    if (!recorder.enabled()) {
        *error = tr("The serial trace is off. Set how much of it to keep in Settings › "
                    "Application, then repeat what went wrong and save it again.");
        return false;
    }
    if (const std::string &firmware = m_link->state().firmware; !firmware.empty())
        recorder.setValue("firmware", firmware); // what the unit said, not the profile's
    recorder.setValue("saved", "Machine > Save serial trace");
    return recorder.save(path, error);
}

} // namespace frezka::gui
