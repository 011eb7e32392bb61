// The "Grinder transfer" window, offscreen, against k51-emu on a pty and the in-process
// emulator. No modal dialog: files are chosen through the panels' file choosers.
#include "ptyprocess.h"

#include "driver/grinder/controlleremulator.h"
#include "driver/grinder/emulatortransport.h"
#include "gui/grinder/grinderwindow.h"
#include "gui/grinder/hardchromeeditor.h"
#include "gui/grinder/serialmonitor.h"
#include "gui/grinder/zpositionpanel.h"

#include <QComboBox>
#include <QLabel>
#include <QLineEdit>
#include <QPlainTextEdit>
#include <QPushButton>
#include <QSettings>
#include <QtTest>

using namespace frezka::grinder;
using namespace frezka::grinder::test;
using frezka::gui::GrinderWindow;
using frezka::gui::TransferPanel;

class GrinderWindowTest : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase();
    void saveThenLoadRoundTripsByteExactlyOnPty();
    void silentControllerShowsNoConnection();
    void zPositionForm1WithTheInProcessEmulator();
    void serialMonitorShowsBothDirectionsAndCaptures();
    void choosingAControlSetsItsRate();
    void everyFailureEndsVisiblyWithNoStaleSave();
    void unsavedDataIsGuardedOnCloseAndLinkChecksStayOutOfTheLog();
    void czechHeaderRoundTripsThroughSaveAndLoad();
    void tableGoesToTheEmulatorInTableModeAndK51IsTheFirstChoice();
    void heditEditRoundTripsThroughTheController();

private:
    QTemporaryDir m_dir;
    QString file(const QString &name) const { return m_dir.filePath(name); }
};

void GrinderWindowTest::initTestCase()
{
    QCoreApplication::setOrganizationName(QStringLiteral("FrezkaTest"));
    QCoreApplication::setApplicationName(QStringLiteral("grinderwindow_test"));
    QStandardPaths::setTestModeEnabled(true);
    // Settings of this run only: nothing leaks between runs or into the user's settings.
    QSettings::setDefaultFormat(QSettings::IniFormat);
    QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.filePath("settings"));
}

void GrinderWindowTest::saveThenLoadRoundTripsByteExactlyOnPty()
{
    const Bytes generated = generatedImage(Family::K51, kK51ImageSize);
    const QByteArray image(reinterpret_cast<const char *>(generated.data()),
                           qsizetype(generated.size()));
    QVERIFY(writeAll(file("held.bin"), image));
    EmuProcess emu({"--fast", "--image", file("held.bin"), "--header", "FROM EMU", "--store",
                    file("stored.bin")});
    QVERIFY(!emu.path().isEmpty());

    GrinderWindow window;
    window.show();
    window.setSerialSettings({emu.path(), 9600, 8, 'n', 1});
    window.setFamily(Family::K51);
    TransferPanel *panel = window.transferPanel();
    panel->setFileChooser([this](TransferPanel::FileChoice choice, const QString &) {
        return choice == TransferPanel::FileChoice::SaveReceived ? file("saved.bin")
                                                                 : file("saved.bin");
    });
    auto *receive = window.findChild<QPushButton *>("receiveButton");
    auto *save = window.findChild<QPushButton *>("saveButton");
    auto *choose = window.findChild<QPushButton *>("chooseButton");
    auto *send = window.findChild<QPushButton *>("sendButton");
    auto *hint = window.findChild<QLabel *>("hint");
    QVERIFY(receive && save && choose && send && hint);
    QVERIFY(!receive->isEnabled()); // transfer buttons only while connected

    QVERIFY(window.connectPort());
    QTRY_VERIFY(window.isLinkUp());
    QVERIFY(window.connectionText().startsWith("Connected"));
    QTRY_VERIFY(receive->isEnabled());

    receive->click();
    QTRY_VERIFY(save->isEnabled());
    QVERIFY(panel->statusText().startsWith("Received"));
    save->click();
    QCOMPARE(readAll(file("saved.bin")), image);

    choose->click();
    QVERIFY(send->isEnabled());
    panel->setHeaderText(QStringLiteral("WINDOW TEST 16CH"));
    send->click();
    QTRY_VERIFY(hint->isVisibleTo(&window));
    QVERIFY(hint->text().contains("no prg set"));
    QVERIFY2(panel->statusText().contains("confirmed"), qPrintable(panel->statusText()));
    QTRY_COMPARE(readAll(file("stored.bin")), image);

    QTRY_VERIFY(receive->isEnabled());
    receive->click();
    QTRY_VERIFY(panel->statusText().startsWith("Received"));
    QCOMPARE(panel->receivedData(), image);
    bool headerShown = false;
    for (QLabel *label : window.findChildren<QLabel *>())
        headerShown |= label->text() == "WINDOW TEST 16CH";
    QVERIFY(headerShown);
    // For documentation: FREZKA_SCREENSHOT_DIR=/some/dir keeps a picture of the window.
    const QString shots = qEnvironmentVariable("FREZKA_SCREENSHOT_DIR");
    if (!shots.isEmpty())
        QVERIFY(window.grab().save(QDir(shots).filePath("grinder-window.png")));
}

