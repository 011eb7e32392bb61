// The program as the operator handles it (issue 16 item 7) on the whole main window
// (workflowfixture.h): a program opened from the recent list, or as the command line opens it
// (a fresh window, before the unit has answered), is checked and planned like any other and runs
// to its end on the unit's counters; File › Reload reads the file again; a file changed on disk
// brings a prompt (after the job, when one runs) whose Reload runs the new version on the wire.

#include "workflowfixture.h"

#include "gui/holdbanner.h"
#include "gui/placementbar.h"
#include "gui/programinfodialog.h"
#include "gui/programlisting.h"
#include "gui/toolpathview.h"
#include "gui/toolpathviewmodel.h"

#include <QAction>
#include <QFile>
#include <QMenu>
#include <QMessageBox>
#include <QStatusBar>
#include <QTableWidget>
#include <QToolButton>

#include <optional>

class WorkflowProgramTest : public WorkflowFixture
{
    Q_OBJECT

    const LoadedProgram &program() const { return m_window->program()->program(); }

    // Rewrites a file in place (as an editor saving it does).
    static bool rewrite(const QString &path, const QByteArray &text)
    {
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly | QIODevice::Truncate))
            return false;
        return f.write(text) == text.size();
    }

    // Runs the loaded program to its end; true when the unit's counters end at x, y (mm).
    bool runsTo(double xMm, double yMm, std::optional<double> zMm = {})
    {
        if (!waitIdle() || !program().runnable())
            return false;
        QSignalSpy finished(m_window->workflow(), &session::RunWorkflow::jobFinished);
        m_window->runProgram();
        if (!finished.wait(kMachineTimeoutMs) || !finished.front().front().toBool())
            return false;
        return waitIdle() && state().positionSteps[0] == steps(0, xMm) &&
               state().positionSteps[1] == steps(1, yMm) &&
               (!zMm || state().positionSteps[2] == steps(2, *zMm));
    }

    QMessageBox *reloadPrompt() const
    {
        return m_window->findChild<QMessageBox *>(QStringLiteral("reloadPrompt"));
    }

