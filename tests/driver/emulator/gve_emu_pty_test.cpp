// A real pty round trip: gve-emu runs as a child process and is spoken to through QSerialPort,
// exactly as the application talks to hardware. Checks the manuals' own examples byte-exactly.
//
// CI runs this on a loaded 2-core machine next to other tests: every wait has a generous ceiling
// (kPatienceMs) that only matters when something is really broken, replies are assembled from
// however many reads they arrive in, and nothing depends on how fast either process runs.

#include <csignal>

#include <QElapsedTimer>
#include <QFile>
#include <QFileInfo>
#include <QProcess>
#include <QSerialPort>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>

namespace {

// Ceiling of every wait for the emulator: generous for a loaded machine, reached only on failure.
constexpr int kPatienceMs = 20000;

} // namespace

class GveEmuPtyTest : public QObject
{
    Q_OBJECT

private slots:
    void init();
    void cleanup();
    void manualExamplesGve64();
    void checksummedPacketGve64();
    void queueCapacityAndHaltOverThePty();
    void exitsCleanlyOnSigint();
    void optionsShapeTheUnit();
    void rejectsBadOptions();
    void surfaceTouchesTheProbe();
    void wheelFromStdinMovesByTheEeprom();
    void comSwitchSetsTheLineSpeed();
    void twoUnitsShareOnePty();

private:
    QByteArray ask(const QByteArray &command);
    bool waitUntilDrained();
    void start(const QStringList &args);

    QProcess *m_process = nullptr;
    QSerialPort *m_port = nullptr;
    QByteArray m_rx;
};

void GveEmuPtyTest::start(const QStringList &args)
{
    m_process = new QProcess(this);
    m_process->setProgram(QStringLiteral(GVE_EMU_PATH));
    m_process->setArguments(args);
    m_process->start();
    QVERIFY(m_process->waitForStarted(kPatienceMs));
    QTRY_VERIFY_WITH_TIMEOUT(m_process->canReadLine(), kPatienceMs);
    const QString path = QString::fromLocal8Bit(m_process->readLine()).trimmed();
    QVERIFY2(path.startsWith(QLatin1String("/dev/pts/")), qPrintable(path));
    m_port = new QSerialPort(path, this);
    m_port->setBaudRate(115200);
    QVERIFY2(m_port->open(QIODevice::ReadWrite), qPrintable(m_port->errorString()));
    connect(m_port, &QSerialPort::readyRead, this, [this] { m_rx += m_port->readAll(); });
}

void GveEmuPtyTest::init()
{
    m_rx.clear();
}

void GveEmuPtyTest::cleanup()
{
    delete m_port;
    m_port = nullptr;
    if (m_process) {
        m_process->terminate();
        m_process->waitForFinished(kPatienceMs);
        delete m_process;
        m_process = nullptr;
    }
}

QByteArray GveEmuPtyTest::ask(const QByteArray &command)
{
    QSignalSpy readyRead(m_port, &QSerialPort::readyRead);
    m_port->write(command);
    QElapsedTimer clock;
    clock.start();
    // A reply may come in several reads (m_rx collects them); wait until its CR is in.
    while (!m_rx.contains('\r')) {
        const qint64 left = kPatienceMs - clock.elapsed();
        if (left <= 0 || !readyRead.wait(static_cast<int>(left)))
            return "(no reply within " + QByteArray::number(kPatienceMs / 1000) + " s)";
    }
    const auto cr = m_rx.indexOf('\r');
    const QByteArray reply = m_rx.left(cr + 1);
    m_rx.remove(0, cr + 1);
    return reply;
}

// The manual's way to learn that the queue has run out: L0,0,0 is refused (1) until it is empty.
bool GveEmuPtyTest::waitUntilDrained()
{
    QElapsedTimer clock;
    clock.start();
    while (clock.elapsed() < 3 * kPatienceMs) {
        const QByteArray r = ask("!0L0,0,0\r");
        if (r == "0\r")
            return true;
        if (r != "1\r")
            return false;
        QTest::qWait(10); // poll, as a driver would, without flooding the line
    }
    return false;
}

