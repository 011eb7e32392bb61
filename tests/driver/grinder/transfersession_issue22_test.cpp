// Issue 22 on the in-process emulator (virtual time): waits start on the wire, files are
// checked before sending, cancel says what the controller does, wrong system and KONFIG6
// messages, table transfer.
#include "sessionrig.h"

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
