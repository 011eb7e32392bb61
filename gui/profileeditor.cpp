#include "profileeditor.h"

#include "profilelabels.h"

#include "machine/configschema.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QEvent>
#include <QFormLayout>
#include <QGroupBox>
#include <QLabel>
#include <QLineEdit>
#include <QListWidget>
#include <QScrollArea>
#include <QSerialPortInfo>
#include <QSpinBox>
#include <QTabWidget>
#include <QVBoxLayout>

#include <cmath>

namespace frezka::gui {

// Walks the schema once and builds one editor per key, bound to the editor's config copy.
struct ProfileFormBuilder
{
    ProfileEditor *ed;
    QFormLayout *form;
    QTabWidget *tabs; // child objects become tabs here (nullptr: group boxes in form)
    QString path;

    QString keyPath(const char *key) const
    {
        return path.isEmpty() ? QLatin1String(key) : path + QLatin1Char('.') + QLatin1String(key);
    }

    void row(const char *key, QWidget *editor)
    {
        auto *label = new QLabel;
        ed->addCaption(label, QLatin1String(key));
        label->setToolTip(keyPath(key));
        editor->setToolTip(keyPath(key));
        form->addRow(label, editor);
    }

    static QString unitSuffix(const char *unit)
    {
        return *unit ? QLatin1Char(' ') + QString::fromUtf8(unit) : QString();
    }

    void number(const char *key, double &value, double min, double max, const char *unit)
    {
        auto *w = new QDoubleSpinBox;
        const int decimals = max <= 10 ? 4 : 3;
        w->setDecimals(decimals);
        w->setRange(min, max);
        w->setSuffix(unitSuffix(unit));
        w->setKeyboardTracking(false);
        double *field = &value;
        QObject::connect(w, &QDoubleSpinBox::valueChanged, ed, [e = ed, field](double v) {
            *field = v;
            e->fieldEdited();
        });
        ed->addBinding(keyPath(key), w, [w, field] {
            const QSignalBlocker b(w);
            w->setValue(*field);
        });
        row(key, w);
    }

    void integer(const char *key, int &value, int min, int max, const char *unit)
    {
        auto *w = new QSpinBox;
        w->setRange(min, max);
        w->setSuffix(unitSuffix(unit));
        w->setKeyboardTracking(false);
        int *field = &value;
        QObject::connect(w, &QSpinBox::valueChanged, ed, [e = ed, field](int v) {
            *field = v;
            e->fieldEdited();
        });
        ed->addBinding(keyPath(key), w, [w, field] {
            const QSignalBlocker b(w);
            w->setValue(*field);
        });
        row(key, w);
    }

    void byte(const char *key, std::uint8_t &value)
    {
        auto *w = new QSpinBox;
        w->setRange(0, 255);
        w->setDisplayIntegerBase(16);
        w->setPrefix(QStringLiteral("0x"));
        w->setKeyboardTracking(false);
        std::uint8_t *field = &value;
        QObject::connect(w, &QSpinBox::valueChanged, ed, [e = ed, field](int v) {
            *field = std::uint8_t(v);
            e->fieldEdited();
        });
        ed->addBinding(keyPath(key), w, [w, field] {
            const QSignalBlocker b(w);
            w->setValue(*field);
        });
        row(key, w);
    }

    void boolean(const char *key, bool &value)
    {
        auto *w = new QCheckBox;
        bool *field = &value;
        QObject::connect(w, &QCheckBox::toggled, ed, [e = ed, field](bool v) {
            *field = v;
            e->fieldEdited();
        });
        ed->addBinding(keyPath(key), w, [w, field] {
            const QSignalBlocker b(w);
            w->setChecked(*field);
        });
        row(key, w);
    }

