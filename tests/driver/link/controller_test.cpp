// MachineController (GUI facade, link thread) in real time: on the built-in emulator, and
// through gve-emu on a pseudo-terminal with QSerialPort, including faults and a lost unit.

#include "driver/link/machinecontroller.h"
#include "simfixture.h"

#include <QElapsedTimer>
#include <QProcess>
#include <QSignalSpy>
#include <QTest>

using namespace frezka;
using namespace frezka::driver;

class ControllerTest : public QObject
{
    Q_OBJECT

private:
    static bool at(const MachineState &s, const machine::UnitProgram &p)
    {
        for (int a = 0; a < 3; ++a) {
            if (s.positionSteps[a] != p.commands.back().endSteps[a])
                return false;
        }
        return true;
    }

    static QString describe(const MachineState &s)
    {
        QString text = QStringLiteral("mode %1 hold %2 (%3) acked %4/%5 progress %6")
                           .arg(int(s.mode))
                           .arg(int(s.hold))
                           .arg(QString::fromStdString(s.holdText))
                           .arg(s.commandsAcked)
                           .arg(s.commandsTotal)
                           .arg(s.progress);
        if (s.lastError) {
            text += QStringLiteral("; last error: %1 [%2 -> %3]")
                        .arg(QString::fromStdString(s.lastError->message),
                             QString::fromStdString(s.lastError->command),
                             QString::fromStdString(s.lastError->reply));
        }
        return text;
    }

    // Starts gve-emu with extra options; returns the pty path (empty on failure).
    QString startEmulator(QProcess &emu, const QStringList &extra)
    {
        emu.start(QStringLiteral(GVE_EMU),
                  QStringList{QStringLiteral("--variant"), QStringLiteral("gve64")} + extra);
        if (!emu.waitForStarted(5000))
            return {};
        // The first line of stdout is the terminal's path.
        for (int i = 0; i < 50 && !emu.canReadLine(); ++i)
            emu.waitForReadyRead(100);
        return QString::fromUtf8(emu.readLine()).trimmed();
    }

    // Runs a job to its end. With byte faults on the line a damaged command can pass its checksum
    // (about 1 run in 50 here): the unit then leaves the path, the path guard holds the job, and
    // the operator's Continue returns to the last verified point and runs on, as the hold says.
    // The job must still end exactly at the program's end.
    void runJob(MachineController &c, const machine::UnitProgram &p, bool continueOnPathFault)
    {
        QSignalSpy finished(&c, &MachineController::jobFinished);
        QSignalSpy errors(&c, &MachineController::errorOccurred);
        c.run(p);
        QElapsedTimer clock;
        clock.start();
        int continues = 0;
        while (finished.isEmpty() && clock.elapsed() < 60000) {
            finished.wait(200);
            const MachineState s = c.state();
            if (continueOnPathFault && continues < 5 && s.mode == MachineMode::Paused &&
                s.hold == HoldReason::PathFault) {
                ++continues;
                c.resume();
                QTRY_VERIFY_WITH_TIMEOUT(c.state().mode != MachineMode::Paused, 10000);
            }
        }
        // A refused run (errorOccurred, no jobFinished) or a job that hangs: say what the
        // controller was doing instead of only that the wait ran out.
        if (finished.isEmpty()) {
            qWarning().noquote() << describe(c.state());
            for (const QList<QVariant> &e : errors) {
                qWarning().noquote()
                    << "error:" << QString::fromStdString(e.first().value<MachineError>().message);
            }
        }
        QVERIFY(!finished.isEmpty());
        QCOMPARE(finished.first().first().toBool(), true);
        QTRY_VERIFY_WITH_TIMEOUT(at(c.state(), p), 5000);
    }

private slots:
    void builtInEmulator()
    {
        MachineController c;
        c.setMachineConfig(machine::defaultMachineConfig(protocol::Variant::Gve64));
        ConnectionSettings s;
        s.kind = ConnectionSettings::Kind::Emulator;
        s.latencyMs = 2;
        c.connectTo(s);
        QTRY_COMPARE_WITH_TIMEOUT(c.state().mode, MachineMode::Idle, 10000);
        QVERIFY(c.state().checksums);
        runJob(c, test::denseProgram(300), false);
        QCOMPARE(c.state().mode, MachineMode::Idle);
    }

    void gveEmuOnAPty()
    {
        QProcess emu;
        const QString path = startEmulator(emu, {QStringLiteral("--latency"), QStringLiteral("1")});
        QVERIFY(path.startsWith(QLatin1String("/dev/")));
        MachineController c;
        c.setMachineConfig(machine::defaultMachineConfig(protocol::Variant::Gve64));
        ConnectionSettings s;
        s.kind = ConnectionSettings::Kind::SerialPort;
        s.portName = path;
        c.connectTo(s);
        QTRY_COMPARE_WITH_TIMEOUT(c.state().mode, MachineMode::Idle, 10000);
        QCOMPARE(QString::fromStdString(c.state().firmware),
                 QStringLiteral("IP64MPG v19 10.9.2010"));
        runJob(c, test::denseProgram(400), false);
        c.disconnectFromUnit();
        emu.terminate();
        QVERIFY(emu.waitForFinished(5000));
    }

    void gveEmuWithFaults()
    {
        QProcess emu;
        const QString path = startEmulator(
            emu, {QStringLiteral("--corrupt"), QStringLiteral("0.0004"), QStringLiteral("--drop"),
                  QStringLiteral("0.0003"), QStringLiteral("--duplicate"), QStringLiteral("0.0003"),
                  QStringLiteral("--lose-reply"), QStringLiteral("0.001"), QStringLiteral("--seed"),
                  QStringLiteral("7")});
        QVERIFY(!path.isEmpty());
        MachineController c;
        c.setMachineConfig(machine::defaultMachineConfig(protocol::Variant::Gve64));
        ConnectionSettings s;
        s.kind = ConnectionSettings::Kind::SerialPort;
        s.portName = path;
        c.connectTo(s);
        QTRY_COMPARE_WITH_TIMEOUT(c.state().mode, MachineMode::Idle, 20000);
        runJob(c, test::denseProgram(1500), true);
        emu.terminate();
        QVERIFY(emu.waitForFinished(5000));
    }

    void unitGoneMidJob()
    {
        QProcess emu;
        const QString path = startEmulator(emu, {});
        MachineController c;
        c.setMachineConfig(machine::defaultMachineConfig(protocol::Variant::Gve64));
        QSignalSpy errors(&c, &MachineController::errorOccurred);
        ConnectionSettings s;
        s.kind = ConnectionSettings::Kind::SerialPort;
        s.portName = path;
        c.connectTo(s);
        QTRY_COMPARE_WITH_TIMEOUT(c.state().mode, MachineMode::Idle, 10000);
        c.run(test::denseProgram(3000, 3, 4000, 4000, 400)); // minutes of motion
        QTRY_COMPARE_WITH_TIMEOUT(c.state().mode, MachineMode::Running, 5000);
        QTRY_VERIFY_WITH_TIMEOUT(c.state().commandsAcked > 10, 10000);
        emu.kill();
        emu.waitForFinished(5000);
        QTRY_COMPARE_WITH_TIMEOUT(c.state().mode, MachineMode::LinkLost, 20000);
        QVERIFY(!errors.isEmpty());
        QVERIFY(c.state().jobActive); // progress kept for resuming
        QVERIFY(c.state().commandsAcked > 0);
    }
};

QTEST_MAIN(ControllerTest)
#include "controller_test.moc"
