// Machine › Commission this machine… offscreen (issue 21 item 3, done-when 1): the dialog runs
// every step against the built-in emulator, the test acting as the operator with the dialog's
// own buttons (Run, Yes, a measured distance and OK) and pressing the emulator's switch inputs
// when told to. Asserted on what the emulator did (one wrong checksum, homed at the profile's
// home positions, spindle and outputs off again) and on what reached the wire (the report's
// serial trace), besides the results in the list; and the profile is never saved over the
// original. Skipping every moving step moves nothing. The menu entry opens the dialog.

#include "gui/commissiondialog.h"
#include "gui/mainwindow.h"

#include "driver/link/emulatortransport.h"
#include "machine/steps.h"

#include <QAction>
#include <QFile>
#include <QLineEdit>
#include <QListWidget>
#include <QPushButton>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

using namespace frezka;
using frezka::gui::CommissionDialog;

namespace {

QPushButton *button(QWidget *parent, const char *name)
{
    return parent->findChild<QPushButton *>(QLatin1String(name));
}

machine::MachineConfig emulatorProfile()
{
    machine::MachineConfig profile = machine::defaultMachineConfig(protocol::Variant::Gve64);
    profile.link.port = "emulator";
    return profile;
}

// Answers every question of the dialog with its buttons: Run (or Skip), Yes, 4.9 mm.
void actAsOperator(CommissionDialog &d, bool run)
{
    QObject::connect(&d, &CommissionDialog::operatorAsked, &d, [&d, run] {
        if (button(&d, "commissionRun")->isEnabled()) {
            button(&d, run ? "commissionRun" : "commissionSkip")->click();
        } else if (button(&d, "commissionYes")->isEnabled()) {
            button(&d, "commissionYes")->click();
        } else if (button(&d, "commissionOk")->isEnabled()) {
            d.findChild<QLineEdit *>(QStringLiteral("commissionNumber"))
                ->setText(QStringLiteral("4.9"));
            button(&d, "commissionOk")->click();
        }
    });
    // "Press ... (INn) now.": the emulator's input changes a moment later and back.
    QObject::connect(&d, &CommissionDialog::operatorInstructed, &d, [&d](const QString &text) {
        const int at = static_cast<int>(text.indexOf(QLatin1String("(IN")));
        const int in = text.mid(at + 3, text.indexOf(QLatin1Char(')'), at) - at - 3).toInt();
        emulator::Unit *u = d.emulatedUnit();
        const bool level = u->input(in);
        QTimer::singleShot(150, &d, [u, in, level] { u->setInput(in, !level); });
        QTimer::singleShot(600, &d, [u, in, level] { u->setInput(in, level); });
    });
}

QString readAll(const QString &path)
{
    QFile f(path);
    f.open(QIODevice::ReadOnly);
    return QString::fromUtf8(f.readAll());
}

} // namespace

class CommissionDialogTest : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void runsEveryStepOnTheEmulator();
    void skippingTheMovingStepsMovesNothing();
    void menuEntryOpensTheDialog();

private:
    QTemporaryDir m_dir;
};

void CommissionDialogTest::initTestCase()
{
    QStandardPaths::setTestModeEnabled(true);
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
    QCoreApplication::setOrganizationName(QStringLiteral("FrezkaCommissionTest"));
    QSettings().setValue(QStringLiteral("language"), QStringLiteral("en"));
}

