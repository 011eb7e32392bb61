#pragma once
// ProfileEditor: edits every key of the machine profile, generated from the profile schema
// (machine/configschema.h) so no key can be forgotten: ranges and units come from the schema,
// whole-profile rules from validateMachineConfig(); errors are listed in words and the
// offending fields turn red. Load / save / export go through the machine module's JSON.

#include "machine/machineconfig.h"

#include <QHash>
#include <QWidget>

#include <functional>
#include <vector>

class QLabel;
class QListWidget;
class QTabWidget;

namespace frezka::gui {

class ProfileEditor : public QWidget
{
    Q_OBJECT

public:
    explicit ProfileEditor(QWidget *parent = nullptr);

    void setConfig(const machine::MachineConfig &config);
    const machine::MachineConfig &config() const { return m_config; }
    // Problems of the edited profile (empty = valid), also shown in the list below the form.
    std::vector<machine::ConfigError> errors() const { return m_errors; }
    bool isValid() const { return m_errors.empty(); }

    // Loads a profile file into the editor; on failure the editor is unchanged and error says
    // why in words (every problem, one per line).
    bool loadFile(const QString &path, QString *error);
    // Saves the edited profile; refuses an invalid one.
    bool saveFile(const QString &path, QString *error) const;

    // The editor of a dotted key ("axes.x.stepsPerMm"), for tests.
    QWidget *editorFor(const QString &key) const { return m_editors.value(key); }
    QStringList keys() const { return m_editors.keys(); }

    // Used by the schema visitor that builds the form.
    struct Binding
    {
        std::function<void()> refresh;
    };
    void addBinding(const QString &key, QWidget *editor, std::function<void()> refresh);
    void addCaption(QLabel *label, const QString &key);
    void addTabCaption(QTabWidget *tabs, int index, const QString &key);
    void fieldEdited();

signals:
    void edited();

protected:
    void changeEvent(QEvent *event) override;

private:
    void refreshAll();
    void validate();
    void retranslate();

    machine::MachineConfig m_config;
    std::vector<machine::ConfigError> m_errors;
    QHash<QString, QWidget *> m_editors;
    std::vector<std::function<void()>> m_refresh;
    std::vector<std::pair<QLabel *, QString>> m_captions;
    std::vector<std::tuple<QTabWidget *, int, QString>> m_tabCaptions;
    std::vector<std::function<void()>> m_retranslators;
    QListWidget *m_errorList;
    QLabel *m_status;
    bool m_refreshing = false;

    friend struct ProfileFormBuilder;
};

} // namespace frezka::gui
