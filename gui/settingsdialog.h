#pragma once
// SettingsDialog: the machine profile (every key, with load / save / export) and the
// application settings (language, reconnect) and the keyboard shortcuts. Non-modal: open it with
// show(); it applies by signals and never blocks the machine window.

#include "machine/machineconfig.h"

#include <QDialog>

class QCheckBox;
class QComboBox;
class QDialogButtonBox;
class QLabel;
class QPushButton;
class QSpinBox;
class QTabWidget;

namespace frezka::gui {

// The serial trace's ring (driver/link/tracerecorder.h): QSettings "link/traceMb", megabytes kept
// in memory, 0 = off, 4 unless set. applyTraceSetting() gives the session's recorder that size.
inline const QString kTraceKey = QStringLiteral("link/traceMb");
constexpr int kTraceDefaultMb = 4;
void applyTraceSetting();

class ProfileEditor;
class ShortcutEditor;

class SettingsDialog : public QDialog
{
    Q_OBJECT

public:
    SettingsDialog(const machine::MachineConfig &config, const QString &profilePath,
                   QWidget *parent = nullptr);
    ProfileEditor *editor() const { return m_editor; }
    ShortcutEditor *shortcutEditor() const { return m_shortcuts; }
    QString profilePath() const { return m_path; }

    // The actions behind the buttons, without file dialogs (tests, scripts). Errors are shown
    // in the dialog and returned.
    bool saveTo(const QString &path, QString *error = nullptr);
    bool loadFrom(const QString &path, QString *error = nullptr);
    // Applies the language choice ("cs", "en", "" = system).
    void chooseLanguage(const QString &code);

signals:
    // The user applied or saved a valid profile.
    void profileApplied(const machine::MachineConfig &config, const QString &path);
    void languageChosen(const QString &code);
    // The operator changed a keyboard shortcut (stored in QSettings already).
    void shortcutsChanged();
    // The operator chose mm or inch for the display (stored in QSettings already).
    void displayUnitsChanged();

protected:
    void changeEvent(QEvent *event) override;

private:
    // The constructor's parts (the pages in the order of their tabs).
    QWidget *createProfilePage(const machine::MachineConfig &config);
    QWidget *createApplicationPage();
    void connectProfileButtons();
    void retranslate();
    void apply();
    void showMessage(const QString &text, bool error);

    ProfileEditor *m_editor;
    ShortcutEditor *m_shortcuts;
    QString m_path;
    QTabWidget *m_tabs;
    QLabel *m_pathLabel, *m_message, *m_languageLabel;
    QComboBox *m_language, *m_units;
    QLabel *m_unitsLabel;
    QCheckBox *m_reconnect;
    QLabel *m_traceLabel;
    QSpinBox *m_traceMb;
    QPushButton *m_load, *m_save, *m_export, *m_defaults, *m_apply;
    QDialogButtonBox *m_buttons;
};

} // namespace frezka::gui
