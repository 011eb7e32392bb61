// frezka-cli run-line: two GVE114 units on one line, each running its own program at the same
// time, on the in-process emulator and through gve-emu --units on a pty. Each unit's counters end
// exactly where its program ends, as `frezka-cli run` puts a unit alone (its unit_steps), and
// the emulated units' own counters, asked on the pty after the run, say the same.

#include "cliprocess.h"

#include <QJsonArray>
#include <QProcess>
#include <QSerialPort>
#include <QSignalSpy>
#include <QTest>

using clitest::lastJson;
using clitest::runCli;
using clitest::writeFile;

class CliRunLineTest : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void twoJobsOnTheEmulatedLine();
    void twoJobsThroughGveEmuOnOnePty();
    void refusesBadUnits();
    void rotaryTableOnTheEmulatedLine();
    void rotaryTableThroughGveEmuOnOnePty();
    void refusesBadRotaryTables();
    void rotaryTableFromTheProfilesLine();

private:
    QJsonArray aloneSteps(const QString &file);
    void checkUnits(const QJsonObject &report);

    QTemporaryDir m_dir;
    QJsonObject runRotary(const QStringList &extra);
    QString m_a, m_b;
    QString m_rotaryProgram, m_rotaryProfile;
    QJsonArray m_stepsA, m_stepsB;
};

namespace {
const QStringList kProfile{QStringLiteral("--machine"), QStringLiteral("gve114"),
                           QStringLiteral("--work-zero"), QStringLiteral("100,100,-50")};

QByteArray askPty(QSerialPort &port, const QByteArray &command)
{
    QByteArray rx;
    port.write(command);
    QSignalSpy ready(&port, &QSerialPort::readyRead);
    while (!rx.contains('\r')) {
        if (!port.waitForReadyRead(20000))
            return "(no reply)";
        rx += port.readAll();
    }
    return rx;
}
QList<qint64> stepsOf(const QJsonObject &unit)
{
    QList<qint64> out;
    for (const auto &v : unit.value(QStringLiteral("position_steps")).toArray())
        out << static_cast<qint64>(v.toDouble());
    return out;
}
} // namespace

QJsonArray CliRunLineTest::aloneSteps(const QString &file)
{
    const auto r =
        runCli(QStringLiteral(FREZKA_CLI), QStringList{QStringLiteral("run"), file} + kProfile);
    if (r.code != 0)
        qWarning("%s", qPrintable(r.err));
    return lastJson(r.out).value(QStringLiteral("unit_steps")).toArray();
}

void CliRunLineTest::initTestCase()
{
    QVERIFY(m_dir.isValid());
    m_a = writeFile(m_dir, QStringLiteral("a.nc"),
                    "G21 G90\nG0 Z5\nG0 X0 Y0\nG1 Z-1 F600\n"
                    "G1 X40 Y0 F2400\nG2 X40 Y40 I0 J20\nG1 X0 Y40\nG1 X3.3 Y7.7\nM2\n");
    m_b = writeFile(m_dir, QStringLiteral("b.nc"),
                    "G21 G90\nG0 Z5\nG0 X10 Y-10\nG1 Z-2 F500\n"
                    "G1 X-30 Y-20 F1800\nG3 X-30 Y20 I0 J20\nG1 X12.1 Y-5.4\nM2\n");
    // XYZ, A indexing, X Y Z and A together, XYZ, A indexing at the end.
    m_rotaryProgram = writeFile(m_dir, QStringLiteral("rotary.nc"),
                                "G21 G90 G94\nG1 X5 Y5 F3000\nG0 A30\nG1 X10 Y8 Z-1 A60 F600\n"
                                "G1 X12 Y7\nG0 A45\nM2\n");
    m_rotaryProfile = writeFile(m_dir, QStringLiteral("rotary.json"),
                                R"({"unit": {"variant": "gve114", "maxPulseRate": 125000},
            "axes": {"a": {"present": true, "stepsPerMm": 100, "softMaxMm": 90}}})");
    m_stepsA = aloneSteps(m_a);
    m_stepsB = aloneSteps(m_b);
    QCOMPARE(m_stepsA.size(), 4);
    QVERIFY(m_stepsA != m_stepsB);
}

