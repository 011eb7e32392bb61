// Sessions against the in-process emulator on a virtual clock: whole transfers at 9600 Bd run
// in milliseconds, with the wire timing of the real line.
#include "driver/grinder/emulatortransport.h"
#include "driver/grinder/transfersession.h"

#include <gtest/gtest.h>

#include <optional>

using namespace frezka::grinder;

namespace {

constexpr std::int64_t kLimitUs = 600'000'000; // 10 min of virtual time

struct Rig
{
    VirtualClock clock;
    EmulatorTransport transport;
    TransferSession session;
    std::optional<TransferResult> result;
    std::vector<std::pair<qint64, qint64>> progress;
    QStringList trace;

    Rig(EmulatorConfig config, int baud = 9600)
        : transport(clock, config, baud)
        , session(transport, clock, config.family)
    {
        transport.open(nullptr);
        QObject::connect(&session, &TransferSession::finished,
                         [this](const TransferResult &r) { result = r; });
        QObject::connect(&session, &TransferSession::progressed,
                         [this](qint64 done, qint64 total) { progress.emplace_back(done, total); });
        QObject::connect(&session, &TransferSession::traced,
                         [this](const QString &line) { trace << line; });
    }
    TransferResult run()
    {
        clock.runUntil([this] { return result.has_value(); }, kLimitUs);
        EXPECT_TRUE(result.has_value());
        return result.value_or(TransferResult{});
    }
    TransferResult save()
    {
        result.reset();
        session.save();
        return run();
    }
    TransferResult load(const std::string &header, const Bytes &data)
    {
        result.reset();
        session.load(headerFromText(header), QByteArray(reinterpret_cast<const char *>(data.data()),
                                                        qsizetype(data.size())));
        return run();
    }
};

EmulatorConfig config(Family family)
{
    EmulatorConfig c;
    c.family = family;
    return c;
}

Bytes toBytes(const QByteArray &data)
{
    return Bytes(data.begin(), data.end());
}

const Family kFamilies[] = {Family::Anc, Family::K51, Family::HardChrome};

} // namespace

TEST(GrinderSession, PingEachFamily)
{
    for (Family family : kFamilies) {
        Rig rig(config(family));
        rig.result.reset();
        rig.session.ping();
        const TransferResult r = rig.run();
        EXPECT_TRUE(r.ok()) << r.message.toStdString();
        EXPECT_EQ(r.message, "Connected.");
    }
}

TEST(GrinderSession, SaveEachFamilyReceivesTheControllersDataExactly)
{
    for (Family family : kFamilies) {
        Rig rig(config(family));
        const TransferResult r = rig.save();
        ASSERT_TRUE(r.ok()) << r.message.toStdString();
        EXPECT_EQ(toBytes(r.data), rig.transport.emulator().image());
        EXPECT_EQ(r.data.size(), qsizetype(familyInfo(family).defaultSize));
        EXPECT_TRUE(r.image.ok()) << r.image.summary();
        if (family == Family::K51) {
            EXPECT_EQ(headerText(r.header), "FREZKA EMU");
            // ~21.8 KB at 960 B/s: the manual's "about 25 s" (virtual time).
            EXPECT_GT(r.elapsedUs, 22'000'000);
            EXPECT_LT(r.elapsedUs, 24'000'000);
        }
        ASSERT_FALSE(rig.progress.empty());
        EXPECT_EQ(rig.progress.back().first, rig.progress.back().second);
        for (std::size_t i = 1; i < rig.progress.size(); ++i)
            EXPECT_GE(rig.progress[i].first, rig.progress[i - 1].first);
    }
}

TEST(GrinderSession, LoadEachFamilyStoresTheFileExactly)
{
    for (Family family : kFamilies) {
        EmulatorConfig c = config(family);
        c.image = Bytes(familyInfo(family).defaultSize, 0x00);
        Rig rig(c);
        const Bytes file = generatedImage(Family::K51, familyInfo(family).defaultSize);
        const TransferResult r = rig.load("NEW PROGRAM", file);
        ASSERT_TRUE(r.ok()) << r.message.toStdString();
        EXPECT_EQ(rig.transport.emulator().image(), file);
        EXPECT_EQ(rig.transport.emulator().loadsStored(), 1);
        if (family != Family::HardChrome) {
            EXPECT_EQ(rig.transport.emulator().prenos(), 0xB1);
            EXPECT_TRUE(rig.transport.emulator().noProgramSet());
        }
        ASSERT_FALSE(rig.progress.empty());
        EXPECT_EQ(rig.progress.back().first, rig.progress.back().second);
    }
}

