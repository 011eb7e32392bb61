// What the screen says (issue 14 item 6, issue 13 item 4), on the whole main window against the
// built-in emulator in real time (offscreen, software view): the current line, progress and cut
// drawing follow the unit through a pause, a tool lift and a resume; M6 and M0 are named with
// their line, tool and comment; a console line leaves the loaded program's display alone; the
// status bar names the connection and a port set with Apply is connected; a hold banner and a
// driver error are Czech in the Czech interface; the EEPROM dialog asks before it writes.
// Never sleeps on a guess: every wait is on the machine's own state.
#include "gui/consolewidget.h"
#include "gui/eepromdecode.h"
#include "gui/holdbanner.h"
#include "gui/mainwindow.h"
#include "gui/outputspanel.h"
#include "gui/programlisting.h"
#include "gui/programsession.h"
#include "gui/runpanel.h"
#include "gui/settingsdialog.h"
#include "gui/speedplot.h"
#include "gui/toolpathview.h"
#include "gui/toolpathviewmodel.h"
#include "gui/unitconfigdialog.h"

#include "windowtest.h"

#include "driver/link/machinecontroller.h"

#include <QDockWidget>
#include <QLabel>
#include <QMessageBox>
#include <QProcess>
#include <QProgressBar>
#include <QPushButton>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace frezka;
using namespace frezka::gui;
using driver::MachineMode;

namespace {
constexpr int kMachineTimeoutMs = 60000;
constexpr char kPtyFirmware[] = "IP64MPG v19 26.11.2026"; // gve-emu's, not the built-in's
} // namespace

class ScreenTest : public QObject
{
    Q_OBJECT

private:
    const driver::MachineState &state() const { return m_window->controller()->state(); }

    QString writeProgram(const QString &name, const QByteArray &text)
    {
        return test::writeProgram(m_dir, name, text);
    }

    bool load(const QString &path)
    {
        return test::openAndWait(m_window.get(), path) && m_window->program()->program().runnable();
    }

    QPushButton *button(QWidget *parent, const char *name) { return test::button(parent, name); }

    int progress() const
    {
        return m_window->runPanel()
            ->findChild<QProgressBar *>(QStringLiteral("runProgress"))
            ->value();
    }

    QString statusLine() const
    {
        return m_window->findChild<QLabel *>(QStringLiteral("machineStatus"))->text();
    }

    QString connectionText() const
    {
        return m_window->findChild<QLabel *>(QStringLiteral("connectionStatus"))->text();
    }

    bool waitIdle()
    {
        return QTest::qWaitFor([&] { return state().mode == MachineMode::Idle; },
                               kMachineTimeoutMs);
    }

    MainWindowOptions windowOptions() const
    {
        MainWindowOptions options;
        options.view = MainWindowOptions::View::Software;
        options.restoreLayout = false;
        return options;
    }

    // gve-emu on a pty of its own (started once), with a firmware text the built-in emulator
    // does not have; its path, empty when it cannot be started (QSKIP then).
    QString ptyUnit()
    {
#ifdef FREZKA_GVE_EMU
        if (m_pty.isEmpty()) {
            m_emu.setProgram(QStringLiteral(FREZKA_GVE_EMU));
            m_emu.setArguments({QStringLiteral("--variant"), QStringLiteral("gve64"),
                                QStringLiteral("--firmware"), QLatin1String(kPtyFirmware),
                                QStringLiteral("--verbose")});
            m_emu.start();
            if (!m_emu.waitForStarted() ||
                !QTest::qWaitFor([this] { return m_emu.canReadLine(); }, 10000))
                return {};
            m_pty = QString::fromLocal8Bit(m_emu.readLine()).trimmed();
        }
#endif
        return m_pty;
    }

    // What gve-emu has received so far ("pc>" lines of its --verbose log), joined.
    QByteArray ptyReceived()
    {
        m_emuLog += m_emu.readAllStandardError();
        QByteArray in;
        for (const QByteArray &line : m_emuLog.split('\n')) {
            const int at = int(line.indexOf(" pc> "));
            if (at >= 0)
                in += line.mid(at + 5).replace("\\r", "\r");
        }
        return in;
    }

    bool connectedTo(const QString &port) const
    {
        return state().mode == MachineMode::Idle && connectionText().contains(port) &&
               state().firmware == kPtyFirmware;
    }