void CommissionDialogTest::runsEveryStepOnTheEmulator()
{
    const machine::MachineConfig profile = emulatorProfile();
    const QString original = m_dir.filePath(QStringLiteral("mill.json"));
    QVERIFY(!machine::saveMachineConfig(profile, original.toStdString()));
    CommissionDialog d(profile, original);
    d.show();
    actAsOperator(d, true);
    button(&d, "commissionStart")->click(); // returns when every step has run
    // The built-in emulator's EEPROM is the profile's: every step holds.
    for (const auto &s : d.result().steps)
        QVERIFY2(s.result == session::StepResult::Held,
                 qPrintable(QString::fromStdString(s.id) + QLatin1String(": ") + s.details));
    const auto *list = d.findChild<QListWidget *>(QStringLiteral("commissionSteps"));
    QCOMPARE(list->count(), static_cast<int>(d.result().steps.size()));
    QVERIFY(list->item(0)->text().startsWith(QLatin1String("[held] Identify the unit")));
    // The emulator: one wrong checksum (the reading's check), homed at the profile's home
    // positions, the spindle and every output off again.
    emulator::Unit &unit = *d.emulatedUnit();
    QCOMPARE(unit.stats().checksumErrors, 1);
    for (int a = 0; a < 3; ++a)
        QCOMPARE(unit.position()[static_cast<std::size_t>(a)],
                 machine::stepsOf(profile.axes[static_cast<std::size_t>(a)].homing.homePositionMm,
                                  profile.axes[static_cast<std::size_t>(a)].stepsPerMm));
    QVERIFY(!unit.spindleTurning());
    QCOMPARE(unit.outputs(), std::uint8_t{0xFF});
    // The wire, from the report's trace: both parts of the session.
    const QString report = d.reportText();
    for (const char *sent : {"!0%+", "!0ER05", "!7V250", "!7V500", "!7V0", "!0WX", "!0WZ"})
        QVERIFY2(report.contains(QLatin1String(sent)), sent);
    QVERIFY(report.contains(QLatin1String("proposed steps/mm")));
    // Save report; the profile only under a new name, with X's corrected steps per mm.
    QVERIFY(button(&d, "commissionSaveReport")->isEnabled());
    QString error;
    QVERIFY(d.saveReport(m_dir.filePath(QStringLiteral("report.txt")), &error));
    QVERIFY(readAll(m_dir.filePath(QStringLiteral("report.txt")))
                .contains(QLatin1String("Serial trace")));
    QVERIFY(!d.saveProfile(original, &error));
    QVERIFY2(error.contains(QLatin1String("name a new file")), qPrintable(error));
    QVERIFY(d.saveProfile(m_dir.filePath(QStringLiteral("checked.json")), &error));
    const auto saved =
        machine::loadMachineConfig(m_dir.filePath(QStringLiteral("checked.json")).toStdString());
    QVERIFY(saved.config);
    QCOMPARE(saved.config->axes[0].stepsPerMm, profile.axes[0].stepsPerMm * 5.0 / 4.9);
    QCOMPARE(machine::loadMachineConfig(original.toStdString()).config->axes[0].stepsPerMm,
             profile.axes[0].stepsPerMm);
}

void CommissionDialogTest::skippingTheMovingStepsMovesNothing()
{
    CommissionDialog d(emulatorProfile(), QString());
    actAsOperator(d, false);
    button(&d, "commissionStart")->click();
    for (const auto &s : d.result().steps)
        if (s.needsOperator)
            QCOMPARE(s.result, session::StepResult::Skipped);
    QCOMPARE(d.emulatedUnit()->position(), (std::array<std::int64_t, 4>{}));
    const QString report = d.reportText();
    for (const char *moving : {"!0WX", "!7V", "!0O0"})
        QVERIFY2(!report.contains(QLatin1String(moving)), moving);
}

void CommissionDialogTest::menuEntryOpensTheDialog()
{
    machine::MachineConfig profile = emulatorProfile();
    const QString path = m_dir.filePath(QStringLiteral("window.json"));
    QVERIFY(!machine::saveMachineConfig(profile, path.toStdString()));
    QSettings().setValue(QStringLiteral("lastProfile"), path);
    gui::MainWindowOptions options;
    options.view = gui::MainWindowOptions::View::Software;
    options.restoreLayout = false;
    gui::MainWindow window(options);
    auto *action = window.findChild<QAction *>(QStringLiteral("commission"));
    QVERIFY(action);
    QCOMPARE(action->text(), QStringLiteral("C&ommission this machine…"));
    action->trigger();
    auto *dialog = window.findChild<CommissionDialog *>();
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    dialog->reject();
}

QTEST_MAIN(CommissionDialogTest)
#include "commission_test.moc"
