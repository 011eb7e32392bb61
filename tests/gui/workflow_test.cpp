// The operator's workflows of issue 6 on the whole main window against the emulated unit in real
// time (workflowfixture.h: the built-in emulator, or gve-emu on a pty), one window for the whole
// run, like an operator's day: run before homing asks to home first; homed marks on a new link;
// connect -> open -> check -> home -> run; pause -> tool lift -> resume; jog and soft-limit
// refusal; the program's outputs; the sample programs; work zero; the console's modes; Run, Esc
// and Stop. The panels and the program's check are in workflow_panels_test.cpp, jogging and
// homing from an unhomed unit in workflow_jog_test.cpp.

#include "workflowfixture.h"

class WorkflowTest : public WorkflowFixture
{
    Q_OBJECT

private slots:
    // Run before homing with the profile's default (motion.runBeforeHoming false) asks to home
    // first (issue 14: "a program can be run before homing with no word of warning"). Cancel:
    // nothing of the job (nor homing) goes on the wire and the unit stays; "Home and run": the
    // homing legs (W) go on the wire and reach the unit before any vector of the job, and the
    // job ends with the unit's counters exactly at the program's end.
    void runBeforeHomingAsksToHomeFirst()
    {
        QVERIFY(waitIdle());
        QVERIFY(!m_window->profile().motion.runBeforeHoming);
        QVERIFY(!state().homed);
        QVERIFY(load(writeProgram(QStringLiteral("homefirst.nc"), "G21 G90\n"
                                                                  "G1 X10 Y10 Z-2 F1200\n"
                                                                  "G1 X22.5 Y17.25\n"
                                                                  "G1 Z-1\n"
                                                                  "M30\n")));
        QVERIFY(m_window->program()->program().runnable());
        // The driver logs a packet of vectors (C, and B between them) as "packet of ...".
        const QRegularExpression homing(QStringLiteral("!0W.*"));
        const QRegularExpression vector(QStringLiteral("(!0C|packet of ).*"));
        const auto start = state().positionSteps;
        const QByteArray emuBefore = m_pty ? emulatorReceived() : QByteArray();
        auto ask = [this]() -> QMessageBox * {
            QMessageBox *box = nullptr;
            (void)QTest::qWaitFor(
                [&] {
                    box = m_window->findChild<QMessageBox *>(QStringLiteral("askToHome"));
                    return box && box->isVisible();
                },
                5000);
            return box && box->isVisible() ? box : nullptr;
        };
        QPushButton *run = button(m_window->runPanel(), "run");
        {
            WireTap wire;
            tapWire(wire);
            run->click();
            QPointer<QMessageBox> box = ask();
            QVERIFY(box);
            QCOMPARE(box->button(QMessageBox::Yes)->text(), MainWindow::tr("Home and run"));
            box->button(QMessageBox::Cancel)->click();
            QTRY_VERIFY(!box || !box->isVisible());
            QSignalSpy polls(m_window->controller(), &driver::MachineController::stateChanged);
            QTRY_VERIFY(polls.count() >= 5); // the link runs on: the job would have been sent
            QCOMPARE(state().mode, MachineMode::Idle);
            QVERIFY(!state().jobActive);
            QCOMPARE(state().positionSteps, start);
            // Only the polls (position, flags, inputs) went on the wire.
            const QRegularExpression poll(QRegularExpression::anchoredPattern(
                QStringLiteral("!0(P|PF|P4|F|I1|I2|SR6)(,[0-9A-F]{2})?")));
            QVERIFY(!wire.sent.isEmpty());
            for (const QString &command : std::as_const(wire.sent))
                QVERIFY2(poll.match(command).hasMatch(), qPrintable(command));
            if (m_pty)
                QCOMPARE(emulatorReceived().mid(emuBefore.size()).indexOf("!0W"), -1);
        }
        WireTap wire;
        tapWire(wire);
        QSignalSpy started(m_window->workflow(), &session::RunWorkflow::jobStarted);
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        int sentAtStart = -1;
        auto mark = connect(m_window->workflow(), &session::RunWorkflow::jobStarted, this,
                            [&] { sentAtStart = int(wire.sent.size()); });
        const auto unmark = qScopeGuard([&] { disconnect(mark); });
        run->click();
        QPointer<QMessageBox> box = ask();
        QVERIFY(box);
        box->button(QMessageBox::Yes)->click();
        QVERIFY2(finished.wait(kMachineTimeoutMs), qPrintable(describe()));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QVERIFY(waitIdle());
        QCOMPARE(started.size(), 1);
        // On the wire: homing legs, then the job's vectors, none of them before the last leg.
        const int firstW = wire.first(homing), lastW = wire.last(homing);
        const int firstVector = wire.first(vector);
        QVERIFY2(firstW >= 0 && firstVector > lastW && sentAtStart > lastW,
                 qPrintable(QStringLiteral("W %1..%2, first vector %3, job started at %4: %5")
                                .arg(firstW)
                                .arg(lastW)
                                .arg(firstVector)
                                .arg(sentAtStart)
                                .arg(wire.sent.join(QLatin1Char('|')))));
        if (m_pty) {
            // The unit received them in that order too.
            const QByteArray in = emulatorReceived().mid(emuBefore.size());
            const qsizetype w = in.lastIndexOf("!0W");
            QVERIFY2(w >= 0 && in.indexOf("!0*S") > w, in.right(2000).constData());
        }
        QVERIFY(state().homed);
        // The unit's counters at the program's end, exactly.
        const auto &plan = m_window->program()->program().unitProgram;
        QVERIFY(plan && !plan->commands.empty());
        const machine::Steps4 end = plan->commands.back().endSteps;
        QCOMPARE(end[0], steps(0, 22.5));
        QCOMPARE(end[1], steps(1, 17.25));
        QCOMPARE(end[2], steps(2, -1));
        QTRY_VERIFY2_WITH_TIMEOUT(state().positionSteps[0] == end[0] &&
                                      state().positionSteps[1] == end[1] &&
                                      state().positionSteps[2] == end[2],
                                  qPrintable(describe()), 10000);
    }

