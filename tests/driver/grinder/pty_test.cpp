// End to end on a pseudo-terminal: k51-emu as a process, frezka-cli and the sessions on
// QSerialPort against it, in real time (k51-emu --fast: no baud pacing).
#include "ptyprocess.h"

#include "driver/grinder/controlleremulator.h"
#include "driver/grinder/transfersession.h"
#include "driver/grinder/zlinksession.h"

#include <QElapsedTimer>
#include <QSignalSpy>
#include <QTemporaryDir>
#include <QtTest>

using namespace frezka::grinder;
using namespace frezka::grinder::test;

class GrinderPtyTest : public QObject
{
    Q_OBJECT

private slots:
    void cliSaveThenLoadRoundTripsByteExactly();
    void cliRoundTripEachFamily_data();
    void cliRoundTripEachFamily();
    void cliReportsNakThenSuccessAndChecksumRepeats();
    void cliReportsFailuresWithNonZeroExit();
    void cliZPositionBothForms();
    void sessionOnSerialPortWithNoise();
    void emulatorExitsCleanlyOnSigterm();
    void cliHelpGoRangeAndUnwritableTarget();
    void cliRefusesAWrongLengthBeforeSendingAndSendsAnywayOnRequest();
    void cliSavedFileKeepsTheHeaderAndCzechLettersAreMappedVisibly();
    void cliSendsATableToAControllerInTableMode();
    void emulatorTakesTheFirmwareDefaultForAnUnprogrammedKonfig6();
    void aBusyPortNamesWhoHasItAndAVanishedOneIsCalledUnplugged();

private:
    QTemporaryDir m_dir;
    QString file(const QString &name) const { return m_dir.filePath(name); }
};

// The "Done when": save then load against k51-emu on a pty, byte for byte.
void GrinderPtyTest::cliSaveThenLoadRoundTripsByteExactly()
{
    QByteArray image;
    const Bytes generated = generatedImage(Family::K51, kK51ImageSize);
    image =
        QByteArray(reinterpret_cast<const char *>(generated.data()), qsizetype(generated.size()));
    // Arbitrary content, inner AA bytes included; the block's 8-bit sum stays as it was.
    image[101] = char(image[100] + image[101] - char(0xAA));
    image[100] = char(0xAA);
    QVERIFY(writeAll(file("held.bin"), image));

    EmuProcess emu({"--fast", "--image", file("held.bin"), "--header", "ORIGINAL", "--store",
                    file("stored.bin")});
    QVERIFY2(!emu.path().isEmpty(), qPrintable(emu.errorOutput()));

    CliRun save = runCli({"grinder", "save", "--port", emu.path(), file("saved.bin")});
    QCOMPARE(save.exitCode, 0);
    QVERIFY2(save.out.contains("header \"ORIGINAL\""), qPrintable(save.out));
    QCOMPARE(readAll(file("saved.bin")), image);

    CliRun load = runCli({"grinder", "load", "--port", emu.path(), "--header", "ROUND TRIP 16CH",
                          file("saved.bin")});
    QCOMPARE(load.exitCode, 0);
    QVERIFY2(load.out.contains("no prg set"), qPrintable(load.out));
    QTRY_COMPARE(readAll(file("stored.bin")), image);

    CliRun again = runCli({"grinder", "save", "--port", emu.path(), file("again.bin")});
    QCOMPARE(again.exitCode, 0);
    QVERIFY2(again.out.contains("header \"ROUND TRIP 16CH\""), qPrintable(again.out));
    QCOMPARE(readAll(file("again.bin")), image);
}

void GrinderPtyTest::cliRoundTripEachFamily_data()
{
    QTest::addColumn<QString>("family");
    QTest::newRow("anc") << "anc";
    QTest::newRow("k51") << "k51";
    QTest::newRow("hedit") << "hedit";
}

