// `frezka-cli run` end to end: G-code -> plan -> stream on the emulator (virtual clock, with
// faults) or through gve-emu on a pty; its JSON line, exit codes and error messages.

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

class CliRunTest : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    QString write(const QString &name, const QByteArray &text)
    {
        const QString path = m_dir.filePath(name);
        QFile f(path);
        f.open(QIODevice::WriteOnly);
        f.write(text);
        return path;
    }

    struct Run
    {
        int code = -1;
        QByteArray out;
        QByteArray err;
    };

    Run cli(const QStringList &args)
    {
        QProcess p;
        p.start(QStringLiteral(FREZKA_CLI), QStringList{QStringLiteral("run")} + args);
        p.waitForFinished(120000);
        return {p.exitCode(), p.readAllStandardOutput(), p.readAllStandardError()};
    }

    static QJsonObject lastJson(const QByteArray &out)
    {
        const QList<QByteArray> lines = out.trimmed().split('\n');
        return QJsonDocument::fromJson(lines.last()).object();
    }

    QString job()
    {
        return write(QStringLiteral("job.nc"), "G21 G90\n"
                                               "G0 X10 Y10 Z-1\n"
                                               "G1 X50 Y10 F3000\n"
                                               "G2 X50 Y50 I0 J20\n"
                                               "G1 X10 Y50\n"
                                               "G1 X10 Y10\n"
                                               "M2\n");
    }

    static void checkExact(const QJsonObject &j)
    {
        QVERIFY(j.contains(QStringLiteral("vectors")));
        QVERIFY(j[QStringLiteral("vectors")].toInt() > 50);
        QCOMPARE(j[QStringLiteral("final_steps")].toArray(),
                 j[QStringLiteral("expected_steps")].toArray());
        for (const char *key : {"job_s", "link_bytes", "wire_limit_vectors_per_s", "vectors_per_s",
                                "starvation_stops", "brake_violations", "resent", "recovered"})
            QVERIFY2(j.contains(QLatin1String(key)), key);
    }

