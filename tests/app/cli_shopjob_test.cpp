// frezka-cli for a shop job (issue 16 item 8), run as a process: --help on standard output with
// the exit codes, check against the machine's travel (the line and how far), the work offset
// on check, plan and run (the emulator's own counters end at the program's end on the machine),
// and the program's stops (M0, M1, M6) answered by Enter, by --continue-at-stops, or ending the
// run when nobody answers.

#include "cliprocess.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

class CliShopJobTest : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    using Run = clitest::Run;

    QString write(const QString &name, const QByteArray &text)
    {
        return clitest::writeFile(m_dir, name, text);
    }

    static Run cli(const QStringList &args, bool closeInput = true)
    {
        return clitest::runCli(QStringLiteral(FREZKA_CLI), args, closeInput);
    }

    static QJsonObject lastJson(const QString &out) { return clitest::lastJson(out); }

    static QJsonArray steps(std::initializer_list<qint64> s)
    {
        QJsonArray a;
        for (qint64 v : s)
            a.append(v);
        return a;
    }

    // A CAM program measured from the top of the stock: Z+5 safe height, X/Y from 0.
    QString camJob()
    {
        return write(QStringLiteral("cam.nc"), "G21 G90 G94\n"
                                               "M3 S10000\n"
                                               "G0 Z5\n"
                                               "G0 X0 Y0\n"
                                               "G1 Z-1 F300\n"
                                               "G1 X40 F1200\n"
                                               "G1 Y30\n"
                                               "G1 X0\n"
                                               "G1 Y0\n"
                                               "G0 Z5\n"
                                               "M5\n"
                                               "M2\n");
    }

    // A job with an M0 (with a comment), an M6 and an M1, the spindle on throughout.
    QString stopsJob()
    {
        return write(QStringLiteral("stops.nc"), "G21 G90\n"
                                                 "M3 S10000\n"
                                                 "G0 X10 Y10\n"
                                                 "G1 Z-2 F300\n"
                                                 "G1 X30 F1200\n"
                                                 "M0 (check the slot depth)\n"
                                                 "G1 Y30\n"
                                                 "G0 Z0\n"
                                                 "M6 T2\n"
                                                 "G1 Z-2 F300\n"
                                                 "M1\n"
                                                 "G1 X10 F1200\n"
                                                 "G0 Z0\n"
                                                 "M5\n"
                                                 "M2\n");
    }

    static void checkEndsAt(const QJsonObject &j, const QJsonArray &machineSteps)
    {
        QCOMPARE(j[QStringLiteral("expected_steps")].toArray(), machineSteps);
        QCOMPARE(j[QStringLiteral("final_steps")].toArray(), machineSteps);
        QCOMPARE(j[QStringLiteral("unit_steps")].toArray(), machineSteps);
        for (const char *key :
             {"cut_without_spindle", "spindle_on_while_held", "axis_over_max", "brake_violations"})
            QVERIFY2(j[QLatin1String(key)].isDouble() && j[QLatin1String(key)].toInt() == 0, key);
    }

