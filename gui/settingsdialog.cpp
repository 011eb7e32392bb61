#include "settingsdialog.h"

#include "displayunits.h"
#include "language.h"
#include "profileeditor.h"
#include "profilestore.h"
#include "shortcuteditor.h"

#include "driver/link/tracerecorder.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDialogButtonBox>
#include <QEvent>
#include <QFileDialog>
#include <QFormLayout>
#include <QHBoxLayout>
#include <QLabel>
#include <QPushButton>
#include <QSettings>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>

namespace frezka::gui {

SettingsDialog::SettingsDialog(const machine::MachineConfig &config, const QString &profilePath,
                               QWidget *parent)
    : QDialog(parent)
    , m_path(profilePath)
{
    setObjectName(QStringLiteral("settingsDialog"));
    m_tabs = new QTabWidget(this);
    m_tabs->addTab(createProfilePage(config), QString());
    m_tabs->addTab(createApplicationPage(), QString());
    m_shortcuts = new ShortcutEditor;
    m_shortcuts->setObjectName(QStringLiteral("shortcutEditor"));
    connect(m_shortcuts, &ShortcutEditor::shortcutsChanged, this,
            &SettingsDialog::shortcutsChanged);
    m_tabs->addTab(m_shortcuts, QString());

    m_message = new QLabel(this);
    m_message->setWordWrap(true);
    m_buttons = new QDialogButtonBox(QDialogButtonBox::Close, this);
    m_apply = m_buttons->addButton(QString(), QDialogButtonBox::ApplyRole);
    connect(m_buttons, &QDialogButtonBox::rejected, this, &QDialog::close);
    connect(m_apply, &QPushButton::clicked, this, &SettingsDialog::apply);
    connectProfileButtons();
    auto *layout = new QVBoxLayout(this);
    layout->addWidget(m_tabs, 1);
    layout->addWidget(m_message);
    layout->addWidget(m_buttons);
    resize(760, 640);
    retranslate();
}

// The machine profile's editor and its file buttons.
QWidget *SettingsDialog::createProfilePage(const machine::MachineConfig &config)
{
    auto *profilePage = new QWidget;
    m_editor = new ProfileEditor(profilePage);
    m_editor->setConfig(config);
    m_pathLabel = new QLabel(profilePage);
    m_pathLabel->setTextInteractionFlags(Qt::TextSelectableByMouse);
    m_load = new QPushButton(profilePage);
    m_save = new QPushButton(profilePage);
    m_save->setObjectName(QStringLiteral("saveProfile"));
    m_export = new QPushButton(profilePage);
    m_defaults = new QPushButton(profilePage);
    auto *fileRow = new QHBoxLayout;
    fileRow->addWidget(m_pathLabel, 1);
    fileRow->addWidget(m_defaults);
    fileRow->addWidget(m_load);
    fileRow->addWidget(m_export);
    fileRow->addWidget(m_save);
    auto *profileLayout = new QVBoxLayout(profilePage);
    profileLayout->addWidget(m_editor, 1);
    profileLayout->addLayout(fileRow);
    return profilePage;
}

void applyTraceSetting()
{
    const int mb = QSettings().value(kTraceKey, kTraceDefaultMb).toInt();
    driver::TraceRecorder::session().setLimitBytes(std::int64_t{std::max(0, mb)} * 1024 * 1024);
}

// The application's own settings: the language and reconnecting by itself.
QWidget *SettingsDialog::createApplicationPage()
{
    auto *appPage = new QWidget;
    auto *appForm = new QFormLayout(appPage);
    m_languageLabel = new QLabel(appPage);
    m_language = new QComboBox(appPage);
    m_language->setObjectName(QStringLiteral("language"));
    m_language->addItem(QString(), QString());
    m_language->addItem(QStringLiteral("Čeština"), QStringLiteral("cs"));
    m_language->addItem(QStringLiteral("English"), QStringLiteral("en"));
    const QString saved = QSettings().value(QStringLiteral("language")).toString();
    m_language->setCurrentIndex(std::max(0, m_language->findData(saved)));
    connect(m_language, &QComboBox::activated, this,
            [this](int i) { chooseLanguage(m_language->itemData(i).toString()); });
    m_reconnect = new QCheckBox(appPage);
    m_reconnect->setChecked(QSettings().value(QStringLiteral("link/autoReconnect"), true).toBool());
    connect(m_reconnect, &QCheckBox::toggled, this,
            [](bool on) { QSettings().setValue(QStringLiteral("link/autoReconnect"), on); });
    m_traceLabel = new QLabel(appPage);
    m_traceMb = new QSpinBox(appPage);
    m_traceMb->setObjectName(QStringLiteral("traceMb"));
    m_traceMb->setRange(0, 1024);
    m_traceMb->setValue(QSettings().value(kTraceKey, kTraceDefaultMb).toInt());
    connect(m_traceMb, &QSpinBox::valueChanged, this, [](int mb) {
        QSettings().setValue(kTraceKey, mb);
        applyTraceSetting();
    });
    m_unitsLabel = new QLabel(appPage);
    m_units = new QComboBox(appPage);
    m_units->setObjectName(QStringLiteral("displayUnits"));
    m_units->addItem(QString(), int(LengthUnit::Mm));
    m_units->addItem(QString(), int(LengthUnit::Inch));
    m_units->setCurrentIndex(m_units->findData(int(displayUnit())));
    connect(m_units, &QComboBox::activated, this, [this](int i) {
        setDisplayUnit(LengthUnit(m_units->itemData(i).toInt()));
        emit displayUnitsChanged();
    });
    appForm->addRow(m_languageLabel, m_language);
    appForm->addRow(m_unitsLabel, m_units);
    appForm->addRow(m_reconnect);
    appForm->addRow(m_traceLabel, m_traceMb);
    return appPage;
}

// Save, Export, Load and Defaults of the profile page.
void SettingsDialog::connectProfileButtons()
{
    connect(m_save, &QPushButton::clicked, this, [this] { saveTo(m_path); });
    connect(m_export, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getSaveFileName(this, tr("Export profile"), m_path,
                                                          tr("Machine profiles (*.json)"));
        if (!path.isEmpty())
            saveTo(path);
    });
    connect(m_load, &QPushButton::clicked, this, [this] {
        const QString path = QFileDialog::getOpenFileName(this, tr("Load profile"), m_path,
                                                          tr("Machine profiles (*.json)"));
        if (!path.isEmpty())
            loadFrom(path);
    });
    connect(m_defaults, &QPushButton::clicked, this, [this] {
        m_editor->setConfig(machine::defaultMachineConfig(m_editor->config().unit.variant));
        showMessage(tr("Defaults of the unit type loaded; Apply or Save to use them."), false);
    });
}