    void text(const char *key, std::string &value)
    {
        if (keyPath(key) == QLatin1String("link.port"))
            return port(key, value);
        auto *w = new QLineEdit;
        std::string *field = &value;
        QObject::connect(w, &QLineEdit::textEdited, ed, [e = ed, field](const QString &v) {
            *field = v.toStdString();
            e->fieldEdited();
        });
        ed->addBinding(keyPath(key), w, [w, field] {
            const QSignalBlocker b(w);
            w->setText(QString::fromStdString(*field));
        });
        row(key, w);
    }

    // The serial port: the ports the system lists, the built-in emulator, or any typed path
    // (a pty from gve-emu is not listed by QSerialPortInfo).
    void port(const char *key, std::string &value)
    {
        auto *w = new QComboBox;
        w->setEditable(true);
        w->addItem(QStringLiteral("emulator"));
        for (const auto &info : QSerialPortInfo::availablePorts())
            w->addItem(info.systemLocation());
        std::string *field = &value;
        QObject::connect(w, &QComboBox::currentTextChanged, ed, [e = ed, field](const QString &v) {
            *field = v.trimmed().toStdString();
            e->fieldEdited();
        });
        ed->addBinding(keyPath(key), w, [w, field] {
            const QSignalBlocker b(w);
            w->setCurrentText(QString::fromStdString(*field));
        });
        ed->m_retranslators.push_back([w] {
            w->setItemText(0, QStringLiteral("emulator"));
            w->setToolTip(ProfileEditor::tr("\"emulator\" = the built-in unit emulator; or a "
                                            "serial port such as /dev/ttyUSB0; or a typed path "
                                            "such as the pty printed by gve-emu"));
        });
        row(key, w);
    }

    template<class E>
    void choice(const char *key, E &value, std::span<const machine::schema::Choice<E>> choices)
    {
        auto *w = new QComboBox;
        for (const auto &c : choices)
            w->addItem(QString(), QLatin1String(c.name));
        E *field = &value;
        QObject::connect(w, &QComboBox::activated, ed, [e = ed, field, choices](int i) {
            *field = choices[std::size_t(i)].value;
            e->fieldEdited();
        });
        ed->addBinding(keyPath(key), w, [w, field, choices] {
            const QSignalBlocker b(w);
            for (std::size_t i = 0; i < choices.size(); ++i) {
                if (choices[i].value == *field)
                    w->setCurrentIndex(int(i));
            }
        });
        ed->m_retranslators.push_back([w] {
            for (int i = 0; i < w->count(); ++i)
                w->setItemText(i, profileChoiceLabel(w->itemData(i).toString()));
        });
        row(key, w);
    }

