// The simulated handwheel of the built-in emulator on the whole main window (workflowfixture.h):
// with the Handwheel (MPG) switch on, - / + turn the emulated unit's wheel and its counters move
// by the detents times the step switch on the axis switch's axis; with the switch off the wheel
// moves nothing. Against gve-emu on a pty the control is hidden and a turn changes nothing.

#include "workflowfixture.h"

#include "gui/simulatedwheel.h"

#include <QComboBox>

class WorkflowWheelTest : public WorkflowFixture
{
    Q_OBJECT

    SimulatedWheel *wheel() const { return m_window->jogPanel()->findChild<SimulatedWheel *>(); }
    QCheckBox *mpgSwitch() const
    {
        return m_window->jogPanel()->findChild<QCheckBox *>(QStringLiteral("mpg"));
    }
    void setSwitches(int axis, int stepIndex)
    {
        wheel()->findChild<QComboBox *>(QStringLiteral("wheelAxis"))->setCurrentIndex(axis);
        wheel()->findChild<QComboBox *>(QStringLiteral("wheelStep"))->setCurrentIndex(stepIndex);
    }
    // Clicks - (detents < 0) or + |detents| times.
    void turn(int detents)
    {
        const char *name = detents < 0 ? "wheelMinus" : "wheelPlus";
        for (int i = 0; i < std::abs(detents); ++i)
            button(wheel(), name)->click();
    }
    // Waits until the link thread logged a line containing `text`, then for two more position
    // polls (snapshots) so that a move the turn started would show.
    bool waitForLog(QSignalSpy &log, const QString &text)
    {
        const bool found = QTest::qWaitFor(
            [&] {
                for (const QList<QVariant> &args : log) {
                    if (args.at(0).toString().contains(text))
                        return true;
                }
                return false;
            },
            kMachineTimeoutMs);
        QSignalSpy snapshots(m_window->controller(), &driver::MachineController::stateChanged);
        return found && (snapshots.count() >= 2 || snapshots.wait(kMachineTimeoutMs)) &&
               (snapshots.count() >= 2 || snapshots.wait(kMachineTimeoutMs));
    }

private slots:
    void wheelMovesTheEmulatorOnlyWithTheMpgOn()
    {
        // ctest runs it only on the built-in emulator (tests/gui/CMakeLists.txt).
        QVERIFY2(!m_pty, "the built-in emulator only: the pty run has onAPortTheWheelIsHidden");
        QVERIFY(waitIdle());
        QTRY_VERIFY(wheel()->isVisible());
        QVERIFY(wheel()->toolTip().contains(QStringLiteral("MPG")));
        WireTap wire;
        tapWire(wire);
        mpgSwitch()->click(); // the operator switches the handwheel on
        QTRY_VERIFY_WITH_TIMEOUT(state().mpgOn, kMachineTimeoutMs);
        QVERIFY2(wire.first(QRegularExpression(QStringLiteral("!0Y&(,[0-9A-F]{2})?"))) >= 0,
                 qPrintable(wire.sent.join(QLatin1Char('|'))));
        const auto start = state().positionSteps;

        setSwitches(1, 1); // Y, x10: 0.1 mm per detent
        turn(3);
        QTRY_VERIFY2_WITH_TIMEOUT(state().positionSteps[1] == start[1] + steps(1, 0.3),
                                  qPrintable(describe()), kMachineTimeoutMs);
        setSwitches(0, 0); // X, x1: 0.01 mm per detent
        turn(-2);
        QTRY_VERIFY2_WITH_TIMEOUT(state().positionSteps[0] == start[0] - steps(0, 0.02),
                                  qPrintable(describe()), kMachineTimeoutMs);
        QVERIFY(waitIdle());
        QCOMPARE(state().positionSteps[1], start[1] + steps(1, 0.3));
        QCOMPARE(state().positionSteps[2], start[2]);
        QVERIFY2(m_window->lastError().isEmpty(), qPrintable(m_window->lastError()));

        // Off: the same turn moves nothing, and the log says what to do.
        mpgSwitch()->click();
        QTRY_VERIFY_WITH_TIMEOUT(!state().mpgOn, kMachineTimeoutMs);
        QVERIFY(wire.first(QRegularExpression(QStringLiteral("!0Y-(,[0-9A-F]{2})?"))) >= 0);
        const auto off = state().positionSteps;
        QSignalSpy log(m_window->controller(), &driver::MachineController::logLine);
        setSwitches(1, 2); // Y, x100: 1 mm per detent
        turn(2);
        QVERIFY(waitForLog(log, QStringLiteral("ignored the turn")));
        QCOMPARE(state().positionSteps, off);
    }

    // On another port (gve-emu on a pty: the hardware path) there is no wheel to turn.
    void onAPortTheWheelIsHidden()
    {
        // ctest runs it only on the pty (tests/gui/CMakeLists.txt).
        QVERIFY2(m_pty, "the pty run only (FREZKA_WORKFLOW_UNIT=pty)");
        QVERIFY(waitIdle());
        QVERIFY(!wheel()->isVisible());
        const auto before = state().positionSteps;
        QSignalSpy log(m_window->controller(), &driver::MachineController::logLine);
        m_window->controller()->turnEmulatedWheel(0, 100, 1);
        QVERIFY(waitForLog(log, QStringLiteral("not connected to the built-in emulator")));
        QCOMPARE(state().positionSteps, before);
    }
};

QTEST_MAIN(WorkflowWheelTest)
#include "workflow_wheel_test.moc"
