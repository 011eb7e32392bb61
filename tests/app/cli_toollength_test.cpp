// frezka-cli probe tool-length (issue 19 item 1) on the in-process emulator: a profile with a
// tool length sensor; the simulated sensor top where each tool trips (a longer tool trips
// higher). The measured length is the trip minus the reference within a motor step, written
// into the profile's tool table (other tools and words kept); a program with G43 H of the
// measured tool then ends at the right machine Z on the unit's counters; a sensor that never
// trips is an error with the table untouched and the tool back at the clearance; a profile
// without a sensor is refused before anything moves.

#include "cliprocess.h"

#include <QFile>
#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

namespace {

constexpr double kStepMm = 1.0 / 200; // the shipped GVE64 profile: 200 steps/mm

// The sensor at machine X 350 Y 20, travel from Z -5 down at most 40 mm; the reference tool
// (length 0) trips at machine Z -30.
const QByteArray kProfile = R"({
  "unit": {"variant": "gve64"},
  "tools": {"tableFile": "tool.tbl",
            "sensor": {"enabled": true, "xMm": 350, "yMm": 20, "clearanceZMm": -5,
                       "travelMm": 40, "feedMmPerMin": 300, "slowFeedMmPerMin": 30,
                       "retractMm": 1.5, "referenceZMm": -30}}
})";

} // namespace

class CliToolLengthTest : public QObject
{
    Q_OBJECT

private:
    using Run = clitest::Run;

    static Run cli(const QStringList &args)
    {
        return clitest::runCli(QStringLiteral(FREZKA_CLI), args, true, 600000);
    }

    static QByteArray readAll(const QString &path)
    {
        QFile f(path);
        return f.open(QIODevice::ReadOnly) ? f.readAll() : QByteArray();
    }

private slots:
    void measuresTheToolIntoTheTableAndG43UsesIt()
    {
        QTemporaryDir dir;
        const QString profile = clitest::writeFile(dir, QStringLiteral("mill.json"), kProfile);
        const QString table = clitest::writeFile(dir, QStringLiteral("tool.tbl"),
                                                 "T1 P1 Z0 D6 ;reference\nT2 P2 Z3 D3 ;engraver\n");
        // Tool 2 is 5.5 mm longer than the reference: it trips at -24.5.
        const Run r =
            cli({QStringLiteral("probe"), QStringLiteral("tool-length"), QStringLiteral("--tool"),
                 QStringLiteral("2"), QStringLiteral("--machine"), profile,
                 QStringLiteral("--surface"), QStringLiteral("plane:-24.5,0,0")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject j = clitest::lastJson(r.out);
        QVERIFY2(std::abs(j[QStringLiteral("trip_z_mm")].toDouble() + 24.5) <= kStepMm,
                 qPrintable(r.out));
        const double length = j[QStringLiteral("length_mm")].toDouble();
        QVERIFY2(std::abs(length - 5.5) <= kStepMm, qPrintable(r.out));
        // Over the sensor, back at the clearance.
        const QJsonArray at = j[QStringLiteral("unit_steps")].toArray();
        QCOMPARE(at[0].toInt(), 350 * 200);
        QCOMPARE(at[1].toInt(), 20 * 200);
        QCOMPARE(at[2].toInt(), -5 * 200);
        const QByteArray tbl = readAll(table);
        QVERIFY2(tbl.contains("T1 P1") && tbl.contains("reference"), tbl.constData());
        QVERIFY2(tbl.contains("engraver") && tbl.contains("D3"), tbl.constData());
        QVERIFY2(!tbl.contains("Z3 "), tbl.constData());
        QVERIFY2(r.err.contains(QStringLiteral("written to")), qPrintable(r.err));

        // The same tool's G43 lifts the controlled point by its length: G0 Z2 in a G54 whose
        // zero is at machine Z -40 ends at -40 + 2 + length.
        const QString program = clitest::writeFile(dir, QStringLiteral("g43.nc"),
                                                   "G21 G90\nG43 H2\nG0 X10 Y10 Z2\nM2\n");
        const Run run = cli({QStringLiteral("run"), program, QStringLiteral("--machine"), profile,
                             QStringLiteral("--offset"), QStringLiteral("G54:0,0,-40")});
        QVERIFY2(run.code == 0, qPrintable(run.err));
        const QJsonArray end = clitest::lastJson(run.out)[QStringLiteral("unit_steps")].toArray();
        QCOMPARE(end[2].toInt(), qRound((-40 + 2 + length) * 200));
    }

    void aToolNotInTheTableIsAdded()
    {
        QTemporaryDir dir;
        const QString profile = clitest::writeFile(dir, QStringLiteral("mill.json"), kProfile);
        const Run r =
            cli({QStringLiteral("probe"), QStringLiteral("tool-length"), QStringLiteral("--tool"),
                 QStringLiteral("7"), QStringLiteral("--machine"), profile,
                 QStringLiteral("--surface"), QStringLiteral("plane:-31.25,0,0")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QByteArray tbl = readAll(dir.filePath(QStringLiteral("tool.tbl")));
        QVERIFY2(tbl.startsWith("T7 P7 Z-1.25"), tbl.constData());
    }

    // The sensor 50 mm below the clearance, the travel 40: down to Z -45, an error, the table
    // untouched, the tool back up at the clearance.
    void aSensorThatNeverTripsIsAnError()
    {
        QTemporaryDir dir;
        const QString profile = clitest::writeFile(dir, QStringLiteral("mill.json"), kProfile);
        const QString table =
            clitest::writeFile(dir, QStringLiteral("tool.tbl"), "T2 P2 Z3 D3 ;engraver\n");
        const Run r =
            cli({QStringLiteral("probe"), QStringLiteral("tool-length"), QStringLiteral("--tool"),
                 QStringLiteral("2"), QStringLiteral("--machine"), profile,
                 QStringLiteral("--surface"), QStringLiteral("plane:-55,0,0")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("without touching")), qPrintable(r.err));
        const QJsonObject j = clitest::lastJson(r.out);
        QVERIFY(j[QStringLiteral("length_mm")].isNull());
        QCOMPARE(j[QStringLiteral("unit_steps")].toArray()[2].toInt(), -5 * 200);
        QCOMPARE(readAll(table), QByteArray("T2 P2 Z3 D3 ;engraver\n"));
    }

    void withoutASensorNothingMoves()
    {
        const Run r = cli({QStringLiteral("probe"), QStringLiteral("tool-length"),
                           QStringLiteral("--tool"), QStringLiteral("1")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("no tool length sensor")), qPrintable(r.err));
        QCOMPARE(cli({QStringLiteral("probe"), QStringLiteral("tool-length")}).code, 2);
        QCOMPARE(cli({QStringLiteral("probe"), QStringLiteral("tool-length"),
                      QStringLiteral("--tool"), QStringLiteral("0")})
                     .code,
                 2);
    }
};

QTEST_GUILESS_MAIN(CliToolLengthTest)
#include "cli_toollength_test.moc"