TEST(GrinderSession, HeaderRoundTrip)
{
    Rig rig(config(Family::K51));
    ASSERT_TRUE(rig.load("HRIDEL 42 ABC", generatedImage(Family::K51, kK51ImageSize)).ok());
    EXPECT_EQ(headerText(rig.transport.emulator().header()), "HRIDEL 42 ABC");
    const TransferResult saved = rig.save();
    ASSERT_TRUE(saved.ok());
    EXPECT_EQ(headerText(saved.header), "HRIDEL 42 ABC");
}

TEST(GrinderSession, ImageRoundTripIsByteExactEvenWithBadInnerBlocks)
{
    Bytes image = generatedImage(Family::K51, kK51ImageSize);
    image[7 + 2 * kTchinBlockSize + 10] ^= 0xFF; // block 0x02 checksum now wrong
    EmulatorConfig source = config(Family::K51);
    source.image = image;
    Rig from(source);
    const TransferResult saved = from.save();
    ASSERT_TRUE(saved.ok());
    EXPECT_EQ(saved.image.badBlocks(), 1u);
    EXPECT_EQ(saved.image.summary(), "1 of 20 blocks invalid: 0x02 (checksum)");

    Rig to(config(Family::K51));
    const TransferResult refused = to.load(headerText(saved.header), toBytes(saved.data));
    EXPECT_EQ(refused.error, TransferError::InvalidInput);
    EXPECT_TRUE(refused.message.contains("wrong checksum: 0x02")) << refused.message.toStdString();
    EXPECT_TRUE(refused.message.contains("Send anyway")) << refused.message.toStdString();
    EXPECT_EQ(to.transport.deliveredToController(), 0);
    to.result.reset();
    to.session.load(saved.header, saved.data, /*sendAnyway=*/true);
    ASSERT_TRUE(to.run().ok());
    EXPECT_EQ(to.transport.emulator().image(), image);
    EXPECT_TRUE(
        to.trace.join('\n').contains("Sent anyway: inner blocks with a wrong checksum: 0x02"))
        << to.trace.join('\n').toStdString();
}

TEST(GrinderSession, NakThenSuccess)
{
    EmulatorConfig c = config(Family::K51);
    c.nakCount = 2;
    Rig rig(c);
    const Bytes file = generatedImage(Family::K51, kK51ImageSize);
    const TransferResult r = rig.load("X", file);
    ASSERT_TRUE(r.ok()) << r.message.toStdString();
    EXPECT_EQ(r.naks, 2);
    EXPECT_EQ(r.retries, 2);
    EXPECT_EQ(rig.transport.emulator().image(), file);
}

TEST(GrinderSession, PersistentNakIsReported)
{
    EmulatorConfig c = config(Family::Anc);
    c.nakCount = 100;
    Rig rig(c);
    const TransferResult r = rig.load("", generatedImage(Family::Anc, kAncImageSizeWithWheel));
    EXPECT_EQ(r.error, TransferError::Rejected);
    EXPECT_EQ(r.naks, 4); // first send + 3 repeats
    EXPECT_TRUE(r.message.contains("NAK to LOA")) << r.message.toStdString();
    EXPECT_EQ(rig.transport.emulator().loadsStored(), 0);
}

TEST(GrinderSession, ChecksumFailureThenSuccess)
{
    EmulatorConfig c = config(Family::K51);
    c.corruptCount = 1;
    Rig rig(c);
    const TransferResult r = rig.save();
    ASSERT_TRUE(r.ok()) << r.message.toStdString();
    EXPECT_EQ(r.checksumFailures, 1);
    EXPECT_EQ(toBytes(r.data), rig.transport.emulator().image());
}

TEST(GrinderSession, PersistentChecksumFailureIsReported)
{
    for (Family family : kFamilies) {
        EmulatorConfig c = config(family);
        c.corruptCount = 100;
        Rig rig(c);
        const TransferResult r = rig.save();
        EXPECT_EQ(r.error, TransferError::ChecksumFailed);
        EXPECT_EQ(r.checksumFailures, 4);
        EXPECT_TRUE(r.message.contains("Bad checksum")) << r.message.toStdString();
        EXPECT_TRUE(r.data.isEmpty());
    }
}