void GrinderWindowTest::silentControllerShowsNoConnection()
{
    EmuProcess emu({"--fast", "--silent"});
    GrinderWindow window;
    window.setSerialSettings({emu.path(), 9600, 8, 'n', 1});
    QVERIFY(window.connectPort());
    QTRY_VERIFY_WITH_TIMEOUT(window.connectionText().startsWith("No connection") &&
                                 window.connectionText().contains("No answer to ENQ"),
                             10000);
    QVERIFY(!window.isLinkUp());
    QVERIFY(!window.findChild<QPushButton *>("receiveButton")->isEnabled());
    window.disconnectPort();
    QCOMPARE(window.connectionText(), QStringLiteral("Not connected."));

    GrinderWindow other;
    other.setSerialSettings({file("no-such-port"), 9600, 8, 'n', 1});
    QVERIFY(!other.connectPort());
    QVERIFY(other.connectionText().startsWith("Cannot connect"));
}

void GrinderWindowTest::zPositionForm1WithTheInProcessEmulator()
{
    GrinderWindow window;
    window.setSerialSettings({QStringLiteral("emulator"), 115200, 8, 'n', 1});
    window.setLinkMode(GrinderWindow::LinkMode::ZForm1);
    QVERIFY(window.connectPort());
    frezka::gui::ZPositionPanel *z = window.zPositionPanel();
    QVERIFY(z->readPosition());
    QTRY_COMPARE(z->positionText(), QStringLiteral("-0001.234 mm"));
    QVERIFY(z->goTo(0.5));
    QTRY_COMPARE(z->positionText(), QStringLiteral("0000.500 mm"));
}

void GrinderWindowTest::serialMonitorShowsBothDirectionsAndCaptures()
{
    EmuProcess emu({"--fast"});
    GrinderWindow window;
    frezka::gui::SerialMonitor *monitor = window.serialMonitor();
    QVERIFY(monitor->openPort(0, {emu.path(), 9600, 8, 'n', 1}));
    QVERIFY(!monitor->sendMessage(1)); // port 2 is not open: said so
    QVERIFY(monitor->statusText().contains("not open"));
    monitor->setHexView(true);
    monitor->setMessage(QStringLiteral("AA 05 00 00 FF 51"), true);
    QVERIFY(monitor->sendMessage(0));
    QTRY_VERIFY(monitor->viewText().contains("<-1  AA 06 00 00 FF 50"));
    QVERIFY(monitor->viewText().contains("->1  AA 05 00 00 FF 51"));
    monitor->setHexView(false);
    QVERIFY(monitor->viewText().contains("<-1  <AA><06><00><00><FF>P"));
    QVERIFY(monitor->captureTo(file("capture-000.txt")));
    QVERIFY(readAll(file("capture-000.txt")).contains("<AA><06>"));
    // A second port at the same time, answering on its own line of the view.
    EmuProcess second({"--fast", "--family", "anc"});
    QVERIFY(monitor->openPort(1, {second.path(), 4800, 8, 'n', 1}));
    monitor->setHexView(true);
    monitor->setMessage(QStringLiteral("AA 05 00 00 51"), true); // ANC ENQ
    QVERIFY(monitor->sendMessage(1));
    QTRY_VERIFY(monitor->viewText().contains("<-2  AA 06 00 00 50"));
    monitor->setMessage(QStringLiteral("AA 0"), true);
    QVERIFY(!monitor->sendMessage(0));
    QVERIFY(monitor->statusText().contains("not hex bytes"));
}

