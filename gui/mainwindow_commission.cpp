// MainWindow: Machine › Commission this machine… — the commissioning assistant's dialog
// (gui/commissiondialog.h). The window lets go of the unit while the dialog has it and
// connects again when it closes.

#include "mainwindow.h"

#include "gui/commissiondialog.h"

#include <QAction>
#include <QMenu>

namespace frezka::gui {

void MainWindow::buildCommissionAction()
{
    m_commissionAction = m_machineMenu->addAction(QString(), this, [this] {
        disconnectFromUnit();
        auto *dialog = new CommissionDialog(profile(), profilePath(), this);
        dialog->setAttribute(Qt::WA_DeleteOnClose);
        connect(dialog, &QDialog::finished, this, [this] { connectToUnit(); });
        dialog->open();
    });
    m_commissionAction->setObjectName(QStringLiteral("commission"));
}

} // namespace frezka::gui