TEST(GrinderSession, SilentControllerTimesOut)
{
    EmulatorConfig c = config(Family::K51);
    c.silentAfterReplies = 0;
    Rig rig(c);
    rig.session.ping();
    const TransferResult r = rig.run();
    EXPECT_EQ(r.error, TransferError::Timeout);
    EXPECT_TRUE(r.message.contains("No answer to ENQ")) << r.message.toStdString();
    EXPECT_EQ(r.retries, 3);
}

TEST(GrinderSession, SilenceAfterTheLinkCheckTimesOutTheSave)
{
    EmulatorConfig c = config(Family::K51);
    c.silentAfterReplies = 1; // answers ENQ, then never again
    Rig rig(c);
    const TransferResult r = rig.save();
    EXPECT_EQ(r.error, TransferError::Timeout);
    EXPECT_TRUE(r.message.contains("No data from the controller")) << r.message.toStdString();
}

TEST(GrinderSession, NoiseBetweenMessagesIsSkippedAndCounted)
{
    EmulatorConfig c = config(Family::K51);
    c.noise = true;
    Rig rig(c);
    const TransferResult r = rig.save();
    ASSERT_TRUE(r.ok()) << r.message.toStdString();
    EXPECT_EQ(r.noiseBytes, qint64(2 * emulatorNoise().size())); // before ACK and before SAV
    EXPECT_EQ(toBytes(r.data), rig.transport.emulator().image());
}

TEST(GrinderSession, SlowControllerWithinTheTimeoutsSucceeds)
{
    EmulatorConfig c = config(Family::K51);
    c.replyDelayUs = 2'500'000; // 2.5 s before every answer
    Rig rig(c, 4800);
    const TransferResult r = rig.save();
    ASSERT_TRUE(r.ok()) << r.message.toStdString();
    EXPECT_EQ(r.retries, 0);
}

TEST(GrinderSession, WrongSizedFilesAreRefusedBeforeSending)
{
    Rig anc(config(Family::Anc));
    TransferResult r = anc.load("", Bytes(1000, 1));
    EXPECT_EQ(r.error, TransferError::InvalidInput);
    EXPECT_TRUE(r.message.contains("has 1000")) << r.message.toStdString();
    Rig hedit(config(Family::HardChrome));
    EXPECT_EQ(hedit.load("", Bytes(47, 1)).error, TransferError::InvalidInput);
    Rig k51(config(Family::K51));
    EXPECT_EQ(k51.load("", Bytes()).error, TransferError::InvalidInput);
    EXPECT_EQ(k51.transport.emulator().loadsStored(), 0);
}

// Issue 22: a K51 load checks length and inner blocks before a single byte goes out.
TEST(GrinderSession, K51FilesAreCheckedBeforeAnyByteIsSent)
{
    Rig rig(config(Family::K51));
    TransferResult r = rig.load("", Bytes(1000, 1));
    EXPECT_EQ(r.error, TransferError::InvalidInput);
    EXPECT_TRUE(r.message.contains("21767 bytes (0x5507); the file has 1000"))
        << r.message.toStdString();
    EXPECT_EQ(rig.transport.deliveredToController(), 0);
    EXPECT_TRUE(rig.progress.empty());

    r = rig.load("", generatedImage(Family::Anc, kAncImageSizeWithWheel));
    EXPECT_EQ(r.error, TransferError::InvalidInput);
    EXPECT_TRUE(r.message.contains("length of ANC data: is the wrong system selected?"))
        << r.message.toStdString();

    r = rig.load("", Bytes(kK51ImageSize, 0x11)); // the right length, no block anywhere
    EXPECT_EQ(r.error, TransferError::InvalidInput);
    EXPECT_TRUE(r.message.contains("20 of the 20 inner program blocks lack"))
        << r.message.toStdString();
    EXPECT_EQ(rig.transport.deliveredToController(), 0);
    EXPECT_EQ(rig.transport.emulator().loadsStored(), 0);
    EXPECT_TRUE(rig.load("", generatedImage(Family::K51, kK51ImageSize)).ok());
}

