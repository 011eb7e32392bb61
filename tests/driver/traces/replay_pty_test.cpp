// The replay in real time: gve-emu --replay on a pseudo-terminal (spoken to through QSerialPort
// as the application speaks to hardware), ReplayTransport under the link worker, and the
// session's record of a link worker's transport (TracingTransport), saved on an alarm.
//
// Every wait has a generous ceiling (kPatienceMs) that only matters when something is broken.

#include "driver/emulator/serialtrace.h"
#include "driver/link/linkworker.h"
#include "driver/link/replaytransport.h"
#include "driver/link/tracerecorder.h"
#include "driver/link/tracingtransport.h"
#include "tracedrive.h"

#include <QDir>
#include <QFile>
#include <QProcess>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QSerialPort>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QTest>
#include <QTimer>

#include <algorithm>
#include <utility>

using namespace frezka;

namespace {

constexpr int kPatienceMs = 20000;

emulator::SerialTrace readTrace(const QString &name)
{
    QFile f(QStringLiteral(TRACES_DIR "/") + name);
    emulator::SerialTrace t;
    emulator::TraceMessage error;
    if (!f.open(QIODevice::ReadOnly) || !emulator::parseTrace(f.readAll().toStdString(), t, error))
        qFatal("cannot read the trace %s", qPrintable(name));
    return t;
}

// A line the test holds: records what the driver writes, answers what the test says.
class FakeLine : public driver::Transport
{
public:
    void open() override
    {
        QTimer::singleShot(0, this, [this] {
            m_open = true;
            emit opened();
        });
    }
    void close() override
    {
        if (std::exchange(m_open, false))
            emit closed(QString());
    }
    void write(const QByteArray &bytes) override { written += bytes; }
    bool isOpen() const override { return m_open; }
    QString description() const override { return QStringLiteral("a line of the test"); }
    void pullOut()
    {
        m_open = false;
        emit closed(QStringLiteral("USB adapter pulled out"));
    }
    QByteArray written;

private:
    bool m_open = false;
};

} // namespace

class ReplayPtyTest : public QObject
{
    Q_OBJECT

private slots:
    void cleanup();
    void gveEmuAnswersAsRecorded();
    void gveEmuNamesTheLineOfAnotherCommand();
    void linkWorkerConnectsToAReplay();
    void aRealTimeTraceRefusesAnotherJob();
    void cliTraceOnTheVirtualClockReplaysExactly();
    void linkWorkerRecordsAndSavesOnAnAlarm();

private:
    // gve-emu --replay trace (a name in tests/driver/traces/ or a path); the pty opened here
    // unless openPort is false (another program opens it). Returns the pty's path.
    QString start(const QString &trace, bool openPort = true);
    QByteArray ask(const QByteArray &command);

    QProcess *m_process = nullptr;
    QSerialPort *m_port = nullptr;
    QByteArray m_rx;
};

QString ReplayPtyTest::start(const QString &trace, bool openPort)
{
    m_rx.clear();
    m_process = new QProcess(this);
    m_process->setProgram(QStringLiteral(GVE_EMU_PATH));
    m_process->setArguments(
        {QStringLiteral("--replay"),
         trace.startsWith(QLatin1Char('/')) ? trace : QStringLiteral(TRACES_DIR "/") + trace});
    m_process->start();
    if (!m_process->waitForStarted(kPatienceMs) ||
        !QTest::qWaitFor([this] { return m_process->canReadLine(); }, kPatienceMs))
        return {};
    const QString path = QString::fromLocal8Bit(m_process->readLine()).trimmed();
    if (!path.startsWith(QLatin1String("/dev/pts/")) || !openPort)
        return path;
    m_port = new QSerialPort(path, this);
    m_port->setBaudRate(115200);
    if (!m_port->open(QIODevice::ReadWrite))
        return {};
    connect(m_port, &QSerialPort::readyRead, this, [this] { m_rx += m_port->readAll(); });
    return path;
}

void ReplayPtyTest::cleanup()
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

QByteArray ReplayPtyTest::ask(const QByteArray &command)
{
    m_rx.clear();
    m_port->write(command);
    if (!QTest::qWaitFor([this] { return m_rx.endsWith('\r'); }, kPatienceMs))
        return {};
    return m_rx;
}