QTEST_MAIN(GrinderWindowTest)
// The manual's table: ANCLOAD/ANCSAVE talk at 4800 Bd, K51LOAD/K51SAVE and HEDIT at 9600.
// Choosing the control in the list sets its rate, and the port opens at it.
void GrinderWindowTest::choosingAControlSetsItsRate()
{
    GrinderWindow window;
    window.setSerialSettings({QStringLiteral("emulator"), 9600, 8, 'n', 1});
    auto *family = window.findChild<QComboBox *>(QStringLiteral("family"));
    QVERIFY(family);
    const auto choose = [family](Family f) {
        const int index = family->findData(int(f));
        family->setCurrentIndex(index);
        emit family->activated(index);
    };
    window.setLinkMode(GrinderWindow::LinkMode::ZForm1); // its "Open: ... at N Bd." names the rate
    const auto openedAt = [&window](const QString &rate) {
        const bool ok = window.connectPort() && window.connectionText().contains(rate);
        const QString text = window.connectionText();
        window.disconnectPort();
        return ok ? QString() : text;
    };
    choose(Family::Anc);
    QCOMPARE(openedAt(QStringLiteral("4800 Bd")), QString());
    window.setLinkMode(GrinderWindow::LinkMode::Programs); // ANC has no header: the field is off
    QVERIFY(window.connectPort());
    QVERIFY(!window.findChild<QLineEdit *>("header")->isEnabled());
    window.disconnectPort();
    window.setLinkMode(GrinderWindow::LinkMode::ZForm1);
    choose(Family::K51);
    QCOMPARE(openedAt(QStringLiteral("9600 Bd")), QString());
}

namespace {

// A window connected to k51-emu (started with `args`) with its link up.
struct WindowRig
{
    EmuProcess emu;
    GrinderWindow window;
    TransferPanel *panel;
    QPushButton *save;
    explicit WindowRig(const QStringList &args)
        : emu(args)
        , panel(window.transferPanel())
        , save(window.findChild<QPushButton *>("saveButton"))
    {
        window.setCloseConfirmer([] { return true; });
        window.setSerialSettings({emu.path(), 9600, 8, 'n', 1});
        window.setFamily(Family::K51);
        window.show();
    }
    bool connectAndWait()
    {
        return window.connectPort() && QTest::qWaitFor([this] { return window.isLinkUp(); });
    }
};

} // namespace

// Issue 22's second "Done when": NAKs past the limit, bad checksums, cancel, disconnect and a
// wrong-size file each end in a visible failure (status and banner), and Save never offers the
// data of an earlier transfer.
void GrinderWindowTest::everyFailureEndsVisiblyWithNoStaleSave()
{
    const Bytes generated = generatedImage(Family::K51, kK51ImageSize);
    QVERIFY(writeAll(file("good.bin"), QByteArray(reinterpret_cast<const char *>(generated.data()),
                                                  qsizetype(generated.size()))));
    QVERIFY(writeAll(file("short.bin"), QByteArray(1000, 'x')));
    const auto ended = [](WindowRig &rig, const QString &status, const QString &banner) {
        if (!QTest::qWaitFor([&] { return !rig.panel->failureText().isEmpty(); }, 30000))
            return QStringLiteral("no failure banner; status: ") + rig.panel->statusText() +
                   rig.window.findChild<QPlainTextEdit *>("transferLog")->toPlainText();
        if (!rig.panel->statusText().startsWith(status) ||
            !rig.panel->failureText().contains(banner))
            return rig.panel->statusText() + QStringLiteral(" | ") + rig.panel->failureText();
        return QString();
    };
    { // NAKs past the limit
        WindowRig rig({"--fast", "--naks", "100"});
        QVERIFY(rig.connectAndWait());
        QVERIFY(rig.panel->openFileToSend(file("good.bin")));
        QVERIFY(rig.panel->send());
        QCOMPARE(ended(rig, "Transfer failed", "NAK to LOA"), QString());
        QVERIFY(rig.panel->failureText().startsWith("Sending to the controller failed"));
    }
    { // bad checksums: a good receive first, then one that fails, and Save is off
        WindowRig rig({"--fast", "--corrupt", "4", "--silent-after", "100"});
        QVERIFY(rig.connectAndWait());
        QVERIFY(rig.panel->receive());
        QCOMPARE(ended(rig, "Transfer failed", "Bad checksum"), QString());
        QVERIFY(!rig.save->isEnabled());
        QVERIFY(rig.panel->receivedData().isEmpty());
        QTRY_VERIFY(rig.window.isLinkUp());
        QVERIFY(rig.panel->receive()); // the fifth message is good
        QTRY_VERIFY(rig.save->isEnabled());
        QVERIFY(rig.panel->failureText().isEmpty()); // a new transfer clears the banner
    }
    { // cancel while the controller sends (paced at 9600 Bd)
        WindowRig rig({"--header", "OLD"});
        QVERIFY(rig.connectAndWait());
        QVERIFY(rig.panel->receive());
        QTest::qWait(1500);
        rig.panel->cancel();
        QCOMPARE(ended(rig, "Cancelled", "may still be sending its data"), QString());
        QVERIFY(!rig.save->isEnabled());
        QVERIFY(rig.window.connectionText().startsWith("Waiting for the controller"));
    }
    { // disconnect during a load
        WindowRig rig({});
        QVERIFY(rig.connectAndWait());
        QVERIFY(rig.panel->openFileToSend(file("good.bin")));
        QVERIFY(rig.panel->send());
        QTest::qWait(1000);
        rig.window.disconnectPort();
        QCOMPARE(ended(rig, "Cancelled", "Disconnected during the transfer"), QString());
        QVERIFY(rig.panel->failureText().contains("received only part"));
    }
    { // a 1000-byte file as K51: refused, nothing sent
        WindowRig rig({"--fast", "--verbose"});
        QVERIFY(rig.connectAndWait());
        QVERIFY(rig.panel->openFileToSend(file("short.bin")));
        QVERIFY(rig.panel->send());
        QCOMPARE(ended(rig, "Transfer failed", "the file has 1000"), QString());
        QTest::qWait(100);
        QVERIFY(!rig.emu.errorOutput().contains("rx LOA"));
    }
}

