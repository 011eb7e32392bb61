// frezka-cli probe z-plate (issue 19 item 2): on the emulator with a known work top, the probe
// touches it fast then slow, the active offset's Z puts the work's top at Z 0 under the plate
// (within a motor step), the tool ends the retract above the plate, and a program engraving 0.1
// mm deep with that offset cuts 0.1 mm into the surface (run --cut-depth reads the emulator's
// counters); a probe that never trips fails with its error, never below the depth, back at the
// start; gve-emu on a pty is probed through the link worker as hardware is; bad values and
// usage are refused.

#include "cliprocess.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

namespace {

constexpr double kStepMm = 1.0 / 200; // the shipped GVE64 profile: 200 steps/mm
// The probe's contact (the plate's top, or the work's with --plate 0) at machine Z -17.437.
const QString kTop = QStringLiteral("plane:-17.437,0,0");

} // namespace

class CliProbeTest : public QObject
{
    Q_OBJECT

private:
    QTemporaryDir m_dir;
    using Run = clitest::Run;

    static Run cli(const QStringList &args)
    {
        return clitest::runCli(QStringLiteral(FREZKA_CLI), args, true, 600000);
    }

    static Run zPlate(const QStringList &extra)
    {
        return cli(QStringList{QStringLiteral("probe"), QStringLiteral("z-plate"),
                               QStringLiteral("--surface"), kTop, QStringLiteral("--depth"),
                               QStringLiteral("20"), QStringLiteral("--feed"),
                               QStringLiteral("300"), QStringLiteral("--retract"),
                               QStringLiteral("1")} +
                   extra);
    }

private slots:
    void thePlateSetsTheWorkZeroOnTheTop()
    {
        const Run r = zPlate({QStringLiteral("--plate"), QStringLiteral("1.5"),
                              QStringLiteral("--offset"), QStringLiteral("G55:10,20,3"),
                              QStringLiteral("--offset"), QStringLiteral("G54:1,2,3")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject j = clitest::lastJson(r.out);
        const double trip = j[QStringLiteral("trip_z_mm")].toDouble();
        QVERIFY2(std::abs(trip + 17.437) <= kStepMm, qPrintable(r.out));
        QCOMPARE(j[QStringLiteral("work_offset")].toString(), QStringLiteral("G54"));
        const QJsonArray offset = j[QStringLiteral("offset_mm")].toArray();
        QCOMPARE(offset[0].toDouble(), 1.0); // X and Y as they were
        QCOMPARE(offset[1].toDouble(), 2.0);
        // The work's top 1.5 mm under the plate's is Z 0, within a step of the true top.
        QVERIFY2(std::abs(offset[2].toDouble() - (-17.437 - 1.5)) <= kStepMm, qPrintable(r.out));
        // The tool 1 mm above the plate; below the top only by the fast probe's stop after the
        // trip (its deceleration at 300 mm/min: 12 steps).
        const QJsonArray at = j[QStringLiteral("unit_steps")].toArray();
        QCOMPARE(at[2].toInt(), qRound((trip + 1) * 200));
        QVERIFY2(j[QStringLiteral("unit_lowest_z_steps")].toInt() >= -17.437 * 200 - 20,
                 qPrintable(r.out));
        QVERIFY2(r.err.contains(QStringLiteral("G54 Z is now -18.940 (was 3.000)")),
                 qPrintable(r.err));
        QVERIFY2(r.err.contains(QStringLiteral("the tool stands at Z 2.500")), qPrintable(r.err));
    }

    // With no plate (the tool touches the work): a program engraving 0.1 mm deep at the offset
    // given back cuts 0.1 mm into the simulated top, within a step.
    void aProgramAtTheProbedZeroCutsItsDepth()
    {
        const Run r = zPlate({QStringLiteral("--plate"), QStringLiteral("0")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QString offset = clitest::lastJson(r.out)[QStringLiteral("offset_arg")].toString();
        QVERIFY2(offset.startsWith(QStringLiteral("G54:0.0000,0.0000,")), qPrintable(r.out));
        QVERIFY2(std::abs(offset.split(QLatin1Char(','))[2].toDouble() + 17.437) <= kStepMm,
                 qPrintable(r.out));
        const QString program = clitest::writeFile(
            m_dir, QStringLiteral("line.nc"),
            "G21 G90 G17\nM3 S10000\nG0 X10 Y10 Z1\nG1 Z-0.1 F100\nG1 X40 F300\nG0 Z1\nM5\nM2\n");
        const Run cut = cli({QStringLiteral("run"), program, QStringLiteral("--offset"), offset,
                             QStringLiteral("--surface"), kTop, QStringLiteral("--cut-depth")});
        QVERIFY2(cut.code == 0, qPrintable(cut.err));
        const QJsonObject d = clitest::lastJson(cut.out)[QStringLiteral("cut_depth")].toObject();
        QVERIFY2(d[QStringLiteral("samples")].toInt() > 100, qPrintable(cut.out));
        QVERIFY2(std::abs(d[QStringLiteral("min_mm")].toDouble() - 0.1) <= kStepMm + 1e-9 &&
                     std::abs(d[QStringLiteral("max_mm")].toDouble() - 0.1) <= kStepMm + 1e-9,
                 qPrintable(cut.out));
    }

    // The top 20 mm down, the depth 5: the probe goes down to Z -5, fails, goes back up.
    void aProbeThatNeverTripsStopsWithItsError()
    {
        const Run r =
            cli({QStringLiteral("probe"), QStringLiteral("z-plate"), QStringLiteral("--plate"),
                 QStringLiteral("1"), QStringLiteral("--surface"), QStringLiteral("plane:-20,0,0"),
                 QStringLiteral("--depth"), QStringLiteral("5")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("went down to Z -5.000 without touching the "
                                               "surface")),
                 qPrintable(r.err));
        const QJsonObject j = clitest::lastJson(r.out);
        QVERIFY(j[QStringLiteral("trip_z_mm")].isNull());
        QCOMPARE(j[QStringLiteral("unit_lowest_z_steps")].toInt(), -5 * 200);
        QCOMPARE(j[QStringLiteral("unit_steps")].toArray(), (QJsonArray{0, 0, 0, 0}));
    }

    // The same on a serial line: gve-emu on a pty, probed in real time through the link worker.
    void probesGveEmuOnAPty()
    {
        QProcess emu;
        emu.start(QStringLiteral(GVE_EMU_PATH),
                  {QStringLiteral("--variant"), QStringLiteral("gve64"),
                   QStringLiteral("--surface"), QStringLiteral("plane:-3.21,0,0")});
        QVERIFY(emu.waitForStarted(20000));
        QTRY_VERIFY_WITH_TIMEOUT(emu.canReadLine(), 20000);
        const QString pty = QString::fromLocal8Bit(emu.readLine()).trimmed();
        const Run r =
            cli({QStringLiteral("probe"), QStringLiteral("z-plate"), QStringLiteral("--port"), pty,
                 QStringLiteral("--plate"), QStringLiteral("0.5"), QStringLiteral("--depth"),
                 QStringLiteral("5"), QStringLiteral("--feed"), QStringLiteral("200")});
        emu.terminate();
        emu.waitForFinished(20000);
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject j = clitest::lastJson(r.out);
        QVERIFY2(std::abs(j[QStringLiteral("trip_z_mm")].toDouble() + 3.21) <= kStepMm,
                 qPrintable(r.out));
        QVERIFY2(std::abs(j[QStringLiteral("offset_mm")].toArray()[2].toDouble() + 3.71) <= kStepMm,
                 qPrintable(r.out));
        QVERIFY(j[QStringLiteral("unit_steps")].isNull()); // not the in-process emulator
    }

    void badUsageAndValuesAreRefused()
    {
        QCOMPARE(cli({QStringLiteral("probe")}).code, 2);
        QCOMPARE(cli({QStringLiteral("probe"), QStringLiteral("z-plate")}).code, 2); // no --plate
        const Run neg = zPlate({QStringLiteral("--plate"), QStringLiteral("-1")});
        QCOMPARE(neg.code, 2);
        QVERIFY2(neg.err.contains(QStringLiteral("must be 0 mm or more")), qPrintable(neg.err));
        const Run port =
            cli({QStringLiteral("probe"), QStringLiteral("z-plate"), QStringLiteral("--plate"),
                 QStringLiteral("1"), QStringLiteral("--port"), QStringLiteral("/dev/null"),
                 QStringLiteral("--surface"), kTop});
        QCOMPARE(port.code, 2); // the simulated surface is the in-process emulator's
    }
};

QTEST_GUILESS_MAIN(CliProbeTest)
#include "cli_probe_test.moc"
