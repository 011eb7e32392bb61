// The unit configuration page against gve-emu on a pty (issue 20 item 3): the page writes a
// setting through its buttons and the emulated unit then behaves by it. Asserted on what gve-emu
// itself answered (its --verbose log), not on the page.
#include "gui/unitconfigdialog.h"

#include "driver/link/machinecontroller.h"
#include "machine/machineconfig.h"

#include <QMessageBox>
#include <QProcess>
#include <QPushButton>
#include <QSignalSpy>
#include <QTest>

using namespace frezka;

class UnitConfigEmulatorTest : public QObject
{
    Q_OBJECT

private:
    QProcess m_emu;
    QByteArray m_log;
    QString m_pty;

    // What gve-emu has sent ("<unit" lines of its --verbose log), joined.
    QByteArray unitSent()
    {
        m_log += m_emu.readAllStandardError();
        QByteArray out;
        for (const QByteArray &line : m_log.split('\n')) {
            const auto at = line.indexOf(" <unit ");
            if (at >= 0)
                out += line.mid(at + 7).replace("\\r", "\r");
        }
        return out;
    }

private slots:
    void initTestCase()
    {
        m_emu.setProgram(QStringLiteral(FREZKA_GVE_EMU));
        m_emu.setArguments(
            {QStringLiteral("--variant"), QStringLiteral("gve64"), QStringLiteral("--verbose")});
        m_emu.start();
        QVERIFY(m_emu.waitForStarted());
        QVERIFY(QTest::qWaitFor([this] { return m_emu.canReadLine(); }, 20000));
        m_pty = QString::fromLocal8Bit(m_emu.readLine()).trimmed();
        QVERIFY(!m_pty.isEmpty());
    }

    void cleanupTestCase()
    {
        m_emu.terminate();
        m_emu.waitForFinished(5000);
    }

    // 0x0C written by the page's "Write differences" (confirmed): A then runs with X, as P4
    // answered by gve-emu shows.
    void writtenASlavingMovesAWithX()
    {
        driver::MachineController controller;
        machine::MachineConfig profile = machine::defaultMachineConfig(protocol::Variant::Gve64);
        controller.setMachineConfig(profile);
        driver::ConnectionSettings port;
        port.kind = driver::ConnectionSettings::Kind::SerialPort;
        port.portName = m_pty;
        controller.connectTo(port);
        QTRY_VERIFY_WITH_TIMEOUT(controller.state().mode == driver::MachineMode::Idle, 20000);

        controller.jogStep(0, 2, 600); // X +400 steps; A independent
        QTRY_VERIFY2_WITH_TIMEOUT(unitSent().contains("0,400,0,0,0,"),
                                  unitSent().right(300).constData(), 20000);
        QTRY_VERIFY_WITH_TIMEOUT(controller.state().mode == driver::MachineMode::Idle, 20000);

        profile.eeprom.aSlavedTo = 1;
        gui::UnitConfigDialog page(&controller, profile);
        QSignalSpy finished(&page, &gui::UnitConfigDialog::finished);
        page.readUnit();
        QVERIFY(finished.wait(20000));
        QVERIFY2(finished.last().at(0).toBool(), qPrintable(page.statusText()));
        QVERIFY(page.differences() > 0);
        page.findChild<QPushButton *>(QStringLiteral("eepromWriteDifferences"))->click();
        auto *confirm = page.findChild<QMessageBox *>(QStringLiteral("confirmEepromWrite"));
        QVERIFY(confirm);
        confirm->button(QMessageBox::Yes)->click();
        QVERIFY(finished.wait(30000));
        QVERIFY2(finished.last().at(0).toBool(), qPrintable(page.statusText()));
        QCOMPARE(page.differences(), 0);

        controller.jogStep(0, 2, 600); // X to 800: A with it
        QTRY_VERIFY_WITH_TIMEOUT(unitSent().contains("0,800,0,0,800,"), 20000);
        QVERIFY(!unitSent().contains("0,800,0,0,0,"));
        controller.disconnectFromUnit();
    }
};

QTEST_MAIN(UnitConfigEmulatorTest)
#include "unitconfig_emulator_test.moc"