    // "Homed" belongs to one link's unit: homed marks are shown once homed, and after Disconnect
    // and Connect (a new link; a fresh unit on the built-in emulator) no axis is marked homed and
    // the limits are off again (issue 14: "The 'homed' marks stay green after Disconnect and
    // Connect to a fresh, unhomed unit").
    void homedMarksAreClearedOnANewLink()
    {
        QVERIFY(waitIdle());
        if (!state().homed) {
            button(m_window->jogPanel(), "homeAll")->click();
            QTRY_VERIFY_WITH_TIMEOUT(state().homed && state().mode == MachineMode::Idle,
                                     kMachineTimeoutMs);
        }
        auto *limitsOff = m_window->jogPanel()->findChild<QLabel *>(QStringLiteral("limitsOff"));
        QTRY_VERIFY(homedMarksShown(0b111));
        QTRY_VERIFY(!limitsOff->isVisible());
        m_window->disconnectFromUnit();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Disconnected, 10000);
        m_window->connectToUnit();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Idle, 20000);
        QVERIFY(!state().firmware.empty());
        QTRY_VERIFY(homedMarksShown(0));
        QTRY_VERIFY(limitsOff->isVisible());
        QVERIFY(!state().homed);
        QCOMPARE(int(state().homedAxes), 0);
    }

    void openCheckHomeRunToTheEnd()
    {
        const QString path = writeProgram(QStringLiteral("square.nc"), R"(G21 G90
G0 X10 Y10
G1 Z-2 F600
G1 X30 F2400
G1 Y25
G1 X10
G1 Y10
G0 Z-1
G0 X22.5 Y17.25
M30
)");
        QVERIFY(load(path));
        QVERIFY2(m_window->program()->program().runnable(), qPrintable(m_window->lastError()));
        QSignalSpy checked(m_window.get(), &MainWindow::programChecked);
        m_window->checkProgram();
        QVERIFY(checked.wait(20000));
        QCOMPARE(checked.at(0).at(0).toBool(), true);
        // Home Z alone (its own button), then all axes in the profile's order.
        button(m_window.get(), "homeZ")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().homedAxes == 0b100 && state().mode == MachineMode::Idle,
                                 kMachineTimeoutMs);
        QVERIFY(!state().homed);
        button(m_window.get(), "homeAll")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().homed && state().mode == MachineMode::Idle,
                                 kMachineTimeoutMs);
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        m_window->runProgram();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QVERIFY(waitIdle());
        // The DRO ends at the program's end point (work = machine with G54 = 0 here).
        QTRY_COMPARE(m_window->dro()->workText(0), QStringLiteral("22.500"));
        QTRY_COMPARE(m_window->dro()->workText(1), QStringLiteral("17.250"));
        QTRY_COMPARE(m_window->dro()->workText(2), QStringLiteral("-1.000"));
    }

    void pauseToolLiftResumeEndsAtTheSamePoint()
    {
        const QString path = writeProgram(QStringLiteral("long.nc"), R"(G21 G90
G0 X5 Y5
G1 Z-20 F600
G1 X60 F1200
G1 Y40
G1 X5
G1 Y5
G0 Z-15.5
G0 X40 Y30
M30
)");
        QVERIFY(load(path));
        QVERIFY(m_window->program()->program().runnable());
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        m_window->runProgram();
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running &&
                                     state().positionMm[2] < -19.9 && state().positionMm[0] > 20,
                                 kMachineTimeoutMs);
        button(m_window->runPanel(), "pause")->click();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Paused, kMachineTimeoutMs);
        QTRY_COMPARE(m_window->holdBanner()->kind(), HoldBanner::Kind::Paused);
        const double zBefore = state().positionMm[2];
        button(m_window->holdBanner(), "holdLift")->click();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::ToolLifted, kMachineTimeoutMs);
        QTRY_COMPARE(m_window->holdBanner()->kind(), HoldBanner::Kind::ToolLifted);
        QTRY_VERIFY2(std::abs(state().positionMm[2] - zBefore -
                              m_window->profile().motion.toolLiftMm) < 1e-6,
                     qPrintable(describe() + QStringLiteral(" z before %1").arg(zBefore)));
        button(m_window->holdBanner(), "holdLowerContinue")->click();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QVERIFY(waitIdle());
        QTRY_COMPARE(m_window->dro()->workText(0), QStringLiteral("40.000"));
        QTRY_COMPARE(m_window->dro()->workText(1), QStringLiteral("30.000"));
        QTRY_COMPARE(m_window->dro()->workText(2), QStringLiteral("-15.500"));
        QVERIFY(m_window->holdBanner()->isHidden());
    }

    void jogAndSoftLimitRefusal()
    {
        QVERIFY(waitIdle());
        const double x0 = state().positionMm[0];
        m_window->jogStep(0, 1.0, 1200);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(state().positionMm[0] - (x0 + 1.0)) < 1e-6,
                                 kMachineTimeoutMs);
        QVERIFY(waitIdle());
        const double beyond = m_window->profile().axes[0].softMaxMm - state().positionMm[0] + 5;
        m_window->jogStep(0, beyond, 1200);
        QVERIFY(m_window->lastError().contains(QStringLiteral("soft limits")));
        QTest::qWait(0);
        QCOMPARE(state().mode, MachineMode::Idle);
        QCOMPARE(state().positionMm[0], x0 + 1.0);
    }

    // Issue 14: the lights and buttons show what the program switched on the unit (M3, M8),
    // and a pause with "Stop the spindle" ticked switches the spindle off and says so.
    void outputsFollowTheProgram()
    {
        QVERIFY(waitIdle());
        const QString path = writeProgram(QStringLiteral("m3m8.nc"), R"(G21 G90
M3 S12000
M8
G0 X5 Y5
G1 Z-5 F600
G1 X60 F600
G1 Y30
G0 Z-1
M9
M5
M30
)");
        QVERIFY(load(path));
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        m_window->runProgram();
        const std::uint8_t coolant =
            machine::outputBit(m_window->profile(), machine::OutputFunction::Coolant);
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running && state().spindleOn &&
                                     (state().outputs & coolant) == 0,
                                 kMachineTimeoutMs);
        QTRY_VERIFY(m_window->ioPanel()->outputLed(0)); // OUT0: the spindle
        QTRY_VERIFY(m_window->ioPanel()->outputLed(1)); // OUT1: coolant in the default profile
        QTRY_VERIFY(button(m_window->outputsPanel(), "spindle")->isChecked());
        QTRY_VERIFY(button(m_window->outputsPanel(), "coolant")->isChecked());
        button(m_window->runPanel(), "pause")->click();
        QTRY_COMPARE_WITH_TIMEOUT(m_window->holdBanner()->kind(), HoldBanner::Kind::Paused,
                                  kMachineTimeoutMs);
        QTRY_VERIFY_WITH_TIMEOUT(!state().spindleOn && state().outputsHeld, kMachineTimeoutMs);
        QTRY_VERIFY(!m_window->ioPanel()->outputLed(0));
        QTRY_VERIFY(!m_window->ioPanel()->outputLed(1));
        QTRY_VERIFY(!button(m_window->outputsPanel(), "spindle")->isChecked());
        QVERIFY(m_window->holdBanner()
                    ->findChild<QLabel *>(QStringLiteral("holdSpindle"))
                    ->text()
                    .contains(QStringLiteral("off for the hold")));
        // Unticking the box switches them on again at once, ticking it off again.
        auto *box =
            m_window->holdBanner()->findChild<QCheckBox *>(QStringLiteral("holdStopSpindle"));
        QVERIFY(box && box->isChecked());
        box->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().spindleOn && (state().outputs & coolant) == 0,
                                 kMachineTimeoutMs);
        QTRY_VERIFY(m_window->ioPanel()->outputLed(0));
        box->click();
        QTRY_VERIFY_WITH_TIMEOUT(!state().spindleOn && state().outputsHeld, kMachineTimeoutMs);
        button(m_window->holdBanner(), "holdContinue")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().spindleOn, kMachineTimeoutMs);
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QTRY_VERIFY(!m_window->ioPanel()->outputLed(0));
        QTRY_VERIFY(!m_window->ioPanel()->outputLed(1));
        QTRY_VERIFY(!button(m_window->outputsPanel(), "coolant")->isChecked());
    }

    // Every shipped sample program checks clean against the default profile; the short one runs
    // to completion from the GUI.
    void samplePrograms()
    {
        QVERIFY(waitIdle());
        const QDir dir(QStringLiteral(FREZKA_SOURCE_DIR "/resources/programs"));
        const QStringList files = dir.entryList({QStringLiteral("*.nc")}, QDir::Files);
        QVERIFY(files.size() >= 2);
        for (const QString &f : files) {
            QVERIFY(load(dir.filePath(f)));
            const LoadedProgram &p = m_window->program()->program();
            QVERIFY2(p.runnable(), qPrintable(f + QStringLiteral(": ") + m_window->lastError()));
            QVERIFY(p.estimatedS > 0);
            qInfo("%s: %d lines, estimated %.1f s", qPrintable(f), p.text->lineCount(),
                  p.estimatedS);
        }
        if (qgetenv("FREZKA_WORKFLOW_UNIT") == "pty")
            QSKIP("The sample run is covered by the built-in emulator run.");
        QVERIFY(load(dir.filePath(QStringLiteral("engraving-star.nc"))));
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        m_window->runProgram();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QVERIFY(waitIdle());
        // Ends at X0 Y0 Z3 of its own G54 (X100 Y100 Z-60 in machine coordinates).
        QTRY_COMPARE(m_window->dro()->machineText(0), QStringLiteral("100.000"));
        QTRY_COMPARE(m_window->dro()->machineText(1), QStringLiteral("100.000"));
        QTRY_COMPARE(m_window->dro()->machineText(2), QStringLiteral("-57.000"));
    }

    // Work zero per axis and for all, persisted, per offset G54..G59.
    void workZero()
    {
        QVERIFY(waitIdle());
        const auto pos = state().positionMm;
        button(m_window->dro(), "zeroX")->click();
        QCOMPARE(m_window->dro()->workText(0), QStringLiteral("0.000"));
        QCOMPARE(m_window->workOffsets()[0][0], pos[0]);
        QCOMPARE(m_window->dro()->workText(1), QString::number(pos[1], 'f', 3));
        button(m_window->dro(), "zeroAll")->click();
        QCOMPARE(m_window->dro()->workText(1), QStringLiteral("0.000"));
        QCOMPARE(m_window->dro()->workText(2), QStringLiteral("0.000"));
        const QVariantList saved = QSettings().value(QStringLiteral("workOffsets")).toList();
        QCOMPARE(saved.size(), 24);
        QCOMPARE(saved[2].toDouble(), pos[2]);
        m_window->selectWorkOffset(1); // G55 is still zero: work = machine
        QCOMPARE(m_window->dro()->workText(0), QString::number(pos[0], 'f', 3));
        QCOMPARE(QSettings().value(QStringLiteral("activeOffset")).toInt(), 1);
        m_window->selectWorkOffset(0);
        QCOMPARE(m_window->dro()->workText(0), QStringLiteral("0.000"));
    }

    // The console keeps its modes between lines as LinuxCNC's MDI does (G91, G20, F).
    void consoleKeepsItsModes()
    {
        QVERIFY(waitIdle());
        const double x0 = state().positionMm[0];
        auto line = [&](const char *text, bool moves) {
            QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
            m_window->executeManualLine(QLatin1String(text));
            if (moves) {
                QVERIFY2(finished.wait(kMachineTimeoutMs), qPrintable(describe()));
                QCOMPARE(finished.at(0).at(0).toBool(), true);
            }
            QVERIFY(waitIdle());
        };
        line("G91", false);
        line("G1 X1 F600", true);
        line("G1 X1", true);
        QVERIFY2(std::abs(state().positionMm[0] - (x0 + 2)) < 1e-3, qPrintable(describe()));
        line("G20", false);
        line("X-1", true); // G1, incremental, inches
        QVERIFY2(std::abs(state().positionMm[0] - (x0 + 2 - 25.4)) < 1e-2, qPrintable(describe()));
        line("G21 G90", false);
    }

    // The Run button drives the session's run workflow (the class frezka-cli run drives): the
    // machine was jogged away from where the plan starts, so it plans again from there first.
    void runButtonDrivesTheSessionWorkflow()
    {
        QVERIFY(waitIdle());
        QVERIFY(load(writeProgram(QStringLiteral("rel.nc"), "G21 G91\nG1 X2 F600\nG1 X-2\nM2\n")));
        QVERIFY(m_window->program()->program().runnable());
        const double x0 = state().positionMm[0];
        m_window->jogStep(0, 1.0, 600);
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(state().positionMm[0] - (x0 + 1)) < 1e-3,
                                 kMachineTimeoutMs);
        QVERIFY(waitIdle());
        auto *workflow = m_window->workflow();
        QSignalSpy started(workflow, &session::RunWorkflow::jobStarted);
        QSignalSpy finished(workflow, &session::RunWorkflow::jobFinished);
        QSignalSpy messages(workflow, &session::RunWorkflow::message);
        button(m_window->runPanel(), "run")->click();
        QVERIFY2(finished.wait(kMachineTimeoutMs), qPrintable(describe()));
        QCOMPARE(finished.at(0).at(0).toBool(), true);
        QCOMPARE(started.size(), 1);
        QStringList said;
        for (const auto &m : messages)
            said << m.at(0).toString();
        QVERIFY2(said.contains(session::RunWorkflow::tr("Planning from the current position…")),
                 qPrintable(said.join(QLatin1Char('|'))));
        QVERIFY(waitIdle());
        QVERIFY(std::abs(state().positionMm[0] - (x0 + 1)) < 1e-3); // there and back
    }

    // Esc is the controlled stop from anywhere in the window (issue 14): the job is held along
    // the ramp, kept and resumable, not dropped; Stop in the run panel does the same.
    void escStopsARunAndTheJobCanResume()
    {
        QVERIFY(waitIdle());
        QVERIFY(state().homed); // homed earlier: Run does not ask for homing
        QVERIFY(
            load(writeProgram(QStringLiteral("long.nc"), "G21 G90\nG1 X60 Y5 F300\nG1 X1\nM2\n")));
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        button(m_window->runPanel(), "run")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running, kMachineTimeoutMs);
        QTest::keyClick(m_window.get(), Qt::Key_Escape);
        QTRY_VERIFY2_WITH_TIMEOUT(state().mode == MachineMode::Paused, qPrintable(describe()),
                                  10000);
        QCOMPARE(state().hold, driver::HoldReason::User);
        QVERIFY2(state().jobActive, "Esc holds the job, it does not drop it");
        // The machine stands: the position read after the hold no longer changes (the state
        // published with Paused may still carry a poll from while it braked).
        QTest::qWait(300);
        const double held = state().positionMm[0];
        QTest::qWait(500);
        QCOMPARE(state().positionMm[0], held);
        QVERIFY(button(m_window->runPanel(), "resume")->isEnabled());
        // Resume, then the Stop button: the same controlled stop (it used to abort the job).
        button(m_window->runPanel(), "resume")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running, 10000);
        button(m_window->runPanel(), "stop")->click();
        QTRY_VERIFY2_WITH_TIMEOUT(state().mode == MachineMode::Paused, qPrintable(describe()),
                                  10000);
        QVERIFY2(state().jobActive, "Stop holds the job, it does not drop it");
        m_window->workflow()->abort();
        QVERIFY(waitIdle());
    }

    // The operator clicks Run with the mouse, then presses Space or Enter (meaning something
    // else): no run button has the keyboard focus, so the job runs on.
    void spaceOrEnterNeverPressARunButton()
    {
        QVERIFY(waitIdle());
        QVERIFY(
            load(writeProgram(QStringLiteral("long2.nc"), "G21 G90\nG1 X60 Y5 F300\nG1 X1\nM2\n")));
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        QTest::mouseClick(button(m_window->runPanel(), "run"), Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running, kMachineTimeoutMs);
        for (Qt::Key key : {Qt::Key_Space, Qt::Key_Return, Qt::Key_Enter}) {
            QWidget *focus = QApplication::focusWidget();
            QVERIFY2(!focus || !m_window->runPanel()->isAncestorOf(focus),
                     qPrintable(focus->objectName()));
            QTest::keyClick(focus ? focus : m_window.get(), key);
        }
        QTest::qWait(500);
        QCOMPARE(state().mode, MachineMode::Running);
        m_window->workflow()->abort();
        QVERIFY(waitIdle());
    }
};

QTEST_MAIN(WorkflowTest)
#include "workflow_test.moc"