void GrinderPtyTest::cliRoundTripEachFamily()
{
    QFETCH(QString, family);
    EmuProcess emu({"--fast", "--family", family, "--store", file(family + "-stored.bin")});
    QVERIFY(!emu.path().isEmpty());
    CliRun ping = runCli({"grinder", "ping", "--port", emu.path(), "--family", family});
    QCOMPARE(ping.exitCode, 0);
    QCOMPARE(ping.out.trimmed(), QStringLiteral("Connected."));
    const QString saved = file(family + ".bin");
    QCOMPARE(runCli({"grinder", "save", "--port", emu.path(), "--family", family, saved}).exitCode,
             0);
    const QByteArray data = readAll(saved);
    QCOMPARE(std::size_t(data.size()), familyInfo(*familyFromId(family.toStdString())).defaultSize);
    QCOMPARE(runCli({"grinder", "load", "--port", emu.path(), "--family", family, saved}).exitCode,
             0);
    QTRY_COMPARE(readAll(file(family + "-stored.bin")), data);
}

void GrinderPtyTest::cliReportsNakThenSuccessAndChecksumRepeats()
{
    EmuProcess emu({"--fast", "--naks", "2", "--corrupt", "1", "--noise"});
    QVERIFY(!emu.path().isEmpty());
    CliRun save = runCli({"grinder", "save", "--port", emu.path(), file("c.bin")});
    QCOMPARE(save.exitCode, 0);
    QVERIFY2(save.out.contains("Repeats: 1 (NAK 0, bad checksum 1)"), qPrintable(save.out));
    CliRun load = runCli({"grinder", "load", "--port", emu.path(), file("c.bin")});
    QCOMPARE(load.exitCode, 0);
    QVERIFY2(load.out.contains("Repeats: 2 (NAK 2, bad checksum 0)"), qPrintable(load.out));
}

void GrinderPtyTest::cliReportsFailuresWithNonZeroExit()
{
    {
        EmuProcess emu({"--fast", "--silent"});
        CliRun ping = runCli({"grinder", "ping", "--port", emu.path(), "--retries", "1",
                              "--reply-timeout-ms", "300"});
        QCOMPARE(ping.exitCode, 1);
        QVERIFY2(ping.err.contains("(timeout)") && ping.err.contains("No answer to ENQ"),
                 qPrintable(ping.err));
    }
    {
        EmuProcess emu({"--fast", "--corrupt", "100"});
        CliRun save =
            runCli({"grinder", "save", "--port", emu.path(), "--retries", "2", file("never.bin")});
        QCOMPARE(save.exitCode, 1);
        QVERIFY2(save.err.contains("(checksum)") && save.err.contains("Bad checksum"),
                 qPrintable(save.err));
        QVERIFY(!QFile::exists(file("never.bin"))); // nothing half-written
    }
    CliRun noPort = runCli({"grinder", "ping", "--port", file("no-such-port")});
    QCOMPARE(noPort.exitCode, 1);
    QVERIFY2(noPort.err.contains("Cannot open"), qPrintable(noPort.err));
    CliRun badFile = runCli({"grinder", "load", "--port", "/dev/null", file("missing.bin")});
    QCOMPARE(badFile.exitCode, 1);
    QCOMPARE(runCli({"grinder", "save", "--port", "/dev/null"}).exitCode, 2);
    QCOMPARE(runCli({"grinder", "ping", "--family", "xyz", "--port", "/dev/null"}).exitCode, 2);
    CliRun header = runCli({"grinder", "load", "--port", "/dev/null", "--header",
                            QStringLiteral("BRUS\u20AC"), file("x.bin")});
    QCOMPARE(header.exitCode, 2);
    QVERIFY2(header.err.contains("cannot show"), qPrintable(header.err));
    CliRun anc = runCli({"grinder", "load", "--port", "/dev/null", "--family", "anc", "--header",
                         "X", file("x.bin")});
    QCOMPARE(anc.exitCode, 2);
    QVERIFY2(anc.err.contains("ANC messages carry no header"), qPrintable(anc.err));
}