void CliRunLineTest::checkUnits(const QJsonObject &report)
{
    const QJsonArray units = report.value(QStringLiteral("units")).toArray();
    QCOMPARE(units.size(), 2);
    const QJsonObject u0 = units[0].toObject(), u1 = units[1].toObject();
    QCOMPARE(u0.value(QStringLiteral("address")).toInt(), 0);
    QCOMPARE(u1.value(QStringLiteral("address")).toInt(), 1);
    QVERIFY(u0.value(QStringLiteral("ok")).toBool());
    QVERIFY(u1.value(QStringLiteral("ok")).toBool());
    QCOMPARE(u0.value(QStringLiteral("position_steps")).toArray(), m_stepsA);
    QCOMPARE(u1.value(QStringLiteral("position_steps")).toArray(), m_stepsB);
    QVERIFY(u0.value(QStringLiteral("exchanges")).toDouble() > 10);
    QVERIFY(u1.value(QStringLiteral("exchanges")).toDouble() > 10);
    const double s0 = u0.value(QStringLiteral("line_share")).toDouble();
    const double s1 = u1.value(QStringLiteral("line_share")).toDouble();
    QVERIFY(s0 > 0 && s1 > 0);
    QVERIFY(qAbs(report.value(QStringLiteral("line_share")).toDouble() - (s0 + s1)) < 1e-6);
}

void CliRunLineTest::twoJobsOnTheEmulatedLine()
{
    // Unit 1 with a profile of its own (the shipped GVE114 one, named per unit).
    const auto r = runCli(QStringLiteral(FREZKA_CLI),
                          QStringList{QStringLiteral("run-line"), QStringLiteral("--unit"),
                                      QStringLiteral("0:") + m_a, QStringLiteral("--unit"),
                                      QStringLiteral("1:") + m_b + QStringLiteral(":gve114")} +
                              kProfile);
    QVERIFY2(r.code == 0, qPrintable(r.err + r.out));
    checkUnits(lastJson(r.out));
}

void CliRunLineTest::twoJobsThroughGveEmuOnOnePty()
{
    QProcess emu;
    emu.start(QStringLiteral(GVE_EMU_PATH),
              {QStringLiteral("--units"), QStringLiteral("0:gve114,1:gve114")});
    QVERIFY(emu.waitForStarted(20000));
    QTRY_VERIFY_WITH_TIMEOUT(emu.canReadLine(), 20000);
    const QString pty = QString::fromLocal8Bit(emu.readLine()).trimmed();
    const auto r = runCli(QStringLiteral(FREZKA_CLI),
                          QStringList{QStringLiteral("run-line"), QStringLiteral("--unit"),
                                      QStringLiteral("0:") + m_a, QStringLiteral("--unit"),
                                      QStringLiteral("1:") + m_b, QStringLiteral("--port"), pty} +
                              kProfile);
    QVERIFY2(r.code == 0, qPrintable(r.err + r.out));
    checkUnits(lastJson(r.out));
    // The emulated units' own counters (checksums are still on: the CLI left them so).
    QSerialPort port(pty);
    port.setBaudRate(115200);
    QVERIFY(port.open(QIODevice::ReadWrite));
    auto steps = [](const QJsonArray &a) {
        QStringList s;
        for (const auto &v : a)
            s << QString::number(static_cast<qint64>(v.toDouble()));
        return s.join(QLatin1Char(','));
    };
    // A reply to the CLI's last poll may still be on its way: let it pass first.
    while (port.waitForReadyRead(300))
        port.readAll();
    QVERIFY(askPty(port, "!0%-,CF\r").startsWith('0'));
    QVERIFY(askPty(port, "!1%-,D0\r").startsWith('0'));
    QCOMPARE(QString::fromLatin1(askPty(port, "!0P4\r")),
             QStringLiteral("0,") + steps(m_stepsA) + QLatin1Char('\r'));
    QCOMPARE(QString::fromLatin1(askPty(port, "!1P4\r")),
             QStringLiteral("0,") + steps(m_stepsB) + QLatin1Char('\r'));
    port.close();
    emu.terminate();
    emu.waitForFinished(20000);
}

