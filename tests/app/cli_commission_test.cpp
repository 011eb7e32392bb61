// frezka-cli commission against gve-emu on a pseudo-terminal (issue 21, done-when 1): without
// a terminal on standard input the assistant runs the steps that move nothing, lists the ones
// it skipped and writes the report, for each variant; a unit started with a different reading
// (a wrong checksum answered 5, not 4) gets a report that says that reading did not hold.
// Afterwards the test asks the emulator itself what the assistant left behind: nothing moved,
// checksums off again.

#include "cliprocess.h"

#include "machine/machineconfig.h"

#include <QFile>
#include <QProcess>
#include <QSerialPort>
#include <QSignalSpy>
#include <QTest>

namespace {

constexpr int kPatienceMs = 20000;

class Emulator
{
public:
    explicit Emulator(const QStringList &args)
    {
        m_process.start(QStringLiteral(GVE_EMU_PATH), args);
        m_process.waitForStarted(kPatienceMs);
        QTRY_VERIFY_WITH_TIMEOUT(m_process.canReadLine(), kPatienceMs);
        path = QString::fromLocal8Bit(m_process.readLine()).trimmed();
    }
    ~Emulator()
    {
        m_process.terminate();
        m_process.waitForFinished(kPatienceMs);
    }
    // One command straight to the unit after the CLI has let go of the terminal.
    QByteArray ask(const QByteArray &command)
    {
        QSerialPort port(path);
        port.setBaudRate(115200);
        if (!port.open(QIODevice::ReadWrite))
            return "cannot open: " + port.errorString().toUtf8();
        port.write(command);
        QByteArray rx;
        QSignalSpy ready(&port, &QSerialPort::readyRead);
        while (!rx.contains('\r') && ready.wait(kPatienceMs))
            rx += port.readAll();
        return rx;
    }
    QString path;

private:
    QProcess m_process;
};

QString readAll(const QString &path)
{
    QFile f(path);
    f.open(QIODevice::ReadOnly);
    return QString::fromUtf8(f.readAll());
}

} // namespace

class CliCommissionTest : public QObject
{
    Q_OBJECT

private slots:
    void eachVariantWithoutTerminal_data();
    void eachVariantWithoutTerminal();
    void aReadingThatDoesNotHold();
    void anOlderFirmware();
    void anotherUnitThanTheProfiles();
    void aSlowerLinkThanTheProfile();
    void refusesToOverwriteTheProfile();
};

void CliCommissionTest::eachVariantWithoutTerminal_data()
{
    QTest::addColumn<QString>("variant");
    QTest::addColumn<QString>("firmware");
    QTest::addColumn<QString>("stepsMoved"); // an axis step that must be listed as skipped
    QTest::newRow("gve84") << "gve84"
                           << "IP84 v3 27.1.2010"
                           << "Move axis Z";
    QTest::newRow("gve64") << "gve64"
                           << "IP64MPG v19 10.9.2010"
                           << "Move axis Z";
    QTest::newRow("gve114") << "gve114"
                            << "IP114/500 x16 16.9.2018"
                            << "Move axis Z";
}

