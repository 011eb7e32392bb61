// MainWindow: the operator's keyboard shortcuts (issue 16 item 4, gui/shortcuts.h).
#include "mainwindow.h"

#include "drowidget.h"
#include "jogpanel.h"
#include "outputspanel.h"
#include "runpanel.h"
#include "shortcuts.h"

#include "driver/link/machinecontroller.h"

#include <QAbstractButton>
#include <QAbstractSpinBox>
#include <QApplication>
#include <QKeyEvent>
#include <QKeySequenceEdit>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QShortcut>
#include <QTextEdit>

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

// A widget the operator types into: it keeps every key, so no jog key acts through it.
bool typesText(const QWidget *w)
{
    return qobject_cast<const QLineEdit *>(w) || qobject_cast<const QAbstractSpinBox *>(w) ||
           qobject_cast<const QPlainTextEdit *>(w) || qobject_cast<const QTextEdit *>(w) ||
           qobject_cast<const QKeySequenceEdit *>(w);
}

} // namespace

void MainWindow::installShortcuts()
{
    for (const OperatorShortcut &s : operatorShortcuts()) {
        if (s.held)
            continue; // jog: press and release in keyPressEvent / keyReleaseEvent
        auto *shortcut = new QShortcut(shortcutKey(s), this);
        shortcut->setObjectName(QLatin1String(s.name));
        shortcut->setContext(Qt::WindowShortcut);
        shortcut->setAutoRepeat(false);
        const OperatorAction action = s.action;
        connect(shortcut, &QShortcut::activated, this, [this, action] { operatorKey(action); });
    }
}

void MainWindow::applyShortcutKeys()
{
    for (const OperatorShortcut &s : operatorShortcuts()) {
        if (auto *shortcut = findChild<QShortcut *>(QLatin1String(s.name)))
            shortcut->setKey(shortcutKey(s));
    }
}

// A jog key (gui/shortcuts.h, held = true) pressed or released: the jog panel jogs as if its
// button were pressed, only while it is enabled (not while a job runs) and no text field has the
// focus. Returns whether the key is a jog key (it is then used up either way).
bool MainWindow::jogKey(QKeyEvent *event, bool pressed)
{
    const QKeySequence key(
        QKeyCombination(event->modifiers() & ~Qt::KeypadModifier, Qt::Key(event->key())));
    for (const OperatorShortcut &s : operatorShortcuts()) {
        if (!s.held || shortcutKey(s) != key)
            continue;
        if (event->isAutoRepeat() || (pressed && typesText(QApplication::focusWidget())))
            return true; // a release always passes: it ends a continuous jog
        const int index = int(s.action) - int(OperatorAction::JogXMinus);
        if (m_jog->isEnabled())
            m_jog->jogKey(index / 2, index % 2 ? 1 : -1, pressed);
        return true;
    }
    return false;
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
    case OperatorAction::ZeroX:
        return clickIfEnabled(m_dro, "zeroX");
    case OperatorAction::ZeroY:
        return clickIfEnabled(m_dro, "zeroY");
    case OperatorAction::ZeroZ:
        return clickIfEnabled(m_dro, "zeroZ");
    case OperatorAction::ZeroAll:
        return clickIfEnabled(m_dro, "zeroAll");
    case OperatorAction::Spindle:
        return clickIfEnabled(m_outputs, "spindle");
    default: // the jog keys act in jogKey()
        return;
    }
}

} // namespace frezka::gui