void GveEmuPtyTest::manualExamplesGve64()
{
    start({QStringLiteral("--variant"), QStringLiteral("gve64")});
    QCOMPARE(ask("!0?\r"), QByteArray("0,IP64MPG v19 10.9.2010\r"));
    QCOMPARE(ask("!0Q\r"), QByteArray("0,25020304\r"));
    QCOMPARE(ask("!0Y-\r"), QByteArray("0,Y-\r"));
    QCOMPARE(ask("!0V20000\r"), QByteArray("0\r"));
    QCOMPARE(ask("!0L1000,0,0\r"), QByteArray("0\r"));
    // L is accepted only on an empty queue: poll with L0,0,0 until the move has ended.
    QVERIFY(waitUntilDrained());
    QCOMPARE(ask("!0NX-1000\r"), QByteArray("0\r"));
    QCOMPARE(ask("!0NY2000\r"), QByteArray("0\r"));
    QCOMPARE(ask("!0NZ50\r"), QByteArray("0\r"));
    QCOMPARE(ask("!0PF\r"), QByteArray("0,-1000,2000,50\r"));
    QCOMPARE(ask("!0SW8,F1\r"), QByteArray("5\r"));
    QCOMPARE(ask("!0SW2,2B\r"), QByteArray("0\r"));
    QCOMPARE(ask("!0SR2\r"), QByteArray("0,2B\r"));
    QCOMPARE(ask("!0H\r"), QByteArray("8\r"));
    QCOMPARE(ask("!0V1000\r"), QByteArray("8\r"));
    QCOMPARE(ask("!0G\r"), QByteArray("6\r")); // INTA cleared, nothing left to run
    QCOMPARE(ask("!0%+\r"), QByteArray("0,5C\r"));
    QCOMPARE(ask("!0A100,4F\r"), QByteArray("0,5C\r"));
    QCOMPARE(ask("!0%-,CF\r"), QByteArray("0\r"));
}

void GveEmuPtyTest::checksummedPacketGve64()
{
    start({QStringLiteral("--variant"), QStringLiteral("gve64")});
    QCOMPARE(ask("!0Y-\r"), QByteArray("0,Y-\r"));
    QCOMPARE(ask("!0V20000\r"), QByteArray("0\r")); // keep the test short
    QCOMPARE(ask("!0A500\r"), QByteArray("0\r"));
    QCOMPARE(ask("!0%+\r"), QByteArray("0,5C\r"));
    // The manuals' packet, byte for byte: one reply at the end. One write, so that a stall of
    // this process cannot open a gap between the lines longer than the unit's watchdog.
    QCOMPARE(ask("!0*S,FA\r!0C697,30,0,51\r!0C692,92,0,54\r!0C682,151,0,7F\r"
                 "!0C665,209,0,84\r!0C645,268,0,87\r!0C619,322,0,7F\r!0C589,375,0,8D\r"
                 "!0C553,425,0,80\r!0C515,471,0,7F\r!0C471,515,0,7F\r!0*E10,4D\r"),
             QByteArray("0,10,E9\r"));
    QCOMPARE(ask("!0%-,CF\r"), QByteArray("0\r"));
    QVERIFY(waitUntilDrained());
    QCOMPARE(ask("!0PF\r"), QByteArray("0,6128,2858,0\r"));
}

void GveEmuPtyTest::queueCapacityAndHaltOverThePty()
{
    start({QStringLiteral("--variant"), QStringLiteral("gve84")});
    QCOMPARE(ask("!0V10\r"), QByteArray("0\r"));
    // At 10 pulses/s the first vector takes 10^5 s: however slowly this machine fills the queue,
    // nothing leaves it meanwhile.
    int accepted = 0;
    for (;;) {
        const QByteArray r = ask("!0C1000000,20,0\r");
        if (r != "0\r") {
            QCOMPARE(r, QByteArray("1\r")); // the manual's "vector not accepted"
            break;
        }
        ++accepted;
        QVERIFY(accepted <= 64);
    }
    QCOMPARE(accepted, 64);
    QCOMPARE(ask("!0F\r"), QByteArray("0,60\r")); // RUN + queue full
    QCOMPARE(ask("!0H\r"), QByteArray("8\r"));
    QCOMPARE(ask("!0SR6\r"), QByteArray("8,D0\r")); // INTA, RUN (vectors left), INTCOM
    QCOMPARE(ask("!0D\r"), QByteArray("0\r"));
    QCOMPARE(ask("!0SR6\r"), QByteArray("0,00\r"));
}

void GveEmuPtyTest::exitsCleanlyOnSigint()
{
    start({});
    QCOMPARE(ask("!0?\r"), QByteArray("0,IP64MPG v19 10.9.2010\r"));
    QSignalSpy finished(m_process, &QProcess::finished);
    ::kill(static_cast<pid_t>(m_process->processId()), SIGINT);
    QVERIFY(finished.wait(kPatienceMs));
    QCOMPARE(m_process->exitStatus(), QProcess::NormalExit);
    QCOMPARE(m_process->exitCode(), 0);
}