// "Send anyway" passes an odd length only when this controller reported it.
TEST(GrinderSession, SendAnywayOnlyForALengthTheControllerReported)
{
    EmulatorConfig c = config(Family::K51);
    c.image = generatedImage(Family::K51, kProgramImageSize); // this controller has 0x5500
    Rig rig(c);
    const Bytes odd = generatedImage(Family::K51, kProgramImageSize + 3);
    TransferResult r = rig.load("", odd);
    EXPECT_EQ(r.error, TransferError::InvalidInput);
    rig.result.reset();
    rig.session.load(Header{},
                     QByteArray(reinterpret_cast<const char *>(odd.data()), qsizetype(odd.size())),
                     true);
    EXPECT_EQ(rig.run().error, TransferError::InvalidInput); // never reported: refused anyway

    const TransferResult saved = rig.save();
    ASSERT_TRUE(saved.ok());
    r = rig.load("", toBytes(saved.data));
    EXPECT_EQ(r.error, TransferError::InvalidInput);
    EXPECT_TRUE(r.message.contains("This controller reported this length"))
        << r.message.toStdString();
    rig.result.reset();
    rig.session.load(saved.header, saved.data, true);
    ASSERT_TRUE(rig.run().ok());
    EXPECT_EQ(rig.transport.emulator().loadsStored(), 1);
}

TEST(GrinderSession, TableModeRefusesAProgramRequest)
{
    EmulatorConfig c = config(Family::K51);
    c.mode = TransferMode::Table;
    Rig rig(c);
    const TransferResult r = rig.save();
    EXPECT_EQ(r.error, TransferError::Rejected);
    EXPECT_TRUE(r.message.contains("KONFIG6")) << r.message.toStdString();
}

TEST(GrinderSession, ClosedTransportIsReported)
{
    Rig rig(config(Family::K51));
    rig.transport.close();
    rig.session.ping();
    ASSERT_TRUE(rig.result.has_value());
    EXPECT_EQ(rig.result->error, TransferError::NotOpen);
}

TEST(GrinderSession, TimeLeftEstimate)
{
    EXPECT_DOUBLE_EQ(estimateSecondsLeft(0, 9600, 0, 9600), 10.0);          // from the baud rate
    EXPECT_DOUBLE_EQ(estimateSecondsLeft(500, 1500, 1'000'000, 9600), 2.0); // measured rate
}

TEST(GrinderSession, CancelStopsATransferAndTheLinkStaysUsable)
{
    Rig rig(config(Family::K51));
    rig.session.save();
    rig.clock.advance(5'000'000); // part of the 22 s message is in
    ASSERT_TRUE(rig.session.isBusy());
    ASSERT_FALSE(rig.progress.empty());
    rig.session.cancel();
    ASSERT_TRUE(rig.result.has_value());
    EXPECT_EQ(rig.result->error, TransferError::Cancelled);
    EXPECT_FALSE(rig.session.isBusy());
    rig.clock.advance(30'000'000); // the controller finishes its message; nobody listens
    rig.result.reset();
    rig.session.ping();
    EXPECT_TRUE(rig.run().ok());
}

// The controller answers after the reply timeout: ENQ is repeated, both ENQs are answered, and
// the second ACK must not be taken for the answer to the request or to the data.
TEST(GrinderSession, LateDuplicateAckIsNotTakenForTheAnswer)
{
    EmulatorConfig c = config(Family::K51);
    c.replyDelayUs = 3'500'000; // beyond the 3 s reply timeout
    Rig saver(c);
    const TransferResult saved = saver.save();
    ASSERT_TRUE(saved.ok()) << saved.message.toStdString();
    EXPECT_EQ(saved.retries, 1) << saver.trace.join(QLatin1Char(10)).toStdString();
    EXPECT_EQ(toBytes(saved.data), saver.transport.emulator().image());

    c.image = Bytes(kK51ImageSize, 0);
    c.nakCount = 0;
    Rig loader(c);
    const Bytes file = generatedImage(Family::K51, kK51ImageSize);
    const TransferResult loaded = loader.load("LATE", file);
    ASSERT_TRUE(loaded.ok()) << loaded.message.toStdString();
    EXPECT_EQ(loader.transport.emulator().image(), file);
    EXPECT_TRUE(loader.trace.join('\n').contains("ACK ignored"))
        << loader.trace.join('\n').toStdString();
}