void GrinderWindowTest::unsavedDataIsGuardedOnCloseAndLinkChecksStayOutOfTheLog()
{
    WindowRig rig({"--fast"});
    bool asked = false;
    bool allow = false;
    rig.window.setCloseConfirmer([&] {
        asked = true;
        return allow;
    });
    QVERIFY(rig.connectAndWait());
    rig.window.checkLink();
    QTest::qWait(300);
    auto *log = rig.window.findChild<QPlainTextEdit *>("transferLog");
    QVERIFY(log);
    QVERIFY2(!log->toPlainText().contains("ENQ"), qPrintable(log->toPlainText()));
    QVERIFY(rig.panel->receive());
    QTRY_VERIFY(rig.save->isEnabled());
    QVERIFY(log->toPlainText().contains("-> DEJ"));
    QVERIFY(!rig.window.close());
    QVERIFY(asked);
    QVERIFY(rig.window.isVisible());
    QVERIFY(rig.panel->saveReceived(file("kept.bin")));
    asked = false;
    QVERIFY(rig.window.close()); // saved: no question
    QVERIFY(!asked);
}

// Issue 22's second "Done when", last part: a header with Czech letters is sent with base
// letters (the window says so before sending), comes back from the controller, is kept in the
// saved file and restored when that file is opened to send (docs/grinder.md, "Headers").
void GrinderWindowTest::czechHeaderRoundTripsThroughSaveAndLoad()
{
    const Bytes generated = generatedImage(Family::K51, kK51ImageSize);
    QVERIFY(writeAll(file("plain.bin"), QByteArray(reinterpret_cast<const char *>(generated.data()),
                                                   qsizetype(generated.size()))));
    WindowRig rig({"--fast"});
    QVERIFY(rig.connectAndWait());
    QVERIFY(rig.panel->openFileToSend(file("plain.bin")));
    rig.panel->setHeaderText(QStringLiteral("H\u0158\u00CDDEL \u010D.5"));
    QVERIFY2(rig.panel->headerNote().contains("is sent as \"HRIDEL c.5\""),
             qPrintable(rig.panel->headerNote()));
    QVERIFY(rig.panel->send());
    QTRY_VERIFY(rig.panel->statusText().contains("confirmed"));
    QString emuErr; // accumulated: QTRY evaluates twice and each read consumes
    QTRY_VERIFY2((emuErr += rig.emu.errorOutput()).contains("header \"HRIDEL c.5\""),
                 qPrintable(emuErr));
    auto *receive = rig.window.findChild<QPushButton *>("receiveButton");
    QTRY_VERIFY(receive->isEnabled());
    QVERIFY(rig.panel->receive());
    QTRY_VERIFY(rig.save->isEnabled());
    QCOMPARE(rig.panel->receivedHeaderText(), QStringLiteral("HRIDEL c.5"));
    QVERIFY(rig.panel->saveReceived(file("kept.frg")));
    rig.panel->setHeaderText(QStringLiteral("SOMETHING ELSE"));
    QVERIFY(rig.panel->openFileToSend(file("kept.frg")));
    QCOMPARE(rig.window.findChild<QLineEdit *>("header")->text(), QStringLiteral("HRIDEL c.5"));
    QTRY_VERIFY(rig.window.findChild<QPushButton *>("sendButton")->isEnabled());
    QVERIFY(rig.panel->send());
    QTRY_VERIFY(rig.panel->statusText().contains("confirmed"));
    rig.panel->setHeaderText(QStringLiteral("BRUS\u20AC"));
    QVERIFY(rig.panel->headerNote().contains("cannot show"));
}