private slots:
    void helpGoesToStandardOutputWithTheExitCodes()
    {
        const Run r = cli({QStringLiteral("--help")});
        QCOMPARE(r.code, 0);
        QVERIFY(r.err.isEmpty());
        for (const char *text : {"usage: frezka-cli COMMAND", "exit codes:", "--continue-at-stops",
                                 "--offset G54:X,Y,Z", "check FILE", "run FILE"})
            QVERIFY2(r.out.contains(QLatin1String(text)), text);
        const Run run = cli({QStringLiteral("run"), QStringLiteral("--help")});
        QCOMPARE(run.code, 0);
        QVERIFY(run.out.contains(QLatin1String("--work-zero X,Y,Z[,A]")));
        QVERIFY(run.out.contains(QLatin1String("exit codes:")));
        QCOMPARE(cli({}).code, 2);
        QCOMPARE(cli({QStringLiteral("nonsense")}).code, 2);
        QCOMPARE(cli({QStringLiteral("check"), camJob(), QStringLiteral("--offset"),
                      QStringLiteral("G53:1,2,3")})
                     .code,
                 2);
    }

    // X600 on the GVE64's 0 .. 400 mm: the line that leaves the travel and by how much.
    void checkRefusesAProgramPastTheTravel()
    {
        const QString file =
            write(QStringLiteral("far.nc"), "G21 G90\nG0 X10 Y10\nG1 X600 F1000\nG1 X650\nM2\n");
        const Run r = cli({QStringLiteral("check"), file});
        QCOMPARE(r.code, 1);
        QVERIFY2(
            r.err.contains(file + QStringLiteral(":3: X 600.000 is 200.000 mm above the machine's "
                                                 "travel (X 0.000 .. 400.000 mm); the program goes "
                                                 "250.000 mm beyond it at line 4")),
            qPrintable(r.err));
        QVERIFY(r.err.contains(QLatin1String("larger than the machine's travel")));
        QVERIFY(!r.out.contains(QLatin1String("OK")));
    }

    // The Z+5 program: without a work zero it would fit (a warning with the offset that puts it
    // inside); with the profile named it fails at its line; with the offset it is good.
    void checkTakesTheWorkOffset()
    {
        const QString file = camJob();
        const Run loose = cli({QStringLiteral("check"), file});
        QCOMPARE(loose.code, 0);
        QVERIFY2(loose.err.contains(file + QStringLiteral(":3: warning: Z 5.000 is 5.000 mm above "
                                                          "the machine's travel")),
                 qPrintable(loose.err));
        QVERIFY(loose.err.contains(QLatin1String("--offset G54:0.000,0.000,-5.000")));
        const QString profile =
            QStringLiteral(FREZKA_SOURCE_DIR) + "/resources/machines/gve64.json";
        const Run placed =
            cli({QStringLiteral("check"), file, QStringLiteral("--machine"), profile});
        QCOMPARE(placed.code, 1);
        QVERIFY2(placed.err.contains(file + QStringLiteral(":3: Z 5.000 is 5.000 mm above")),
                 qPrintable(placed.err));
        const Run good = cli({QStringLiteral("check"), file, QStringLiteral("--offset"),
                              QStringLiteral("G54:60,60,-60")});
        QCOMPARE(good.code, 0);
        QVERIFY2(good.err.isEmpty(), qPrintable(good.err));
        QVERIFY2(good.out.contains(QLatin1String("bounds (machine, mm): X 0.0000 .. 100.0000, "
                                                 "Y 0.0000 .. 90.0000, Z -61.0000 .. 0.0000")),
                 qPrintable(good.out));
        const Run zero = cli({QStringLiteral("check"), file, QStringLiteral("--work-zero"),
                              QStringLiteral("60,60,-60")});
        QCOMPARE(zero.code, 0);
        QCOMPARE(zero.out, good.out);
    }

    // plan: the program's first move to its zero goes to the offset on the machine.
    void planTakesTheWorkOffset()
    {
        const QString file = camJob();
        QCOMPARE(cli({QStringLiteral("plan"), file}).code, 1);
        const Run r = cli({QStringLiteral("plan"), file, QStringLiteral("--offset"),
                           QStringLiteral("G54:60,60,-60")});
        QCOMPARE(r.code, 0);
        QVERIFY2(r.out.contains(QLatin1String("!0C0,0,-11000")), qPrintable(r.out.left(400)));
    }

    // Done when (issue 16): the Z+5 program with --offset G54:60,60,-60 runs to the end on the
    // default profile; the emulator's counters end at X60 Y60 Z-55 (200 steps/mm, A 0).
    void runWithTheWorkOffsetRunsToTheEnd()
    {
        const QString file = camJob();
        const Run refused =
            cli({QStringLiteral("run"), file, QStringLiteral("--port"), QStringLiteral("sim"),
                 QStringLiteral("--clock"), QStringLiteral("virtual")});
        QCOMPARE(refused.code, 1);
        const Run r =
            cli({QStringLiteral("run"), file, QStringLiteral("--port"), QStringLiteral("sim"),
                 QStringLiteral("--clock"), QStringLiteral("virtual"), QStringLiteral("--offset"),
                 QStringLiteral("G54:60,60,-60")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        checkEndsAt(lastJson(r.out), steps({12000, 12000, -11000, 0}));
    }

    void continueAtStopsRunsUnattended()
    {
        const Run r =
            cli({QStringLiteral("run"), stopsJob(), QStringLiteral("--continue-at-stops")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject j = lastJson(r.out);
        QCOMPARE(j[QStringLiteral("program_stops")].toInt(), 3);
        checkEndsAt(j, steps({2000, 6000, 0, 0}));
    }

    // An attended run waits at each stop for Enter; the prompt names the stop and its comment.
    void anAttendedRunWaitsForEnterAtEachStop()
    {
        QProcess p;
        p.setReadChannel(QProcess::StandardError);
        p.start(QStringLiteral(FREZKA_CLI), {QStringLiteral("run"), stopsJob()});
        QByteArray err;
        for (int stop = 0; stop < 3; ++stop) {
            while (err.count("Press Enter") <= stop && p.waitForReadyRead(30000))
                err += p.readAllStandardError();
            QCOMPARE(err.count("Press Enter"), stop + 1);
            QCOMPARE(p.state(), QProcess::Running);
            p.write("\n");
        }
        p.closeWriteChannel();
        QVERIFY(p.waitForFinished(60000));
        err += p.readAllStandardError();
        QVERIFY2(p.exitCode() == 0, err.constData());
        QVERIFY2(err.contains("Program stop (M0) at line 6 (check the slot depth). Press Enter"),
                 err.constData());
        QVERIFY(err.contains("Tool change (M6) at line 9: change to tool 2"));
        QVERIFY(err.contains("Optional stop (M1) at line 11"));
        const QJsonObject j = lastJson(QString::fromUtf8(p.readAllStandardOutput()));
        QCOMPARE(j[QStringLiteral("program_stops")].toInt(), 3);
        checkEndsAt(j, steps({2000, 6000, 0, 0}));
    }

    // Nobody answers (standard input at its end): the run ends at the first stop, exit 1.
    void withoutAnAnswerTheRunEndsAtTheStop()
    {
        const Run r = cli({QStringLiteral("run"), stopsJob()});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QLatin1String("Program stop (M0) at line 6")), qPrintable(r.err));
        QVERIFY(r.err.contains(QLatin1String("--continue-at-stops")));
    }
};

QTEST_GUILESS_MAIN(CliShopJobTest)
#include "cli_shopjob_test.moc"