// Issue 22: a port that takes the whole 21 KB message at once (a USB adapter's buffer) reports
// it written 22.7 s before its last byte has left at 9600 Bd. The store wait must start on the
// wire: the load is sent once and the progress follows the bytes the controller has received.
TEST(GrinderSession, LoadThroughALargePortBufferIsSentOnceAndProgressFollowsTheWire)
{
    EmulatorConfig c = config(Family::K51);
    c.image = Bytes(kK51ImageSize, 0);
    Rig rig(c);
    rig.transport.setOsBufferBytes(1 << 20);
    qint64 deliveredBefore = -1;
    qint64 worstLagBytes = 0;
    int samples = 0;
    QObject::connect(&rig.session, &TransferSession::progressed, [&](qint64 done, qint64) {
        const qint64 delivered = rig.transport.deliveredToController();
        if (deliveredBefore < 0)
            deliveredBefore = delivered; // the data message starts here
        worstLagBytes = std::max(worstLagBytes, std::abs(done - (delivered - deliveredBefore)));
        ++samples;
    });
    const Bytes file = generatedImage(Family::K51, kK51ImageSize);
    const TransferResult r = rig.load("ONCE", file);
    ASSERT_TRUE(r.ok()) << r.message.toStdString() << rig.trace.join('\n').toStdString();
    EXPECT_EQ(r.retries, 0);
    EXPECT_EQ(rig.transport.emulator().loadsStored(), 1);
    EXPECT_EQ(rig.transport.emulator().image(), file);
    EXPECT_GE(r.elapsedUs, 22'000'000);
    EXPECT_LE(r.elapsedUs, 25'000'000);
    EXPECT_GT(samples, 100); // at least every 0.2 s of the 22.7 s
    EXPECT_LE(worstLagBytes, 960) << "progress strayed more than 1 s of wire from the controller";
}

// A port that stops taking bytes (adapter unplugged) is reported as such, not as a silent
// controller, once the wire time of what it holds and the gap timeout have passed.
TEST(GrinderSession, APortThatStopsTakingBytesIsReported)
{
    Rig rig(config(Family::K51));
    rig.result.reset();
    const Bytes file = generatedImage(Family::K51, kK51ImageSize);
    rig.session.load(
        headerFromText("STALL"), // 4 KB of it fit in the port
        QByteArray(reinterpret_cast<const char *>(file.data()), qsizetype(file.size())));
    rig.clock.advance(3'000'000); // ENQ, ACK and the first 2.8 KB of the data message are out
    ASSERT_TRUE(rig.session.isBusy());
    rig.transport.setWireStopped(true);
    const TransferResult r = rig.run();
    EXPECT_EQ(r.error, TransferError::Transport);
    EXPECT_TRUE(r.message.contains("stopped taking data")) << r.message.toStdString();
}

// The controller at 4800 Bd, the PC at 9600 Bd: nothing gets through, and the session says to
// check the line settings rather than hanging or pretending.
TEST(GrinderSession, ABaudRateMismatchGetsNoAnswer)
{
    Rig rig(config(Family::K51));
    rig.transport.setControllerBaud(4800);
    rig.result.reset();
    rig.session.ping();
    const TransferResult r = rig.run();
    EXPECT_EQ(r.error, TransferError::Timeout) << rig.trace.join('\n').toStdString();
    EXPECT_TRUE(r.message.contains("9600 Bd")) << r.message.toStdString();
    EXPECT_EQ(rig.transport.emulator().loadsStored(), 0);

    Rig matched(config(Family::K51), 4800);
    matched.transport.setControllerBaud(4800);
    matched.session.ping();
    EXPECT_TRUE(matched.run().ok());
}

// Issue 22: the session set to K51 against an ANC controller says "wrong system", not a
// checksum in hex; an ANC is never told about KONFIG6, which it does not have.
TEST(GrinderSession, AWrongSystemIsNamedAndAncMessagesSayNoKonfig6)
{
    VirtualClock clock;
    EmulatorTransport transport(clock, config(Family::Anc), 4800);
    transport.open(nullptr);
    TransferSession session(transport, clock, Family::K51);
    std::optional<TransferResult> result;
    QObject::connect(&session, &TransferSession::finished,
                     [&](const TransferResult &r) { result = r; });
    session.ping();
    clock.runUntil([&] { return result.has_value(); }, kLimitUs);
    ASSERT_TRUE(result.has_value());
    EXPECT_FALSE(result->ok());
    EXPECT_TRUE(result->message.contains("is the wrong system selected (ANC or K51)?"))
        << result->message.toStdString();

    EmulatorConfig silent = config(Family::Anc);
    silent.silentAfterReplies = 0;
    Rig anc(silent, 4800);
    anc.session.ping();
    const TransferResult r = anc.run();
    EXPECT_EQ(r.error, TransferError::Timeout);
    EXPECT_FALSE(r.message.contains("KONFIG6")) << r.message.toStdString();
    EXPECT_TRUE(r.message.contains("not grinding")) << r.message.toStdString();
}

