// A job run from the window on the built-in emulator on a virtual clock (issue 17 item 3,
// MainWindowOptions::Clock::Virtual, frezka --clock virtual): the spiral of bench_gui_load
// (40 000 lines, some 220 s of machine time) runs in seconds of wall time. At every slice of the
// clock during the job the listing shows the line of the command the driver models as cut, that
// line is the one the emulator is cutting (within the lines the machine cuts between two
// states), and the ETA is the planner's model of what is left; at the end the emulator's
// counters are the program's end, nothing braked late or ran dry, and the job's (virtual) time
// is the estimate's. A port is refused on the virtual clock.

#include "gui/jogpanel.h"
#include "gui/mainwindow.h"
#include "gui/programlisting.h"
#include "gui/runpanel.h"

#include "spiralprogram.h"
#include "windowtest.h"

#include "session/virtualclocklink.h"

#include <QPushButton>
#include <QTemporaryDir>
#include <QTest>

#include <cmath>
#include <cstdlib>
#include <vector>

using namespace frezka;
using namespace frezka::gui;
using driver::MachineMode;

namespace {

constexpr long kLines = 40'000;
constexpr int kWallTimeoutMs = 240'000; // a loaded machine; the job itself takes seconds
// The most machine time the listing may lag the emulator's cut: the driver's model between two
// polls (20 Hz, pollIntervalS) and the reply's way on the wire, five polls' room (measured:
// under 0.05 s). The ETA reads the polled line, which a busy wire polls less often (the poller
// defers polls to the job's commands): ten polls' room (measured: under 0.16 s).
constexpr double kListingLagS = 0.25;
constexpr double kEtaLagS = 0.5;

} // namespace

class WorkflowVirtualClockTest : public QObject
{
    Q_OBJECT

    QTemporaryDir m_dir;

