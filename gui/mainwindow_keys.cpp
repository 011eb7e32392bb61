// MainWindow: the operator's keyboard shortcuts (issue 16 item 4, gui/shortcuts.h).
#include "mainwindow.h"

#include "jogpanel.h"
#include "outputspanel.h"
#include "runpanel.h"
#include "shortcuts.h"

#include "driver/link/machinecontroller.h"

#include <QAbstractButton>
#include <QShortcut>

namespace frezka::gui {

namespace {

// Clicks the named button of a panel when it is enabled: the key does what the button does,
// when the button would.
void clickIfEnabled(QWidget *panel, const char *name)
{
    auto *b = panel->findChild<QAbstractButton *>(QLatin1String(name));
    if (b && b->isEnabled() && b->isVisible())
        b->click();
}

} // namespace

void MainWindow::installShortcuts()
{
    for (const OperatorShortcut &s : operatorShortcuts()) {
        auto *shortcut = new QShortcut(s.key, this);
        shortcut->setObjectName(QLatin1String(s.name));
        shortcut->setContext(Qt::WindowShortcut);
        shortcut->setAutoRepeat(false);
        const OperatorAction action = s.action;
        connect(shortcut, &QShortcut::activated, this, [this, action] { operatorKey(action); });
    }
}

void MainWindow::operatorKey(OperatorAction action)
{
    switch (action) {
    case OperatorAction::Run:
        return clickIfEnabled(m_run, "run");
    case OperatorAction::Pause:
        return clickIfEnabled(m_run, "pause");
    case OperatorAction::Resume:
        return clickIfEnabled(m_run, "resume");
    case OperatorAction::ToolLift:
        return clickIfEnabled(m_run, "toolLift");
    case OperatorAction::Stop: // from anywhere, always: the controlled stop (and homing's end)
        return m_workflow->stop();
    case OperatorAction::Abort:
        return m_workflow->abort();
    case OperatorAction::FeedUp:
        return clickIfEnabled(m_outputs, "feedUp");
    case OperatorAction::FeedDown:
        return clickIfEnabled(m_outputs, "feedDown");
    case OperatorAction::Feed100:
        return clickIfEnabled(m_outputs, "feedReset");
    case OperatorAction::HomeAll:
        return clickIfEnabled(m_jog, "homeAll");
    }
}

} // namespace frezka::gui
