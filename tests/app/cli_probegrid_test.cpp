// frezka-cli probe-grid (issue 19): a height map probed on the emulator's tilted and warped work
// top matches the surface within a motor step at every node (heights relative to the first); a
// probe that never trips stops with its error naming the node, never below the depth, and the
// tool back at the clearance; gve-emu on a pty is probed through the link worker as hardware is;
// and the done-when through the CLI: a PCB-isolation-style program (0.1 mm deep, 80 x 80
// mm) run with its probed map keeps the tool tip 0.08 .. 0.12 mm below the surface (run
// --cut-depth samples the emulator's counters), and without the map it does not.

#include "cliprocess.h"

#include "gcode/heightmap.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <numbers>

namespace {

// 0.24 mm of tilt plus a 0.05 mm sine over the 80 x 80 mm work: about 0.3 mm over 100 mm.
const QString kWarp = QStringLiteral("warp:-20,0.002,0.001,0.05,100");

double warp(double x, double y)
{
    const double w = 2 * std::numbers::pi / 100;
    return -20 + 0.002 * x + 0.001 * y + 0.05 * std::sin(w * x) * std::sin(w * y);
}

constexpr double kStepMm = 1.0 / 200; // the shipped GVE64 profile: 200 steps/mm

} // namespace

class CliProbeGridTest : public QObject
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
        return clitest::runCli(QStringLiteral(FREZKA_CLI), args, true, 600000);
    }

    static QJsonObject lastJson(const QString &out) { return clitest::lastJson(out); }

    // Engraves 0.1 mm deep along 9 lines in X and 9 in Y over the work's 0..80 mm square.
    QString pcbProgram()
    {
        QByteArray text = "G21 G90 G94\nM3 S10000\nG0 Z2\n";
        for (int dir = 0; dir < 2; ++dir)
            for (int k = 0; k <= 8; ++k) {
                const QByteArray c = QByteArray::number(k * 10);
                text += dir == 0 ? "G0 X0 Y" + c + "\n" : "G0 X" + c + " Y0\n";
                text += "G1 Z-0.1 F100\n";
                text += dir == 0 ? "G1 X80 F600\n" : "G1 Y80 F600\n";
                text += "G0 Z2\n";
            }
        text += "M5\nM2\n";
        return write(QStringLiteral("pcb.nc"), text);
    }

    Run probeGrid(const QStringList &extra, const QString &out)
    {
        return cli(QStringList{QStringLiteral("probe-grid"), QStringLiteral("--offset"),
                               QStringLiteral("G54:10,10,-20"), QStringLiteral("--spacing"),
                               QStringLiteral("10"), QStringLiteral("--clearance"),
                               QStringLiteral("1"), QStringLiteral("--depth"), QStringLiteral("2"),
                               QStringLiteral("--feed"), QStringLiteral("100"),
                               QStringLiteral("--out"), out} +
                   extra);
    }

