// The connection on the screen (issue 14 item 6), on the whole main window (screenfixture.h):
// the status bar names it; a port set with Apply is connected (gve-emu on a pty) and used again
// after a restart, as is the port used last.

#include "screenfixture.h"

class ScreenPortsTest : public ScreenFixture
{
    Q_OBJECT

private slots:
    // The status bar names the built-in emulator; a port set with Apply is connected at once
    // (and named), and the built-in emulator again when it is chosen again.
    void statusBarNamesTheConnection()
    {
        QVERIFY(waitIdle());
        QVERIFY2(connectionText().contains(QStringLiteral("built-in emulator")),
                 qPrintable(connectionText()));
        QVERIFY2(connectionText().contains(QStringLiteral("Ready")), qPrintable(connectionText()));
        machine::MachineConfig port = m_window->profile();
        port.link.port = "/nonexistent/ttyFREZKA";
        m_window->applyProfile(port, m_window->profilePath());
        QTRY_VERIFY_WITH_TIMEOUT(
            connectionText().contains(QStringLiteral("/nonexistent/ttyFREZKA")), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Disconnected, 10000);
        QCOMPARE(QSettings().value(QStringLiteral("link/port")).toString(),
                 QStringLiteral("/nonexistent/ttyFREZKA"));
        machine::MachineConfig emulator = m_window->profile();
        emulator.link.port = "emulator";
        m_window->applyProfile(emulator, m_window->profilePath());
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Idle, 20000);
        QTRY_VERIFY(connectionText().contains(QStringLiteral("built-in emulator")));
    }

    // A port set with Apply is connected at once on a serial line like the hardware's (gve-emu
    // on a pty, opened by its path): the pty's unit is read (its own firmware text) and Ready;
    // after a restart of the window with the same settings the pty is connected again (issue
    // 14: "after a restart the application silently uses the built-in emulator instead of the
    // last port; a new port set with Apply does not reconnect").
    void appliedPtyPortIsConnectedAndUsedAfterARestart()
    {
        const QString pty = ptyUnit();
        QVERIFY2(!pty.isEmpty(), qPrintable(m_emuError));
        QVERIFY(waitIdle());
        QVERIFY2(connectionText().contains(QStringLiteral("built-in emulator")),
                 qPrintable(connectionText()));
        QCOMPARE(m_window->profile().link.port, std::string("emulator"));
        machine::MachineConfig config = m_window->profile();
        config.link.port = pty.toStdString();
        const qsizetype heard = ptyReceived().size();
        m_window->applyProfile(config, m_window->profilePath());
        QTRY_VERIFY2_WITH_TIMEOUT(connectedTo(pty), qPrintable(connectionText()), 20000);
        QVERIFY2(connectionText().contains(QStringLiteral("Ready")), qPrintable(connectionText()));
        QVERIFY(ptyReceived().mid(heard).contains("!0?")); // the unit on the pty was asked
        QCOMPARE(QSettings().value(QStringLiteral("link/port")).toString(), pty);
        // A restart: the saved profile still says the built-in emulator.
        m_window.reset();
        const qsizetype heardBefore = ptyReceived().size();
        m_window = std::make_unique<MainWindow>(windowOptions());
        m_window->show();
        QTRY_VERIFY2_WITH_TIMEOUT(connectedTo(pty), qPrintable(connectionText()), 20000);
        QVERIFY(ptyReceived().mid(heardBefore).contains("!0?"));
        QCOMPARE(m_window->profile().link.port, pty.toStdString()); // what the settings show
        // Applying the saved profile's port (the built-in emulator) connects it.
        const machine::ConfigResult saved =
            machine::loadMachineConfig(m_window->profilePath().toStdString());
        QVERIFY(saved.config);
        QCOMPARE(saved.config->link.port, std::string("emulator"));
        m_window->applyProfile(*saved.config, m_window->profilePath());
        QTRY_VERIFY2_WITH_TIMEOUT(state().mode == MachineMode::Idle &&
                                      connectionText().contains(QStringLiteral("built-in")),
                                  qPrintable(connectionText()), 20000);
        QCOMPARE(QSettings().value(QStringLiteral("link/port")).toString(),
                 QStringLiteral("emulator"));
    }

    // After a restart the port used last is used again (and the console says so), even when
    // it was only applied, never saved in the profile.
    void lastPortIsUsedAfterARestart()
    {
        QSettings().setValue(QStringLiteral("link/port"), QStringLiteral("/nonexistent/ttyLAST"));
        m_window.reset();
        MainWindowOptions options;
        options.view = MainWindowOptions::View::Software;
        options.restoreLayout = false;
        m_window = std::make_unique<MainWindow>(options);
        m_window->show();
        QTRY_VERIFY_WITH_TIMEOUT(connectionText().contains(QStringLiteral("/nonexistent/ttyLAST")),
                                 10000);
        bool told = false;
        for (const LogEntry &e : m_window->console()->entries())
            told = told || QString::fromUtf8(e.bytes).contains(QStringLiteral("port used last"));
        QVERIFY(told);
        // The window's profile names the port in use; the saved profile is unchanged.
        QCOMPARE(m_window->profile().link.port, std::string("/nonexistent/ttyLAST"));
        const machine::ConfigResult saved =
            machine::loadMachineConfig(m_window->profilePath().toStdString());
        QVERIFY(saved.config);
        QCOMPARE(saved.config->link.port, std::string("emulator"));
    }
};

QTEST_MAIN(ScreenPortsTest)
#include "screen_ports_test.moc"
