#pragma once
// The operator's keyboard shortcuts (issue 16 item 4): one table, the keys installed on the main
// window from it and listed from it in Help › Keyboard shortcuts. The defaults follow LinuxCNC
// AXIS where it has a key (R run, P pause, S resume, Esc stop, 0 feed 100 %, Ctrl+Home home all).
// Every shortcut acts as its button would (only when that button is enabled) or on the run
// workflow itself (Stop, Abort: from anywhere, always). Buttons that act on the machine take no
// keyboard focus, so Space or Enter never presses one; a line edit keeps its typed letters (Qt
// lets a focused text field override single-key shortcuts).

#include <QKeySequence>
#include <QString>

#include <vector>

class QDialog;
class QWidget;

namespace frezka::gui {

enum class OperatorAction {
    Run,
    Pause,
    Resume,
    Stop,
    Abort,
    ToolLift,
    FeedUp,
    FeedDown,
    Feed100,
    HomeAll,
};

struct OperatorShortcut
{
    OperatorAction action;
    const char *name;    // object name of its QShortcut: "shortcutRun"
    const char *caption; // what it does (translated in context frezka::gui::Shortcuts)
    QKeySequence key;
    const char *axis; // AXIS's key for the same, "" = none
};

const std::vector<OperatorShortcut> &operatorShortcuts();
// The caption in the user's language.
QString shortcutCaption(const OperatorShortcut &shortcut);
// Help › Keyboard shortcuts: a non-modal window listing every shortcut (object name
// "shortcutsDialog"), created once per parent and shown.
QDialog *showShortcutsDialog(QWidget *parent);

} // namespace frezka::gui
