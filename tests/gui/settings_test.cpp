// Machine profile editing: every key has an editor, validation shows errors in words and
// refuses to save, edit -> save -> reload gives the edited profile.
#include "gui/language.h"
#include "gui/profileeditor.h"
#include "gui/settingsdialog.h"

#include "driver/link/tracerecorder.h"

#include <QCheckBox>
#include <QComboBox>
#include <QDoubleSpinBox>
#include <QListWidget>
#include <QSettings>
#include <QSpinBox>
#include <QTabWidget>
#include <QTemporaryDir>
#include <QtTest>

using namespace frezka;
using namespace frezka::gui;

class SettingsTest : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("FrezkaTest"));
    }

    // The serial trace's size (issue 21): kept in the settings, given to the session's recorder.
    void theSerialTraceSizeIsASetting()
    {
        SettingsDialog dialog(machine::defaultMachineConfig(protocol::Variant::Gve64), QString());
        auto *mb = dialog.findChild<QSpinBox *>(QStringLiteral("traceMb"));
        QVERIFY(mb);
        QCOMPARE(mb->value(), kTraceDefaultMb);
        mb->setValue(0);
        QVERIFY(!driver::TraceRecorder::session().enabled());
        QCOMPARE(QSettings().value(kTraceKey).toInt(), 0);
        mb->setValue(2);
        QCOMPARE(driver::TraceRecorder::session().limitBytes(), 2 * 1024 * 1024);
        QSettings().remove(kTraceKey);
        applyTraceSetting();
        QCOMPARE(driver::TraceRecorder::session().limitBytes(),
                 driver::TraceRecorder::kDefaultLimitBytes);
    }

    void everyKeyOfTheProfileHasAnEditor()
    {
        ProfileEditor ed;
        // Every key of the JSON the machine module writes has an editor with the same path.
        const QByteArray json = QByteArray::fromStdString(machine::toJson(ed.config()));
        const QJsonObject root = QJsonDocument::fromJson(json).object();
        QStringList keys;
        std::function<void(const QJsonObject &, const QString &)> walk =
            [&](const QJsonObject &o, const QString &prefix) {
                for (auto it = o.begin(); it != o.end(); ++it) {
                    const QString k = prefix.isEmpty() ? it.key() : prefix + '.' + it.key();
                    if (it.value().isObject())
                        walk(it.value().toObject(), k);
                    else
                        keys << k;
                }
            };
        walk(root, QString());
        QVERIFY(keys.size() > 60);
        for (const QString &k : keys)
            QVERIFY2(ed.editorFor(k), qPrintable(k));
        QCOMPARE(ed.keys().size(), keys.size());
    }

    void invalidValueIsShownAndNotSaved()
    {
        ProfileEditor ed;
        QVERIFY(ed.isValid());
        auto *rapid = qobject_cast<QDoubleSpinBox *>(ed.editorFor("axes.x.rapidMmPerMin"));
        auto *maxSpeed = qobject_cast<QDoubleSpinBox *>(ed.editorFor("axes.x.maxSpeedMmPerMin"));
        QVERIFY(rapid && maxSpeed);
        rapid->setValue(maxSpeed->value() + 500); // rapid above the axis maximum
        QVERIFY(!ed.isValid());
        auto *list = ed.findChild<QListWidget *>(QStringLiteral("profileErrors"));
        QVERIFY(list->count() >= 1);
        QVERIFY(list->item(0)->text().contains(QStringLiteral("rapidMmPerMin")));
        QVERIFY(!rapid->styleSheet().isEmpty());
        QString error;
        QVERIFY(!ed.saveFile(m_dir.filePath(QStringLiteral("bad.json")), &error));
        QVERIFY(!error.isEmpty());
        QVERIFY(!QFile::exists(m_dir.filePath(QStringLiteral("bad.json"))));
    }

    void editSaveReload()
    {
        SettingsDialog dlg(machine::defaultMachineConfig(protocol::Variant::Gve64),
                           m_dir.filePath(QStringLiteral("machine.json")));
        QSignalSpy applied(&dlg, &SettingsDialog::profileApplied);
        auto *ed = dlg.editor();
        qobject_cast<QDoubleSpinBox *>(ed->editorFor("axes.y.stepsPerMm"))->setValue(321.5);
        qobject_cast<QCheckBox *>(ed->editorFor("axes.z.invertDirection"))->setChecked(true);
        auto *out3 = qobject_cast<QComboBox *>(ed->editorFor("outputs.out3"));
        out3->setCurrentIndex(out3->findData(QStringLiteral("laser")));
        emit out3->activated(out3->currentIndex());
        qobject_cast<QSpinBox *>(ed->editorFor("eeprom.polarity"))->setValue(0xA5);
        auto *port = qobject_cast<QComboBox *>(ed->editorFor("link.port"));
        port->setCurrentText(QStringLiteral("/dev/pts/7")); // a typed path (pty)
        QVERIFY2(ed->isValid(), ed->errors().empty() ? "" : ed->errors().front().message.c_str());
        const QString path = m_dir.filePath(QStringLiteral("edited.json"));
        QString error;
        QVERIFY2(dlg.saveTo(path, &error), qPrintable(error));
        QCOMPARE(applied.count(), 1);
        QCOMPARE(QSettings().value(QStringLiteral("lastProfile")).toString(), path);

        const auto loaded = machine::loadMachineConfig(path.toStdString());
        QVERIFY(loaded.config);
        QCOMPARE(loaded.config->axes[1].stepsPerMm, 321.5);
        QVERIFY(loaded.config->axes[2].invertDirection);
        QCOMPARE(loaded.config->outputs.out[2], machine::OutputFunction::Laser);
        QCOMPARE(loaded.config->eeprom.polarity, std::uint8_t(0xA5));
        QCOMPARE(loaded.config->link.port, std::string("/dev/pts/7"));

        SettingsDialog again(machine::defaultMachineConfig(protocol::Variant::Gve84), QString());
        QVERIFY(again.loadFrom(path, &error));
        QCOMPARE(again.editor()->config(), *loaded.config);
        QCOMPARE(
            qobject_cast<QDoubleSpinBox *>(again.editor()->editorFor("axes.y.stepsPerMm"))->value(),
            321.5);
    }

    void brokenFileIsRefusedInWords()
    {
        const QString path = m_dir.filePath(QStringLiteral("broken.json"));
        QFile f(path);
        QVERIFY(f.open(QIODevice::WriteOnly));
        f.write("{ \"axes\": { \"x\": { \"stepsPerMn\": 200 } } }");
        f.close();
        ProfileEditor ed;
        const auto before = ed.config();
        QString error;
        QVERIFY(!ed.loadFile(path, &error));
        QVERIFY(error.contains(QStringLiteral("stepsPerMn")));
        QCOMPARE(ed.config(), before);
    }

    void everyWidgetFollowsTheLanguage()
    {
        SettingsDialog dlg(machine::defaultMachineConfig(protocol::Variant::Gve64), QString());
        ProfileEditor *ed = dlg.editor();
        auto *tabs = ed->findChild<QTabWidget *>(QStringLiteral("profileTabs"));
        QCOMPARE(tabs->tabText(0), QStringLiteral("General"));
        dlg.chooseLanguage(QStringLiteral("cs"));
        QCOMPARE(currentLanguage(), QStringLiteral("cs"));
        QTRY_COMPARE(tabs->tabText(0), QStringLiteral("Obecné"));
        QCOMPARE(dlg.windowTitle(), QStringLiteral("Nastavení"));
        // Error texts of the profile follow too.
        qobject_cast<QDoubleSpinBox *>(ed->editorFor("axes.x.rapidMmPerMin"))->setValue(99999);
        QVERIFY(ed->findChild<QListWidget *>(QStringLiteral("profileErrors"))
                    ->item(0)
                    ->text()
                    .contains(QStringLiteral("Rychloposuv")));
        dlg.chooseLanguage(QStringLiteral("en"));
        QTRY_COMPARE(tabs->tabText(0), QStringLiteral("General"));
    }

private:
    QTemporaryDir m_dir;
};

QTEST_MAIN(SettingsTest)
#include "settings_test.moc"