void GrinderPtyTest::cliZPositionBothForms()
{
    {
        EmuProcess emu({"--fast", "--konfig6", "1", "--z-start", "-1,234", "--z-speed", "100"});
        CliRun query = runCli({"grinder", "z", "--port", emu.path()});
        QCOMPARE(query.exitCode, 0);
        QCOMPARE(query.out.trimmed(), QStringLiteral("Z = -0001.234 mm"));
        CliRun go = runCli({"grinder", "z", "--port", emu.path(), "--go", "2.5"});
        QCOMPARE(go.exitCode, 0);
        QVERIFY2(go.out.contains("Z = 0002.500 mm"), qPrintable(go.out));
    }
    {
        EmuProcess emu({"--fast", "--konfig6", "1", "--zform", "2", "--z-start", "7.007"});
        CliRun frame = runCli({"grinder", "z", "--port", emu.path(), "--form", "2"});
        QCOMPARE(frame.exitCode, 0);
        QCOMPARE(frame.out.trimmed(), QStringLiteral("Z = 0007.007 mm"));
    }
}

void GrinderPtyTest::sessionOnSerialPortWithNoise()
{
    EmuProcess emu({"--fast", "--noise", "--header", "SERIAL"});
    QVERIFY(!emu.path().isEmpty());
    RealClock clock;
    SerialTransport transport({emu.path(), 9600, 8, 'n', 1});
    QString error;
    QVERIFY2(transport.open(&error), qPrintable(error));
    TransferSession session(transport, clock, Family::K51);
    QSignalSpy finished(&session, &TransferSession::finished);
    session.save();
    QVERIFY(finished.wait(10000));
    const auto result = finished.first().first().value<TransferResult>();
    QVERIFY2(result.ok(), qPrintable(result.message));
    QCOMPARE(QString::fromLatin1(headerText(result.header)), QStringLiteral("SERIAL"));
    QCOMPARE(result.noiseBytes, qint64(2 * emulatorNoise().size()));
    QCOMPARE(std::size_t(result.data.size()), kK51ImageSize);
}

void GrinderPtyTest::emulatorExitsCleanlyOnSigterm()
{
    EmuProcess emu({"--fast"});
    QVERIFY(!emu.path().isEmpty());
    QCOMPARE(emu.terminate(), 0);
    QProcess help;
    help.start(QStringLiteral(K51_EMU_PATH), {"--help"});
    QVERIFY(help.waitForFinished(5000));
    QCOMPARE(help.exitCode(), 0);
    const QString text = QString::fromLocal8Bit(help.readAllStandardOutput());
    for (const char *option : {"--family", "--image", "--header", "--konfig6", "--zform", "--baud",
                               "--fast", "--naks", "--corrupt", "--noise", "--silent", "--store"})
        QVERIFY2(text.contains(QLatin1String(option)), option);
}

// Issue 22: --help exits 0; --go is held to the window's range; an unwritable target fails
// before the controller is asked (a silent controller proves nothing was waited for).
void GrinderPtyTest::cliHelpGoRangeAndUnwritableTarget()
{
    QCOMPARE(runCli({"grinder", "--help"}).exitCode, 0);
    CliRun help = runCli({"grinder", "load", "--port", "/dev/null", "--help"});
    QCOMPARE(help.exitCode, 0);
    QVERIFY2(help.out.contains("--send-anyway"), qPrintable(help.out));
    CliRun far = runCli({"grinder", "z", "--port", "/dev/null", "--go", "99999"});
    QCOMPARE(far.exitCode, 2);
    QVERIFY2(far.err.contains("-9999.999 to 9999.999"), qPrintable(far.err));
    EmuProcess emu({"--fast", "--silent"});
    QVERIFY(!emu.path().isEmpty());
    QElapsedTimer timer;
    timer.start();
    CliRun save = runCli({"grinder", "save", "--port", emu.path(), file("no-such-dir/out.bin")});
    QCOMPARE(save.exitCode, 1);
    QVERIFY2(save.err.contains("nothing was asked from the controller"), qPrintable(save.err));
    QVERIFY2(timer.elapsed() < 3000, "the save waited for the controller first");
}