private slots:
    // A 5 x 4 grid over the work's 0..40 x 0..30 mm: every node's height within a step of the
    // surface there; the emulator never went below the depth; the tool ends at the clearance.
    void theProbedMapMatchesTheSurface()
    {
        const QString out = m_dir.filePath(QStringLiteral("map.csv"));
        const Run r = probeGrid({QStringLiteral("--area"), QStringLiteral("0,0,40,30"),
                                 QStringLiteral("--surface"), kWarp},
                                out);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject j = lastJson(r.out);
        QCOMPARE(j[QStringLiteral("points_probed")].toInt(), 20);
        QVERIFY(j[QStringLiteral("unit_lowest_z_steps")].toInt() >= -22 * 200);
        QCOMPARE(j[QStringLiteral("unit_steps")].toArray()[2].toInt(), -19 * 200);
        QString error;
        const auto map = frezka::gcode::HeightMap::load(out, &error);
        QVERIFY2(map, qPrintable(error));
        QCOMPARE(map->countX(), 5);
        QCOMPARE(map->countY(), 4);
        // The first node's trip point: the surface's step, and the step the unit takes while it
        // brakes after the input fires.
        const double reference = map->probing().referenceZMm;
        QVERIFY(std::abs(reference - warp(10, 10)) <= 2 * kStepMm + 1e-9);
        // Every height (relative to the first node) within a step of the surface's there.
        for (int jy = 0; jy < map->countY(); ++jy)
            for (int ix = 0; ix < map->countX(); ++ix) {
                const double x = map->nodeX(ix), y = map->nodeY(jy);
                QVERIFY(std::abs(x - (10 + 10 * ix)) < 1e-9 && std::abs(y - (10 + 10 * jy)) < 1e-9);
                const double surface = warp(x, y) - warp(10, 10);
                QVERIFY2(std::abs(map->z(ix, jy) - surface) <= kStepMm + 1e-9,
                         qPrintable(QStringLiteral("%1,%2: %3 vs %4")
                                        .arg(x)
                                        .arg(y)
                                        .arg(map->z(ix, jy))
                                        .arg(surface)));
            }
    }

    // The surface 5 mm below the depth: the first node's probe goes down to the depth, fails
    // naming the node, the tool goes back up; no map is written.
    void aProbeThatNeverTripsStopsWithItsError()
    {
        const QString out = m_dir.filePath(QStringLiteral("none.csv"));
        const Run r = probeGrid({QStringLiteral("--area"), QStringLiteral("0,0,40,30"),
                                 QStringLiteral("--surface"), QStringLiteral("plane:-27,0,0")},
                                out);
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("The probe at X 10.000, Y 10.000 went down to "
                                               "Z -22.000 without touching the surface")),
                 qPrintable(r.err));
        const QJsonObject j = lastJson(r.out);
        QCOMPARE(j[QStringLiteral("points_probed")].toInt(), 0);
        QCOMPARE(j[QStringLiteral("unit_lowest_z_steps")].toInt(), -22 * 200);
        QCOMPARE(j[QStringLiteral("unit_steps")].toArray(),
                 (QJsonArray{10 * 200, 10 * 200, -19 * 200, 0}));
        QVERIFY(!QFile::exists(out));
    }

    // The same sequence on a serial line: gve-emu on a pty with a tilted work top, probed in
    // real time through the link worker (as on hardware): the heights of the plane's nodes.
    void probesGveEmuOnAPty()
    {
        QProcess emu;
        emu.start(QStringLiteral(GVE_EMU_PATH),
                  {QStringLiteral("--variant"), QStringLiteral("gve64"),
                   QStringLiteral("--surface"), QStringLiteral("plane:-5,0.01,0.005")});
        QVERIFY(emu.waitForStarted(20000));
        QTRY_VERIFY_WITH_TIMEOUT(emu.canReadLine(), 20000);
        const QString pty = QString::fromLocal8Bit(emu.readLine()).trimmed();
        const QString out = m_dir.filePath(QStringLiteral("pty.csv"));
        const Run r =
            cli({QStringLiteral("probe-grid"), QStringLiteral("--port"), pty,
                 QStringLiteral("--area"), QStringLiteral("0,0,10,10"), QStringLiteral("--spacing"),
                 QStringLiteral("10"), QStringLiteral("--clearance"), QStringLiteral("-4"),
                 QStringLiteral("--depth"), QStringLiteral("7"), QStringLiteral("--feed"),
                 QStringLiteral("200"), QStringLiteral("--out"), out});
        emu.terminate();
        emu.waitForFinished(20000);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        QString error;
        const auto map = frezka::gcode::HeightMap::load(out, &error);
        QVERIFY2(map, qPrintable(error));
        QCOMPARE(lastJson(r.out)[QStringLiteral("points_probed")].toInt(), 4);
        for (int j = 0; j < 2; ++j)
            for (int i = 0; i < 2; ++i)
                QVERIFY(std::abs(map->z(i, j) - (0.1 * i + 0.05 * j)) <= kStepMm + 1e-9);
    }

    void badUsageAndValuesAreRefused()
    {
        const QString out = m_dir.filePath(QStringLiteral("x.csv"));
        QCOMPARE(probeGrid({}, out).code, 2); // neither --area nor --program
        const Run empty = probeGrid({QStringLiteral("--area"), QStringLiteral("5,5,5,30")}, out);
        QCOMPARE(empty.code, 1);
        QVERIFY2(empty.err.contains(QStringLiteral("The area to probe is empty")),
                 qPrintable(empty.err));
    }

    // The done-when through the CLI: probe the program's area, run it with the map:
    // the tool tip 0.08 .. 0.12 mm below the surface wherever it cuts; without the map not.
    void aPcbProgramWithItsMapKeepsTheDepth()
    {
        const QString program = pcbProgram();
        const QString out = m_dir.filePath(QStringLiteral("pcb-map.csv"));
        const Run probed = probeGrid(
            {QStringLiteral("--program"), program, QStringLiteral("--surface"), kWarp}, out);
        QVERIFY2(probed.code == 0, qPrintable(probed.err));
        QCOMPARE(lastJson(probed.out)[QStringLiteral("points_probed")].toInt(), 81);
        const double reference = lastJson(probed.out)[QStringLiteral("reference_z_mm")].toDouble();
        // The work's Z zero on the surface at the first node, as the operator sets it.
        const QString offset = QStringLiteral("G54:10,10,%1").arg(reference, 0, 'f', 4);
        auto run = [&](const QStringList &extra) {
            return cli(QStringList{QStringLiteral("run"), program, QStringLiteral("--offset"),
                                   offset, QStringLiteral("--surface"), kWarp,
                                   QStringLiteral("--cut-depth")} +
                       extra);
        };
        const Run bent = run({QStringLiteral("--height-map"), out});
        QVERIFY2(bent.code == 0, qPrintable(bent.err));
        const QJsonObject j = lastJson(bent.out);
        const QJsonObject depth = j[QStringLiteral("cut_depth")].toObject();
        QVERIFY2(depth[QStringLiteral("samples")].toInt() > 10000, qPrintable(bent.out));
        QVERIFY2(depth[QStringLiteral("min_mm")].toDouble() >= 0.08 &&
                     depth[QStringLiteral("max_mm")].toDouble() <= 0.12,
                 qPrintable(bent.out));
        for (const char *key : {"cut_without_spindle", "axis_over_max", "brake_violations"})
            QVERIFY2(j[QLatin1String(key)].toInt(-1) == 0, key);

        const Run flat = run({});
        QVERIFY2(flat.code == 0, qPrintable(flat.err));
        const QJsonObject d = lastJson(flat.out)[QStringLiteral("cut_depth")].toObject();
        QVERIFY2(d[QStringLiteral("min_mm")].toDouble() < 0.08 ||
                     d[QStringLiteral("max_mm")].toDouble() > 0.12,
                 qPrintable(flat.out));
    }
};

QTEST_GUILESS_MAIN(CliProbeGridTest)
#include "cli_probegrid_test.moc"