private slots:
    void simVirtualClock()
    {
        const Run r = cli({job()});
        QCOMPARE(r.code, 0);
        checkExact(lastJson(r.out));
        // Starvation is measured by the benchmark (tests/bench/link): on the planner's output,
        // which puts an A between many vectors, a chain start can run dry (see docs).
        QVERIFY(lastJson(r.out)[QStringLiteral("starvation_stops")].isDouble());
    }

    // Coolant, a dwell and the spindle between moves: the program drains the unit's queue before
    // each, and the unit starts the next move from rest as planned. The emulator counts such a
    // restart as a starvation stop (it cannot tell it from a queue that ran dry, 3 here); the
    // report counts only the unit running dry (machine::plannedRestarts subtracted).
    void plannedRestsAreNoStarvation()
    {
        const Run r = cli({write(QStringLiteral("rests.nc"),
                                 "G21 G90\nG1 X10 F1000\nM8\nG1 X20\nG4 P0.5\nG1 X30\n"
                                 "M3 S10000\nG1 X40\nM5 M9\nM2\n")});
        QCOMPARE(r.code, 0);
        const QJsonObject j = lastJson(r.out);
        QCOMPARE(j[QStringLiteral("final_steps")].toArray(),
                 j[QStringLiteral("expected_steps")].toArray());
        QCOMPARE(j[QStringLiteral("starvation_stops")].toInt(), 0);
        QCOMPARE(j[QStringLiteral("brake_violations")].toInt(), 0);
    }

    void simWithFaultsAndLatency()
    {
        const Run r =
            cli({job(), QStringLiteral("--latency-ms"), QStringLiteral("8"),
                 QStringLiteral("--faults"), QStringLiteral("0.001"), QStringLiteral("--seed"),
                 QStringLiteral("5"), QStringLiteral("--home")});
        QCOMPARE(r.code, 0);
        checkExact(lastJson(r.out));
    }

    void gveEmuOnAPty()
    {
        QProcess emu;
        emu.start(QStringLiteral(GVE_EMU), {QStringLiteral("--variant"), QStringLiteral("gve64")});
        QVERIFY(emu.waitForStarted(5000));
        for (int i = 0; i < 50 && !emu.canReadLine(); ++i)
            emu.waitForReadyRead(100);
        const QString path = QString::fromUtf8(emu.readLine()).trimmed();
        const Run r = cli({job(), QStringLiteral("--port"), path});
        QCOMPARE(r.code, 0);
        const QJsonObject j = lastJson(r.out);
        QCOMPARE(j[QStringLiteral("final_steps")].toArray(),
                 j[QStringLiteral("expected_steps")].toArray());
        QVERIFY(j[QStringLiteral("starvation_stops")].isNull()); // not known from a real port
        emu.terminate();
        emu.waitForFinished(5000);
    }

    // Issue 14: a cut with the spindle and coolant, held at line 8 by the scripted operator.
    QString spindleJob()
    {
        return write(QStringLiteral("spindle.nc"), "G21 G90\n"
                                                   "M3 S12000\n"
                                                   "M8\n"
                                                   "G0 X10 Y10\n"
                                                   "G0 Z-8\n"
                                                   "G1 Z-10 F300\n"
                                                   "G1 X40 F600\n"
                                                   "G1 Y40\n"
                                                   "G1 X10\n"
                                                   "G1 Y10\n"
                                                   "G0 Z0\n"
                                                   "M9\n"
                                                   "M5\n"
                                                   "M2\n");
    }

    void holdAtLineWithLift()
    {
        const Run plain = cli({spindleJob()});
        QCOMPARE(plain.code, 0);
        const Run held = cli({spindleJob(), QStringLiteral("--hold-at-line"), QStringLiteral("8"),
                              QStringLiteral("--lift")});
        QVERIFY2(held.code == 0, held.err.constData());
        const QJsonObject j = lastJson(held.out);
        QCOMPARE(j[QStringLiteral("final_steps")].toArray(),
                 j[QStringLiteral("expected_steps")].toArray());
        for (const char *key :
             {"cut_without_spindle", "spindle_on_while_held", "axis_over_max", "brake_violations"})
            QVERIFY2(j[QLatin1String(key)].isDouble() && j[QLatin1String(key)].toInt() == 0, key);
        QCOMPARE(j[QStringLiteral("spindle_on_at_end")].toBool(), false);
        // The hold really happened: 5 s of waiting and 2 s of spin-up more than the plain run.
        QVERIFY(j[QStringLiteral("job_s")].toDouble() >
                lastJson(plain.out)[QStringLiteral("job_s")].toDouble() + 7);
        const Run paused =
            cli({spindleJob(), QStringLiteral("--hold-at-line"), QStringLiteral("8")});
        QVERIFY2(paused.code == 0, paused.err.constData());
        QCOMPARE(lastJson(paused.out)[QStringLiteral("cut_without_spindle")].toInt(), 0);
        QCOMPARE(lastJson(paused.out)[QStringLiteral("spindle_on_while_held")].toInt(), 0);
    }

    void feedOverride()
    {
        const Run plain = cli({spindleJob()});
        const Run faster =
            cli({spindleJob(), QStringLiteral("--feed-override"), QStringLiteral("150")});
        QVERIFY2(faster.code == 0, faster.err.constData());
        const QJsonObject j = lastJson(faster.out);
        QCOMPARE(j[QStringLiteral("final_steps")].toArray(),
                 j[QStringLiteral("expected_steps")].toArray());
        QVERIFY(j[QStringLiteral("axis_over_max")].isDouble());
        QVERIFY(j[QStringLiteral("job_s")].toDouble() <
                0.9 * lastJson(plain.out)[QStringLiteral("job_s")].toDouble());
        QCOMPARE(cli({spindleJob(), QStringLiteral("--feed-override"), QStringLiteral("0")}).code,
                 2);
        QCOMPARE(cli({spindleJob(), QStringLiteral("--lift")}).code, 2); // a lift needs a hold
        QCOMPARE(cli({spindleJob(), QStringLiteral("--hold-at-line"), QStringLiteral("3"),
                      QStringLiteral("--clock"), QStringLiteral("real")})
                     .code,
                 2); // the scripted operator plays on the virtual clock only
    }

    void errors()
    {
        const Run bad = cli({write(QStringLiteral("bad.nc"), "G21\nG1 X10 Q\n")});
        QCOMPARE(bad.code, 1);
        QVERIFY2(bad.err.contains("bad.nc:2"), bad.err.constData());
        QVERIFY(bad.out.isEmpty());
        const Run limits = cli({write(QStringLiteral("far.nc"), "G21 G90\nG0 X5000\nM2\n")});
        QCOMPARE(limits.code, 1);
        QVERIFY2(limits.err.contains("far.nc:2"), limits.err.constData());
        QCOMPARE(cli({}).code, 2);
        QCOMPARE(cli({job(), QStringLiteral("--port"), QStringLiteral("/dev/null"),
                      QStringLiteral("--faults"), QStringLiteral("0.1")})
                     .code,
                 2); // faults are injected only into the emulator
        const Run noPort =
            cli({job(), QStringLiteral("--port"), QStringLiteral("/dev/nonexistent-tty")});
        QCOMPARE(noPort.code, 1);
        QVERIFY2(noPort.err.contains("nonexistent-tty"), noPort.err.constData());
    }
};

QTEST_MAIN(CliRunTest)
#include "cli_run_test.moc"
