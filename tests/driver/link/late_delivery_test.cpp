// A reply that came in time but whose notification the event loop served late (a busy thread, a
// slow PC at the machine) is read before its deadline is judged: the link worker asks the
// transport for what has arrived (Transport::deliverPending) before it declares a reply lost.
// Judged on the wire: a reply taken for lost sends the unit the index query `@` and repeats
// the command; neither may happen here.

#include "driver/link/emulatortransport.h"
#include "driver/link/linkworker.h"
#include "driver/link/serialtransport.h"
#include "machine/machineconfig.h"

#include <QSignalSpy>
#include <QTest>
#include <QTimer>

#include <fcntl.h>
#include <stdlib.h>
#include <unistd.h>

using namespace frezka;

namespace {

constexpr int kPatienceMs = 20000;

// The built-in emulator behind an event loop that serves its first replies a second late: the
// bytes have arrived (deliverPending hands them over at once), their notification has not.
class LateLine : public driver::Transport
{
    Q_OBJECT

public:
    LateLine(const machine::MachineConfig &config, int lateReplies, QObject *parent)
        : driver::Transport(parent)
        , m_inner(new driver::EmulatorTransport(driver::unitOptionsFor(config), {}, this))
        , m_lateReplies(lateReplies)
    {
        connect(m_inner, &driver::Transport::opened, this, &LateLine::opened);
        connect(m_inner, &driver::Transport::closed, this, &LateLine::closed);
        connect(m_inner, &driver::Transport::bytesReceived, this, [this](const QByteArray &b) {
            if (m_lateReplies <= 0) {
                emit bytesReceived(b);
                return;
            }
            m_held += b;
            m_lateReplies -= static_cast<int>(b.count('\r'));
            QTimer::singleShot(1000, this, &LateLine::handOver); // the late notification
        });
    }
    void open() override { m_inner->open(); }
    void close() override { m_inner->close(); }
    void write(const QByteArray &bytes) override
    {
        written += bytes;
        m_inner->write(bytes);
    }
    bool isOpen() const override { return m_inner->isOpen(); }
    QString description() const override { return QStringLiteral("a late event loop"); }
    void deliverPending() override
    {
        m_inner->deliverPending();
        handOver();
    }

    QByteArray written;

private:
    void handOver()
    {
        if (m_held.isEmpty())
            return;
        const QByteArray b = std::exchange(m_held, {});
        emit bytesReceived(b);
    }

    driver::EmulatorTransport *m_inner;
    int m_lateReplies;
    QByteArray m_held;
};

} // namespace

class LateDeliveryTest : public QObject
{
    Q_OBJECT

private slots:
    void repliesReadLateAreNotTakenForLost();
    void serialPortHandsOverWhatHasArrived();
};

void LateDeliveryTest::repliesReadLateAreNotTakenForLost()
{
    const auto config = machine::defaultMachineConfig(protocol::Variant::Gve64);
    driver::LinkWorker worker;
    worker.setMachineConfig(config);
    LateLine *line = nullptr;
    worker.setTransportFactory([&](const driver::ConnectionSettings &,
                                   const machine::MachineConfig &c, QObject *parent, QString *) {
        line = new LateLine(c, 5, parent);
        return line;
    });
    driver::MachineMode mode = driver::MachineMode::Disconnected;
    connect(&worker, &driver::LinkWorker::stateChanged, this,
            [&](const driver::MachineState &s) { mode = s.mode; });
    QSignalSpy errors(&worker, &driver::LinkWorker::errorOccurred);
    worker.connectTo({});
    QTRY_VERIFY_WITH_TIMEOUT(mode == driver::MachineMode::Idle, kPatienceMs);
    QVERIFY(line);
    QCOMPARE(errors.count(), 0);
    // No reply was queried for (a reply taken for lost sends `@`, then the command again; the
    // opening of the packets asks `@` once):
    // the first five replies, a second late in the event loop, were read at their deadline.
    QVERIFY2(line->written.count("@") == 1, line->written.constData()); // the packets' opening
    // Nor sent again: every command of the connection once (the polls and *S *S aside).
    QStringList seen;
    for (const QByteArray &l : line->written.split('\r')) {
        const QString command = QString::fromLatin1(l).section(QLatin1Char(','), 0, 0);
        if (command.isEmpty() || command == QLatin1String("!0F") ||
            command == QLatin1String("!0P4") || command == QLatin1String("!0*S"))
            continue;
        QVERIFY2(!seen.contains(command), qPrintable(command + QStringLiteral(" sent again")));
        seen << command;
    }
    QVERIFY(seen.contains(QStringLiteral("!0%+")));
}

// The real port: bytes that came in on a pseudo-terminal are handed over by deliverPending
// without the event loop running.
void LateDeliveryTest::serialPortHandsOverWhatHasArrived()
{
    const int master = ::posix_openpt(O_RDWR | O_NOCTTY);
    QVERIFY(master >= 0);
    QVERIFY(::grantpt(master) == 0 && ::unlockpt(master) == 0);
    const QString slave = QString::fromLocal8Bit(::ptsname(master));
    driver::SerialTransport port(slave, 115200);
    QSignalSpy opened(&port, &driver::Transport::opened);
    QSignalSpy received(&port, &driver::Transport::bytesReceived);
    port.open();
    QTRY_VERIFY_WITH_TIMEOUT(opened.count() == 1, kPatienceMs);
    QVERIFY(port.isOpen());
    const char reply[] = "0,5C\r";
    QCOMPARE(::write(master, reply, sizeof reply - 1), static_cast<ssize_t>(sizeof reply - 1));
    // Wait for the bytes to reach the slave's buffer without serving the event loop.
    for (int i = 0; i < 200 && received.isEmpty(); ++i) {
        QTest::qSleep(5);
        port.deliverPending();
    }
    QCOMPARE(received.count(), 1);
    QCOMPARE(received.first().first().toByteArray(), QByteArray(reply));
    port.deliverPending(); // nothing more has come: nothing is handed over, nothing waits
    QCOMPARE(received.count(), 1);
    port.close();
    ::close(master);
}

QTEST_GUILESS_MAIN(LateDeliveryTest)
#include "late_delivery_test.moc"