void CliCommissionTest::eachVariantWithoutTerminal()
{
    QFETCH(QString, variant);
    QFETCH(QString, firmware);
    QFETCH(QString, stepsMoved);
    Emulator emu({QStringLiteral("--variant"), variant});
    QVERIFY2(emu.path.startsWith(QLatin1String("/dev/pts/")), qPrintable(emu.path));
    QTemporaryDir dir;
    const QString report = dir.filePath(QStringLiteral("report.txt"));
    const QString profileOut = dir.filePath(QStringLiteral("out.json"));
    const auto run =
        clitest::runCli(QStringLiteral(FREZKA_CLI),
                        {QStringLiteral("commission"), QStringLiteral("--port"), emu.path,
                         QStringLiteral("--machine"), variant, QStringLiteral("--report"), report,
                         QStringLiteral("--profile-out"), profileOut});
    QVERIFY2(run.code == 0, qPrintable(run.out + run.err));
    // The steps that move were not run, and the output says so.
    QVERIFY2(run.out.contains(QLatin1String("Skipped (they move or need the operator):")),
             qPrintable(run.out));
    QVERIFY2(run.out.contains(QStringLiteral("  ") + stepsMoved), qPrintable(run.out));
    QVERIFY(run.out.contains(QLatin1String("  Home the machine")));
    const QString text = readAll(report);
    QVERIFY2(text.contains(QStringLiteral("firmware: ") + firmware), qPrintable(text));
    QVERIFY2(text.contains(QLatin1String("[held] Identify the unit")), qPrintable(text));
    QVERIFY(text.contains(QLatin1String("[held] Check the protocol readings")));
    // The emulator's factory EEPROM is not the shipped profile's: read, decoded, compared.
    QVERIFY(text.contains(QLatin1String("[did not hold] Read the EEPROM")));
    QVERIFY(text.contains(QLatin1String("0x05 STEP/DIR polarity: unit FF, profile FF - same")));
    QVERIFY(text.contains(QStringLiteral("[skipped] ") + stepsMoved));
    QVERIFY(text.contains(QStringLiteral(
        "[held] §2.1, §8 a command with a wrong checksum is answered 4 and does not advance")));
    QVERIFY(text.contains(QStringLiteral("[held] §2.2 a packet is answered once")));
    QVERIFY(!text.contains(QLatin1String("[did not hold] Identify")));
    QVERIFY(!text.contains(QLatin1String("[did not hold] Check")));
    QVERIFY(!text.contains(QStringLiteral("[did not hold] §")));
    QVERIFY(text.contains(QLatin1String("link.latencyMs: profile 8.0, proposed")));
    // The trace is attached: the deliberately wrong checksum went over the line, and no
    // command that moves or switches anything did.
    QVERIFY(text.contains(QLatin1String("Serial trace")));
    QVERIFY(text.contains(QLatin1String("!0%+")));
    for (const char *moving : {"!0C", "!0W", "!7V", "!0O0", "!0L1", "!0L-"})
        QVERIFY2(!text.contains(QLatin1String(moving)), moving);
    // The updated profile carries the proposed latency, not the original's 8 ms.
    const QString json = readAll(profileOut);
    QVERIFY2(json.contains(QLatin1String("\"latencyMs\"")) &&
                 !json.contains(QLatin1String("\"latencyMs\": 8")),
             qPrintable(json));
    // The unit: not moved, and checksums off again as after a reset.
    QCOMPARE(emu.ask(variant == QLatin1String("gve84") ? "!0PF\r" : "!0P4\r"),
             QByteArray(variant == QLatin1String("gve84") ? "0,0,0,0\r" : "0,0,0,0,0\r"));
}

void CliCommissionTest::aReadingThatDoesNotHold()
{
    Emulator emu({QStringLiteral("--variant"), QStringLiteral("gve64"),
                  QStringLiteral("--bad-checksum-code"), QStringLiteral("5")});
    QTemporaryDir dir;
    const QString report = dir.filePath(QStringLiteral("report.txt"));
    const auto run = clitest::runCli(QStringLiteral(FREZKA_CLI),
                                     {QStringLiteral("commission"), QStringLiteral("--port"),
                                      emu.path, QStringLiteral("--machine"),
                                      QStringLiteral("gve64"), QStringLiteral("--report"), report});
    QCOMPARE(run.code, 1);
    const QString text = readAll(report);
    QVERIFY2(text.contains(QLatin1String("[did not hold] Check the protocol readings")),
             qPrintable(text));
    QVERIFY2(text.contains(QStringLiteral("[did not hold] §2.1, §8 a command with a wrong "
                                          "checksum is answered 4")),
             qPrintable(text));
    // What the unit answered is in the report's line for it.
    QVERIFY(text.contains(QLatin1String("!0F,")) && text.contains(QLatin1String("-> 5")));
    // The other readings still held.
    QVERIFY(text.contains(QStringLiteral("[held] §8 > repeats the last reply")));
}

// A GVE64 with firmware v9 against the shipped v19 profile: the identification says so, the
// EEPROM float reading cannot be checked on it (no EFR/EUR), the rest still holds.
void CliCommissionTest::anOlderFirmware()
{
    Emulator emu({QStringLiteral("--variant"), QStringLiteral("gve64"),
                  QStringLiteral("--firmware"), QStringLiteral("IP64MPG v9 1.2.2009")});
    QTemporaryDir dir;
    const QString report = dir.filePath(QStringLiteral("report.txt"));
    const auto run = clitest::runCli(QStringLiteral(FREZKA_CLI),
                                     {QStringLiteral("commission"), QStringLiteral("--port"),
                                      emu.path, QStringLiteral("--machine"),
                                      QStringLiteral("gve64"), QStringLiteral("--report"), report});
    QCOMPARE(run.code, 1);
    const QString text = readAll(report);
    QVERIFY2(text.contains(QLatin1String("[did not hold] Identify the unit")), qPrintable(text));
    QVERIFY(text.contains(QLatin1String("the firmware is v9, the profile says v19")));
    QVERIFY(text.contains(
        QStringLiteral("[not checked] §12 float and 32-bit EEPROM values travel as decimal text")));
    QVERIFY(text.contains(QLatin1String("[held] Check the protocol readings")));
}

