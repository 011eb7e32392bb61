// The one grinder test that runs in real time (ctest label "realtime", about 23 s): issue 22's
// "Done when" load. A K51 program of 21 767 bytes goes through QSerialPort to k51-emu, which
// reads what the PC sends at 9600 Bd (pacing on), so the pty's buffer fills as on a real line
// and the port reports bytes written long before they have left the wire. The load must take
// 22-25 s, be sent once, and its progress must follow what the controller has received.
#include "ptyprocess.h"

#include "driver/grinder/controlleremulator.h"
#include "driver/grinder/transfersession.h"

#include <QElapsedTimer>
#include <QRegularExpression>
#include <QSignalSpy>
#include <QtTest>

using namespace frezka::grinder;
using namespace frezka::grinder::test;

class GrinderPtyRealtimeTest : public QObject
{
    Q_OBJECT

private slots:
    void k51LoadAt9600BdIsSentOnceAndProgressFollowsTheWire();
};

void GrinderPtyRealtimeTest::k51LoadAt9600BdIsSentOnceAndProgressFollowsTheWire()
{
    EmuProcess emu({"--verbose"}); // K51 at 9600 Bd, paced both ways
    QVERIFY2(!emu.path().isEmpty(), qPrintable(emu.errorOutput()));
    QElapsedTimer timer;
    timer.start();
    std::vector<std::pair<qint64, qint64>> received; // (ms, bytes the controller has read)
    int stored = 0;
    QByteArray pending;
    connect(&emu.process(), &QProcess::readyReadStandardError, this, [&] {
        pending += emu.process().readAllStandardError();
        static const QRegularExpression rx(QStringLiteral("received (\\d+) bytes"));
        qsizetype nl;
        while ((nl = pending.indexOf('\n')) >= 0) {
            const QString line = QString::fromLocal8Bit(pending.left(nl));
            pending.remove(0, nl + 1);
            const auto match = rx.match(line);
            if (match.hasMatch())
                received.emplace_back(timer.elapsed(), match.captured(1).toLongLong());
            if (line.contains(QLatin1String("stored")))
                ++stored;
        }
    });

    RealClock clock;
    SerialTransport transport({emu.path(), 9600, 8, 'n', 1});
    QString error;
    QVERIFY2(transport.open(&error), qPrintable(error));
    TransferSession session(transport, clock, Family::K51);
    std::vector<std::pair<qint64, qint64>> progress; // (ms, bytes the session shows as sent)
    connect(&session, &TransferSession::progressed, this,
            [&](qint64 done, qint64) { progress.emplace_back(timer.elapsed(), done); });
    QSignalSpy finished(&session, &TransferSession::finished);
    const Bytes image = generatedImage(Family::K51, kK51ImageSize);
    QCOMPARE(image.size(), std::size_t(21767));
    session.load(headerFromText("REALTIME"),
                 QByteArray(reinterpret_cast<const char *>(image.data()), qsizetype(image.size())));
    QVERIFY(finished.wait(60000));
    const auto result = finished.first().first().value<TransferResult>();
    QVERIFY2(result.ok(), qPrintable(result.message));
    QCOMPARE(result.retries, 0);
    QVERIFY2(result.elapsedUs >= 22'000'000 && result.elapsedUs <= 25'000'000,
             qPrintable(QString::number(result.elapsedUs / 1e6) + " s"));
    QTRY_COMPARE(stored, 1);
    QTest::qWait(500); // a second copy would follow at once; none may
    QCOMPARE(stored, 1);

    // The controller read ENQ (6 bytes), then the data message. At every 1024 bytes it read,
    // the progress shown last must lie within 960 bytes (1 s at 9600 Bd) of it.
    QVERIFY(received.size() >= 20);
    QVERIFY2(received.back().second < 2 * 21789, "the data message was sent twice");
    for (const auto &[ms, bytes] : received) {
        qint64 shown = 0;
        for (const auto &[pms, done] : progress) {
            if (pms <= ms)
                shown = done;
        }
        const qint64 wire = bytes - 6;
        QVERIFY2(std::abs(shown - wire) <= 960, qPrintable(QStringLiteral("at %1 ms: shown %2, on "
                                                                          "the wire %3")
                                                               .arg(ms)
                                                               .arg(shown)
                                                               .arg(wire)));
    }
}

QTEST_GUILESS_MAIN(GrinderPtyRealtimeTest)
#include "pty_realtime_test.moc"