    // Line k (3 .. 42) of the stepped program cuts X from 2(k-3) to 2(k-2) mm past its start.
    static QByteArray steppedProgram()
    {
        QByteArray p = "G21 G91\nG1 Z-1 F600\n";
        for (int k = 3; k <= 42; ++k)
            p += "G1 X2\n";
        p += "G1 Z1\nM30\n";
        return p;
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("FrezkaScreenTest"));
        machine::MachineConfig profile = machine::defaultMachineConfig(protocol::Variant::Gve64);
        profile.link.port = "emulator";
        // The screen is under test, not homing: runs start on the unhomed emulator (warned).
        profile.motion.runBeforeHoming = true;
        const QString profilePath = m_dir.filePath(QStringLiteral("machine.json"));
        QVERIFY(!machine::saveMachineConfig(profile, profilePath.toStdString()));
        QSettings().setValue(QStringLiteral("lastProfile"), profilePath);
        QSettings().setValue(QStringLiteral("language"), QStringLiteral("en"));
        MainWindowOptions options;
        options.view = MainWindowOptions::View::Software;
        options.restoreLayout = false;
        m_window = std::make_unique<MainWindow>(options);
        m_window->show();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Idle, 20000);
    }

    // The status bar names the built-in emulator; a port set with Apply is connected at once
    // (and named), and the built-in emulator again when it is chosen again.
    void statusBarNamesTheConnection()
    {
        QVERIFY(waitIdle());
        QVERIFY2(connectionText().contains(QStringLiteral("built-in emulator")),
                 qPrintable(connectionText()));
        QVERIFY2(connectionText().contains(QStringLiteral("Ready")), qPrintable(connectionText()));
        machine::MachineConfig port = m_window->profile();
        port.link.port = "/nonexistent/ttyFREZKA";
        m_window->applyProfile(port, m_window->profilePath());
        QTRY_VERIFY_WITH_TIMEOUT(
            connectionText().contains(QStringLiteral("/nonexistent/ttyFREZKA")), 10000);
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Disconnected, 10000);
        QCOMPARE(QSettings().value(QStringLiteral("link/port")).toString(),
                 QStringLiteral("/nonexistent/ttyFREZKA"));
        machine::MachineConfig emulator = m_window->profile();
        emulator.link.port = "emulator";
        m_window->applyProfile(emulator, m_window->profilePath());
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Idle, 20000);
        QTRY_VERIFY(connectionText().contains(QStringLiteral("built-in emulator")));
    }

    // Pause, lift, lower and continue: the line shown is never ahead of the line the unit's
    // counters say is being cut, the progress never runs ahead of the cut drawing's line, and
    // neither shows 100 % before the end.
    void lineAndProgressFollowTheUnitThroughAHold()
    {
        QVERIFY(waitIdle());
        QVERIFY(load(writeProgram(QStringLiteral("stepped.nc"), steppedProgram())));
        const double x0 = state().positionMm[0];
        int worstAhead = 0;
        QString worst;
        auto check = [&] {
            const auto &s = state();
            if (!s.jobActive || s.mode == MachineMode::Stopping)
                return;
            // The line whose X range holds the unit's X (lines 1-2 are the plunge).
            const double x = s.positionMm[0] - x0;
            if (x >= 80 - 1e-6)
                return; // the cut is done: the unit stands at its end, on the program's last lines
            const int cutting = x <= 0 ? 2 : std::min(42, 3 + int(std::floor((x - 1e-6) / 2)));
            const int shown = m_window->listing()->currentLine();
            if (shown - cutting > worstAhead) {
                worstAhead = shown - cutting;
                worst = QStringLiteral("shown %1 cutting %2 (x %3, mode %4, progress %5)")
                            .arg(shown)
                            .arg(cutting)
                            .arg(x)
                            .arg(driver::machineModeName(s.mode))
                            .arg(progress());
            }
            // The cut drawing: nothing beyond the line after the one being cut is drawn as cut.
            const auto cut = m_window->toolpathView()->model()->cutEntry();
            const auto limit =
                m_window->program()->program().entryOfLine(std::uint32_t(cutting + 1));
            if (cut != ToolpathViewModel::kNoneCut && cut > limit)
                worst += QStringLiteral(" | cut to entry %1 while cutting line %2 (entry %3)")
                             .arg(cut)
                             .arg(cutting)
                             .arg(limit);
            if (x < 78 && progress() >= 1000)
                worst +=
                    QStringLiteral(" | 100 % at x %1, ").arg(x) + driver::machineModeName(s.mode);
        };
        auto conn = connect(m_window->controller(), &driver::MachineController::stateChanged, this,
                            check, Qt::QueuedConnection);
        const auto stopChecking = qScopeGuard([&] { disconnect(conn); });
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        m_window->runProgram();
        QTRY_VERIFY_WITH_TIMEOUT(state().positionMm[0] - x0 > 12, kMachineTimeoutMs);
        button(m_window->runPanel(), "pause")->click();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Paused, kMachineTimeoutMs);
        const int lineAtPause = m_window->listing()->currentLine();
        const int progressAtPause = progress();
        QVERIFY2(
            m_window->holdBanner()->text().contains(QStringLiteral("line %1").arg(lineAtPause)),
            qPrintable(m_window->holdBanner()->text()));
        QCOMPARE(statusLine(), QStringLiteral("Line %1").arg(lineAtPause));
        button(m_window->holdBanner(), "holdLift")->click();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::ToolLifted, kMachineTimeoutMs);
        QTest::qWait(400); // several polls of the lifted position
        QCOMPARE(m_window->listing()->currentLine(), lineAtPause);
        QCOMPARE(progress(), progressAtPause);
        button(m_window->holdBanner(), "holdLowerContinue")->click();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Running, kMachineTimeoutMs);
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        disconnect(conn);
        QVERIFY2(worstAhead <= 1 && !worst.contains(QLatin1String("100 %")) &&
                     !worst.contains(QLatin1String("cut to entry")),
                 qPrintable(worst));
        QCOMPARE(progress(), 1000);
        QVERIFY(waitIdle());
    }

    // T1 M6 holds as a tool change naming tool 1 at its own line; M0 with a comment names its
    // line and shows the comment; banner title, body, listing and status bar agree.
    void operatorStopsAreNamedWithLineToolAndComment()
    {
        QVERIFY(waitIdle());
        QVERIFY(load(writeProgram(QStringLiteral("stops.nc"), "G21 G91\n"
                                                              "G1 Z-1 F600\n"
                                                              "G1 X2\n"
                                                              "G1 Y2\n"
                                                              "T1 M6\n"
                                                              "G1 X2\n"
                                                              "G1 Y-2\n"
                                                              "G1 X-2\n"
                                                              "M0 (check the slot depth)\n"
                                                              "G1 X-2 Z1\n"
                                                              "M30\n")));
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        m_window->runProgram();
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Paused &&
                                     state().hold == driver::HoldReason::OperatorStop,
                                 kMachineTimeoutMs);
        QTRY_COMPARE(m_window->holdBanner()->kind(), HoldBanner::Kind::OperatorStop);
        QString text = m_window->holdBanner()->text();
        QVERIFY2(text.contains(QStringLiteral("M6")) && text.contains(QStringLiteral("tool 1")) &&
                     !text.contains(QStringLiteral("M0")),
                 qPrintable(text));
        QVERIFY2(text.count(QStringLiteral("line 5")) >= 2, qPrintable(text)); // title and body
        QCOMPARE(m_window->listing()->currentLine(), 5);
        QCOMPARE(statusLine(), QStringLiteral("Line 5"));
        button(m_window->holdBanner(), "holdContinue")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Paused &&
                                     state().hold == driver::HoldReason::OperatorStop &&
                                     state().holdLine == 9,
                                 kMachineTimeoutMs);
        QTRY_VERIFY(
            m_window->holdBanner()->text().contains(QStringLiteral("check the slot depth")));
        text = m_window->holdBanner()->text();
        QVERIFY2(text.contains(QStringLiteral("M0")) && !text.contains(QStringLiteral("line 5")),
                 qPrintable(text));
        QVERIFY2(text.count(QStringLiteral("line 9")) >= 2, qPrintable(text));
        QCOMPARE(m_window->listing()->currentLine(), 9);
        QCOMPARE(statusLine(), QStringLiteral("Line 9"));
        button(m_window->holdBanner(), "holdContinue")->click();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QVERIFY(waitIdle());
    }

    // A console line runs as its own small job: the unit moves, the loaded program's listing,
    // progress, cut drawing and status stay as they were.
    void consoleLineLeavesTheProgramAlone()
    {
        QVERIFY(waitIdle());
        QVERIFY(load(writeProgram(QStringLiteral("square.nc"),
                                  "G21 G91\nG1 X3 F600\nG1 Y3\nG1 X-3\nG1 Y-3\nM30\n")));
        const int line = m_window->listing()->currentLine();
        const int progressBefore = progress();
        const auto cut = m_window->toolpathView()->model()->cutEntry();
        const QString eta =
            m_window->runPanel()->findChild<QLabel *>(QStringLiteral("eta"))->text();
        const double x0 = state().positionMm[0];
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        m_window->executeManualLine(QStringLiteral("G91 G1 X1.5 F600"));
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY(waitIdle());
        QVERIFY(std::abs(state().positionMm[0] - (x0 + 1.5)) < 1e-3); // the unit moved
        QCOMPARE(m_window->listing()->currentLine(), line);
        QCOMPARE(progress(), progressBefore);
        QCOMPARE(m_window->toolpathView()->model()->cutEntry(), cut);
        QCOMPARE(m_window->runPanel()->findChild<QLabel *>(QStringLiteral("eta"))->text(), eta);
        QVERIFY(!m_window->statusBar()->currentMessage().contains(QStringLiteral("finished")));
        m_window->executeManualLine(QStringLiteral("G90"));
    }

    // An override the serial link cannot feed (issue 14 item 5: "an override that would outrun
    // the wire is capped and the GUI says so"): 1 mm segments at F3000 on the built-in emulator
    // at 9 600 Bd, planned at the link's pace. With the slider at 200 % the label says what the
    // unit runs and why, every XM the driver sent while the job streamed is below 200, and the
    // operator's 200 % is sent again when the job has ended.
    void anOverrideTheLinkCannotFeedIsShownAsHeld()
    {
        QVERIFY(waitIdle());
        const machine::MachineConfig fast = m_window->profile();
        machine::MachineConfig slow = fast;
        slow.link.baud = 9600;
        // Idle again on the new link (the old one is Idle until the reconnect begins).
        auto reconnect = [&](const machine::MachineConfig &profile) {
            bool connecting = false;
            const auto watch =
                connect(m_window->controller(), &driver::MachineController::stateChanged, this,
                        [&connecting](const driver::MachineState &s) {
                            connecting = connecting || s.mode == MachineMode::Connecting;
                        });
            m_window->applyProfile(profile, m_window->profilePath());
            const bool idle = QTest::qWaitFor(
                [&] { return connecting && state().mode == MachineMode::Idle; }, 20000);
            disconnect(watch);
            return idle;
        };
        QVERIFY(reconnect(slow));
        QByteArray program = "G21 G90\nG0 X10 Y10\nG1 Z-1 F300\nF3000\n";
        for (int row = 0; row < 6; ++row) {
            for (int j = 0; j <= 60; ++j) {
                const int t = row % 2 == 0 ? j : 60 - j;
                program += QStringLiteral("G1 X%1 Y%2\n")
                               .arg(10 + t)
                               .arg(10 + row * 0.5 + 0.02 * (j % 2), 0, 'f', 2)
                               .toLatin1();
            }
        }
        program += "G0 Z0\nM30\n";
        QVERIFY(load(writeProgram(QStringLiteral("paced.nc"), program)));
        QStringList xm;
        const auto tap = connect(m_window->controller(), &driver::MachineController::logLine, this,
                                 [&xm](const QString &line) {
                                     if (line.startsWith(QLatin1String("> !0XM")))
                                         xm << line.mid(6);
                                 });
        const auto untap = qScopeGuard([&] { disconnect(tap); });
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        m_window->runProgram();
        QTest::qWaitFor([&] { return state().jobActive && state().positionMm[0] > 20; },
                        kMachineTimeoutMs);
        QVERIFY2(state().jobActive && state().positionMm[0] > 20,
                 qPrintable(QStringLiteral("%1 job %2 X %3 error %4")
                                .arg(QLatin1String(driver::machineModeName(state().mode)))
                                .arg(state().jobActive)
                                .arg(state().positionMm[0])
                                .arg(m_window->lastError())));
        auto *slider =
            m_window->outputsPanel()->findChild<QSlider *>(QStringLiteral("feedOverride"));
        slider->setValue(200);
        emit slider->sliderReleased();
        QTRY_COMPARE_WITH_TIMEOUT(state().overridePercent, 200, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(state().overrideCeilingPercent > 0, 10000);
        QLabel *value = nullptr;
        for (QLabel *l : m_window->outputsPanel()->findChildren<QLabel *>())
            value = l->text().startsWith(QStringLiteral("200 %")) ? l : value;
        QVERIFY(value);
        QTRY_VERIFY_WITH_TIMEOUT(value->text().contains(QStringLiteral("runs")), 5000);
        QVERIFY2(value->text().contains(QString::number(state().overrideCeilingPercent)),
                 qPrintable(value->text()));
        QVERIFY(value->toolTip().contains(QStringLiteral("serial link")));
        QVERIFY(finished.wait(120000));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QVERIFY(waitIdle());
        QVERIFY(!xm.isEmpty());
        for (qsizetype i = 0; i + 1 < xm.size(); ++i)
            QVERIFY2(xm[i].toInt() < 200, qPrintable(xm.join(QLatin1Char(' '))));
        QTRY_COMPARE_WITH_TIMEOUT(xm.last(), QStringLiteral("200"), 5000); // the operator's again
        QTRY_COMPARE(value->text(), QStringLiteral("200 %"));
        button(m_window->outputsPanel(), "feedReset")->click();
        QTRY_COMPARE_WITH_TIMEOUT(state().overridePercent, 100, 10000);
        QVERIFY(reconnect(fast));
        QSignalSpy home(m_window->controller(), &driver::MachineController::jobFinished);
        m_window->executeManualLine(QStringLiteral("G90 G0 X0 Y0 Z0"));
        QVERIFY(home.wait(kMachineTimeoutMs));
        QVERIFY(waitIdle());
    }

    // The actual-speed plot never shows a speed the machine cannot reach.
    void actualSpeedStaysWithinTheMachine()
    {
        const auto &axes = m_window->profile().axes;
        double reach = 0;
        for (int a = 0; a < 3; ++a)
            reach += axes[std::size_t(a)].maxSpeedMmPerMin * axes[std::size_t(a)].maxSpeedMmPerMin;
        reach = std::sqrt(reach);
        QVERIFY(waitIdle());
        QVERIFY(load(writeProgram(QStringLiteral("fast.nc"),
                                  "G21 G91\nG1 X20 Y20 F6000\nG1 X-20 Y-20\nM30\n")));
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        m_window->runProgram();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY2(m_window->speedPlot()->actual().size() > 10,
                 qPrintable(QStringLiteral("%1 samples, job %2, %3")
                                .arg(m_window->speedPlot()->actual().size())
                                .arg(finished.at(0).at(0).toBool())
                                .arg(m_window->lastError())));
        for (const SpeedSample &s : m_window->speedPlot()->actual())
            QVERIFY2(s.speedMmPerMin <= reach + 1e-6, qPrintable(QString::number(s.speedMmPerMin)));
    }

    // The speed plot's top label (its highest speed) is drawn whole (issue 14: "its top label
    // is cut off"): at the size the main window gives the plot and at the plot's smallest
    // height, for speeds of four to six digits, the label's box lies inside the widget and no
    // pixel of it is drawn on the widget's top row (a label whose ascent went above y = 0 would
    // be cut there).
    void speedPlotTopLabelIsWhole()
    {
        auto *dock = m_window->findChild<QDockWidget *>(QStringLiteral("plotDock"));
        QVERIFY(dock);
        dock->raise();
        SpeedPlot *inWindow = m_window->speedPlot();
        QTRY_VERIFY(inWindow->isVisible() && inWindow->height() >= inWindow->minimumHeight());
        const std::vector<SpeedSample> kept = inWindow->planned();
        const auto restore = qScopeGuard([&] {
            inWindow->setPlanned(kept);
            m_window->findChild<QDockWidget *>(QStringLiteral("consoleDock"))->raise();
        });
        SpeedPlot small;
        small.resize(inWindow->width(), small.minimumHeight());
        for (SpeedPlot *plot : {inWindow, &small}) {
            for (double top : {4000.0, 57300.0, 123456.0}) {
                plot->setPlanned({{0, 0, 1}, {50, top, 2}, {100, 0, 3}});
                const QString where =
                    QStringLiteral("%1x%2, top %3").arg(plot->width()).arg(plot->height()).arg(top);
                const QRect label = plot->topLabelRect();
                QVERIFY2(plot->rect().contains(label),
                         qPrintable(where + QStringLiteral(": label at %1,%2 %3x%4")
                                                .arg(label.x())
                                                .arg(label.y())
                                                .arg(label.width())
                                                .arg(label.height())));
                // What is drawn: the label's pixels, none on the top row.
                const QImage image = plot->grab().toImage();
                const QRgb background = image.pixel(0, image.height() / 2);
                int labelPixels = 0;
                for (int y = label.top(); y <= label.bottom(); ++y)
                    for (int x = label.left(); x <= label.right(); ++x)
                        labelPixels += image.pixel(x, y) != background ? 1 : 0;
                QVERIFY2(labelPixels > 0, qPrintable(where + QStringLiteral(": no label drawn")));
                for (int x = 0; x < image.width(); ++x)
                    QVERIFY2(image.pixel(x, 0) == background,
                             qPrintable(where +
                                        QStringLiteral(": drawn on the top row at x %1").arg(x)));
            }
        }
    }

    // The EEPROM dialog asks before "Write differences" writes: nothing goes to the unit until
    // the operator says yes; Cancel writes nothing.
    void eepromWriteAsksFirst()
    {
        QVERIFY(waitIdle());
        UnitConfigDialog *dlg = m_window->openUnitConfig();
        QSignalSpy finished(dlg, &UnitConfigDialog::finished);
        machine::MachineConfig changed = m_window->profile();
        changed.axes[1].stepsPerMm = 250;
        dlg->setProfile(changed);
        dlg->readUnit();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY(dlg->differences() >= 1);
        auto writes = [&] {
            int n = 0;
            for (const LogEntry &e : m_window->console()->entries())
                n += e.direction == LogDirection::Sent &&
                             (e.bytes.contains("EW") || e.bytes.contains("EFW") ||
                              e.bytes.contains("EUW"))
                         ? 1
                         : 0;
            return n;
        };
        const int before = writes();
        button(dlg, "eepromWriteDifferences")->click();
        auto *ask = dlg->findChild<QMessageBox *>(QStringLiteral("confirmEepromWrite"));
        QVERIFY(ask);
        QTRY_VERIFY(ask->isVisible());
        QTest::qWait(300);
        QCOMPARE(writes(), before); // nothing written while the question is open
        QVERIFY(!dlg->isBusy());
        ask->button(QMessageBox::Cancel)->click();
        QTest::qWait(300);
        QCOMPARE(writes(), before);
        QVERIFY(dlg->differences() >= 1);
        button(dlg, "eepromWriteDifferences")->click();
        ask = dlg->findChild<QMessageBox *>(QStringLiteral("confirmEepromWrite"));
        QVERIFY(ask);
        ask->button(QMessageBox::Yes)->click();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY2(finished.last().at(0).toBool(), qPrintable(dlg->statusText()));
        QCOMPARE(dlg->differences(), 0);
        QTRY_VERIFY(writes() > before);
        // Back to the profile's values for the tests after this one.
        dlg->setProfile(m_window->profile());
        dlg->readUnit();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        dlg->writeUnit(false);
        QVERIFY(finished.wait(kMachineTimeoutMs));
        dlg->close();
    }

    // In the Czech interface (chosen in the settings, as the operator does) an M0 banner and a
    // driver's refusal are Czech, with no English words of the driver left in them.
    void czechHoldBannerAndDriverError()
    {
        QVERIFY(waitIdle());
        SettingsDialog *settings = m_window->openSettings();
        settings->chooseLanguage(QStringLiteral("cs"));
        settings->close();
        QTRY_COMPARE(button(m_window->runPanel(), "run")->text(), QStringLiteral("Spustit"));
        QTRY_VERIFY(connectionText().contains(QStringLiteral("vestavěný emulátor")));
        QVERIFY(load(writeProgram(QStringLiteral("m0.nc"),
                                  "G21 G91\nG1 X1 F600\nM0 (zkontroluj hloubku)\nG1 X-1\nM30\n")));
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        const std::size_t logFrom = m_window->console()->entries().size();
        m_window->runProgram();
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Paused &&
                                     state().hold == driver::HoldReason::OperatorStop,
                                 kMachineTimeoutMs);
        QTRY_COMPARE(m_window->holdBanner()->kind(), HoldBanner::Kind::OperatorStop);
        // The machine's state changes in the console are Czech too.
        int czechStates = 0;
        const auto &log = m_window->console()->entries();
        for (std::size_t i = logFrom; i < log.size(); ++i) {
            const QString e = QString::fromUtf8(log[i].bytes);
            QVERIFY2(!e.startsWith(QLatin1String("mode: ")), qPrintable(e));
            czechStates += e.startsWith(QStringLiteral("Stav: Připraven → Obrábění")) ? 1 : 0;
        }
        QCOMPARE(czechStates, 1);
        const QString banner = m_window->holdBanner()->text();
        QVERIFY2(banner.contains(QStringLiteral("Programový stop (M0) na řádku 3")),
                 qPrintable(banner));
        QVERIFY2(banner.contains(QStringLiteral("zkontroluj hloubku")), qPrintable(banner));
        for (const char *english : {"Program stop", "line", "Continue"})
            QVERIFY2(!banner.contains(QLatin1String(english)), qPrintable(banner));
        // A refusal of the driver: lowering a tool that is not lifted.
        QSignalSpy errors(m_window.get(), &MainWindow::errorShown);
        m_window->controller()->toolLower(0);
        QVERIFY(errors.wait(10000));
        const QString error = m_window->lastError();
        QVERIFY2(error.contains(QStringLiteral("Spouštění nástroje")) &&
                     error.contains(QStringLiteral("nyní není možné")) &&
                     error.contains(QStringLiteral("Pozastaveno")),
                 qPrintable(error));
        for (const char *english : {"Lowering", "not possible", "Paused", "machine is"})
            QVERIFY2(!error.contains(QLatin1String(english)), qPrintable(error));
        button(m_window->holdBanner(), "holdContinue")->click();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        SettingsDialog *back = m_window->openSettings();
        back->chooseLanguage(QStringLiteral("en"));
        back->close();
        QTRY_COMPARE(button(m_window->runPanel(), "run")->text(), QStringLiteral("Run"));
    }

    // The EEPROM differences found on connecting are in the console once each, in the user's
    // words, with plain numbers (issue 14: "EEPROM differences are logged twice, once in each
    // language, with values like 'profile 10.000000'"), in English and again in Czech: a unit
    // (gve-emu on a pty, its EEPROM as shipped) that differs from the profile in Y's steps per mm
    // and the STEP/DIR polarity.
    void eepromDifferencesAreLoggedOncePerConnect()
    {
        const QString pty = ptyUnit();
        if (pty.isEmpty())
            QSKIP("gve-emu is not available");
        QVERIFY(waitIdle());
        const machine::MachineConfig original = m_window->profile();
        machine::MachineConfig differs = original;
        differs.link.port = pty.toStdString();
        differs.axes[1].stepsPerMm = 250;
        differs.eeprom.polarity = 0x5A;
        const auto restore = qScopeGuard([&] {
            SettingsDialog *settings = m_window->openSettings();
            settings->chooseLanguage(QStringLiteral("en"));
            settings->close();
            m_window->applyProfile(original, m_window->profilePath());
            (void)QTest::qWaitFor(
                [&] { return connectionText().contains(QStringLiteral("built-in")); }, 20000);
        });
        // The entries of the two settings changed here.
        machine::EepromEntry stepsY, polarity;
        for (const machine::EepromEntry &e : machine::eepromEntries(differs)) {
            if (e.what == "steps per mm Y")
                stepsY = e;
            if (e.kind == machine::EepromKind::Byte && e.value == 0x5A)
                polarity = e;
        }
        QVERIFY(!stepsY.what.empty() && !polarity.what.empty());
        // Each difference the unit reported, once, in console entries from `from` on; the two
        // made here with their captions and values as the unit shows them (a byte in hex).
        auto told = [&](std::size_t from, const QString &prefix, bool czech) {
            const auto &differences = state().eepromDifferences;
            QStringList problems;
            if (differences.size() < 2)
                problems << QStringLiteral("%1 differences").arg(differences.size());
            const auto &log = m_window->console()->entries();
            QStringList lines;
            for (std::size_t i = from; i < log.size(); ++i) {
                const QString e = QString::fromUtf8(log[i].bytes);
                if (e.contains(QStringLiteral("EEPROM")) &&
                    !(log[i].direction == LogDirection::Sent ||
                      log[i].direction == LogDirection::Received))
                    lines << e;
            }
            if (lines.size() != int(differences.size()))
                problems << QStringLiteral("%1 EEPROM lines for %2 differences")
                                .arg(lines.size())
                                .arg(differences.size());
            static const QRegularExpression kLong(QStringLiteral("\\d\\.\\d{5}"));
            static const QRegularExpression kEnglish(QStringLiteral("\\b(unit|profile|steps)\\b"),
                                                     QRegularExpression::CaseInsensitiveOption);
            for (const QString &line : std::as_const(lines)) {
                if (!line.startsWith(prefix))
                    problems << QStringLiteral("not in the user's words: ") + line;
                if (line.contains(kLong))
                    problems << QStringLiteral("long number: ") + line;
                if (czech && line.contains(kEnglish))
                    problems << QStringLiteral("English words: ") + line;
            }
            const auto variant = differs.unit.variant;
            const QStringList y = lines.filter(eepromLabel(variant, stepsY.address));
            if (y.size() != 1 || !y.front().contains(QStringLiteral("250")))
                problems << QStringLiteral("steps per mm Y (250) not told once");
            const QStringList p = lines.filter(eepromLabel(variant, polarity.address));
            if (p.size() != 1 || !p.front().contains(QStringLiteral("5A")) ||
                p.front().contains(QStringLiteral("90")))
                problems << QStringLiteral("polarity 5A not told once in hex");
            return problems.isEmpty() ? QString()
                                      : problems.join(QLatin1Char('\n')) + QStringLiteral("\n") +
                                            lines.join(QLatin1Char('\n'));
        };
        std::size_t from = m_window->console()->entries().size();
        m_window->applyProfile(differs, m_window->profilePath());
        QTRY_VERIFY_WITH_TIMEOUT(connectedTo(pty), 20000);
        QTRY_VERIFY(!state().eepromDifferences.empty());
        QTest::qWait(0);
        QString problems =
            told(from, QStringLiteral("Unit EEPROM differs from the profile: "), false);
        QVERIFY2(problems.isEmpty(), qPrintable(problems));
        // Again in Czech, on a new connect.
        SettingsDialog *settings = m_window->openSettings();
        settings->chooseLanguage(QStringLiteral("cs"));
        settings->close();
        QTRY_COMPARE(button(m_window->runPanel(), "run")->text(), QStringLiteral("Spustit"));
        m_window->disconnectFromUnit();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Disconnected, 10000);
        from = m_window->console()->entries().size();
        m_window->connectToUnit();
        QTRY_VERIFY_WITH_TIMEOUT(connectedTo(pty), 20000);
        QTRY_VERIFY(!state().eepromDifferences.empty());
        QTest::qWait(0);
        problems = told(from, QStringLiteral("EEPROM jednotky se liší od profilu: "), true);
        QVERIFY2(problems.isEmpty(), qPrintable(problems));
    }

    // A port set with Apply is connected at once on a serial line like the hardware's (gve-emu
    // on a pty, opened by its path): the pty's unit is read (its own firmware text) and Ready;
    // after a restart of the window with the same settings the pty is connected again (issue
    // 14: "after a restart the application silently uses the built-in emulator instead of the
    // last port; a new port set with Apply does not reconnect").
    void appliedPtyPortIsConnectedAndUsedAfterARestart()
    {
        const QString pty = ptyUnit();
        if (pty.isEmpty())
            QSKIP("gve-emu is not available");
        QVERIFY(waitIdle());
        QVERIFY2(connectionText().contains(QStringLiteral("built-in emulator")),
                 qPrintable(connectionText()));
        QCOMPARE(m_window->profile().link.port, std::string("emulator"));
        machine::MachineConfig config = m_window->profile();
        config.link.port = pty.toStdString();
        const qsizetype heard = ptyReceived().size();
        m_window->applyProfile(config, m_window->profilePath());
        QTRY_VERIFY2_WITH_TIMEOUT(connectedTo(pty), qPrintable(connectionText()), 20000);
        QVERIFY2(connectionText().contains(QStringLiteral("Ready")), qPrintable(connectionText()));
        QVERIFY(ptyReceived().mid(heard).contains("!0?")); // the unit on the pty was asked
        QCOMPARE(QSettings().value(QStringLiteral("link/port")).toString(), pty);
        // A restart: the saved profile still says the built-in emulator.
        m_window.reset();
        const qsizetype heardBefore = ptyReceived().size();
        m_window = std::make_unique<MainWindow>(windowOptions());
        m_window->show();
        QTRY_VERIFY2_WITH_TIMEOUT(connectedTo(pty), qPrintable(connectionText()), 20000);
        QVERIFY(ptyReceived().mid(heardBefore).contains("!0?"));
        QCOMPARE(m_window->profile().link.port, pty.toStdString()); // what the settings show
        // Applying the saved profile's port (the built-in emulator) connects it.
        const machine::ConfigResult saved =
            machine::loadMachineConfig(m_window->profilePath().toStdString());
        QVERIFY(saved.config);
        QCOMPARE(saved.config->link.port, std::string("emulator"));
        m_window->applyProfile(*saved.config, m_window->profilePath());
        QTRY_VERIFY2_WITH_TIMEOUT(state().mode == MachineMode::Idle &&
                                      connectionText().contains(QStringLiteral("built-in")),
                                  qPrintable(connectionText()), 20000);
        QCOMPARE(QSettings().value(QStringLiteral("link/port")).toString(),
                 QStringLiteral("emulator"));
    }

    // A multi-line error is shown on console lines, not with a literal "\n"; a good file clears
    // the previous file's error; after an abort no progress is left shown.
    void staleErrorsAndProgressAreCleared()
    {
        QVERIFY(waitIdle());
        QSignalSpy loaded(m_window->program(), &ProgramSession::loaded);
        m_window->openProgram(writeProgram(QStringLiteral("bad.nc"), "G21\nG1 X1 Q\nM30\n"));
        QVERIFY(loaded.wait(20000));
        QVERIFY(!m_window->lastError().isEmpty());
        QVERIFY(m_window->lastError().contains(QLatin1Char('\n')));
        const auto &log = m_window->console()->entries();
        const auto shown = std::find_if(log.rbegin(), log.rend(), [](const LogEntry &e) {
            return e.direction == LogDirection::Error;
        });
        QVERIFY(shown != log.rend());
        QVERIFY(shown->bytes.contains('\n'));
        const QString text = m_window->console()->formatEntry(*shown);
        QVERIFY2(!text.contains(QLatin1String("\\n")), qPrintable(text));
        QVERIFY(text.contains(QLatin1Char('\n')));
        QVERIFY(load(writeProgram(QStringLiteral("stepped.nc"), steppedProgram())));
        QVERIFY2(m_window->lastError().isEmpty(), qPrintable(m_window->lastError()));
        QVERIFY(m_window->statusBar()->currentMessage().isEmpty());
        const double x0 = state().positionMm[0];
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        m_window->runProgram();
        QTRY_VERIFY_WITH_TIMEOUT(state().positionMm[0] - x0 > 8, kMachineTimeoutMs);
        QVERIFY(progress() > 0);
        button(m_window->runPanel(), "abort")->click();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QCOMPARE(finished.at(0).at(0).toBool(), false);
        QVERIFY(waitIdle());
        QCOMPARE(progress(), 0);
        QCOMPARE(statusLine(), QString());
        // The stepped plunge back, planned from where the abort left the machine (it was planned
        // from the last poll's counters and the path guard held it).
        const double z0 = state().positionMm[2];
        QSignalSpy lineDone(m_window->controller(), &driver::MachineController::jobFinished);
        m_window->executeManualLine(QStringLiteral("G91 G1 Z1 F600"));
        QVERIFY(lineDone.wait(kMachineTimeoutMs));
        QCOMPARE(lineDone.at(0).at(0).toBool(), true);
        QVERIFY(waitIdle());
        QVERIFY(std::abs(state().positionMm[2] - (z0 + 1)) < 1e-3);
        m_window->executeManualLine(QStringLiteral("G90"));
    }

    // After a restart the port used last is used again (and the console says so), even when
    // it was only applied, never saved in the profile.
    void lastPortIsUsedAfterARestart()
    {
        QSettings().setValue(QStringLiteral("link/port"), QStringLiteral("/nonexistent/ttyLAST"));
        m_window.reset();
        MainWindowOptions options;
        options.view = MainWindowOptions::View::Software;
        options.restoreLayout = false;
        m_window = std::make_unique<MainWindow>(options);
        m_window->show();
        QTRY_VERIFY_WITH_TIMEOUT(connectionText().contains(QStringLiteral("/nonexistent/ttyLAST")),
                                 10000);
        bool told = false;
        for (const LogEntry &e : m_window->console()->entries())
            told = told || QString::fromUtf8(e.bytes).contains(QStringLiteral("port used last"));
        QVERIFY(told);
        // The window's profile names the port in use; the saved profile is unchanged.
        QCOMPARE(m_window->profile().link.port, std::string("/nonexistent/ttyLAST"));
        const machine::ConfigResult saved =
            machine::loadMachineConfig(m_window->profilePath().toStdString());
        QVERIFY(saved.config);
        QCOMPARE(saved.config->link.port, std::string("emulator"));
    }

    void cleanup()
    {
        if (state().mode != MachineMode::Idle && state().mode != MachineMode::Disconnected) {
            m_window->controller()->abort();
            waitIdle();
        }
    }

    void cleanupTestCase()
    {
        m_window.reset();
        m_emu.terminate();
        m_emu.waitForFinished(5000);
    }

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
    QProcess m_emu;      // gve-emu, once a test asks for the pty unit
    QString m_pty;       // its pty
    QByteArray m_emuLog; // its --verbose log read so far
};

QTEST_MAIN(ScreenTest)
#include "screen_test.moc"