// Issue 22: the window sends a table (LOA1) to the in-process K51 in table mode; a table cannot
// be received; on a first start (no settings) the window offers K51, as the docs say.
void GrinderWindowTest::tableGoesToTheEmulatorInTableModeAndK51IsTheFirstChoice()
{
    QSettings().clear();
    {
        GrinderWindow fresh;
        QCOMPARE(fresh.findChild<QComboBox *>("family")->currentData().toInt(), int(Family::K51));
    }
    QVERIFY(writeAll(file("shape.tab"), QByteArray(200, char(0x22))));
    GrinderWindow window;
    window.setSerialSettings({QStringLiteral("emulator"), 115200, 8, 'n', 1});
    window.setFamily(Family::Table);
    QVERIFY(window.connectPort());
    QTRY_VERIFY(window.isLinkUp());
    QVERIFY(!window.findChild<QPushButton *>("receiveButton")->isEnabled());
    QVERIFY(window.findChild<QLineEdit *>("header")->isEnabled()); // a table has a header
    TransferPanel *panel = window.transferPanel();
    QVERIFY(panel->openFileToSend(file("shape.tab")));
    QVERIFY(panel->send());
    QTRY_VERIFY2(panel->statusText().contains("confirmed"), qPrintable(panel->failureText()));
    auto *emulator = dynamic_cast<EmulatorTransport *>(window.transport());
    QVERIFY(emulator);
    QCOMPARE(emulator->emulator().tablesStored(), 1);
    QCOMPARE(emulator->emulator().table(), Bytes(200, 0x22));
}

// Issue 22: HEDIT's editor — the controller's 0x2E bytes are received, one byte edited, sent
// back (LOA2) and stored: only that byte differs; a save without edits is byte-exact.
void GrinderWindowTest::heditEditRoundTripsThroughTheController()
{
    WindowRig rig({"--fast", "--family", "hedit", "--header", "CHROM 1", "--store",
                   file("hedit-stored.bin")});
    rig.window.setFamily(Family::HardChrome);
    QVERIFY(rig.connectAndWait());
    QVERIFY(rig.panel->receive());
    QTRY_VERIFY(rig.save->isEnabled());
    const QByteArray original = rig.panel->receivedData();
    QCOMPARE(original.size(), 46);
    frezka::gui::HardChromeEditor *editor = rig.window.hardChromeEditor();
    QVERIFY(editor->setData(rig.panel->receivedData(), rig.panel->receivedHeader()));
    QCOMPARE(editor->headerText(), QStringLiteral("CHROM 1"));
    QVERIFY(editor->saveFile(file("unchanged.bin")));
    QCOMPARE(readAll(file("unchanged.bin")), original);
    QVERIFY(!editor->setByte(0x112E, 1)); // past the 0x2E bytes
    QVERIFY(editor->setByte(0x1105, 0x7F));
    QVERIFY(editor->saveFile(file("edited.frg")));
    QVERIFY(editor->setByte(0x1105, 0x00));
    QVERIFY(editor->openFile(file("edited.frg"))); // the header and the edit come back
    QCOMPARE(editor->headerText(), QStringLiteral("CHROM 1"));
    QByteArray expected = original;
    expected[5] = char(0x7F);
    QCOMPARE(editor->data(), expected);
    QTRY_VERIFY(rig.window.findChild<QPushButton *>("receiveButton")->isEnabled());
    rig.window.findChild<QPushButton *>("hardChromeSend")->click();
    QTRY_VERIFY2(rig.panel->statusText().contains("confirmed"),
                 qPrintable(rig.panel->failureText()));
    QTRY_COMPARE(readAll(file("hedit-stored.bin")), expected);
}

#include "grinderwindow_test.moc"
