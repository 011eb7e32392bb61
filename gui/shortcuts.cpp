#include "shortcuts.h"

#include <QCoreApplication>
#include <QDialog>
#include <QDialogButtonBox>
#include <QHeaderView>
#include <QLabel>
#include <QSettings>
#include <QTableWidget>
#include <QVBoxLayout>

#include <utility>

namespace frezka::gui {

namespace {

const char *const kContext = "frezka::gui::Shortcuts";

QString translated(const char *text)
{
    return QCoreApplication::translate(kContext, text);
}

void fill(QTableWidget *table)
{
    const auto &all = operatorShortcuts();
    table->setRowCount(int(all.size()));
    for (int row = 0; row < int(all.size()); ++row) {
        const OperatorShortcut &s = all[std::size_t(row)];
        table->setItem(row, 0, new QTableWidgetItem(shortcutCaption(s)));
        table->setItem(row, 1,
                       new QTableWidgetItem(shortcutKey(s).toString(QKeySequence::NativeText)));
        table->setItem(
            row, 2,
            new QTableWidgetItem(*s.axis ? QString::fromLatin1(s.axis) : QStringLiteral("–")));
    }
}

} // namespace

const std::vector<OperatorShortcut> &operatorShortcuts()
{
    using A = OperatorAction;
    static const std::vector<OperatorShortcut> table = {
        {A::Run, "shortcutRun", QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Run the program"),
         QKeySequence(Qt::Key_R), "R"},
        {A::Pause, "shortcutPause", QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Pause"),
         QKeySequence(Qt::Key_P), "P"},
        {A::Resume, "shortcutResume", QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Resume"),
         QKeySequence(Qt::Key_S), "S"},
        {A::Stop, "stopShortcut",
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts",
                           "Stop: brake along the ramp and hold the job (resumable)"),
         QKeySequence(Qt::Key_Escape), "Esc"},
        {A::Abort, "shortcutAbort",
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Abort: brake and drop the job"),
         QKeySequence(Qt::SHIFT | Qt::Key_Escape), "Esc"},
        {A::ToolLift, "shortcutToolLift", QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Tool lift"),
         QKeySequence(Qt::Key_L), ""},
        {A::FeedUp, "shortcutFeedUp",
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Feed override up (6.25 %)"),
         QKeySequence(Qt::Key_Plus), ""},
        {A::FeedDown, "shortcutFeedDown",
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Feed override down (6.25 %)"),
         QKeySequence(Qt::Key_Minus), ""},
        {A::Feed100, "shortcutFeed100",
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Feed override 100 %"),
         QKeySequence(Qt::Key_0), "0"},
        {A::HomeAll, "shortcutHomeAll",
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Home all axes"),
         QKeySequence(Qt::CTRL | Qt::Key_Home), "Ctrl+Home"},
        {A::JogXMinus, "shortcutJogXMinus", QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Jog X−"),
         QKeySequence(Qt::Key_Left), "Left", true},
        {A::JogXPlus, "shortcutJogXPlus", QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Jog X+"),
         QKeySequence(Qt::Key_Right), "Right", true},
        {A::JogYMinus, "shortcutJogYMinus", QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Jog Y−"),
         QKeySequence(Qt::Key_Down), "Down", true},
        {A::JogYPlus, "shortcutJogYPlus", QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Jog Y+"),
         QKeySequence(Qt::Key_Up), "Up", true},
        {A::JogZMinus, "shortcutJogZMinus", QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Jog Z−"),
         QKeySequence(Qt::Key_PageDown), "Page Down", true},
        {A::JogZPlus, "shortcutJogZPlus", QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Jog Z+"),
         QKeySequence(Qt::Key_PageUp), "Page Up", true},
        {A::ZeroX, "shortcutZeroX",
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Work zero of X here"),
         QKeySequence(Qt::SHIFT | Qt::Key_X), ""},
        {A::ZeroY, "shortcutZeroY",
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Work zero of Y here"),
         QKeySequence(Qt::SHIFT | Qt::Key_Y), ""},
        {A::ZeroZ, "shortcutZeroZ",
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Work zero of Z here"),
         QKeySequence(Qt::SHIFT | Qt::Key_Z), ""},
        {A::ZeroAll, "shortcutZeroAll",
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Work zero of all axes here"),
         QKeySequence(Qt::Key_End), ""},
        {A::Spindle, "shortcutSpindle",
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "Spindle on / off"), QKeySequence(Qt::Key_F9),
         "F9"},
    };
    return table;
}

const OperatorShortcut &operatorShortcut(OperatorAction action)
{
    for (const OperatorShortcut &s : operatorShortcuts())
        if (s.action == action)
            return s;
    return operatorShortcuts().front(); // every action has a row
}

