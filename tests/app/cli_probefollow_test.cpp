// frezka-cli run of a program that probes for itself (issue 19 item 4) on the in-process
// emulator with a simulated work top: G38.2, G10 L20 making the trip point Z0, then a cut 0.1
// deep ends on the unit 0.1 below the surface (not at the probe's programmed depth), the report
// counts the probe followed and the cut's depth below the surface; a probe that never touches
// still ends the run with its error.

#include "cliprocess.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

class CliProbeFollowTest : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;

    using Run = clitest::Run;

    QString program()
    {
        return clitest::writeFile(m_dir, QStringLiteral("touchoff.nc"),
                                  "G21 G90 G54\n"
                                  "G0 X10 Y10\n"
                                  "G38.2 Z-10 F50\n"
                                  "G10 L20 P1 Z0\n"
                                  "G0 Z1\n"
                                  "M3 S10000\n"
                                  "G1 Z-0.1 F100\n"
                                  "G1 X30 F300\n"
                                  "M5\n"
                                  "M2\n");
    }

    Run run(const QString &surface)
    {
        return clitest::runCli(QStringLiteral(FREZKA_CLI),
                               {QStringLiteral("run"), program(), QStringLiteral("--port"),
                                QStringLiteral("sim"), QStringLiteral("--surface"), surface,
                                QStringLiteral("--cut-depth")});
    }

private slots:
    void touchOffThenCutEndsAtTheSurfaceMinusTheDepth()
    {
        const Run r = run(QStringLiteral("plane:-3.2,0,0"));
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("touchoff.nc:3: the path after this probe depends "
                                               "on where it stops")),
                 qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("line 3: the probe has run")), qPrintable(r.err));
        const QJsonObject report = clitest::lastJson(r.out);
        QCOMPARE(report[QStringLiteral("probes_followed")].toInt(), 1);
        const QJsonArray at = report[QStringLiteral("unit_steps")].toArray();
        QCOMPARE(at[0].toInt(), 30 * 200);
        QCOMPARE(at[1].toInt(), 10 * 200);
        QVERIFY2(std::abs(at[2].toInt() - (-3.3 * 200)) <= 1, qPrintable(r.out));
        const QJsonObject depth = report[QStringLiteral("cut_depth")].toObject();
        QVERIFY(depth[QStringLiteral("samples")].toInt() > 10);
        QVERIFY2(std::abs(depth[QStringLiteral("min_mm")].toDouble() - 0.1) <= 0.005 + 1e-9,
                 qPrintable(r.out));
        QVERIFY2(std::abs(depth[QStringLiteral("max_mm")].toDouble() - 0.1) <= 0.005 + 1e-9,
                 qPrintable(r.out));
        QCOMPARE(report[QStringLiteral("brake_violations")].toInt(), 0);
        // The probe went down with the spindle stopped, as it must: no cut without the spindle;
        // each part starts from rest as planned: no starvation.
        QCOMPARE(report[QStringLiteral("cut_without_spindle")].toInt(), 0);
        QCOMPARE(report[QStringLiteral("starvation_stops")].toInt(), 0);
    }

    void checkSaysWhereThePathBecomesProvisional()
    {
        const Run r =
            clitest::runCli(QStringLiteral(FREZKA_CLI), {QStringLiteral("check"), program()});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("touchoff.nc:3: note: after this line the path "
                                               "depends on the probe's result")),
                 qPrintable(r.err));
    }

    // From a line after the probe, or with a height map, the path after the probe would run as
    // provisional (from line 7 the tool went 5.8 mm into the work top): refused, nothing moves.
    void runFromALineOrWithAHeightMapIsRefused()
    {
        const QString map = clitest::writeFile(
            m_dir, QStringLiteral("map.csv"),
            "# frezka-height-map 1\n# origin_x_mm: 0\n# origin_y_mm: 0\n# spacing_x_mm: 40\n"
            "# spacing_y_mm: 40\n# count_x: 2\n# count_y: 2\nx_mm,y_mm,z_mm\n0,0,0\n40,0,0\n"
            "0,40,0\n40,40,0\n");
        const struct
        {
            QStringList args;
            const char *says;
        } cases[] = {
            {{QStringLiteral("--from-line"), QStringLiteral("7")},
             "touchoff.nc: Line 7: the program probes for itself: after line 3 its path depends "
             "on that probe's result"},
            {{QStringLiteral("--height-map"), map},
             "touchoff.nc: Line 3: the program probes for itself (after this line its path "
             "depends on the probe's result): a height map cannot be applied to it"},
        };
        for (const auto &c : cases) {
            const Run r = clitest::runCli(
                QStringLiteral(FREZKA_CLI),
                QStringList{QStringLiteral("run"), program(), QStringLiteral("--port"),
                            QStringLiteral("sim"), QStringLiteral("--surface"),
                            QStringLiteral("plane:-3.2,0,0")} +
                    c.args);
            QCOMPARE(r.code, 1);
            QVERIFY2(r.err.contains(QLatin1String(c.says)), qPrintable(r.err));
            QVERIFY2(!r.out.contains(QLatin1String("\"final_steps\"")),
                     qPrintable(r.out)); // no run
        }
    }

    void aProbeThatNeverTouchesEndsTheRunWithItsError()
    {
        const Run r = run(QStringLiteral("plane:-12,0,0"));
        // The run's error is the driver's: it reports the probe before it ends the job.
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("Line 3: the probe move ended without the probe "
                                               "tripping")),
                 qPrintable(r.err));
        QVERIFY2(!r.err.contains(QStringLiteral("the job did not finish")), qPrintable(r.err));
        QVERIFY2(!r.err.contains(QStringLiteral("the probe has run")), qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(CliProbeFollowTest)
#include "cli_probefollow_test.moc"
