// What the screen says (issue 14 items 5 and 6), on the whole main window against the built-in
// emulator in real time (screenfixture.h): the current line, progress and cut drawing follow the
// unit through a pause, a tool lift and a resume; M6 and M0 are named with their line, tool and
// comment; a console line leaves the loaded program's display alone; an override the link
// cannot feed is shown as held; the speeds shown stay within the machine; stale errors and
// progress are cleared. The language and the EEPROM are in screen_words_test.cpp, the connection
// and the ports in screen_ports_test.cpp.

#include "screenfixture.h"

#include "gui/outputspanel.h"

#include <QSlider>

class ScreenTest : public ScreenFixture
{
    Q_OBJECT

private slots:
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
            // The line whose X range holds the unit's X as the window shows it (lines 1-2 are the
            // plunge): between polls the DRO, the listing and the cut drawing follow the driver's
            // model of the unit (MachineState::live), ahead of the last poll by up to a poll's age.
            const double x = s.shownMm()[0] - x0;
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
        const bool cutting = QTest::qWaitFor(
            [&] { return state().jobActive && state().positionMm[0] > 20; }, kMachineTimeoutMs);
        QVERIFY2(cutting, qPrintable(QStringLiteral("%1 job %2 X %3 error %4")
                                         .arg(QLatin1String(driver::machineModeName(state().mode)))
                                         .arg(state().jobActive)
                                         .arg(state().positionMm[0])
                                         .arg(m_window->lastError())));
        auto *slider =
            m_window->outputsPanel()->findChild<QSlider *>(QStringLiteral("feedOverride"));
        slider->setValue(200);
        emit slider->sliderReleased();
        QTRY_COMPARE_WITH_TIMEOUT(state().overridePercent, 200, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(state().overrideHeldPercent() > 0, 10000);
        QLabel *value = nullptr;
        for (QLabel *l : m_window->outputsPanel()->findChildren<QLabel *>())
            value = l->text().startsWith(QStringLiteral("200 %")) ? l : value;
        QVERIFY(value);
        QTRY_VERIFY_WITH_TIMEOUT(value->text().contains(QStringLiteral("runs")), 5000);
        QVERIFY2(value->text().contains(QString::number(state().overrideHeldPercent())),
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
};

QTEST_MAIN(ScreenTest)
#include "screen_test.moc"
