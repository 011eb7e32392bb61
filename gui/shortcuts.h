#pragma once
// The operator's keyboard shortcuts (issue 16 item 4): one table, the keys installed on the main
// window from it and listed from it in Help › Keyboard shortcuts. The defaults follow LinuxCNC
// AXIS where it has a key (R run, P pause, S resume, Esc stop, 0 feed 100 %, Ctrl+Home home all,
// arrows and Page Up/Down jog, F9 spindle). The operator may change every key in the settings
// (stored in QSettings under "shortcuts/<name>"); a key used by another action is refused.
// Jog keys act while held (press and release, handled by the main window's key events, and only
// while the jog panel is enabled and no text field has the focus); the others are QShortcuts.
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
    JogXMinus,
    JogXPlus,
    JogYMinus,
    JogYPlus,
    JogZMinus,
    JogZPlus,
    ZeroX,
    ZeroY,
    ZeroZ,
    ZeroAll,
    Spindle,
};

struct OperatorShortcut
{
    OperatorAction action;
    const char *name;    // object name of its QShortcut: "shortcutRun"
    const char *caption; // what it does (translated in context frezka::gui::Shortcuts)
    QKeySequence key;    // the default key
    const char *axis;    // AXIS's key for the same, "" = none
    bool held = false;   // acts while the key is held (jog): no QShortcut
};

const std::vector<OperatorShortcut> &operatorShortcuts();
const OperatorShortcut &operatorShortcut(OperatorAction action);
// The key in use: the operator's from the settings, else the default (empty = none).
QKeySequence shortcutKey(const OperatorShortcut &shortcut);
// Gives an action another key (empty = none) and stores it. Refused, with the reason in *error,
// when another action already has that key or the key has more than one combination.
bool setShortcutKey(OperatorAction action, const QKeySequence &key, QString *error = nullptr);
// Every key back to its default.
void resetShortcutKeys();
// The caption in the user's language.
QString shortcutCaption(const OperatorShortcut &shortcut);
// Help › Keyboard shortcuts: a non-modal window listing every shortcut (object name
// "shortcutsDialog"), created once per parent and shown.
QDialog *showShortcutsDialog(QWidget *parent);

} // namespace frezka::gui