// A GVE114 on the line of a GVE64 profile: both have four axes and the spindle at address 7,
// but the queue, the rates and the EEPROM differ, so the identification does not hold.
void CliCommissionTest::anotherUnitThanTheProfiles()
{
    Emulator emu({QStringLiteral("--variant"), QStringLiteral("gve114")});
    QTemporaryDir dir;
    const QString report = dir.filePath(QStringLiteral("report.txt"));
    const auto run = clitest::runCli(QStringLiteral(FREZKA_CLI),
                                     {QStringLiteral("commission"), QStringLiteral("--port"),
                                      emu.path, QStringLiteral("--machine"),
                                      QStringLiteral("gve64"), QStringLiteral("--report"), report});
    QCOMPARE(run.code, 1);
    const QString text = readAll(report);
    QVERIFY2(text.contains(QLatin1String("[did not hold] Identify the unit")), qPrintable(text));
    QVERIFY(text.contains(QLatin1String("the unit is a GVE114, the profile is for a GVE64")));
}

// An adapter slower than the profile's 8 ms each way (the emulator adds 12 ms each way): the
// link step says so and the updated profile carries at least the added latency (only a lower
// bound: a loaded machine can only add to it).
void CliCommissionTest::aSlowerLinkThanTheProfile()
{
    Emulator emu({QStringLiteral("--variant"), QStringLiteral("gve64"), QStringLiteral("--latency"),
                  QStringLiteral("12")});
    QTemporaryDir dir;
    const QString report = dir.filePath(QStringLiteral("report.txt"));
    const QString out = dir.filePath(QStringLiteral("out.json"));
    const auto run =
        clitest::runCli(QStringLiteral(FREZKA_CLI),
                        {QStringLiteral("commission"), QStringLiteral("--port"), emu.path,
                         QStringLiteral("--machine"), QStringLiteral("gve64"),
                         QStringLiteral("--report"), report, QStringLiteral("--profile-out"), out});
    QCOMPARE(run.code, 1);
    const QString text = readAll(report);
    QVERIFY2(text.contains(QLatin1String("[did not hold] Measure the link")), qPrintable(text));
    QVERIFY(text.contains(QLatin1String("The link is slower than the profile says")));
    QVERIFY(text.contains(QLatin1String("[held] Check the protocol readings")));
    const auto saved = frezka::machine::loadMachineConfig(out.toStdString());
    QVERIFY(saved.config);
    QVERIFY2(saved.config->link.latencyMs >= 12.0,
             qPrintable(QString::number(saved.config->link.latencyMs)));
}

void CliCommissionTest::refusesToOverwriteTheProfile()
{
    Emulator emu({QStringLiteral("--variant"), QStringLiteral("gve64")});
    QTemporaryDir dir;
    QFile::copy(QStringLiteral(FREZKA_SOURCE_DIR "/resources/machines/gve64.json"),
                dir.filePath(QStringLiteral("mill.json")));
    const QString profile = dir.filePath(QStringLiteral("mill.json"));
    const QByteArray before = readAll(profile).toUtf8();
    const auto run = clitest::runCli(
        QStringLiteral(FREZKA_CLI),
        {QStringLiteral("commission"), QStringLiteral("--port"), emu.path,
         QStringLiteral("--machine"), profile, QStringLiteral("--report"),
         dir.filePath(QStringLiteral("r.txt")), QStringLiteral("--profile-out"), profile});
    QCOMPARE(run.code, 1);
    QVERIFY2(run.err.contains(QLatin1String("name a new file")), qPrintable(run.err));
    QCOMPARE(readAll(profile).toUtf8(), before);
    QVERIFY(QFile::exists(dir.filePath(QStringLiteral("r.txt"))));
}

QTEST_GUILESS_MAIN(CliCommissionTest)
#include "cli_commission_test.moc"