// Issue 22: a 1000-byte file is refused as K51 before a byte is sent (the emulator's verbose
// trace shows no message arrived); a block checksum error needs --send-anyway.
void GrinderPtyTest::cliRefusesAWrongLengthBeforeSendingAndSendsAnywayOnRequest()
{
    QVERIFY(writeAll(file("short.bin"), QByteArray(1000, 'x')));
    EmuProcess emu({"--fast", "--verbose", "--store", file("anyway-stored.bin")});
    QVERIFY(!emu.path().isEmpty());
    CliRun load = runCli({"grinder", "load", "--port", emu.path(), file("short.bin")});
    QCOMPARE(load.exitCode, 1);
    QVERIFY2(load.err.contains("(invalid-input)") && load.err.contains("the file has 1000"),
             qPrintable(load.err));
    QTest::qWait(200);
    QVERIFY2(!emu.errorOutput().contains("rx"), "bytes reached the controller");

    Bytes image = generatedImage(Family::K51, kK51ImageSize);
    image[7 + 3 * kTchinBlockSize + 100] ^= 0x01; // block 0x03's checksum now fails
    const QByteArray data(reinterpret_cast<const char *>(image.data()), qsizetype(image.size()));
    QVERIFY(writeAll(file("bad-block.bin"), data));
    CliRun refused = runCli({"grinder", "load", "--port", emu.path(), file("bad-block.bin")});
    QCOMPARE(refused.exitCode, 1);
    QVERIFY2(refused.err.contains("wrong checksum: 0x03"), qPrintable(refused.err));
    CliRun anyway =
        runCli({"grinder", "load", "--port", emu.path(), "--send-anyway", file("bad-block.bin")});
    QCOMPARE(anyway.exitCode, 0);
    QTRY_COMPARE(readAll(file("anyway-stored.bin")), data);
}

// Issue 22: a save keeps header and system, so a load restores the header without --header; a
// Czech header is sent with base letters and the CLI says so; a file of another system is
// refused before sending.
void GrinderPtyTest::cliSavedFileKeepsTheHeaderAndCzechLettersAreMappedVisibly()
{
    EmuProcess emu({"--fast", "--store", file("czech-stored.bin")});
    QVERIFY(!emu.path().isEmpty());
    const Bytes image = generatedImage(Family::K51, kK51ImageSize);
    QVERIFY(writeAll(file("src.bin"), QByteArray(reinterpret_cast<const char *>(image.data()),
                                                 qsizetype(image.size()))));
    CliRun load = runCli({"grinder", "load", "--port", emu.path(), "--header",
                          QStringLiteral("H\u0158\u00CDDEL \u010D.5"), file("src.bin")});
    QCOMPARE(load.exitCode, 0);
    QVERIFY2(load.out.contains(QStringLiteral("is sent as \"HRIDEL c.5\"")), qPrintable(load.out));
    QString emuErr; // accumulated: QTRY evaluates twice and each read consumes
    QTRY_VERIFY2((emuErr += emu.errorOutput()).contains("header \"HRIDEL c.5\""),
                 qPrintable(emuErr));

    CliRun save = runCli({"grinder", "save", "--port", emu.path(), file("kept.frg")});
    QCOMPARE(save.exitCode, 0);
    const QByteArray kept = readAll(file("kept.frg"));
    QVERIFY(kept.startsWith("FREZKA-GRINDER 1\nsystem: k51\nheader: 48524944454C20632E35"));
    CliRun raw = runCli({"grinder", "save", "--port", emu.path(), "--raw", file("raw.frg")});
    QCOMPARE(raw.exitCode, 0);
    QCOMPARE(readAll(file("raw.frg")), readAll(file("src.bin")));

    // Another header on the controller, then the kept file restores its own.
    QCOMPARE(runCli({"grinder", "load", "--port", emu.path(), "--header", "OTHER", file("src.bin")})
                 .exitCode,
             0);
    CliRun back = runCli({"grinder", "load", "--port", emu.path(), file("kept.frg")});
    QCOMPARE(back.exitCode, 0);
    CliRun again = runCli({"grinder", "save", "--port", emu.path(), file("again.bin")});
    QVERIFY2(again.out.contains("header \"HRIDEL c.5\""), qPrintable(again.out));
    QCOMPARE(readAll(file("again.bin")), readAll(file("src.bin")));

    CliRun wrong =
        runCli({"grinder", "load", "--port", "/dev/null", "--family", "hedit", file("kept.frg")});
    QCOMPARE(wrong.exitCode, 1);
    QVERIFY2(wrong.err.contains("holds K51 data") && wrong.err.contains("--family k51"),
             qPrintable(wrong.err));
}