void ReplayPtyTest::gveEmuAnswersAsRecorded()
{
    const emulator::SerialTrace trace = readTrace(QStringLiteral("connect-gve84.trace"));
    QVERIFY(!start(QStringLiteral("connect-gve84.trace")).isEmpty());
    // Each run of commands (a packet is several) and the unit lines recorded after it.
    const auto &e = trace.entries;
    int replies = 0;
    for (std::size_t i = 0; i < e.size();) {
        QByteArray commands, expected;
        for (; i < e.size() && e[i].direction != emulator::TraceDirection::ToPc; ++i) {
            if (e[i].direction == emulator::TraceDirection::ToUnit)
                commands += QByteArray::fromStdString(e[i].bytes);
        }
        for (; i < e.size() && e[i].direction != emulator::TraceDirection::ToUnit; ++i) {
            if (e[i].direction == emulator::TraceDirection::ToPc)
                expected += QByteArray::fromStdString(e[i].bytes);
        }
        m_rx.clear();
        m_port->write(commands);
        if (expected.isEmpty())
            break; // the record ends with commands whose reply it did not keep
        QTRY_VERIFY_WITH_TIMEOUT(m_rx.size() >= expected.size(), kPatienceMs);
        QCOMPARE(m_rx, expected);
        ++replies;
    }
    QVERIFY(replies > 10);
    QByteArray err;
    QTRY_VERIFY_WITH_TIMEOUT(
        (err += m_process->readAllStandardError()).contains("the trace was played to its end"),
        kPatienceMs);
    QCOMPARE(m_process->state(), QProcess::Running);
}

void ReplayPtyTest::gveEmuNamesTheLineOfAnotherCommand()
{
    const emulator::SerialTrace trace = readTrace(QStringLiteral("connect-gve64.trace"));
    QVERIFY(!start(QStringLiteral("connect-gve64.trace")).isEmpty());
    const emulator::TraceEntry &first = trace.entries[1]; // entry 0: the mode event
    QCOMPARE(first.direction, emulator::TraceDirection::ToUnit);
    QCOMPARE(ask(QByteArray::fromStdString(first.bytes)),
             QByteArray::fromStdString(trace.entries[2].bytes));
    m_port->write("!0J\r"); // the record goes on with '?'
    QTRY_VERIFY_WITH_TIMEOUT(m_process->state() == QProcess::NotRunning, kPatienceMs);
    QCOMPARE(m_process->exitCode(), 3);
    const QString err = QString::fromLocal8Bit(m_process->readAllStandardError());
    const QString expected =
        QStringLiteral("trace line %1: expected '%2', got '!0J\\r'")
            .arg(trace.entries[3].fileLine)
            .arg(QString::fromStdString(emulator::escapeTraceBytes(trace.entries[3].bytes)));
    QVERIFY2(err.contains(expected), qPrintable(err + QStringLiteral(" / ") + expected));
}

void ReplayPtyTest::linkWorkerConnectsToAReplay()
{
    driver::TraceRecorder::session().setLimitBytes(0); // only the replay on this link
    driver::LinkWorker worker;
    worker.setMachineConfig(machine::defaultMachineConfig(protocol::Variant::Gve114));
    driver::ReplayTransport *replay = nullptr;
    worker.setTransportFactory([&](const driver::ConnectionSettings &,
                                   const machine::MachineConfig &, QObject *parent, QString *) {
        replay = new driver::ReplayTransport(readTrace(QStringLiteral("connect-gve114.trace")),
                                             QStringLiteral("connect-gve114.trace"), parent);
        return replay;
    });
    driver::MachineMode mode = driver::MachineMode::Disconnected;
    connect(&worker, &driver::LinkWorker::stateChanged, this,
            [&](const driver::MachineState &s) { mode = s.mode; });
    worker.connectTo({});
    QTRY_VERIFY_WITH_TIMEOUT(mode == driver::MachineMode::Idle, kPatienceMs);
    QVERIFY(replay);
    QVERIFY2(!replay->replay().divergence(),
             emulator::englishText(replay->replay().divergence()).c_str());
    QTRY_VERIFY_WITH_TIMEOUT(replay->replay().finished(), kPatienceMs);
    driver::TraceRecorder::session().setLimitBytes(driver::TraceRecorder::kDefaultLimitBytes);
}