// Cancel in the middle of a load: the port's unsent bytes are dropped, the controller drops
// its incomplete message and stores nothing, the result says so, and the link works after.
TEST(GrinderSession, CancelDuringALoadDropsTheRestAndSaysWhatTheControllerDoes)
{
    Rig rig(config(Family::K51));
    rig.transport.setOsBufferBytes(1 << 20);
    const Bytes file = generatedImage(Family::K51, kK51ImageSize);
    rig.result.reset();
    rig.session.load(
        headerFromText("CANCEL"),
        QByteArray(reinterpret_cast<const char *>(file.data()), qsizetype(file.size())));
    rig.clock.advance(5'000'000);
    ASSERT_TRUE(rig.session.isBusy());
    rig.session.cancel();
    ASSERT_TRUE(rig.result.has_value());
    EXPECT_EQ(rig.result->error, TransferError::Cancelled);
    EXPECT_TRUE(rig.result->message.contains("received only part of the data"))
        << rig.result->message.toStdString();
    EXPECT_GT(rig.result->controllerBusyUs, 0);
    const qint64 delivered = rig.transport.deliveredToController();
    rig.clock.advance(rig.result->controllerBusyUs);
    EXPECT_LE(rig.transport.deliveredToController(), delivered + 2); // nothing more went out
    EXPECT_LT(delivered, 21789 / 2);
    EXPECT_EQ(rig.transport.emulator().loadsStored(), 0);
    rig.result.reset();
    rig.session.ping();
    EXPECT_TRUE(rig.run().ok());
}

// Issue 22: table transfer (LOA1, APROXTAB's job) against a K51 in table mode; a program load
// to that controller, and a table to one in program mode, are refused with the KONFIG6 hint.
TEST(GrinderSession, TableTransferGoesToAControllerInTableModeOnly)
{
    EmulatorConfig c = config(Family::K51);
    c.mode = TransferMode::Table;
    VirtualClock clock;
    EmulatorTransport transport(clock, c, 9600);
    transport.open(nullptr);
    TransferSession session(transport, clock, Family::Table);
    std::optional<TransferResult> result;
    QStringList trace;
    QObject::connect(&session, &TransferSession::finished,
                     [&](const TransferResult &r) { result = r; });
    QObject::connect(&session, &TransferSession::traced, [&](const QString &l) { trace << l; });
    QByteArray table(300, 0);
    for (int i = 0; i < table.size(); ++i)
        table[i] = char(i * 7);
    session.load(headerFromText("SHAFT 12"), table);
    clock.runUntil([&] { return result.has_value(); }, kLimitUs);
    ASSERT_TRUE(result && result->ok()) << (result ? result->message.toStdString() : "");
    EXPECT_TRUE(trace.contains("-> LOA1 (316 B)")) << trace.join('\n').toStdString();
    EXPECT_EQ(transport.emulator().table(), Bytes(table.begin(), table.end()));
    EXPECT_EQ(transport.emulator().tablesStored(), 1);
    EXPECT_EQ(transport.emulator().loadsStored(), 0);
    result.reset();
    session.save();
    ASSERT_TRUE(result.has_value());
    EXPECT_EQ(result->error, TransferError::InvalidInput);
    EXPECT_TRUE(result->message.contains("only from the PC")) << result->message.toStdString();

    Rig programs(c); // K51 programs to the controller in table mode
    const TransferResult refused = programs.load("P", generatedImage(Family::K51, kK51ImageSize));
    EXPECT_EQ(refused.error, TransferError::Rejected);
    EXPECT_TRUE(refused.message.contains("KONFIG6 = 2")) << refused.message.toStdString();

    VirtualClock clock2;
    EmulatorTransport programMode(clock2, config(Family::K51), 9600);
    programMode.open(nullptr);
    TransferSession tableSession(programMode, clock2, Family::Table);
    result.reset();
    QObject::connect(&tableSession, &TransferSession::finished,
                     [&](const TransferResult &r) { result = r; });
    tableSession.load(headerFromText("T"), table);
    clock2.runUntil([&] { return result.has_value(); }, kLimitUs);
    ASSERT_TRUE(result.has_value());
    EXPECT_EQ(result->error, TransferError::Rejected);
    EXPECT_TRUE(result->message.contains("KONFIG6 = 3")) << result->message.toStdString();
    EXPECT_EQ(programMode.emulator().tablesStored(), 0);
}