void CliRunLineTest::refusesBadUnits()
{
    auto r =
        runCli(QStringLiteral(FREZKA_CLI),
               {QStringLiteral("run-line"), QStringLiteral("--unit"), QStringLiteral("0:") + m_a,
                QStringLiteral("--unit"), QStringLiteral("0:") + m_b});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(QStringLiteral("twice")), qPrintable(r.err));
    r = runCli(QStringLiteral(FREZKA_CLI),
               {QStringLiteral("run-line"), QStringLiteral("--unit"), QStringLiteral("7:") + m_a});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(QStringLiteral("0..6")), qPrintable(r.err));
    // Only a GVE114 is ordered with another address: a GVE64 profile for unit 1 is refused.
    r = runCli(QStringLiteral(FREZKA_CLI),
               QStringList{QStringLiteral("run-line"), QStringLiteral("--unit"),
                           QStringLiteral("0:") + m_a, QStringLiteral("--unit"),
                           QStringLiteral("1:") + m_b + QStringLiteral(":gve64")} +
                   kProfile);
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(QStringLiteral("address 0 only")), qPrintable(r.err));
}

// One program on the machine's unit (X Y Z) and a rotary table's unit at address 1 (A): both
// end at exact counters, every sync point was passed, and each unit waited for the other.
QJsonObject CliRunLineTest::runRotary(const QStringList &extra)
{
    const auto r = runCli(QStringLiteral(FREZKA_CLI),
                          QStringList{QStringLiteral("run-line"), QStringLiteral("--machine"),
                                      QStringLiteral("gve114"), QStringLiteral("--rotary-a"),
                                      QStringLiteral("1:") + m_rotaryProfile} +
                              extra + QStringList{m_rotaryProgram});
    if (r.code != 0)
        qWarning("%s", qPrintable(r.err + r.out));
    const QJsonObject report = lastJson(r.out);
    const QJsonArray units = report.value(QStringLiteral("units")).toArray();
    if (units.size() != 2)
        return {};
    const QJsonObject u0 = units[0].toObject(), u1 = units[1].toObject();
    if (!u0.value(QStringLiteral("ok")).toBool() || !u1.value(QStringLiteral("ok")).toBool() ||
        stepsOf(u0) != QList<qint64>{4800, 2800, -400, 0} ||
        stepsOf(u1) != QList<qint64>{0, 0, 0, 4500} ||
        u0.value(QStringLiteral("role")).toString() != QStringLiteral("machine") ||
        u1.value(QStringLiteral("role")).toString() != QStringLiteral("rotaryA") ||
        u0.value(QStringLiteral("sync_waits")).toDouble() < 1 ||
        u1.value(QStringLiteral("sync_waits")).toDouble() < 1 ||
        u1.value(QStringLiteral("vectors")).toDouble() != 3) {
        qWarning("%s", qPrintable(r.out));
        return {};
    }
    return report;
}

void CliRunLineTest::rotaryTableOnTheEmulatedLine()
{
    const QJsonObject report = runRotary({});
    QVERIFY(!report.isEmpty());
    // Before A30, before and after the joint block, before and after A45.
    QCOMPARE(report.value(QStringLiteral("sync_points")).toInt(), 5);
}

// The machine's profile lists the rotary table on its line (line.units, role rotaryA, its own
// profile beside it): run-line FILE runs the same two-unit job without --rotary-a.
void CliRunLineTest::rotaryTableFromTheProfilesLine()
{
    const QString profile = writeFile(m_dir, QStringLiteral("line.json"), R"({
        "unit": {"variant": "gve114"},
        "line": {"units": [
            {"address": 0, "variant": "gve114", "name": "Mill", "role": "machine"},
            {"address": 1, "variant": "gve114", "name": "Table", "role": "rotaryA",
             "profile": "rotary.json"}]}})");
    const auto r =
        runCli(QStringLiteral(FREZKA_CLI),
               {QStringLiteral("run-line"), QStringLiteral("--machine"), profile, m_rotaryProgram});
    QVERIFY2(r.code == 0, qPrintable(r.err + r.out));
    const QJsonObject report = lastJson(r.out);
    const QJsonArray units = report.value(QStringLiteral("units")).toArray();
    QCOMPARE(units.size(), 2);
    QCOMPARE(units[1].toObject().value(QStringLiteral("role")).toString(),
             QStringLiteral("rotaryA"));
    QCOMPARE(stepsOf(units[0].toObject()), (QList<qint64>{4800, 2800, -400, 0}));
    QCOMPARE(stepsOf(units[1].toObject()), (QList<qint64>{0, 0, 0, 4500}));
    QCOMPARE(report.value(QStringLiteral("sync_points")).toInt(), 5);
}

