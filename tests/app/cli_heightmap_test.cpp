// frezka-cli check/plan/run --height-map (issue 19 item 3): the map's range said, the program
// bent to it before planning (the emulator's counters end on the raised point), and a program
// that cuts outside the map refused naming its line; run --surface: G38.2 on the emulator's
// simulated work top trips at its height.

#include "cliprocess.h"

#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

class CliHeightMapTest : public QObject
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

    // Machine X 10..30, Y 10..20: a plane rising 0.01 mm/mm in X and 0.005 mm/mm in Y.
    QString map()
    {
        return write(QStringLiteral("map.csv"), "# frezka-height-map 1\n"
                                                "# origin_x_mm: 10\n# origin_y_mm: 10\n"
                                                "# spacing_x_mm: 10\n# spacing_y_mm: 10\n"
                                                "# count_x: 3\n# count_y: 2\n"
                                                "x_mm,y_mm,z_mm\n"
                                                "10,10,0\n20,10,0.1\n30,10,0.2\n"
                                                "10,20,0.05\n20,20,0.15\n30,20,0.25\n");
    }

    // Engraves 0.1 mm deep from the work's (0,0) to (20,10) and stays down at the end.
    QString program()
    {
        return write(QStringLiteral("engrave.nc"), "G21 G90 G94\n"
                                                   "M3 S10000\n"
                                                   "G0 Z2\n"
                                                   "G0 X0 Y0\n"
                                                   "G1 Z-0.1 F300\n"
                                                   "G1 X20 Y10 F600\n"
                                                   "M5\n"
                                                   "M2\n");
    }

    Run run(const QStringList &extra)
    {
        return cli(QStringList{QStringLiteral("run"), program(), QStringLiteral("--port"),
                               QStringLiteral("sim"), QStringLiteral("--clock"),
                               QStringLiteral("virtual"), QStringLiteral("--offset"),
                               QStringLiteral("G54:10,10,-20")} +
                   extra);
    }

    static QJsonObject lastJson(const QString &out) { return clitest::lastJson(out); }

private slots:
    // The run ends at machine X30 Y20 (200 steps/mm), Z -20.1 + 0.25 with the map (the
    // height there) and at -20.1 without it: the bent path is what reached the unit.
    void runEndsOnTheRaisedPoint()
    {
        const Run bent = run({QStringLiteral("--height-map"), map()});
        QVERIFY2(bent.code == 0, qPrintable(bent.err));
        QVERIFY2(bent.out.contains(QStringLiteral("applied: X 10.000 to 30.000, Y 10.000 to "
                                                  "20.000 mm, heights 0.000 to 0.250 mm")),
                 qPrintable(bent.out));
        const QJsonObject j = lastJson(bent.out);
        const QJsonArray at{6000, 4000, -3970, 0};
        QCOMPARE(j[QStringLiteral("unit_steps")].toArray(), at);
        QCOMPARE(j[QStringLiteral("expected_steps")].toArray(), at);
        for (const char *key : {"cut_without_spindle", "axis_over_max", "brake_violations"})
            QVERIFY2(j[QLatin1String(key)].toInt(-1) == 0, key);

        const Run flat = run({});
        QVERIFY2(flat.code == 0, qPrintable(flat.err));
        QVERIFY(!flat.out.contains(QStringLiteral("Height map")));
        QCOMPARE(lastJson(flat.out)[QStringLiteral("unit_steps")].toArray(),
                 (QJsonArray{6000, 4000, -4020, 0}));
    }

    // The map moved 5 mm right: line 6 cuts from machine X10, left of it.
    void checkRefusesACutOutsideTheMap()
    {
        QByteArray text;
        {
            QFile f(map());
            f.open(QIODevice::ReadOnly);
            text = f.readAll().replace("# origin_x_mm: 10", "# origin_x_mm: 15");
            text.replace("10,10,", "15,10,")
                .replace("20,10,", "25,10,")
                .replace("30,10,", "35,10,");
            text.replace("10,20,", "15,20,")
                .replace("20,20,", "25,20,")
                .replace("30,20,", "35,20,");
        }
        const QString shifted = write(QStringLiteral("shifted.csv"), text);
        const Run r =
            cli({QStringLiteral("check"), program(), QStringLiteral("--offset"),
                 QStringLiteral("G54:10,10,-20"), QStringLiteral("--height-map"), shifted});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("Line 5 cuts at X 10.000, Y 10.000, outside the "
                                               "height map")),
                 qPrintable(r.err));
    }

    // run --surface: G38.2 at each node of a 3 x 3 grid (10 mm) on the emulator's tilted work
    // top stops within a step (200 steps/mm) of the plane's height there, and the run reports
    // the trip point; without the surface the probe never trips and the run fails.
    void probesATiltedSurfaceOnTheEmulator()
    {
        const QString plane = QStringLiteral("plane:-5,0.01,-0.02");
        for (int j = 0; j < 3; ++j)
            for (int i = 0; i < 3; ++i) {
                const double x = 10 * i, y = 10 * j, z = -5 + 0.01 * x - 0.02 * y;
                const QString file =
                    write(QStringLiteral("probe.nc"), QStringLiteral("G21 G90\nG0 X%1 Y%2 Z0\n"
                                                                     "G38.2 Z-20 F100\nM2\n")
                                                          .arg(x)
                                                          .arg(y)
                                                          .toUtf8());
                const Run r = cli({QStringLiteral("run"), file, QStringLiteral("--port"),
                                   QStringLiteral("sim"), QStringLiteral("--surface"), plane});
                QVERIFY2(r.code == 0, qPrintable(r.err));
                const QJsonArray at = lastJson(r.out)[QStringLiteral("probe_steps")].toArray();
                QCOMPARE(at.size(), 4);
                QCOMPARE(at[0].toInt(), int(x * 200));
                QCOMPARE(at[1].toInt(), int(y * 200));
                QVERIFY2(std::abs(at[2].toDouble() / 200 - z) <= 1.0 / 200 + 1e-9,
                         qPrintable(QStringLiteral("%1,%2: %3").arg(x).arg(y).arg(at[2].toInt())));
                QCOMPARE(lastJson(r.out)[QStringLiteral("unit_steps")].toArray(), at);
            }
        const QString file = write(QStringLiteral("probe.nc"), "G0 X0 Y0 Z0\nG38.2 Z-20 F100\n");
        QCOMPARE(cli({QStringLiteral("run"), file, QStringLiteral("--port"), QStringLiteral("sim")})
                     .code,
                 1);
        QCOMPARE(cli({QStringLiteral("run"), file, QStringLiteral("--surface"),
                      QStringLiteral("cone:1")})
                     .code,
                 2);
    }

    void aBadMapFileNamesItsLine()
    {
        const QString bad = write(QStringLiteral("bad.csv"), "# frezka-height-map 1\n"
                                                             "# origin_x_mm: 10\n"
                                                             "# origin_y_mm: ten\n");
        const Run r = cli({QStringLiteral("plan"), program(), QStringLiteral("--height-map"), bad});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("bad.csv: Height map line 3: 'origin_y_mm' is not "
                                               "a number")),
                 qPrintable(r.err));
    }
};

QTEST_GUILESS_MAIN(CliHeightMapTest)
#include "cli_heightmap_test.moc"
