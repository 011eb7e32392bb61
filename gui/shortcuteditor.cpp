#include "shortcuteditor.h"

#include "shortcuts.h"

#include <QEvent>
#include <QHBoxLayout>
#include <QHeaderView>
#include <QKeySequenceEdit>
#include <QLabel>
#include <QPushButton>
#include <QTableWidget>
#include <QVBoxLayout>

namespace frezka::gui {

ShortcutEditor::ShortcutEditor(QWidget *parent)
    : QWidget(parent)
{
    m_note = new QLabel(this);
    m_note->setWordWrap(true);
    m_table = new QTableWidget(0, 3, this);
    m_table->setObjectName(QStringLiteral("shortcutEditorTable"));
    m_table->setEditTriggers(QAbstractItemView::NoEditTriggers);
    m_table->setSelectionMode(QAbstractItemView::NoSelection);
    m_table->verticalHeader()->hide();
    m_table->horizontalHeader()->setSectionResizeMode(0, QHeaderView::Stretch);
    m_message = new QLabel(this);
    m_message->setObjectName(QStringLiteral("shortcutMessage"));
    m_message->setWordWrap(true);
    m_reset = new QPushButton(this);
    m_reset->setObjectName(QStringLiteral("resetShortcuts"));
    connect(m_reset, &QPushButton::clicked, this, &ShortcutEditor::resetToDefaults);
    auto *row = new QHBoxLayout;
    row->addWidget(m_message, 1);
    row->addWidget(m_reset);
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_note);
    layout->addWidget(m_table, 1);
    layout->addLayout(row);
    fill();
    retranslate();
}

// One row per action: its caption, a key field (object name "key" + the shortcut's name without
// its "shortcut" prefix, e.g. "keyJogXPlus") and the default key.
void ShortcutEditor::fill()
{
    const auto &all = operatorShortcuts();
    m_table->setRowCount(int(all.size()));
    for (int row = 0; row < int(all.size()); ++row) {
        const OperatorShortcut &s = all[std::size_t(row)];
        m_table->setItem(row, 0, new QTableWidgetItem(shortcutCaption(s)));
        auto *edit = qobject_cast<QKeySequenceEdit *>(m_table->cellWidget(row, 1));
        if (!edit) {
            edit = new QKeySequenceEdit(m_table);
            edit->setObjectName(QStringLiteral("key") +
                                QLatin1String(s.name).mid(int(qstrlen("shortcut"))));
            const OperatorAction action = s.action;
            connect(edit, &QKeySequenceEdit::editingFinished, this, [this, edit, action] {
                // The field records up to four keys; the first one is the shortcut.
                const QKeySequence typed = edit->keySequence();
                const QKeySequence key = typed.isEmpty() ? QKeySequence() : QKeySequence(typed[0]);
                assign(action, key);
            });
            m_table->setCellWidget(row, 1, edit);
        }
        const QSignalBlocker block(edit);
        edit->setKeySequence(shortcutKey(s));
        m_table->setItem(row, 2, new QTableWidgetItem(s.key.toString(QKeySequence::NativeText)));
    }
}

bool ShortcutEditor::assign(OperatorAction action, const QKeySequence &key, QString *error)
{
    QString why;
    const bool ok = setShortcutKey(action, key, &why);
    if (ok)
        showMessage(tr("“%1” now has the key %2.")
                        .arg(shortcutCaption(operatorShortcut(action)),
                             key.isEmpty() ? tr("(none)") : key.toString(QKeySequence::NativeText)),
                    false);
    else
        showMessage(why, true);
    if (error)
        *error = why;
    fill(); // a refused key: the field shows the one in use again
    if (ok)
        emit shortcutsChanged();
    return ok;
}

void ShortcutEditor::resetToDefaults()
{
    resetShortcutKeys();
    fill();
    showMessage(tr("Every key is back to its default."), false);
    emit shortcutsChanged();
}

QString ShortcutEditor::message() const
{
    return m_message->text();
}

void ShortcutEditor::showMessage(const QString &text, bool error)
{
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("color: #c00; font-weight: bold;") : QString());
}

void ShortcutEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ShortcutEditor::retranslate()
{
    m_note->setText(tr("Click a key field and press the new key; it applies at once. A key "
                       "that another action already has is refused."));
    m_table->setHorizontalHeaderLabels({tr("Action"), tr("Key"), tr("Default")});
    m_reset->setText(tr("Reset to defaults"));
    fill();
}

} // namespace frezka::gui