// Issue 22: table transfer (LOA1) from the CLI to k51-emu in table mode (--konfig6 3).
void GrinderPtyTest::cliSendsATableToAControllerInTableMode()
{
    QVERIFY(writeAll(file("shape.tab"), QByteArray(512, char(0x11))));
    EmuProcess emu({"--fast", "--konfig6", "3", "--verbose"});
    QVERIFY(!emu.path().isEmpty());
    CliRun load =
        runCli({"grinder", "load", "--port", emu.path(), "--family", "table", file("shape.tab")});
    QCOMPARE(load.exitCode, 0);
    QString emuErr; // accumulated: QTRY evaluates twice and each read consumes
    QTRY_VERIFY2((emuErr += emu.errorOutput()).contains("stored a table of 512 bytes"),
                 qPrintable(emuErr));
    QVERIFY(emuErr.contains("rx LOA1 512 bytes"));
    CliRun save =
        runCli({"grinder", "save", "--port", emu.path(), "--family", "table", file("never.tab")});
    QCOMPARE(save.exitCode, 1);
    QVERIFY2(save.err.contains("only from the PC"), qPrintable(save.err));
    CliRun program = runCli({"grinder", "load", "--port", emu.path(), file("saved-none.bin")});
    QCOMPARE(program.exitCode, 1);
}

// Issue 22: KONFIG6 = FF (an unprogrammed EEPROM byte) is not refused: the firmware programs
// SEE_KONFIG6 at power-on, and k51-emu says so.
void GrinderPtyTest::emulatorTakesTheFirmwareDefaultForAnUnprogrammedKonfig6()
{
    EmuProcess emu({"--fast", "--konfig6", "255"});
    QVERIFY(!emu.path().isEmpty()); // (errorOutput() in a message would consume the note)
    CliRun ping = runCli({"grinder", "ping", "--port", emu.path()});
    QCOMPARE(ping.exitCode, 0);
    QCOMPARE(emu.terminate(), 0);
    const QString said = emu.errorOutput();
    QVERIFY2(said.contains("SEE_KONFIG6 = 2"), qPrintable(said));
    EmuProcess z({"--fast", "--konfig6", "255", "--see-konfig6", "1", "--selector", "other"});
    QVERIFY(!z.path().isEmpty());
    CliRun query = runCli({"grinder", "z", "--port", z.path(), "--reply-timeout-ms", "300"});
    QCOMPARE(query.exitCode, 1); // Z mode, but the selector is not in PGN: no answer
}

// Issue 22: "port busy: who has it" and "cable unplugged" in words, not errno texts.
void GrinderPtyTest::aBusyPortNamesWhoHasItAndAVanishedOneIsCalledUnplugged()
{
    auto emu = std::make_unique<EmuProcess>(QStringList{"--fast"});
    QVERIFY(!emu->path().isEmpty());
    SerialTransport first({emu->path(), 9600, 8, 'n', 1});
    QString error;
    QVERIFY2(first.open(&error), qPrintable(error));
    SerialTransport second({emu->path(), 9600, 8, 'n', 1});
    QVERIFY(!second.open(&error));
    QVERIFY2(error.contains("is in use by") &&
                 error.contains(QString::number(QCoreApplication::applicationPid())),
             qPrintable(error));
    QSignalSpy failed(&first, &Transport::failed);
    emu.reset(); // the controller's side of the line goes away
    first.write(QByteArray(64, 'x'));
    QVERIFY(failed.wait(3000) || !failed.isEmpty());
    const QString message = failed.first().first().toString();
    QVERIFY2(message.contains("unplugged"), qPrintable(message));
}

QTEST_GUILESS_MAIN(GrinderPtyTest)
#include "pty_test.moc"
