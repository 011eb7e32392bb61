// The status panel (issue 16 item 1) on the whole main window (workflowfixture.h) while a job
// runs on the emulated unit: the state in words and colour, the actual feed on a long cut
// against the planned feed and against the unit's own counters, the spindle speed the driver
// sent, the tool of the program's M6, coolant, the program's modes at the line being cut, the
// homed axes and the connection.

#include "workflowfixture.h"

#include "gui/statuspanel.h"

#include <QDockWidget>
#include <QElapsedTimer>

class WorkflowStatusTest : public WorkflowFixture
{
    Q_OBJECT

    QString label(const char *name) const
    {
        auto *l = m_window->statusPanel()->findChild<QLabel *>(QLatin1String(name));
        return l ? l->text() : QStringLiteral("(no label %1)").arg(QLatin1String(name));
    }
    QString stateStyle() const
    {
        return m_window->statusPanel()
            ->findChild<QLabel *>(QStringLiteral("statusState"))
            ->styleSheet();
    }
    bool says(driver::MachineMode mode) const
    {
        return label("statusState") == session::RunWorkflow::modeText(mode) &&
               stateStyle().contains(StatusPanel::stateColour(mode));
    }

private slots:
    void thePanelIsShownWithTheStateAndTheConnection()
    {
        QVERIFY(waitIdle());
        auto *dock = m_window->findChild<QDockWidget *>(QStringLiteral("statusDock"));
        QVERIFY(dock);
        QVERIFY(dock->isVisible());
        QTRY_VERIFY(says(MachineMode::Idle));
        QCOMPARE(StatusPanel::stateColour(MachineMode::Idle), QStringLiteral("#2e7d32"));
        QVERIFY(StatusPanel::stateColour(MachineMode::Alarm) !=
                StatusPanel::stateColour(MachineMode::Running));
        const QString where = label("statusConnection");
        if (m_pty)
            QVERIFY2(where.contains(QString::fromStdString(m_window->profile().link.port)),
                     qPrintable(where));
        else
            QCOMPARE(where, MainWindow::tr("built-in emulator"));
        QCOMPARE(label("statusSpindle"), StatusPanel::tr("off"));
    }

