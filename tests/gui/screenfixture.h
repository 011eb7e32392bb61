#pragma once
// The fixture of the screen tests (screen_test, screen_words_test, screen_ports_test): the whole
// main window against the built-in emulator in real time (offscreen, software view), runs allowed
// before homing; gve-emu on a pty of its own for the tests that need a serial line. One window
// for each test executable (initTestCase), its slots run in order; a failed step does not leave
// the machine held for the next (cleanup). Never sleeps on a guess: every wait is on the
// machine's own state.

#include "gui/consolewidget.h"
#include "gui/eepromdecode.h"
#include "gui/holdbanner.h"
#include "gui/mainwindow.h"
#include "gui/programlisting.h"
#include "gui/programview.h"
#include "gui/runpanel.h"
#include "gui/settingsdialog.h"
#include "gui/speedplot.h"
#include "gui/toolpathview.h"
#include "gui/toolpathviewmodel.h"
#include "gui/unitconfigdialog.h"

#include "windowtest.h"

#include "driver/link/machinecontroller.h"

#include <QDockWidget>
#include <QLabel>
#include <QMessageBox>
#include <QProcess>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace frezka;
using namespace frezka::gui;
using driver::MachineMode;

class ScreenFixture : public QObject
{
    Q_OBJECT

protected:
    static constexpr int kMachineTimeoutMs = 60000;
    static constexpr char kPtyFirmware[] =
        "IP64MPG v19 26.11.2026"; // gve-emu's, not the built-in's

    const driver::MachineState &state() const { return m_window->controller()->state(); }

    QString writeProgram(const QString &name, const QByteArray &text)
    {
        return test::writeProgram(m_dir, name, text);
    }

    bool load(const QString &path)
    {
        return test::openAndWait(m_window.get(), path) && m_window->program()->program().runnable();
    }

    QPushButton *button(QWidget *parent, const char *name) { return test::button(parent, name); }

    int progress() const
    {
        return m_window->runPanel()
            ->findChild<QProgressBar *>(QStringLiteral("runProgress"))
            ->value();
    }

    QString statusLine() const
    {
        return m_window->findChild<QLabel *>(QStringLiteral("machineStatus"))->text();
    }

    QString connectionText() const
    {
        return m_window->findChild<QLabel *>(QStringLiteral("connectionStatus"))->text();
    }

    bool waitIdle()
    {
        return QTest::qWaitFor([&] { return state().mode == MachineMode::Idle; },
                               kMachineTimeoutMs);
    }

    MainWindowOptions windowOptions() const
    {
        MainWindowOptions options;
        options.view = MainWindowOptions::View::Software;
        options.restoreLayout = false;
        return options;
    }

    // gve-emu on a pty of its own (started once), with a firmware text the built-in emulator
    // does not have; its path, or empty with m_emuError saying why it could not be started (a
    // failure: gve-emu is built with every tree).
    QString ptyUnit()
    {
        if (m_pty.isEmpty()) {
            m_emu.setProgram(QStringLiteral(FREZKA_GVE_EMU));
            m_emu.setArguments({QStringLiteral("--variant"), QStringLiteral("gve64"),
                                QStringLiteral("--firmware"), QLatin1String(kPtyFirmware),
                                QStringLiteral("--verbose")});
            m_emu.start();
            if (!m_emu.waitForStarted() ||
                !QTest::qWaitFor([this] { return m_emu.canReadLine(); }, 10000)) {
                m_emuError = QStringLiteral("gve-emu (%1) did not start: %2")
                                 .arg(QStringLiteral(FREZKA_GVE_EMU), m_emu.errorString());
                return {};
            }
            m_pty = QString::fromLocal8Bit(m_emu.readLine()).trimmed();
        }
        return m_pty;
    }

    // What gve-emu has received so far ("pc>" lines of its --verbose log), joined.
    QByteArray ptyReceived() { return test::emulatorReceived(m_emu, m_emuLog); }

    bool connectedTo(const QString &port) const
    {
        return state().mode == MachineMode::Idle && connectionText().contains(port) &&
               state().firmware == kPtyFirmware;
    }

    // Line k (3 .. 42) of the stepped program cuts X from 2(k-3) to 2(k-2) mm past its start.
    static QByteArray steppedProgram()
    {
        QByteArray p = "G21 G91\nG1 Z-1 F600\n";
        for (int k = 3; k <= 42; ++k)
            p += "G1 X2\n";
        p += "G1 Z1\nM30\n";
        return p;
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("FrezkaScreenTest"));
        machine::MachineConfig profile = machine::defaultMachineConfig(protocol::Variant::Gve64);
        profile.link.port = "emulator";
        // The screen is under test, not homing: runs start on the unhomed emulator (warned).
        profile.motion.runBeforeHoming = true;
        const QString profilePath = m_dir.filePath(QStringLiteral("machine.json"));
        QVERIFY(!machine::saveMachineConfig(profile, profilePath.toStdString()));
        QSettings().setValue(QStringLiteral("lastProfile"), profilePath);
        QSettings().setValue(QStringLiteral("language"), QStringLiteral("en"));
        MainWindowOptions options;
        options.view = MainWindowOptions::View::Software;
        options.restoreLayout = false;
        m_window = std::make_unique<MainWindow>(options);
        m_window->show();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Idle, 20000);
    }

    void cleanup()
    {
        if (state().mode != MachineMode::Idle && state().mode != MachineMode::Disconnected) {
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
    std::unique_ptr<MainWindow> m_window;
    QProcess m_emu;      // gve-emu, once a test asks for the pty unit
    QString m_pty;       // its pty
    QString m_emuError;  // why it could not be started
    QByteArray m_emuLog; // its --verbose log read so far
};