void GveEmuPtyTest::optionsShapeTheUnit()
{
    QTemporaryDir dir;
    QVERIFY(dir.isValid());
    const QString eeprom = dir.filePath(QStringLiteral("unit.eeprom"));
    const QString link = dir.filePath(QStringLiteral("gve"));
    start({QStringLiteral("--variant"), QStringLiteral("gve114"), QStringLiteral("--address"),
           QStringLiteral("3"), QStringLiteral("--latency"), QStringLiteral("30"),
           QStringLiteral("--home"), QStringLiteral("X=-200"), QStringLiteral("--eeprom"), eeprom,
           QStringLiteral("--link"), link});
    QVERIFY(QFileInfo(link).isSymLink());
    QElapsedTimer clock;
    clock.start();
    QCOMPARE(ask("!3?\r"), QByteArray("0,IP114/500 x16 16.9.2018\r"));
    QVERIFY(clock.elapsed() >= 60); // 30 ms each way at least: the model cannot be faster
    QCOMPARE(ask("!3Y-\r"), QByteArray("0,Y-\r"));
    QCOMPARE(ask("!3WX,-1000,20000,100,20000\r"), QByteArray("0\r"));
    QCOMPARE(ask("!3P\r"), QByteArray("0,-199,0\r"));
    QCOMPARE(ask("!3EW05,AC\r"), QByteArray("0\r"));
    QFile file(eeprom);
    QVERIFY(file.open(QIODevice::ReadOnly));
    QVERIFY(file.readLine().startsWith("FF 02 03 08 FF AC"));
    // Only address 3 (and the spindle address 7) answer: a command to 0 gets nothing back, and
    // the next one to 3 is answered normally.
    m_port->write("!0?\r");
    QCOMPARE(ask("!3Q\r"), QByteArray("0,16091801\r"));
    QSignalSpy finished(m_process, &QProcess::finished);
    m_process->terminate(); // SIGTERM
    QVERIFY(finished.wait(kPatienceMs));
    QCOMPARE(m_process->exitCode(), 0);
    QVERIFY(!QFileInfo::exists(link) && !QFileInfo(link).isSymLink());
}

void GveEmuPtyTest::rejectsBadOptions()
{
    QProcess p;
    p.start(QStringLiteral(GVE_EMU_PATH), {QStringLiteral("--variant"), QStringLiteral("gve99")});
    QVERIFY(p.waitForFinished(kPatienceMs));
    QCOMPARE(p.exitCode(), 2);
    QVERIFY(p.readAllStandardError().contains("--variant"));
    p.start(QStringLiteral(GVE_EMU_PATH), {QStringLiteral("--baud"), QStringLiteral("921600")});
    QVERIFY(p.waitForFinished(kPatienceMs));
    QCOMPARE(p.exitCode(), 2);
    p.start(QStringLiteral(GVE_EMU_PATH), {QStringLiteral("--help")});
    QVERIFY(p.waitForFinished(kPatienceMs));
    QCOMPARE(p.exitCode(), 0);
    const QByteArray help = p.readAllStandardOutput();
    for (const char *opt :
         {"--variant", "--baud", "--max-rate", "--address", "--latency", "--seed", "--corrupt",
          "--drop", "--duplicate", "--lose-reply", "--eeprom", "--home", "--limit", "--surface",
          "--steps-per-mm", "--probe-contact", "--link", "--verbose"})
        QVERIFY2(help.contains(opt), opt);
}

// --surface: the tool probe input IN15 (I2 bit 7) reads the shipped profiles' contact level 0
// once Z is at or below the work's top (a plane at Z -5 mm, 200 steps/mm: Z counter -1000).
void GveEmuPtyTest::surfaceTouchesTheProbe()
{
    start({QStringLiteral("--surface"), QStringLiteral("plane:-5,0,0"),
           QStringLiteral("--steps-per-mm"), QStringLiteral("200")});
    QCOMPARE(ask("!0Y-\r"), QByteArray("0,Y-\r"));
    QCOMPARE(ask("!0V20000\r"), QByteArray("0\r"));
    QCOMPARE(ask("!0I2\r"), QByteArray("0,80\r"));
    QCOMPARE(ask("!0L0,0,-999\r"), QByteArray("0\r"));
    QVERIFY(waitUntilDrained());
    QCOMPARE(ask("!0I2\r"), QByteArray("0,80\r")); // 0.005 mm above
    QCOMPARE(ask("!0L0,0,-1\r"), QByteArray("0\r"));
    QVERIFY(waitUntilDrained());
    QCOMPARE(ask("!0I2\r"), QByteArray("0,00\r")); // touching
    QProcess p;
    p.start(QStringLiteral(GVE_EMU_PATH), {QStringLiteral("--surface"), QStringLiteral("cone:1")});
    QVERIFY(p.waitForFinished(kPatienceMs));
    QCOMPARE(p.exitCode(), 2);
    QVERIFY(p.readAllStandardError().contains("--surface"));
}