void SettingsDialog::showMessage(const QString &text, bool error)
{
    m_message->setText(text);
    m_message->setStyleSheet(error ? QStringLiteral("color: #c00; font-weight: bold;") : QString());
}

bool SettingsDialog::saveTo(const QString &path, QString *error)
{
    QString why;
    rememberProfile(path);
    if (!m_editor->saveFile(path, &why)) {
        showMessage(why, true);
        if (error)
            *error = why;
        return false;
    }
    m_path = path;
    m_pathLabel->setText(path);
    showMessage(tr("Saved to %1.").arg(path), false);
    emit profileApplied(m_editor->config(), m_path);
    return true;
}

bool SettingsDialog::loadFrom(const QString &path, QString *error)
{
    QString why;
    if (!m_editor->loadFile(path, &why)) {
        showMessage(why, true);
        if (error)
            *error = why;
        return false;
    }
    m_path = path;
    m_pathLabel->setText(path);
    rememberProfile(path);
    showMessage(tr("Loaded %1; Apply to use it.").arg(path), false);
    return true;
}

void SettingsDialog::apply()
{
    if (!m_editor->isValid()) {
        showMessage(tr("The profile has problems; fix the fields marked red first."), true);
        return;
    }
    showMessage(tr("Applied (not yet saved)."), false);
    emit profileApplied(m_editor->config(), m_path);
}

void SettingsDialog::chooseLanguage(const QString &code)
{
    QSettings().setValue(QStringLiteral("language"), code);
    const int i = m_language->findData(code);
    if (i >= 0)
        m_language->setCurrentIndex(i);
    applyLanguage(effectiveLanguage(code));
    emit languageChosen(code);
}

void SettingsDialog::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QDialog::changeEvent(event);
}

void SettingsDialog::retranslate()
{
    setWindowTitle(tr("Settings"));
    m_tabs->setTabText(0, tr("Machine profile"));
    m_tabs->setTabText(1, tr("Application"));
    m_tabs->setTabText(2, tr("Shortcuts"));
    m_pathLabel->setText(m_path);
    m_load->setText(tr("Load…"));
    m_save->setText(tr("Save"));
    m_export->setText(tr("Export…"));
    m_defaults->setText(tr("Defaults"));
    m_apply->setText(tr("Apply"));
    m_languageLabel->setText(tr("Language"));
    m_language->setItemText(0, tr("System language"));
    m_reconnect->setText(tr("Reconnect automatically after a lost link"));
    m_unitsLabel->setText(tr("Lengths shown in"));
    m_traceLabel->setText(tr("Serial trace kept in memory"));
    m_traceMb->setSuffix(tr(" MB"));
    m_traceMb->setSpecialValueText(tr("off"));
    m_traceMb->setToolTip(tr("The last part of the serial line, both ways, saved with Machine › "
                             "Save serial trace and by itself on an alarm into %1")
                              .arg(driver::TraceRecorder::defaultAlarmFolder()));
    m_units->setItemText(0, tr("millimetres (mm)"));
    m_units->setItemText(1, tr("inches (in)"));
    m_units->setToolTip(tr("The DRO, the jog steps and feed, the status panel and the speed plot. "
                           "The machine, its profile and the programs' own G20/G21 are not "
                           "affected."));
}

} // namespace frezka::gui