void CliRunLineTest::rotaryTableThroughGveEmuOnOnePty()
{
    QProcess emu;
    emu.start(QStringLiteral(GVE_EMU_PATH),
              {QStringLiteral("--units"), QStringLiteral("0:gve114,1:gve114")});
    QVERIFY(emu.waitForStarted(20000));
    QTRY_VERIFY_WITH_TIMEOUT(emu.canReadLine(), 20000);
    const QString pty = QString::fromLocal8Bit(emu.readLine()).trimmed();
    const QJsonObject report = runRotary({QStringLiteral("--port"), pty});
    QVERIFY(!report.isEmpty());
    QCOMPARE(report.value(QStringLiteral("sync_points")).toInt(), 5);
    QSerialPort port(pty);
    port.setBaudRate(115200);
    QVERIFY(port.open(QIODevice::ReadWrite));
    while (port.waitForReadyRead(300))
        port.readAll();
    QVERIFY(askPty(port, "!0%-,CF\r").startsWith('0'));
    QVERIFY(askPty(port, "!1%-,D0\r").startsWith('0'));
    QCOMPARE(askPty(port, "!0P4\r"), QByteArray("0,4800,2800,-400,0\r"));
    QCOMPARE(askPty(port, "!1P4\r"), QByteArray("0,0,0,0,4500\r"));
    port.close();
    emu.terminate();
    emu.waitForFinished(20000);
}

void CliRunLineTest::refusesBadRotaryTables()
{
    const QStringList base{QStringLiteral("run-line"), QStringLiteral("--machine"),
                           QStringLiteral("gve114")};
    // The shipped GVE114 profile has no A axis: the rotary unit needs its own.
    auto r = runCli(
        QStringLiteral(FREZKA_CLI),
        base + QStringList{QStringLiteral("--rotary-a"), QStringLiteral("1"), m_rotaryProgram});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(QStringLiteral("no A axis")), qPrintable(r.err));
    // A program with A and no rotary unit: refused by the planner, as for one unit.
    r = runCli(QStringLiteral(FREZKA_CLI),
               base +
                   QStringList{QStringLiteral("--unit"), QStringLiteral("0:") + m_rotaryProgram});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(QStringLiteral("axis A")), qPrintable(r.err));
    // A's soft limits are the rotary unit's (0..90 degrees), checked before the run.
    const QString far = writeFile(m_dir, QStringLiteral("far.nc"), "G21 G90\nG0 A120\nM2\n");
    r = runCli(QStringLiteral(FREZKA_CLI),
               base + QStringList{QStringLiteral("--rotary-a"),
                                  QStringLiteral("1:") + m_rotaryProfile, far});
    QCOMPARE(r.code, 1);
    QVERIFY2(r.err.contains(QStringLiteral("far.nc:2")) &&
                 r.err.contains(QStringLiteral("soft limits")),
             qPrintable(r.err));
    QVERIFY2(!r.out.contains(QStringLiteral("units")), qPrintable(r.out)); // nothing ran
    // The rotary unit's address must differ from the machine's unit's.
    r = runCli(QStringLiteral(FREZKA_CLI),
               base + QStringList{QStringLiteral("--rotary-a"),
                                  QStringLiteral("0:") + m_rotaryProfile, m_rotaryProgram});
    QCOMPARE(r.code, 2);
    QVERIFY2(r.err.contains(QStringLiteral("1..6")), qPrintable(r.err));
}

QTEST_GUILESS_MAIN(CliRunLineTest)
#include "cli_runline_test.moc"