    void homingShowsTheHomedAxes()
    {
        button(m_window->jogPanel(), "homeAll")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().homed && state().mode == MachineMode::Idle,
                                 kMachineTimeoutMs);
        QTRY_COMPARE(label("statusHomed"), QStringLiteral("X Y Z"));
    }

    // A job with a tool change, the spindle, coolant and a 200 mm cut at F1200: the panel's
    // figures against the plan, the wire and the unit's counters.
    void aJobShowsItsFiguresAsTheUnitRunsThem()
    {
        QVERIFY(load(writeProgram(QStringLiteral("status.nc"), "G21 G90 G94\n"
                                                               "T2 M6\n"
                                                               "M3 S12000\n"
                                                               "M8\n"
                                                               "G0 X10 Y10\n"
                                                               "G0 Z-2\n"
                                                               "G1 X210 F1200\n"
                                                               "G1 Y20\n"
                                                               "G0 Z0\n"
                                                               "M9\n"
                                                               "M5\n"
                                                               "M2\n")));
        QTRY_VERIFY(label("statusModes").startsWith(QLatin1String("G80 G17 G40 G21 G90 G94 G54")));
        WireTap wire;
        tapWire(wire);
        button(m_window->runPanel(), "run")->click();
        // The M6: held, in amber, with the tool asked for still to come.
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Paused &&
                                     state().hold == driver::HoldReason::OperatorStop,
                                 kMachineTimeoutMs);
        QTRY_VERIFY(says(MachineMode::Paused));
        m_window->workflow()->resume();
        // The long cut: line 7, running.
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running && state().sourceLine == 7,
                                 kMachineTimeoutMs);
        QTRY_VERIFY(says(MachineMode::Running));
        QTest::qWait(1500); // past the ramp, the smoothing window full
        QVERIFY2(state().sourceLine == 7, qPrintable(describe()));
        // The unit's own counters over three seconds: the speed it runs.
        const double x0 = state().positionMm[0];
        QElapsedTimer clock;
        clock.start();
        QTest::qWait(3000);
        const double unitMmPerMin = (state().positionMm[0] - x0) / (clock.elapsed() / 60000.0);
        const double shown = m_window->statusPanel()->shownActualFeed();
        QVERIFY2(state().sourceLine == 7, qPrintable(describe()));
        QVERIFY2(std::abs(shown - 1200.0) <= 24.0, qPrintable(QString::number(shown)));
        QVERIFY2(std::abs(unitMmPerMin - shown) <= 0.03 * shown,
                 qPrintable(QStringLiteral("unit %1, shown %2").arg(unitMmPerMin).arg(shown)));
        QCOMPARE(label("statusFeed"), StatusPanel::tr("%1 mm/min").arg(shown, 0, 'f', 0));
        QVERIFY2(label("statusProgrammedFeed").contains(QLatin1String("1200 mm/min")),
                 qPrintable(label("statusProgrammedFeed")));
        // The spindle: what the driver sent (12000 of 24000 rpm: !7V500) and the panel says.
        QVERIFY2(wire.first(QRegularExpression(QStringLiteral("!7V500(,[0-9A-F]{2})?"))) >= 0,
                 qPrintable(wire.sent.join(QLatin1Char('|')).right(600)));
        QVERIFY(state().spindleOn);
        QCOMPARE(state().spindleRpm, 12000.0);
        QVERIFY2(label("statusSpindle").contains(QLatin1String("12000 rpm")) &&
                     label("statusSpindle").contains(QLatin1String("M3")),
                 qPrintable(label("statusSpindle")));
        QCOMPARE(label("statusTool"), QStringLiteral("T2"));
        QVERIFY2(label("statusModes").startsWith(QLatin1String("G1 G17 G40 G21 G90 G94 G54")) &&
                     label("statusModes").endsWith(QLatin1String("M3 M8")),
                 qPrintable(label("statusModes")));
        QVERIFY(state().outputOn(m_window->profile(), machine::OutputFunction::Coolant));
        QVERIFY2(label("statusOutputs").contains(MainWindow::tr("Coolant") + QStringLiteral(" on")),
                 qPrintable(label("statusOutputs")));
        // The end: ready again, the spindle off, nothing moving.
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY(waitIdle());
        QTRY_VERIFY(says(MachineMode::Idle));
        QTRY_COMPARE(label("statusSpindle"), StatusPanel::tr("off"));
        QCOMPARE(label("statusFeed"), StatusPanel::tr("%1 mm/min").arg(0));
    }

    // Issue 16 item 5: the spindle override beside the feed override scales the turning spindle at
    // once (!7V on the wire; gve-emu on a pty receives it) and the program's later speeds (S6000
    // of 24000 rpm: !7V250 at 100 %, !7V300 at 120 %), and the status panel says so.
    void spindleOverrideScalesTheSpindleAndTheRestOfTheJob()
    {
        QVERIFY(waitIdle());
        QVERIFY(load(writeProgram(QStringLiteral("spindle.nc"), "G21 G90\n"
                                                                "M3 S12000\n"
                                                                "G0 X10 Y10\n"
                                                                "G0 Z-2\n"
                                                                "G1 X60 F600\n"
                                                                "S6000\n"
                                                                "G1 X10\n"
                                                                "G0 Z0\n"
                                                                "M5\n"
                                                                "M2\n")));
        WireTap wire;
        tapWire(wire);
        const QByteArray emuBefore = m_pty ? emulatorReceived() : QByteArray();
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        button(m_window->runPanel(), "run")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running && state().sourceLine == 5,
                                 kMachineTimeoutMs);
        auto *slider =
            m_window->outputsPanel()->findChild<QSlider *>(QStringLiteral("spindleOverride"));
        QVERIFY(slider);
        slider->setValue(120);
        emit slider->sliderReleased();
        QTRY_COMPARE_WITH_TIMEOUT(state().spindlePermille, 600, 10000);
        QVERIFY2(state().sourceLine == 5, qPrintable(describe())); // at once, in the cut
        QCOMPARE(state().spindleRpm, 14400.0);
        QTRY_VERIFY2(label("statusSpindle").contains(QLatin1String("14400 rpm")) &&
                         label("statusSpindle").contains(QLatin1String("120 %")),
                     qPrintable(label("statusSpindle")));
        QTRY_COMPARE_WITH_TIMEOUT(state().spindlePermille, 300, kMachineTimeoutMs);
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY(waitIdle());
        auto sent = [&](const char *v) {
            return wire.first(
                QRegularExpression(QStringLiteral("!7V%1(,[0-9A-F]{2})?").arg(QLatin1String(v))));
        };
        const QString log = wire.sent.join(QLatin1Char('|')).right(600);
        QVERIFY2(sent("500") >= 0 && sent("500") < sent("600") && sent("600") < sent("300"),
                 qPrintable(log));
        QVERIFY2(sent("250") < 0, qPrintable(log)); // the program's S6000 never unscaled
        if (m_pty) {
            const QByteArray received = emulatorReceived().mid(emuBefore.size());
            QVERIFY(received.contains("!7V600") && received.contains("!7V300"));
        }
        button(m_window->outputsPanel(), "spindleOverrideReset")->click();
        QTRY_COMPARE(state().spindleOverridePercent, 100);
        QCOMPARE(slider->value(), 100);
    }
};

QTEST_MAIN(WorkflowStatusTest)
#include "workflow_status_test.moc"