void ReplayPtyTest::linkWorkerRecordsAndSavesOnAnAlarm()
{
    QTemporaryDir state;
    qputenv("XDG_STATE_HOME", state.path().toLocal8Bit());
    driver::TraceRecorder::session().setAlarmFolder(driver::TraceRecorder::defaultAlarmFolder());
    auto noAlarmFolder = qScopeGuard([] { driver::TraceRecorder::session().setAlarmFolder({}); });
    driver::TraceRecorder::session().setLimitBytes(driver::TraceRecorder::kDefaultLimitBytes);
    driver::LinkWorker worker;
    QStringList log;
    connect(&worker, &driver::LinkWorker::logLine, this, [&](const QString &l) { log << l; });
    // The default factory around a line this test holds: it answers the first command, then the
    // adapter is pulled out.
    FakeLine *line = nullptr;
    worker.setTransportFactory([&](const driver::ConnectionSettings &s,
                                   const machine::MachineConfig &c, QObject *parent, QString *e) {
        driver::Transport *t = driver::createTransport(s, c, parent, e);
        auto *traced = qobject_cast<driver::TracingTransport *>(t);
        line = new FakeLine;
        auto *replaced = new driver::TracingTransport(line, driver::TraceRecorder::session(),
                                                      {{"variant", "gve64"}}, parent);
        replaced->observe(&worker);
        delete traced;
        return replaced;
    });
    QSignalSpy errors(&worker, &driver::LinkWorker::errorOccurred);
    worker.connectTo({});
    QTRY_VERIFY_WITH_TIMEOUT(line && line->written.contains("!0%+\r"), kPatienceMs);
    emit line->bytesReceived("0,5C\r");
    QTRY_VERIFY_WITH_TIMEOUT(line->written.contains("!0?"), kPatienceMs);
    line->pullOut();
    QTRY_VERIFY_WITH_TIMEOUT(errors.count() > 0, kPatienceMs);
    const QString folder = driver::TraceRecorder::session().alarmFolder();
    QVERIFY2(folder.startsWith(state.path()), qPrintable(folder));
    QTRY_VERIFY_WITH_TIMEOUT(!QDir(folder).entryList(QDir::Files).isEmpty(), kPatienceMs);
    const QStringList files = QDir(folder).entryList(QDir::Files);
    QCOMPARE(files.size(), 1); // one alarm, one file: its error and its closed link together
    QFile f(folder + QLatin1Char('/') + files.first());
    QVERIFY(f.open(QIODevice::ReadOnly));
    emulator::SerialTrace saved;
    emulator::TraceMessage bad;
    QVERIFY(emulator::parseTrace(f.readAll().toStdString(), saved, bad));
    QCOMPARE(saved.value("variant"), std::string("gve64"));
    QCOMPARE(saved.value("port"), std::string("a line of the test"));
    std::vector<std::string> lines; // the wire both ways, then the events
    for (const auto &e : saved.entries) {
        if (e.direction != emulator::TraceDirection::Event)
            lines.push_back(
                std::string(e.direction == emulator::TraceDirection::ToUnit ? "> " : "< ") +
                e.bytes);
    }
    for (const auto &e : saved.entries) {
        if (e.direction == emulator::TraceDirection::Event)
            lines.push_back("= " + e.bytes);
    }
    QVERIFY(lines.size() >= 5);
    QCOMPARE(lines[0], std::string("> !0%+\r"));
    QCOMPARE(lines[1], std::string("< 0,5C\r"));
    QCOMPARE(lines[2].substr(0, 5), std::string("> !0?"));
    QVERIFY(std::find(lines.begin(), lines.end(), "= link closed: USB adapter pulled out") !=
            lines.end());
    QVERIFY(log.join(QLatin1Char('\n')).contains(QStringLiteral("serial trace saved to ")));
}