QKeySequence shortcutKey(const OperatorShortcut &shortcut)
{
    const QVariant stored =
        QSettings().value(QStringLiteral("shortcuts/") + QLatin1String(shortcut.name));
    if (!stored.isValid())
        return shortcut.key;
    return QKeySequence::fromString(stored.toString(), QKeySequence::PortableText);
}

bool setShortcutKey(OperatorAction action, const QKeySequence &key, QString *error)
{
    auto refuse = [error](const QString &why) {
        if (error)
            *error = why;
        return false;
    };
    if (key.count() > 1)
        return refuse(QCoreApplication::translate(
            "frezka::gui::Shortcuts",
            "Give one key (with Ctrl, Shift or Alt if you like), not a sequence of keys."));
    // The menu commands' own keys (gui/mainwindow.cpp): an operator key on one of them would
    // make both ambiguous, and Qt then runs neither.
    static const std::pair<QKeySequence, const char *> kMenuKeys[] = {
        {QKeySequence(QKeySequence::Open),
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "File › Open program")},
        {QKeySequence(Qt::CTRL | Qt::Key_R),
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "File › Reload program")},
        {QKeySequence(QKeySequence::Quit),
         QT_TRANSLATE_NOOP("frezka::gui::Shortcuts", "File › Quit")},
    };
    for (const auto &[menuKey, command] : kMenuKeys) {
        if (!key.isEmpty() && key == menuKey)
            return refuse(QCoreApplication::translate(
                              "frezka::gui::Shortcuts",
                              "%1 is the key of the menu command “%2”. Choose a different key.")
                              .arg(key.toString(QKeySequence::NativeText), translated(command)));
    }
    for (const OperatorShortcut &other : operatorShortcuts()) {
        if (other.action != action && !key.isEmpty() && shortcutKey(other) == key)
            return refuse(QCoreApplication::translate(
                              "frezka::gui::Shortcuts",
                              "%1 is already the key of “%2”. Give that action another key "
                              "first, or choose a different key.")
                              .arg(key.toString(QKeySequence::NativeText), shortcutCaption(other)));
    }
    const OperatorShortcut &s = operatorShortcut(action);
    const QString settingsKey = QStringLiteral("shortcuts/") + QLatin1String(s.name);
    if (key == s.key)
        QSettings().remove(settingsKey);
    else
        QSettings().setValue(settingsKey, key.toString(QKeySequence::PortableText));
    return true;
}

void resetShortcutKeys()
{
    QSettings().remove(QStringLiteral("shortcuts"));
}

QString shortcutCaption(const OperatorShortcut &shortcut)
{
    return translated(shortcut.caption);
}

QDialog *showShortcutsDialog(QWidget *parent)
{
    auto *dialog = parent->findChild<QDialog *>(QStringLiteral("shortcutsDialog"));
    if (!dialog) {
        dialog = new QDialog(parent);
        dialog->setObjectName(QStringLiteral("shortcutsDialog"));
        auto *layout = new QVBoxLayout(dialog);
        auto *note = new QLabel(dialog);
        note->setObjectName(QStringLiteral("shortcutsNote"));
        note->setWordWrap(true);
        layout->addWidget(note);
        auto *table = new QTableWidget(0, 3, dialog);
        table->setObjectName(QStringLiteral("shortcutsTable"));
        table->setEditTriggers(QAbstractItemView::NoEditTriggers);
        table->verticalHeader()->hide();
        table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
        layout->addWidget(table);
        auto *buttons = new QDialogButtonBox(QDialogButtonBox::Close, dialog);
        QObject::connect(buttons, &QDialogButtonBox::rejected, dialog, &QDialog::close);
        layout->addWidget(buttons);
        dialog->resize(560, 420);
    }
    dialog->setWindowTitle(
        QCoreApplication::translate("frezka::gui::Shortcuts", "Keyboard shortcuts"));
    dialog->findChild<QLabel *>(QStringLiteral("shortcutsNote"))
        ->setText(QCoreApplication::translate(
            "frezka::gui::Shortcuts",
            "Keys of the main window; change them in Settings › Shortcuts. The jog keys act "
            "while held, only when jogging is possible (not while a job runs) and not while "
            "a text field has the focus. A text field with the focus keeps the letters typed "
            "into it; no key presses a button that merely has the focus."));
    auto *table = dialog->findChild<QTableWidget *>(QStringLiteral("shortcutsTable"));
    table->setHorizontalHeaderLabels(
        {QCoreApplication::translate("frezka::gui::Shortcuts", "Action"),
         QCoreApplication::translate("frezka::gui::Shortcuts", "Key"),
         QCoreApplication::translate("frezka::gui::Shortcuts", "LinuxCNC AXIS")});
    fill(table);
    dialog->show();
    dialog->raise();
    return dialog;
}

} // namespace frezka::gui
