// The workflows of jogging and homing on the whole main window (workflowfixture.h): jogs before
// homing ignore the soft limits, homing can be stopped and the position follows, a continuous
// jog's release is no alarm. From a fresh, unhomed unit, in this order.

#include "workflowfixture.h"

#include "driver/emulator/serialtrace.h"
#include "driver/link/tracerecorder.h"

class WorkflowJogTest : public WorkflowFixture
{
    Q_OBJECT

private slots:
    // Before homing the soft limits refer to nothing (issue 14: "with the shipped profiles (X min
    // 0, Z max 0) the machine cannot be jogged X/Y negative or Z up until it has been homed"):
    // the jog panel says the limits are off, and the X- and Z+ jog buttons move the unit from 0
    // past those limits: the L goes on the wire and the unit's counters end there exactly.
    void unhomedJogIgnoresTheSoftLimits()
    {
        QVERIFY(waitIdle());
        QCOMPARE(int(state().homedAxes), 0);
        const auto &axes = m_window->profile().axes;
        QCOMPARE(axes[0].softMinMm, 0.0); // the shipped GVE64 profile
        QCOMPARE(axes[2].softMaxMm, 0.0);
        auto *limitsOff = m_window->jogPanel()->findChild<QLabel *>(QStringLiteral("limitsOff"));
        QTRY_VERIFY(limitsOff->isVisible());
        QVERIFY2(limitsOff->text().startsWith(QStringLiteral("XYZ not homed")),
                 qPrintable(limitsOff->text()));
        QCOMPARE(m_window->jogPanel()->stepMm(), 1.0);
        for (const auto &[axis, name, mm] :
             {std::tuple{0, "jogXMinus", -1.0}, std::tuple{2, "jogZPlus", 1.0}}) {
            QVERIFY(waitIdle());
            const std::int64_t from = state().positionSteps[std::size_t(axis)];
            QCOMPARE(from, std::int64_t(0));
            WireTap wire;
            tapWire(wire);
            button(m_window->jogPanel(), name)->click();
            QTRY_VERIFY2_WITH_TIMEOUT(
                state().positionSteps[std::size_t(axis)] == steps(axis, mm),
                qPrintable(describe() + QLatin1Char(' ') + QLatin1String(name)), kMachineTimeoutMs);
            QVERIFY(waitIdle());
            QVERIFY2(m_window->lastError().isEmpty(), qPrintable(m_window->lastError()));
            std::array<std::int64_t, 3> d{};
            d[std::size_t(axis)] = steps(axis, mm);
            const QString jog = QStringLiteral("!0L%1,%2,%3").arg(d[0]).arg(d[1]).arg(d[2]);
            QVERIFY2(
                wire.first(QRegularExpression(jog + QStringLiteral("(,0)?(,[0-9A-F]{2})?"))) >= 0,
                qPrintable(jog + QStringLiteral(" not in ") + wire.sent.join(QLatin1Char('|'))));
            if (m_pty)
                QVERIFY(emulatorReceived().contains(jog.toLatin1()));
        }
        QVERIFY(limitsOff->isVisible());
        // Back to 0 for the workflows after this one.
        button(m_window->jogPanel(), "jogXPlus")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().positionSteps[0] == 0, kMachineTimeoutMs);
        QVERIFY(waitIdle());
        button(m_window->jogPanel(), "jogZMinus")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().positionSteps[2] == 0, kMachineTimeoutMs);
        QVERIFY(waitIdle());
    }

    // Homing can be stopped from the window (Stop is enabled, Esc works), the position display
    // follows the axes meanwhile, and the axes then count as not homed (issue 14).
    void homingCanBeStoppedAndThePositionFollows()
    {
        QVERIFY(waitIdle());
        const double zStart = state().positionMm[2];
        m_window->jogStep(2, -20, 1200); // Z 20 mm further from its switch: homing takes seconds
        QTRY_VERIFY_WITH_TIMEOUT(std::abs(state().positionMm[2] - (zStart - 20)) < 1e-3,
                                 kMachineTimeoutMs);
        QVERIFY(waitIdle());
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        const double z0 = state().positionMm[2];
        QVERIFY(button(m_window->jogPanel(), "homeAll")->isEnabled());
        button(m_window->jogPanel(), "homeAll")->click();
        QTRY_VERIFY2_WITH_TIMEOUT(state().mode == MachineMode::Homing, qPrintable(describe()),
                                  10000);
        QTRY_VERIFY_WITH_TIMEOUT(state().positionMm[2] > z0 + 1, 10000); // the display moves
        QVERIFY(button(m_window->runPanel(), "stop")->isEnabled());
        QVERIFY(button(m_window->runPanel(), "abort")->isEnabled());
        QTest::keyClick(m_window.get(), Qt::Key_Escape);
        QTRY_VERIFY2_WITH_TIMEOUT(state().mode == MachineMode::Idle, qPrintable(describe()), 5000);
        QVERIFY(!state().homed);
        QCOMPARE(int(state().homedAxes), 0);
        QVERIFY(
            m_window->jogPanel()->findChild<QLabel *>(QStringLiteral("limitsOff"))->isVisible());
    }

    // Holding a jog button with "Continuous" chosen moves the axis until it is released, and the
    // release is the operator's stop: straight back to Idle, no alarm and no error on the way
    // (issue 14: each release logged "Jogging -> Alarm -> Idle").
    void continuousJogReleaseIsNoAlarm()
    {
        QVERIFY(waitIdle());
        QStringList log;
        auto tap = connect(m_window->controller(), &driver::MachineController::logLine, this,
                           [&log](const QString &line) { log << line; });
        QSignalSpy errors(m_window->controller(), &driver::MachineController::errorOccurred);
        auto radio = [this](const char *name) {
            return m_window->jogPanel()->findChild<QRadioButton *>(QLatin1String(name));
        };
        radio("jogContinuous")->click();
        const double x0 = state().positionMm[0];
        QPushButton *plus = button(m_window->jogPanel(), "jogXPlus");
        QTest::mousePress(plus, Qt::LeftButton);
        QTRY_VERIFY_WITH_TIMEOUT(state().positionMm[0] > x0 + 0.5, 10000);
        QTest::mouseRelease(plus, Qt::LeftButton);
        QVERIFY(waitIdle());
        QSignalSpy polls(m_window->controller(), &driver::MachineController::stateChanged);
        QTRY_VERIFY(polls.count() >= 5); // a few polls after the stop
        disconnect(tap);
        QCOMPARE(state().mode, MachineMode::Idle);
        QCOMPARE(errors.count(), 0);
        const QStringList modes = log.filter(QStringLiteral("mode: "));
        QVERIFY2(modes.filter(QStringLiteral("Alarm")).isEmpty(), qPrintable(modes.join('\n')));
        QVERIFY2(!modes.isEmpty(), "the mode changes are logged");
        QVERIFY(state().positionMm[0] > x0 + 0.5);
        radio("jogStep2")->click(); // the default step again for the tests after
    }

    // Machine › Save serial trace (issue 21): the session's record of the line, with the jogs
    // above on it as the unit saw them, and what the window showed.
    void theSerialTraceHoldsTheJogs()
    {
        QVERIFY(waitIdle());
        QTemporaryDir dir;
        const QString path = dir.filePath(QStringLiteral("saved.trace"));
        QString error;
        QVERIFY2(m_window->saveSerialTrace(path, &error), qPrintable(error));
        QFile f(path);
        QVERIFY(f.open(QIODevice::ReadOnly));
        emulator::SerialTrace trace;
        emulator::TraceMessage bad;
        QVERIFY2(emulator::parseTrace(f.readAll().toStdString(), trace, bad),
                 emulator::englishText(bad).c_str());
        QCOMPARE(trace.value("variant"), std::string("gve64"));
        QCOMPARE(trace.value("firmware"), state().firmware);
        int jogs = 0, jogging = 0;
        for (std::size_t i = 0; i + 1 < trace.entries.size(); ++i) {
            const emulator::TraceEntry &e = trace.entries[i];
            if (e.direction == emulator::TraceDirection::ToUnit && e.bytes.rfind("!0L", 0) == 0 &&
                e.bytes.rfind("!0L0,0,0", 0) != 0) {
                ++jogs;
                QCOMPARE(trace.entries[i + 1].direction, emulator::TraceDirection::ToPc);
            }
            jogging += e.direction == emulator::TraceDirection::Event && e.bytes == "mode Jogging";
        }
        QVERIFY2(jogs >= 3, qPrintable(QString::number(jogs))); // X-, Z+, and the continuous one
        QVERIFY(jogging >= 3);
        driver::TraceRecorder::session().setLimitBytes(0);
        QVERIFY(!m_window->saveSerialTrace(path, &error));
        QVERIFY2(error.contains(QStringLiteral("Settings")), qPrintable(error));
        driver::TraceRecorder::session().setLimitBytes(driver::TraceRecorder::kDefaultLimitBytes);
    }
};

QTEST_MAIN(WorkflowJogTest)
#include "workflow_jog_test.moc"