// --wheel (issue 20): the handwheel turned on stdin moves the unit only with the MPG enabled in
// its EEPROM (0x06), by the EEPROM's steps per mm (factory 100).
void GveEmuPtyTest::wheelFromStdinMovesByTheEeprom()
{
    start({QStringLiteral("--variant"), QStringLiteral("gve64"), QStringLiteral("--wheel")});
    QCOMPARE(ask("!0SR6\r"), QByteArray("0,40\r")); // Y& after reset: the MPG on
    m_process->write("X 10 5\n");
    QByteArray said;
    QTRY_VERIFY2_WITH_TIMEOUT(
        (said += m_process->readAllStandardError()).contains("the wheel does nothing"),
        said.constData(), kPatienceMs);
    QCOMPARE(ask("!0PF\r"), QByteArray("0,0,0,0\r"));
    QCOMPARE(ask("!0EW06,01\r"), QByteArray("0\r"));
    m_process->write("X 10 5\n"); // 5 x 0.1 mm
    QByteArray pf;
    QTRY_VERIFY_WITH_TIMEOUT((pf = ask("!0PF\r")) == "0,50,0,0\r", kPatienceMs);
    m_process->write("Y 1 -3\n"); // 3 x 0.01 mm down
    QTRY_VERIFY_WITH_TIMEOUT((pf = ask("!0PF\r")) == "0,50,-3,0\r", kPatienceMs);
}

// --com-switch (issue 20): the unit listens at the switch's speed.
void GveEmuPtyTest::comSwitchSetsTheLineSpeed()
{
    start({QStringLiteral("--variant"), QStringLiteral("gve64"), QStringLiteral("--baud"),
           QStringLiteral("38400"), QStringLiteral("--com-switch"), QStringLiteral("1")});
    QCOMPARE(ask("!0Q\r"), QByteArray("0,25020304\r")); // OFF ON = 38 400 Bd
    // A client at another speed is not heard: tests/driver/link/eeprom_outputs_test.cpp (the
    // same Simulation, where silence can be asserted without waiting on a clock).
}

// --units: two GVE114 on one pty, each answering only its address, with its own counters and
// index; address 7 is the first unit's; an address nobody has gets no reply.
void GveEmuPtyTest::twoUnitsShareOnePty()
{
    start({QStringLiteral("--units"), QStringLiteral("0:gve114,1:gve114")});
    QCOMPARE(ask("!0Y-\r"), QByteArray("0,Y-\r"));
    QCOMPARE(ask("!1Y-\r"), QByteArray("0,Y-\r"));
    QCOMPARE(ask("!1L0,-300,0\r"), QByteArray("0\r"));
    QCOMPARE(ask("!0L500,0,0\r"), QByteArray("0\r"));
    QElapsedTimer clock;
    clock.start();
    while (ask("!0L0,0,0\r") != "0\r" || ask("!1L0,0,0\r") != "0\r") {
        QVERIFY(clock.elapsed() < kPatienceMs);
        QTest::qWait(10);
    }
    QCOMPARE(ask("!0P4\r"), QByteArray("0,500,0,0,0\r"));
    QCOMPARE(ask("!1P4\r"), QByteArray("0,0,-300,0,0\r"));
    QCOMPARE(ask("!7V250\r"), QByteArray("0\r")); // one reply: only unit 0 has address 7
    m_port->write("!4?\r");                       // nobody: no reply, the next is answered
    QCOMPARE(ask("!1Q\r"), QByteArray("0,16091801\r"));
    QVERIFY(m_rx.isEmpty());
    QProcess p;
    p.start(QStringLiteral(GVE_EMU_PATH),
            {QStringLiteral("--units"), QStringLiteral("0:gve114,0:gve114")});
    QVERIFY(p.waitForFinished(kPatienceMs));
    QCOMPARE(p.exitCode(), 2);
    QVERIFY(p.readAllStandardError().contains("twice"));
}

QTEST_GUILESS_MAIN(GveEmuPtyTest)
#include "gve_emu_pty_test.moc"