    // A window on the virtual clock and the default profile (the built-in emulator), settings
    // in m_dir; null when it does not come up.
    std::unique_ptr<MainWindow> virtualWindow(const machine::MachineConfig *profile = nullptr)
    {
        test::isolateSettings(m_dir, QStringLiteral("FrezkaVirtualClockTest"));
        QSettings().clear();
        QSettings().setValue(QStringLiteral("link/autoReconnect"), false);
        if (profile && !test::useProfile(m_dir, *profile))
            return nullptr;
        MainWindowOptions options;
        options.view = MainWindowOptions::View::Software;
        options.restoreLayout = false;
        options.clock = MainWindowOptions::Clock::Virtual;
        auto window = std::make_unique<MainWindow>(options);
        window->show();
        return window;
    }

private slots:
    void aSpiralRunsFromTheWindowOnTheVirtualClock()
    {
        auto window = virtualWindow();
        QVERIFY(window && window->virtualClock());
        QTRY_VERIFY_WITH_TIMEOUT(window->machineState().mode == MachineMode::Idle, 30000);
        session::SimLink *sim = window->virtualClock()->sim();
        QVERIFY(sim);
        test::button(window->jogPanel(), "homeAll")->click();
        QTRY_VERIFY_WITH_TIMEOUT(window->machineState().homed &&
                                     window->machineState().mode == MachineMode::Idle,
                                 30000);

        const QString path = m_dir.filePath(QStringLiteral("spiral.nc"));
        QVERIFY(test::writeSpiral(path, kLines));
        QVERIFY(test::openAndWait(window.get(), path));
        QVERIFY(window->program()->program().runnable());

        const emulator::Stats before = sim->port().unit().stats();
        QSignalSpy finished(window->workflow(), &session::RunWorkflow::jobFinished);
        // The plan the job runs (planned again from the homed position first, when it differs
        // from the plan's start): captured when the job starts.
        std::shared_ptr<const machine::UnitProgram> plan;
        double estimateS = -1;
        std::vector<float> lineEndS;
        std::vector<std::uint32_t> motionLine; // the source line of each motion command, in order
        connect(window->workflow(), &session::RunWorkflow::jobStarted, this, [&] {
            const LoadedProgram &p = window->program()->program();
            plan = p.unitProgram;
            estimateS = p.estimatedS;
            lineEndS = p.lineEndS;
            for (const machine::UnitCommand &c : plan->commands)
                if (c.op == machine::UnitOp::Vector || c.op == machine::UnitOp::Line ||
                    c.op == machine::UnitOp::Probe)
                    motionLine.push_back(c.sourceLine);
        });

        // Each slice's end, after the window has shown the state (it is connected first).
        int samples = 0;
        double worstEtaS = 0, worstBehindS = 0;
        long worstAhead = -1'000'000;
        QStringList failures;
        connect(
            window->virtualClock(), &session::VirtualClockLink::sliceEnded, this,
            [&](const driver::MachineState &s) {
                if (!plan || !s.jobActive || s.mode != MachineMode::Running || !s.live.modelled)
                    return;
                ++samples;
                // The listing follows the job's executing command (the driver's model).
                const int listed = window->listing()->currentLine();
                const auto &cmd = plan->commands[std::size_t(s.live.command)];
                if (listed != int(cmd.sourceLine))
                    failures << QStringLiteral("listing at %1, the executing command's line %2")
                                    .arg(listed)
                                    .arg(cmd.sourceLine);
                // ... which is the line the emulator cuts, or one it has cut: the model
                // is never ahead of the unit's counters by more than the command ending at
                // this instant, and behind them by what the machine cuts between two
                // states (the poll's period, some tens of ms of machine time).
                const std::int64_t done = sim->port().unit().stats().motion.vectorsExecuted -
                                          before.motion.vectorsExecuted;
                const std::uint32_t cutting = motionLine[std::size_t(
                    std::min<std::int64_t>(done, std::int64_t(motionLine.size()) - 1))];
                auto endOf = [&](std::uint32_t line) {
                    return line == 0
                               ? 0.0
                               : double(lineEndS[std::min<std::size_t>(line, lineEndS.size() - 1)]);
                };
                const long ahead = long(listed) - long(cutting);
                // From the start of the listed line to the start of the one being cut.
                const double behindS =
                    endOf(cutting - 1) - endOf(std::uint32_t(std::max(listed, 1)) - 1);
                worstAhead = std::max(worstAhead, ahead);
                worstBehindS = std::max(worstBehindS, behindS);
                if (ahead > 1 || behindS > kListingLagS)
                    failures << QStringLiteral("listing at line %1, the emulator cuts %2")
                                    .arg(listed)
                                    .arg(cutting);
                // The ETA shown is the planner's model of what is left (the planned time to
                // the end after the line being cut, counting down through it) at the line
                // the state reports: between the model at the emulator's line and at the
                // start of the reported line: the lines between them and the one being cut
                // (1 ms of room: lineEndS are floats).
                const double eta = window->runPanel()->remainingS();
                const double least = estimateS - endOf(cutting) - 0.001;
                const double most = estimateS - endOf(s.sourceLine - 1) + 0.001;
                const double etaLagS = endOf(cutting - 1) - endOf(s.sourceLine - 1);
                worstEtaS = std::max(worstEtaS, etaLagS);
                if (eta < least || eta > most || etaLagS > kEtaLagS)
                    failures << QStringLiteral("ETA %1 s, the model's %2..%3 s")
                                    .arg(eta)
                                    .arg(least)
                                    .arg(most);
                if (qEnvironmentVariableIsSet("FREZKA_TEST_VERBOSE"))
                    qInfo("job %.3f s: line %u (listed %d, emulator %u), ETA %.3f s "
                          "(model %.3f..%.3f s)",
                          window->workflow()->jobElapsedS(), s.sourceLine, listed, cutting, eta,
                          least, most);
            });

        window->runProgram();
        QVERIFY2(finished.wait(kWallTimeoutMs), "the job did not end");
        QVERIFY(finished.front().front().toBool());
        QVERIFY(plan);
        qInfo("%d slices sampled; the listing at most %ld line(s) ahead of the emulator's cut "
              "and %.3f s of machine time behind it; the ETA's line %.3f s behind at most",
              samples, worstAhead, worstBehindS, worstEtaS);
        QVERIFY2(failures.isEmpty(), qPrintable(failures.mid(0, 5).join(QStringLiteral("; "))));
        QVERIFY2(samples >= 5, qPrintable(QString::number(samples)));

        // The end: the emulator's counters are the program's end, every vector ran once, none
        // braked late, the queue never ran dry, and the job took the estimate's time.
        const emulator::Stats after = sim->port().unit().stats();
        QCOMPARE(sim->port().unit().position(), plan->commands.back().endSteps);
        QCOMPARE(after.motion.vectorsExecuted - before.motion.vectorsExecuted,
                 std::int64_t(motionLine.size()));
        QCOMPARE(after.motion.brakeViolations - before.motion.brakeViolations, std::int64_t(0));
        QCOMPARE(after.motion.starvationStops - before.motion.starvationStops,
                 machine::plannedRestarts(*plan));
        const double jobS = window->workflow()->jobElapsedS();
        qInfo("job %.3f s (virtual), estimate %.3f s", jobS, estimateS);
        QVERIFY2(std::abs(jobS - estimateS) <= 0.005 * estimateS,
                 qPrintable(QStringLiteral("%1 s against %2 s").arg(jobS).arg(estimateS)));
        QTRY_COMPARE_WITH_TIMEOUT(window->listing()->currentLine(),
                                  int(plan->commands.back().sourceLine), 5000);
        QVERIFY(window->virtualClock()->longestSliceMs() < 1000);
    }

    // A port never runs on the virtual clock: the window says so and opens nothing.
    void aPortIsRefusedOnTheVirtualClock()
    {
        machine::MachineConfig profile = machine::defaultMachineConfig(protocol::Variant::Gve64);
        profile.link.port = m_dir.filePath(QStringLiteral("ttyS-virtual")).toStdString();
        auto window = virtualWindow(&profile);
        QVERIFY(window);
        QTRY_VERIFY_WITH_TIMEOUT(!window->lastError().isEmpty(), 10000);
        QVERIFY2(window->lastError().contains(QStringLiteral("--clock virtual")),
                 qPrintable(window->lastError()));
        QVERIFY(window->lastError().contains(QString::fromStdString(profile.link.port)));
        QVERIFY(!window->virtualClock()->sim()); // nothing connected
        QCOMPARE(window->machineState().mode, MachineMode::Disconnected);
    }
};

QTEST_MAIN(WorkflowVirtualClockTest)
#include "workflow_virtualclock_test.moc"
