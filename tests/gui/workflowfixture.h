#pragma once
// The fixture of the workflow tests (workflow_test, workflow_jog_test, workflow_panels_test): the
// whole main window against the emulated unit in real time (offscreen, software view): the
// built-in (in-process) emulator, or with FREZKA_WORKFLOW_UNIT=pty gve-emu on a pty connected
// through the profile's port as a typed path, exactly like hardware. One window for each test
// executable, connected once (initTestCase), its slots run in order like an operator's day;
// a failed step does not leave the machine held for the next (cleanup). Never sleeps: every wait
// is QTRY_* / QSignalSpy::wait on the machine's own signals.

#include "gui/consolewidget.h"
#include "gui/drowidget.h"
#include "gui/holdbanner.h"
#include "gui/iopanel.h"
#include "gui/jogpanel.h"
#include "gui/mainwindow.h"
#include "gui/outputspanel.h"
#include "gui/programview.h"
#include "gui/runpanel.h"
#include "gui/settingsdialog.h"
#include "gui/toolpathview.h"
#include "gui/unitconfigdialog.h"

#include "windowtest.h"

#include "driver/link/machinecontroller.h"
#include "session/runworkflow.h"

#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QProcess>
#include <QPushButton>
#include <QRadioButton>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace frezka;
using namespace frezka::gui;
using driver::MachineMode;

class WorkflowFixture : public QObject
{
    Q_OBJECT

protected:
    static constexpr int kMachineTimeoutMs = 60000;

    const driver::MachineState &state() const { return m_window->controller()->state(); }
    QString describe() const
    {
        const auto &s = state();
        return QStringLiteral("mode %1 pos %2 %3 %4 line %5 error: %6 | gui: %7")
            .arg(driver::machineModeName(s.mode))
            .arg(s.positionMm[0])
            .arg(s.positionMm[1])
            .arg(s.positionMm[2])
            .arg(s.sourceLine)
            .arg(s.lastError ? QString::fromStdString(s.lastError->message) : QString())
            .arg(m_window->lastError());
    }

    QString writeProgram(const QString &name, const QByteArray &text)
    {
        return test::writeProgram(m_dir, name, text);
    }

    bool load(const QString &path) { return test::openAndWait(m_window.get(), path); }

    QPushButton *button(QWidget *parent, const char *name) { return test::button(parent, name); }

    bool waitIdle()
    {
        const bool idle =
            QTest::qWaitFor([&] { return state().mode == MachineMode::Idle; }, kMachineTimeoutMs);
        if (!idle)
            qWarning("not idle: %s", qPrintable(describe()));
        return idle;
    }

    // Records every command the driver puts on the wire ("> " lines of its log), in order.
    struct WireTap
    {
        QStringList sent;
        QMetaObject::Connection connection;
        ~WireTap() { QObject::disconnect(connection); }
        // The first / last command that the pattern matches whole (-1: none).
        int first(const QRegularExpression &re) const { return int(sent.indexOf(re)); }
        int last(const QRegularExpression &re) const { return int(sent.lastIndexOf(re)); }
    };
    void tapWire(WireTap &tap)
    {
        tap.connection = connect(m_window->controller(), &driver::MachineController::logLine, this,
                                 [&tap](const QString &line) {
                                     if (line.startsWith(QLatin1String("> ")))
                                         tap.sent << line.mid(2);
                                 });
    }

    // Steps of a position in mm, as the planner rounds them.
    std::int64_t steps(int axis, double mm) const
    {
        return std::llround(mm * m_window->profile().axes[std::size_t(axis)].stepsPerMm);
    }

    // What gve-emu received on its pty ("pc>" lines of --verbose), joined.
    QByteArray emulatorReceived() { return test::emulatorReceived(m_emu, m_emuLog); }

    bool homedMarksShown(std::uint8_t axes) const
    {
        for (int a = 0; a < 3; ++a) {
            if (m_window->dro()->homedShown(a) != bool((axes >> a) & 1))
                return false;
        }
        return true;
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("FrezkaWorkflowTest"));
        machine::MachineConfig profile = machine::defaultMachineConfig(protocol::Variant::Gve64);
        m_pty = qgetenv("FREZKA_WORKFLOW_UNIT") == "pty";
        if (m_pty) {
            // gve-emu with home switches where a GVE64 mill has them, on a pty opened by its
            // path like hardware.
            m_emu.setProgram(QStringLiteral(FREZKA_GVE_EMU));
            m_emu.setArguments({QStringLiteral("--variant"), QStringLiteral("gve64"),
                                QStringLiteral("--home"), QStringLiteral("X=0"),
                                QStringLiteral("--home"), QStringLiteral("Y=0"),
                                QStringLiteral("--home"), QStringLiteral("Z=0,+"),
                                QStringLiteral("--verbose")}); // what it receives, on stderr
            m_emu.start();
            QVERIFY(m_emu.waitForStarted());
            QTRY_VERIFY_WITH_TIMEOUT(m_emu.canReadLine(), 10000);
            const QString pty = QString::fromLocal8Bit(m_emu.readLine()).trimmed();
            QVERIFY2(pty.startsWith(QLatin1Char('/')), qPrintable(pty));
            profile.link.port = pty.toStdString();
        } else {
            profile.link.port = "emulator"; // the built-in emulator, in real time
        }
        const QString profilePath = m_dir.filePath(QStringLiteral("machine.json"));
        QVERIFY(!machine::saveMachineConfig(profile, profilePath.toStdString()));
        QSettings().setValue(QStringLiteral("lastProfile"), profilePath);
        MainWindowOptions options;
        options.view = MainWindowOptions::View::Software;
        options.restoreLayout = false;
        m_window = std::make_unique<MainWindow>(options);
        m_window->show();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Idle, 20000);
        QVERIFY(!state().firmware.empty());
    }

    // A failed step must not leave the machine held for the next one.
    void cleanup()
    {
        if (state().mode != MachineMode::Idle) {
            m_window->controller()->abort();
            waitIdle();
        }
    }

    void cleanupTestCase()
    {
        m_window.reset();
        m_emu.terminate();
        m_emu.waitForFinished(5000);
    }

protected:
    QTemporaryDir m_dir;
    QProcess m_emu;
    QByteArray m_emuLog; // gve-emu's --verbose log read so far
    bool m_pty = false;  // the unit is gve-emu on a pty
    std::unique_ptr<MainWindow> m_window;
};
