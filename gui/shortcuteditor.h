#pragma once
// ShortcutEditor: the Shortcuts page of the settings (issue 16 item 4). One row per operator
// action (gui/shortcuts.h) with its key in a key field; a key another action already has is
// refused with a message and the field shows the old key again; Reset to defaults restores every
// key. Keys are stored in QSettings at once; shortcutsChanged() tells the main window.

#include <QWidget>

class QLabel;
class QPushButton;
class QTableWidget;

namespace frezka::gui {

enum class OperatorAction;

class ShortcutEditor : public QWidget
{
    Q_OBJECT

public:
    explicit ShortcutEditor(QWidget *parent = nullptr);
    // What the key field of an action does when the operator finishes typing a key: true when
    // taken; otherwise the message says why (also shown on the page).
    bool assign(OperatorAction action, const QKeySequence &key, QString *error = nullptr);
    void resetToDefaults();
    QString message() const;

signals:
    void shortcutsChanged();

protected:
    void changeEvent(QEvent *event) override;

private:
    void fill();
    void retranslate();
    void showMessage(const QString &text, bool error);

    QTableWidget *m_table;
    QLabel *m_note, *m_message;
    QPushButton *m_reset;
};

} // namespace frezka::gui
