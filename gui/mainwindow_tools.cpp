// MainWindow, the tool table (issue 15 item 1): Machine › Tool table… edits the file the
// profile names (tools.tableFile, beside the profile); the program session checks and plans
// programs with it (T, M6, G43 lengths) from the next load on, and a program already loaded is
// loaded again with the saved table. A program's G10 L1/L10/L11 change it once the program
// has run (not when it is only checked), written back atomically.
#include "mainwindow.h"

#include "consolewidget.h"
#include "tooltabledialog.h"

#include "driver/link/machinecontroller.h"
#include "session/programsession.h"
#include "session/tooltablefile.h"

#include <QAction>
#include <QMenu>

namespace frezka::gui {

void MainWindow::buildToolTableAction()
{
    m_toolTableAction = m_machineMenu->addAction(QString(), this, [this] { openToolTable(); });
    m_toolTableAction->setObjectName(QStringLiteral("toolTable"));
}

void MainWindow::loadToolTable()
{
    const session::ToolTableFile tools = session::readProfileToolTable(profile(), m_profilePath);
    m_program->setToolTable(tools.table, tools.error);
    m_program->setSubroutinePath(
        machine::subroutineFolders(profile(), m_profilePath.toStdString()));
    if (!tools.error.isEmpty())
        showError(tools.error);
}

void MainWindow::writeBackToolTable()
{
    const auto &changed = m_program->program().changedToolTable;
    const session::ToolTableFile tools = session::readProfileToolTable(profile(), m_profilePath);
    if (!changed || tools.path.isEmpty())
        return;
    gcode::Error error;
    if (!gcode::writeToolTableFile(tools.path.toStdString(), *changed, &error)) {
        showError(gcode::formatError(tools.path, error));
        return;
    }
    m_console->appendInfo(
        tr("The program changed the tool table (G10 L1, L10 or L11): %1 saved.").arg(tools.path));
    loadToolTable();
    if (m_toolTable)
        m_toolTable->reload();
    m_program->reload(); // checked again with the table as it now is
}

QString MainWindow::toolChangeText(const driver::MachineState &state) const
{
    const driver::DriverMessage &m = state.holdMessage;
    const auto &table = m_program->toolTable();
    if (m.code != driver::DriverCode::HoldToolChange || m.args.size() < 2 || !table)
        return {};
    const int tool = QString::fromStdString(m.args[1]).toInt();
    const gcode::ToolEntry *e = table->find(tool);
    if (!e)
        return {};
    const QString comment = e->comment.empty() ? tr("no comment in the tool table")
                                               : QString::fromStdString(e->comment);
    return tr("Tool %1: %2 (length %3 mm, diameter %4 mm)")
        .arg(tool)
        .arg(comment, QString::number(e->offsetMm[2], 'g', 10),
             QString::number(e->diameterMm, 'g', 10));
}

ToolTableDialog *MainWindow::openToolTable()
{
    const session::ToolTableFile tools = session::readProfileToolTable(profile(), m_profilePath);
    if (tools.path.isEmpty()) {
        showError(tr("The machine profile names no tool table file: set it in Machine › "
                     "Settings (Tools), e.g. tool.tbl."));
        return nullptr;
    }
    if (m_toolTable && m_toolTable->path() != tools.path)
        m_toolTable->close(); // another profile since: its own table
    if (!m_toolTable) {
        m_toolTable = new ToolTableDialog(tools.path, this);
        m_toolTable->setAttribute(Qt::WA_DeleteOnClose);
        m_toolTable->setToolSensor(*m_link, profile());
        connect(m_toolTable, &ToolTableDialog::measured, this, [this](int tool, double mm) {
            m_console->appendInfo(tr("Tool %1 measured on the tool sensor: %2 mm long.")
                                      .arg(tool)
                                      .arg(mm, 0, 'f', 4));
        });
        connect(m_toolTable, &ToolTableDialog::saved, this, [this] {
            loadToolTable();
            m_console->appendInfo(tr("Tool table saved; programs are checked with it."));
            if (!m_program->program().path.isEmpty())
                m_program->reload();
        });
    }
    m_toolTable->show();
    m_toolTable->raise();
    return m_toolTable;
}

} // namespace frezka::gui