    template<class Fn>
    void object(const char *key, Fn fn)
    {
        const QString p = keyPath(key);
        if (tabs) {
            auto *page = new QWidget;
            auto *f = new QFormLayout(page);
            auto *scroll = new QScrollArea;
            scroll->setWidgetResizable(true);
            scroll->setWidget(page);
            const int index = tabs->addTab(scroll, QString());
            ed->addTabCaption(tabs, index, QLatin1String(key));
            QTabWidget *inner = nullptr;
            if (p == QLatin1String("axes")) {
                inner = new QTabWidget;
                f->addRow(inner);
            }
            ProfileFormBuilder child{ed, f, inner, p};
            fn(child);
        } else {
            auto *group = new QGroupBox;
            auto *f = new QFormLayout(group);
            auto *caption = new QLabel; // group title is retranslated through its label
            caption->setVisible(false);
            ed->addCaption(caption, QLatin1String(key));
            ed->m_retranslators.push_back([group, caption] { group->setTitle(caption->text()); });
            form->addRow(group);
            ProfileFormBuilder child{ed, f, nullptr, p};
            fn(child);
        }
    }
};

ProfileEditor::ProfileEditor(QWidget *parent)
    : QWidget(parent)
{
    auto *tabs = new QTabWidget(this);
    tabs->setObjectName(QStringLiteral("profileTabs"));
    // Top-level leaf keys (the name) go on a "General" page.
    auto *general = new QWidget;
    auto *generalForm = new QFormLayout(general);
    const int gi = tabs->addTab(general, QString());
    m_retranslators.push_back([tabs, gi] { tabs->setTabText(gi, tr("General")); });
    ProfileFormBuilder builder{this, generalForm, tabs, QString()};
    machine::schema::visitProfile(builder, m_config);

    m_errorList = new QListWidget(this);
    m_errorList->setObjectName(QStringLiteral("profileErrors"));
    m_errorList->setMaximumHeight(110);
    m_errorList->setWordWrap(true);
    m_status = new QLabel(this);
    auto *layout = new QVBoxLayout(this);
    layout->setContentsMargins(0, 0, 0, 0);
    layout->addWidget(tabs, 1);
    layout->addWidget(m_status);
    layout->addWidget(m_errorList);
    setConfig(machine::defaultMachineConfig(protocol::Variant::Gve64));
    retranslate();
}

void ProfileEditor::addBinding(const QString &key, QWidget *editor, std::function<void()> refresh)
{
    editor->setObjectName(key);
    m_editors.insert(key, editor);
    m_refresh.push_back(std::move(refresh));
}

void ProfileEditor::addCaption(QLabel *label, const QString &key)
{
    m_captions.emplace_back(label, key);
}

void ProfileEditor::addTabCaption(QTabWidget *tabs, int index, const QString &key)
{
    m_tabCaptions.emplace_back(tabs, index, key);
}

void ProfileEditor::setConfig(const machine::MachineConfig &config)
{
    m_config = config;
    refreshAll();
    validate();
}

void ProfileEditor::refreshAll()
{
    for (const auto &r : m_refresh)
        r();
}

void ProfileEditor::fieldEdited()
{
    validate();
    emit edited();
}

void ProfileEditor::validate()
{
    m_errors = machine::validateMachineConfig(m_config);
    for (auto *w : std::as_const(m_editors))
        w->setStyleSheet(QString());
    m_errorList->clear();
    for (const auto &e : m_errors) {
        m_errorList->addItem(configErrorText(e));
        if (auto *w = m_editors.value(QString::fromStdString(e.key)))
            w->setStyleSheet(QStringLiteral("background: #ffb0b0; color: black;"));
    }
    m_errorList->setVisible(!m_errors.empty());
    m_status->setText(m_errors.empty() ? tr("The profile is valid.")
                                       : tr("%n problem(s) — the profile cannot be saved yet.",
                                            nullptr, int(m_errors.size())));
}

bool ProfileEditor::loadFile(const QString &path, QString *error)
{
    const auto result = machine::loadMachineConfig(path.toStdString());
    if (!result.config) {
        QStringList lines;
        for (const auto &e : result.errors)
            lines << configErrorText(e);
        if (error)
            *error = tr("Cannot load the profile %1:\n%2").arg(path, lines.join(QLatin1Char('\n')));
        return false;
    }
    setConfig(*result.config);
    return true;
}

bool ProfileEditor::saveFile(const QString &path, QString *error) const
{
    if (!m_errors.empty()) {
        if (error)
            *error = tr("The profile has problems; fix them first:\n%1")
                         .arg(configErrorText(m_errors.front()));
        return false;
    }
    if (auto e = machine::saveMachineConfig(m_config, path.toStdString())) {
        if (error)
            *error = tr("Cannot save the profile %1: %2").arg(path, configErrorText(*e));
        return false;
    }
    return true;
}

void ProfileEditor::changeEvent(QEvent *event)
{
    if (event->type() == QEvent::LanguageChange)
        retranslate();
    QWidget::changeEvent(event);
}

void ProfileEditor::retranslate()
{
    for (auto &[label, key] : m_captions)
        label->setText(profileKeyLabel(key));
    for (auto &[tabs, index, key] : m_tabCaptions)
        tabs->setTabText(index, profileKeyLabel(key));
    for (const auto &r : m_retranslators)
        r();
    validate();
}

} // namespace frezka::gui
