// frezka-cli run --from-line N (issue 16 item 2), run as a process on the emulator's virtual
// clock: from the middle of a program with a tool change, a work offset and G91 before the
// line, the job ends on exactly the emulator counters the whole program ends on, asks no stop
// the lines before it had (M6), never cuts without the spindle, and says the state it took; a
// line inside a loop is refused with the line to choose.

#include "cliprocess.h"

#include "../session/runfromline_program.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

class CliRunFromLineTest : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    using Run = clitest::Run;

    QString write(const QString &name, const QByteArray &text)
    {
        return clitest::writeFile(m_dir, name, text);
    }

    static Run cli(const QStringList &args)
    {
        return clitest::runCli(QStringLiteral(FREZKA_CLI), args);
    }

    static QJsonObject lastJson(const QString &out) { return clitest::lastJson(out); }

    static QStringList runArgs(const QString &file)
    {
        return {QStringLiteral("run"),     file,
                QStringLiteral("--port"),  QStringLiteral("sim"),
                QStringLiteral("--clock"), QStringLiteral("virtual")};
    }

private slots:
    void fromTheMiddleEndsWhereTheWholeProgramEnds()
    {
        const QString file =
            write(QStringLiteral("fromline.nc"), frezka::test::kRunFromLineProgram);
        const Run whole = cli(runArgs(file) << QStringLiteral("--continue-at-stops"));
        QVERIFY2(whole.code == 0, qPrintable(whole.err));
        const QJsonObject w = lastJson(whole.out);
        QCOMPARE(w[QStringLiteral("program_stops")].toInt(), 2); // T1 M6, T2 M6

        const Run from = cli(runArgs(file) << QStringLiteral("--from-line")
                                           << QString::number(frezka::test::kRunFromLine));
        QVERIFY2(from.code == 0, qPrintable(from.err));
        const QJsonObject j = lastJson(from.out);
        // G55 X30 Y15 Z5 (G90 after the cut) is machine X70 Y45 Z-55: 200 steps/mm.
        const QJsonArray end{14000, 9000, -11000, 0};
        QCOMPARE(w[QStringLiteral("unit_steps")].toArray(), end);
        QCOMPARE(j[QStringLiteral("unit_steps")].toArray(), end);
        QCOMPARE(j[QStringLiteral("final_steps")].toArray(), end);
        QCOMPARE(j[QStringLiteral("program_stops")].toInt(), 0); // the M6 before it is not asked
        for (const char *key :
             {"cut_without_spindle", "spindle_on_while_held", "axis_over_max", "brake_violations"})
            QVERIFY2(j[QLatin1String(key)].isDouble() && j[QLatin1String(key)].toInt() == 0, key);
        QVERIFY(j[QStringLiteral("job_s")].toDouble() < w[QStringLiteral("job_s")].toDouble());
        // The approach is the first motion: where the emulator's counters first went below the
        // safe height (machine Z0 here, where Z stood) is straight above line 18's start, X85
        // Y35 (machine), on the way down to it.
        const QStringList lines = from.out.trimmed().split(QLatin1Char('\n'));
        QVERIFY(lines.size() >= 2);
        const QJsonObject a = QJsonDocument::fromJson(lines[lines.size() - 2].toUtf8()).object();
        QCOMPARE(a[QStringLiteral("from_line")].toInt(), 18);
        QCOMPARE(a[QStringLiteral("safe_z_steps")].toInt(), 0);
        QCOMPARE(a[QStringLiteral("start_steps")].toArray(), (QJsonArray{17000, 7000, -12400, 0}));
        const QJsonArray below = a[QStringLiteral("unit_first_below_safe_z")].toArray();
        QCOMPARE(below.size(), 4);
        QCOMPARE(below[0].toInteger(), 17000);
        QCOMPARE(below[1].toInteger(), 7000);
        QVERIFY(below[2].toInteger() < 0 && below[2].toInteger() >= -12400);
        // The state it took, and the approach: across at the machine's Z0, where Z stands (above
        // the program's clearance, Z5 in G55 = -55), down at the feed to where line 18 begins.
        for (const char *text :
             {"Run from line 18.", "tool 2", "S12000 M3", "M8", "F800", "G55 G91 G21 G17",
              "crosses at Z 0.000", "X 85.000 Y 35.000 Z -62.000"})
            QVERIFY2(from.err.contains(QLatin1String(text)), qPrintable(text + from.err));
    }

    void aLineInsideALoopIsRefused()
    {
        const QString file = write(QStringLiteral("loop.nc"),
                                   "G21 G90 F300\n#1=0\no100 while [#1 LT 2]\nG1 X[#1*10]\n"
                                   "#1=[#1+1]\no100 endwhile\nM2\n");
        const Run r = cli(runArgs(file) << QStringLiteral("--from-line") << QStringLiteral("4"));
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(file + QStringLiteral(":4: cannot run from this line: line 4 is "
                                                      "inside the loop o100 that opens on line 3")),
                 qPrintable(r.err));
        QVERIFY(r.err.contains(QLatin1String("Choose line 3")));
        QCOMPARE(cli(runArgs(file) << QStringLiteral("--from-line") << QStringLiteral("0")).code,
                 2);
    }

    void helpNamesTheOption()
    {
        const Run r = cli({QStringLiteral("--help")});
        QVERIFY(r.out.contains(QLatin1String("--from-line N")));
    }
};

QTEST_GUILESS_MAIN(CliRunFromLineTest)
#include "cli_runfromline_test.moc"