private slots:
    void homeFirst()
    {
        QVERIFY(waitIdle());
        button(m_window->jogPanel(), "homeAll")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().homed && state().mode == MachineMode::Idle,
                                 kMachineTimeoutMs);
    }

    // Open recent: the same check and plan as File › Open (planned, estimated, runnable), and the
    // job runs to the program's end on the unit's counters.
    void aProgramFromTheRecentListIsCheckedAndPlanned()
    {
        const QString a = writeProgram(QStringLiteral("recent-a.nc"), "G21 G90\nG0 X12 Y4\nM2\n");
        const QString b = writeProgram(QStringLiteral("recent-b.nc"), "G21 G90\nG0 X3 Y3\nM2\n");
        QVERIFY(load(a));
        QVERIFY(load(b));
        QCOMPARE(program().path, b);
        auto *recent = m_window->findChild<QMenu *>(QStringLiteral("recentMenu"));
        QVERIFY(recent);
        QAction *openA = nullptr;
        for (QAction *action : recent->actions())
            if (action->text() == a)
                openA = action;
        QVERIFY(openA);
        QSignalSpy loaded(m_window->program(), &ProgramSession::loaded);
        openA->trigger();
        QVERIFY(loaded.wait(20000));
        QCOMPARE(program().path, a);
        QVERIFY(program().runnable());
        QVERIFY(program().estimatedS > 0);
        QVERIFY(program().planStats.vectors > 0);
        QCOMPARE(recent->actions().front()->text(), a);
        QVERIFY(runsTo(12, 4));
    }

    // The command line opens its program right after the window is made, before the unit has
    // answered (app/frezka/main.cpp): it is checked and planned as any other, and Check passes.
    void aProgramFromTheCommandLineIsCheckedAndPlanned()
    {
        if (m_pty)
            QSKIP("a second window cannot open the pty the first one holds");
        const QString path =
            writeProgram(QStringLiteral("cmdline.nc"), "G21 G90\nG0 X7 Y9\nG1 X8 F300\nM2\n");
        MainWindowOptions options;
        options.view = MainWindowOptions::View::Software;
        options.restoreLayout = false;
        MainWindow fresh(options);
        fresh.show();
        QSignalSpy loaded(fresh.program(), &ProgramSession::loaded);
        fresh.openProgram(path); // as main.cpp does
        QVERIFY(loaded.wait(20000));
        const LoadedProgram &p = fresh.program()->program();
        QVERIFY(p.runnable());
        QVERIFY(p.estimatedS > 0);
        QVERIFY(p.errors.empty());
        QVERIFY(fresh.findChild<QAction *>(QStringLiteral("reloadProgram"))->isEnabled());
        QTRY_COMPARE_WITH_TIMEOUT(fresh.controller()->state().mode, MachineMode::Idle, 20000);
        QSignalSpy checked(&fresh, &MainWindow::programChecked);
        fresh.checkProgram();
        QVERIFY(checked.wait(20000));
        QVERIFY(checked.front().front().toBool());
    }

    // File › Reload reads the file again; a change on disk prompts, and its Reload runs the new
    // version: the unit ends where the new text says.
    void reloadAndTheChangedFilePrompt()
    {
        const QString path = writeProgram(QStringLiteral("reload.nc"), "G21 G90\nG0 X5 Y5\nM2\n");
        QVERIFY(load(path));
        QVERIFY(runsTo(5, 5));
        // File › Reload, the file edited meanwhile (the prompt is answered by the reload).
        QVERIFY(rewrite(path, "G21 G90\nG0 X15 Y6\nM2\n"));
        QSignalSpy loaded(m_window->program(), &ProgramSession::loaded);
        m_window->findChild<QAction *>(QStringLiteral("reloadProgram"))->trigger();
        QVERIFY(loaded.wait(20000));
        QVERIFY(runsTo(15, 6));
        QVERIFY(!reloadPrompt()); // the edit was read by the reload: nothing to ask
        // Written on disk: the prompt; Reload loads and plans the new text, which runs.
        QVERIFY(rewrite(path, "G21 G90\nG0 X20 Y8\nG0 X21\nM2\n"));
        QTRY_VERIFY_WITH_TIMEOUT(reloadPrompt() && reloadPrompt()->isVisible(), 10000);
        QVERIFY(!reloadPrompt()->isModal());
        QVERIFY2(reloadPrompt()->text().contains(QStringLiteral("reload.nc")),
                 qPrintable(reloadPrompt()->text()));
        loaded.clear();
        reloadPrompt()->findChild<QPushButton *>(QStringLiteral("reloadYes"))->click();
        QVERIFY(loaded.wait(20000));
        QCOMPARE(program().text->lineCount(), 4); // was 3
        QVERIFY(runsTo(21, 8));
        QTRY_VERIFY(!reloadPrompt());
    }

    // Changed while its job runs: the job runs the version it has to its end, then the prompt.
    void aChangeDuringTheJobIsAskedAfterIt()
    {
        const QString path =
            writeProgram(QStringLiteral("during.nc"), "G21 G90\nG1 X60 Y2 F600\nG0 X2\nM2\n");
        QVERIFY(load(path));
        QVERIFY(waitIdle());
        QSignalSpy finished(m_window->workflow(), &session::RunWorkflow::jobFinished);
        m_window->runProgram();
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running, kMachineTimeoutMs);
        QVERIFY(rewrite(path, "G21 G90\nG0 X30 Y3\nM2\n"));
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY(finished.front().front().toBool());
        QVERIFY(waitIdle());
        QCOMPARE(state().positionSteps[0], steps(0, 2)); // the old version's end
        QTRY_VERIFY_WITH_TIMEOUT(reloadPrompt() && reloadPrompt()->isVisible(), 10000);
        QSignalSpy loaded(m_window->program(), &ProgramSession::loaded);
        reloadPrompt()->findChild<QPushButton *>(QStringLiteral("reloadYes"))->click();
        QVERIFY(loaded.wait(20000));
        QVERIFY(runsTo(30, 3));
    }

    // File › Program info: size, extent, the tools in their order with the planner's time and
    // cut length; the job then reaches exactly the extent it shows on the unit's counters.
    void programInfoShowsSizeExtentAndTools()
    {
        QVERIFY(waitIdle());
        const QString path = writeProgram(QStringLiteral("tools.nc"),
                                          "G21 G90\nT1 M6\nG0 X10 Y10\nG1 Z-2 F300\n"
                                          "G1 X30 F600\nT2 M6\nG1 Y40\nG0 Z0\nG0 X0 Y0\nM2\n");
        QVERIFY(load(path));
        QVERIFY(program().runnable());
        QAction *action = m_window->findChild<QAction *>(QStringLiteral("programInfo"));
        QVERIFY(action && action->isEnabled());
        action->trigger();
        auto *info = m_window->findChild<ProgramInfoDialog *>(QStringLiteral("programInfoDialog"));
        QVERIFY(info && info->isVisible() && !info->isModal());
        QVERIFY2(info->summary().contains(
                     QStringLiteral("tools.nc: 10 lines, %1 bytes").arg(QFileInfo(path).size())),
                 qPrintable(info->summary()));
        auto *extent = info->findChild<QTableWidget *>(QStringLiteral("programInfoExtent"));
        const auto cell = [](QTableWidget *t, int r, int c) { return t->item(r, c)->text(); };
        QCOMPARE(extent->rowCount(), 3);
        QCOMPARE(cell(extent, 0, 1) + QLatin1Char(' ') + cell(extent, 0, 2),
                 QStringLiteral("0.000 30.000"));
        QCOMPARE(cell(extent, 1, 1) + QLatin1Char(' ') + cell(extent, 1, 2),
                 QStringLiteral("0.000 40.000"));
        QCOMPARE(cell(extent, 2, 1) + QLatin1Char(' ') + cell(extent, 2, 2),
                 QStringLiteral("-2.000 0.000"));
        auto *tools = info->findChild<QTableWidget *>(QStringLiteral("programInfoTools"));
        QCOMPARE(tools->rowCount(), 2);
        QCOMPARE(cell(tools, 0, 0), QStringLiteral("T1"));
        QCOMPARE(cell(tools, 0, 1), QStringLiteral("2"));
        QCOMPARE(cell(tools, 0, 3), QStringLiteral("22.0"));
        QCOMPARE(cell(tools, 1, 0), QStringLiteral("T2"));
        QCOMPARE(cell(tools, 1, 1), QStringLiteral("6"));
        QCOMPARE(cell(tools, 1, 3), QStringLiteral("30.0"));
        const session::ProgramInfo pi =
            session::programInfo(program(), m_window->offsets()->state(), m_window->profile());
        QVERIFY(pi.tools[0].seconds > 0 && pi.tools[1].seconds > 0);
        QVERIFY(std::abs(pi.tools[0].seconds + pi.tools[1].seconds - program().estimatedS) <
                0.01 * program().estimatedS);
        info->close();
    }

    // The job of tools.nc, continued at both M6: the unit's counters reach exactly the extent
    // the Program info window shows.
    void theJobReachesTheShownExtent()
    {
        QVERIFY(waitIdle());
        QCOMPARE(QFileInfo(program().path).fileName(), QStringLiteral("tools.nc"));
        std::array<std::int64_t, 3> lo{state().positionSteps[0], state().positionSteps[1],
                                       state().positionSteps[2]},
            hi = lo;
        const auto track = connect(m_window->controller(), &driver::MachineController::stateChanged,
                                   this, [&](const driver::MachineState &s) {
                                       for (std::size_t a = 0; a < 3; ++a) {
                                           lo[a] = std::min(lo[a], s.positionSteps[a]);
                                           hi[a] = std::max(hi[a], s.positionSteps[a]);
                                       }
                                   });
        const auto untrack = qScopeGuard([&] { disconnect(track); });
        QSignalSpy finished(m_window->workflow(), &session::RunWorkflow::jobFinished);
        m_window->runProgram();
        for (const std::uint32_t line : {2u, 6u}) {
            QTRY_VERIFY2_WITH_TIMEOUT(state().mode == MachineMode::Paused &&
                                          state().hold == driver::HoldReason::OperatorStop &&
                                          state().holdLine == line,
                                      qPrintable(describe()), kMachineTimeoutMs);
            button(m_window->holdBanner(), "holdContinue")->click();
        }
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY(finished.front().front().toBool());
        QCOMPARE(hi[0], steps(0, 30));
        QCOMPARE(hi[1], steps(1, 40));
        QCOMPARE(lo[0], steps(0, 0));
        QCOMPARE(lo[2], steps(2, -2));
    }

    // A CAM program relative to its stock (safe height Z+5, X/Y around 0) on a machine whose
    // travel starts at 0: the bar says where it leaves the travel (the line), shows where it would
    // sit with the work zero at the chosen point of the stock here, and sets it in one step; the
    // program is then planned and runs on the unit with its centre where the tool stood.
    void aStockRelativeProgramGetsItsWorkZeroInOneStep()
    {
        QVERIFY(waitIdle());
        m_window->offsets()->setSystem(m_window->activeOffset(), {});
        for (const auto &[axis, mm] :
             {std::pair{0, 50.0}, std::pair{1, 40.0}, std::pair{2, -30.0}}) {
            m_window->jogStep(axis, mm - state().positionMm[std::size_t(axis)], 2000);
            QTRY_VERIFY_WITH_TIMEOUT(state().positionSteps[std::size_t(axis)] == steps(axis, mm),
                                     kMachineTimeoutMs);
            QVERIFY(waitIdle());
        }
        const QString path =
            writeProgram(QStringLiteral("stock.nc"), "G21 G90\nG0 Z5\nG0 X-10 Y-5\nG1 Z-1 F300\n"
                                                     "G1 X10 Y5 F600\nG0 Z5\nM2\n");
        QVERIFY(load(path));
        QVERIFY(!program().runnable()); // the planner refuses it at the soft limits
        PlacementBar *bar = m_window->placementBar();
        QTRY_VERIFY(bar->isVisible());
        QVERIFY2(bar->text().contains(QStringLiteral("Z goes to 5.000 mm at line 2")),
                 qPrintable(bar->text()));
        QVERIFY2(bar->text().contains(QStringLiteral("X goes to -10.000 mm at line 3")),
                 qPrintable(bar->text()));
        // At the program's own X0 Y0 here it would sit at X 40..60, Y 35..45, Z -31..-25.
        bar->setAnchor(session::StockAnchor::ProgramZero);
        session::Placement placed = bar->preview();
        QVERIFY(placed.inside);
        QCOMPARE(placed.minMm[0], 40.0);
        QCOMPARE(placed.maxMm[1], 45.0);
        QCOMPARE(placed.maxMm[2], -25.0);
        // Here as the front left corner: X 50..70, Y 40..50.
        bar->setAnchor(session::StockAnchor::FrontLeft);
        placed = bar->preview();
        QVERIFY(placed.inside);
        QCOMPARE(placed.minMm[0], 50.0);
        QCOMPARE(placed.maxMm[0], 70.0);
        QCOMPARE(placed.minMm[1], 40.0);
        QVERIFY2(bar->text().contains(QStringLiteral("X 50.000 … 70.000")),
                 qPrintable(bar->text()));
        QSignalSpy loaded(m_window->program(), &ProgramSession::loaded);
        QPushButton *here = button(bar, "placeHere");
        QVERIFY(here->isEnabled());
        here->click();
        QVERIFY(loaded.wait(20000));
        const session::Axes4 g54 = m_window->workOffsets()[std::size_t(m_window->activeOffset())];
        QCOMPARE(g54[0], 60.0);
        QCOMPARE(g54[1], 45.0);
        QCOMPARE(g54[2], -30.0);
        QVERIFY(!bar->isVisible());
        QVERIFY(program().runnable());
        QCOMPARE(m_window->dro()->findChild<QLabel *>(QStringLiteral("droWorkX"))->text(),
                 QStringLiteral("-10.000")); // the corner
        // The job: its last line (G0 Z5 above X10 Y5) ends at machine X 70, Y 50, Z -25.
        QVERIFY2(runsTo(70, 50, -25), qPrintable(describe()));
    }

    // Shift into the travel: the least shift of the offset that puts the program inside.
    void orShiftedIntoTheTravel()
    {
        QVERIFY(waitIdle());
        m_window->offsets()->setSystem(m_window->activeOffset(), {});
        QSignalSpy loaded(m_window->program(), &ProgramSession::loaded);
        QVERIFY(loaded.wait(20000)); // the new offset reads the program again
        PlacementBar *bar = m_window->placementBar();
        QTRY_VERIFY(bar->isVisible());
        loaded.clear();
        button(bar, "placeFit")->click();
        QVERIFY(loaded.wait(20000));
        const session::Axes4 g54 = m_window->workOffsets()[std::size_t(m_window->activeOffset())];
        QCOMPARE(g54[0], 10.0);
        QCOMPARE(g54[1], 5.0);
        QCOMPARE(g54[2], -5.0);
        QVERIFY(!bar->isVisible());
        QVERIFY2(runsTo(20, 10, 0), qPrintable(describe()));
        m_window->offsets()->setSystem(m_window->activeOffset(), {});
    }

    // Issue 17 item 4: Cancel in the status bar stops a load at any moment (here a program that
    // never ends, still being interpreted); the program loaded before stays, the window says so,
    // and that program still runs to its end on the unit.
    void aLoadCancelledFromTheStatusBarKeepsTheProgramBefore()
    {
        const QString kept =
            writeProgram(QStringLiteral("kept.nc"), "G21 G90\nG0 X5 Y5 Z0\nG1 X6 F600\nM2\n");
        QVERIFY(load(kept));
        QVERIFY(program().runnable());
        const QString endless =
            writeProgram(QStringLiteral("endless.nc"), "G21 F100\no1 while [1]\nG1 X1\nG1 X0\n"
                                                       "o1 endwhile\nM2\n");
        QSignalSpy cancelled(m_window->program(), &ProgramSession::loadCancelled);
        QSignalSpy loaded(m_window->program(), &ProgramSession::loaded);
        m_window->openProgram(endless);
        QVERIFY(m_window->program()->isLoading());
        auto *progress = m_window->findChild<QWidget *>(QStringLiteral("loadProgress"));
        QVERIFY(progress && progress->isVisible());
        auto *cancel = progress->findChild<QToolButton *>(QStringLiteral("loadCancel"));
        QVERIFY(cancel && cancel->isVisible());
        cancel->click();
        QCOMPARE(cancelled.count(), 1);
        QVERIFY(!m_window->program()->isLoading());
        QVERIFY(!progress->isVisible());
        QCOMPARE(program().path, kept);
        QVERIFY(program().runnable());
        const QString file = m_window->findChild<QLabel *>(QStringLiteral("programFile"))->text();
        QVERIFY2(file.startsWith(QStringLiteral("kept.nc — 4 line")), qPrintable(file));
        const QString message = m_window->statusBar()->currentMessage();
        QVERIFY2(message ==
                     QStringLiteral("Loading endless.nc was cancelled; kept.nc stays loaded."),
                 qPrintable(message));
        QCOMPARE(loaded.count(), 0);
        QVERIFY2(runsTo(6, 5, 0), qPrintable(describe()));
    }
};

QTEST_MAIN(WorkflowProgramTest)
#include "workflow_program_test.moc"