// A trace from a session to gve-emu: frezka-cli runs a job on the built-in emulator in real time
// and saves the trace; gve-emu --replay plays that unit on a pty, and frezka-cli running another
// program against it gets through the connection (its polls free) and ends gve-emu at the first
// command of the other job, naming the trace line. (The same job again is not asserted: on the
// wall clock the driver may cut its packets elsewhere, docs/serial-trace.md.)
void ReplayPtyTest::aRealTimeTraceRefusesAnotherJob()
{
    QTemporaryDir dir;
    const QString trace = dir.filePath(QStringLiteral("job.trace"));
    // Its output into files (a pipe nobody drains could stall it), the event loop running.
    auto cli = [&dir](const QStringList &args, QString *err) {
        QProcess p;
        p.setStandardInputFile(QProcess::nullDevice());
        p.setStandardOutputFile(dir.filePath(QStringLiteral("cli.out")));
        p.setStandardErrorFile(dir.filePath(QStringLiteral("cli.err")));
        p.start(QStringLiteral(FREZKA_CLI_PATH), args);
        if (!QTest::qWaitFor([&p] { return p.state() == QProcess::NotRunning; }, 120000))
            return -1;
        QFile e(dir.filePath(QStringLiteral("cli.err")));
        *err = e.open(QIODevice::ReadOnly) ? QString::fromLocal8Bit(e.readAll()) : QString();
        return p.exitStatus() == QProcess::NormalExit ? p.exitCode() : -1;
    };
    QString err;
    QCOMPARE(
        cli({QStringLiteral("run"), QStringLiteral(TRACES_DIR "/short-job.nc"),
             QStringLiteral("--clock"), QStringLiteral("real"), QStringLiteral("--trace"), trace},
            &err),
        0);
    QVERIFY2(err.contains(QStringLiteral("serial trace saved to")), qPrintable(err));
    const QString pty = start(trace, false);
    QVERIFY(!pty.isEmpty());
    QVERIFY(cli({QStringLiteral("run"), QStringLiteral(TRACES_DIR "/slow-job.nc"),
                 QStringLiteral("--port"), pty},
                &err) != 0);
    QTRY_VERIFY_WITH_TIMEOUT(m_process->state() == QProcess::NotRunning, kPatienceMs);
    QCOMPARE(m_process->exitCode(), 3);
    const QString why = QString::fromLocal8Bit(m_process->readAllStandardError());
    // The connection went through: the divergence is a command of the job, not of connecting.
    const QRegularExpressionMatch m =
        QRegularExpression(QStringLiteral("trace line (\\d+): expected '([^']*)', got '([^']*)'"))
            .match(why);
    QVERIFY2(m.hasMatch(), qPrintable(why));
    emulator::SerialTrace recorded;
    QFile f(trace);
    emulator::TraceMessage bad;
    QVERIFY(f.open(QIODevice::ReadOnly) &&
            emulator::parseTrace(f.readAll().toStdString(), recorded, bad));
    int running = 0;
    for (const emulator::TraceEntry &e : recorded.entries) {
        if (e.bytes == "mode Running")
            running = e.fileLine;
    }
    QVERIFY(running > 0);
    QVERIFY2(m.captured(1).toInt() > running, qPrintable(why));
}

// frezka-cli run --trace on the virtual clock: the record names the job and its clock, has the
// spindle's commands on address 7 and the job's end, and the helper replays it line for line.
void ReplayPtyTest::cliTraceOnTheVirtualClockReplaysExactly()
{
    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("virtual.trace"));
    QProcess p;
    p.start(QStringLiteral(FREZKA_CLI_PATH),
            {QStringLiteral("run"), QStringLiteral(TRACES_DIR "/short-job.nc"),
             QStringLiteral("--trace"), path});
    QVERIFY(p.waitForFinished(120000));
    QCOMPARE(p.exitCode(), 0);
    QFile f(path);
    QVERIFY(f.open(QIODevice::ReadOnly));
    emulator::SerialTrace trace;
    emulator::TraceMessage bad;
    QVERIFY(emulator::parseTrace(f.readAll().toStdString(), trace, bad));
    QCOMPARE(trace.value("clock"), std::string("virtual"));
    QCOMPARE(trace.value("operation"), std::string("job"));
    int spindle = 0;
    bool finished = false;
    for (const emulator::TraceEntry &e : trace.entries) {
        spindle += e.direction == emulator::TraceDirection::ToUnit && e.bytes.rfind("!7V", 0) == 0;
        finished = finished || e.bytes == "job finished ok";
    }
    QVERIFY(spindle >= 2); // on and off
    QVERIFY(finished);
    std::string error;
    QVERIFY2(driver::tracetest::replayTrace(trace, TRACES_DIR, error), error.c_str());
    // The same record with the first spindle reply altered fails, naming that line.
    for (std::size_t i = 0; i + 1 < trace.entries.size(); ++i) {
        if (trace.entries[i].bytes.rfind("!7V", 0) == 0) {
            trace.entries[i + 1].bytes = "5\r";
            const std::string line = "trace line " + std::to_string(trace.entries[i + 1].fileLine);
            QVERIFY(!driver::tracetest::replayTrace(trace, TRACES_DIR, error));
            QVERIFY2(error.find(line + ")") != std::string::npos ||
                         error.find(line + ":") != std::string::npos,
                     error.c_str());
            break;
        }
    }
}

QTEST_GUILESS_MAIN(ReplayPtyTest)
#include "replay_pty_test.moc"
