// Sessions against the in-process emulator on a virtual clock: whole transfers at 9600 Bd run
// in milliseconds, with the wire timing of the real line.
#include "sessionrig.h"

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
