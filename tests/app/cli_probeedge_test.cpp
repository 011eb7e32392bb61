// frezka-cli probe edge / probe corner (issue 19 item 2) on the in-process emulator with a
// simulated work block (--surface block:..., its sides trip the probe exactly; given a tool
// radius larger than the work, as the emulator's probe is the tool's centre): the edge is found
// within a motor step with the tool's radius taken into account, the active offset's X or Y
// puts it at 0 (the other axes as they were), the tool ends back where it started on the
// unit's counters; an outside corner with --reach; a program's X0 Y0 at the offset given back
// ends on the corner; a probe that never touches fails with its error and sets nothing; bad
// usage is refused.

#include "cliprocess.h"

#include <QJsonArray>
#include <QJsonObject>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>

namespace {

constexpr double kStepMm = 1.0 / 200; // the shipped GVE64 profile: 200 steps/mm

} // namespace

class CliProbeEdgeTest : public QObject
{
    Q_OBJECT

private:
    using Run = clitest::Run;

    static Run cli(const QStringList &args)
    {
        return clitest::runCli(QStringLiteral(FREZKA_CLI), args, true, 600000);
    }

private slots:
    // The tool (6 mm) at machine X 0 beside a block whose face is at X 12.34: its centre
    // touches at 9.34.
    void anEdgeSetsItsAxisZero()
    {
        const Run r =
            cli({QStringLiteral("probe"), QStringLiteral("edge"), QStringLiteral("--axis"),
                 QStringLiteral("x"), QStringLiteral("--direction"), QStringLiteral("+"),
                 QStringLiteral("--tool-diameter"), QStringLiteral("6"), QStringLiteral("--travel"),
                 QStringLiteral("20"), QStringLiteral("--surface"),
                 QStringLiteral("block:9.34,-50,80,50,5"), QStringLiteral("--offset"),
                 QStringLiteral("G54:1,2,3")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject j = clitest::lastJson(r.out);
        QVERIFY2(std::abs(j[QStringLiteral("trip_x_mm")].toDouble() - 9.34) <= kStepMm,
                 qPrintable(r.out));
        const QJsonArray offset = j[QStringLiteral("offset_mm")].toArray();
        QVERIFY2(std::abs(offset[0].toDouble() - 12.34) <= kStepMm, qPrintable(r.out));
        QCOMPARE(offset[1].toDouble(), 2.0);
        QCOMPARE(offset[2].toDouble(), 3.0);
        QCOMPARE(j[QStringLiteral("unit_steps")].toArray(), (QJsonArray{0, 0, 0, 0}));
        QVERIFY2(r.err.contains(QStringLiteral("the edge is the work's zero")), qPrintable(r.err));
    }

    // An outside corner at (7, 8) with a 4 mm tool, the tool off its diagonal at (0, 0): each
    // probe reaches 15 mm along the other axis first. A program's X0 Y0 at that offset then
    // ends on the corner.
    void anOutsideCornerSetsXAndY()
    {
        const Run r =
            cli({QStringLiteral("probe"), QStringLiteral("corner"), QStringLiteral("--x-direction"),
                 QStringLiteral("+"), QStringLiteral("--y-direction"), QStringLiteral("+"),
                 QStringLiteral("--tool-diameter"), QStringLiteral("4"), QStringLiteral("--reach"),
                 QStringLiteral("15"), QStringLiteral("--surface"),
                 QStringLiteral("block:5,6,90,90,5")});
        QVERIFY2(r.code == 0, qPrintable(r.err));
        const QJsonObject j = clitest::lastJson(r.out);
        const QJsonObject edge = j[QStringLiteral("edge_mm")].toObject();
        QVERIFY2(std::abs(edge[QStringLiteral("x")].toDouble() - 7) <= kStepMm, qPrintable(r.out));
        QVERIFY2(std::abs(edge[QStringLiteral("y")].toDouble() - 8) <= kStepMm, qPrintable(r.out));
        QCOMPARE(j[QStringLiteral("unit_steps")].toArray(), (QJsonArray{0, 0, 0, 0}));
        QTemporaryDir dir;
        const QString program =
            clitest::writeFile(dir, QStringLiteral("zero.nc"), "G21 G90\nG0 X0 Y0\nM2\n");
        const Run run = cli({QStringLiteral("run"), program, QStringLiteral("--offset"),
                             j[QStringLiteral("offset_arg")].toString()});
        QVERIFY2(run.code == 0, qPrintable(run.err));
        const QJsonArray end = clitest::lastJson(run.out)[QStringLiteral("unit_steps")].toArray();
        QCOMPARE(end[0].toInt(), 7 * 200);
        QCOMPARE(end[1].toInt(), 8 * 200);
    }

    // Without the reach the Y probe passes beside the block: it never touches.
    void aProbeThatNeverTouchesSetsNothing()
    {
        const Run r =
            cli({QStringLiteral("probe"), QStringLiteral("edge"), QStringLiteral("--axis"),
                 QStringLiteral("y"), QStringLiteral("--direction"), QStringLiteral("+"),
                 QStringLiteral("--tool-diameter"), QStringLiteral("6"), QStringLiteral("--travel"),
                 QStringLiteral("20"), QStringLiteral("--surface"),
                 QStringLiteral("block:3,10,80,50,5")});
        QCOMPARE(r.code, 1);
        QVERIFY2(r.err.contains(QStringLiteral("moved from Y 0.000 to Y 20.000 without touching "
                                               "the edge")),
                 qPrintable(r.err));
        const QJsonObject j = clitest::lastJson(r.out);
        QVERIFY(j[QStringLiteral("offset_arg")].isNull());
        QCOMPARE(j[QStringLiteral("unit_steps")].toArray(), (QJsonArray{0, 0, 0, 0}));
    }

    void badUsageIsRefused()
    {
        const QStringList edge{QStringLiteral("probe"), QStringLiteral("edge")};
        QCOMPARE(cli(edge).code, 2);
        QCOMPARE(cli(edge + QStringList{QStringLiteral("--axis"), QStringLiteral("z"),
                                        QStringLiteral("--direction"), QStringLiteral("+"),
                                        QStringLiteral("--tool-diameter"), QStringLiteral("6")})
                     .code,
                 2);
        QCOMPARE(cli(edge + QStringList{QStringLiteral("--axis"), QStringLiteral("x"),
                                        QStringLiteral("--direction"), QStringLiteral("+")})
                     .code,
                 2); // no diameter
        const Run neg =
            cli({QStringLiteral("probe"), QStringLiteral("corner"), QStringLiteral("--x-direction"),
                 QStringLiteral("+"), QStringLiteral("--y-direction"), QStringLiteral("-"),
                 QStringLiteral("--tool-diameter"), QStringLiteral("6"), QStringLiteral("--reach"),
                 QStringLiteral("-1")});
        QCOMPARE(neg.code, 2);
        QVERIFY2(neg.err.contains(QStringLiteral("--reach -1")), qPrintable(neg.err));
    }
};

QTEST_GUILESS_MAIN(CliProbeEdgeTest)
#include "cli_probeedge_test.moc"
