// Run from a line (issue 16 item 2) on the whole main window (workflowfixture.h): the listing's
// "Run from this line…" on line 18 of a program with a tool change, a work offset and G91
// before it loads the job (the preview shows the approach), Run runs it through the run
// workflow: on the wire the spindle comes on before any motion, the machine's polled positions
// show the safe approach as the first motion (across at the safe height, then down onto the
// line's start), and the unit's counters end on exactly the whole program's planned end; the
// program is whole again afterwards. A line inside a loop is refused with the line to choose.

#include "workflowfixture.h"

#include "../session/runfromline_program.h"

#include "gui/programlisting.h"

#include <QAction>
#include <QMenu>

class WorkflowFromLineTest : public WorkflowFixture
{
    Q_OBJECT

    std::array<std::int64_t, 4> wholeEndSteps;

private slots:
    void homeFirst()
    {
        button(m_window->jogPanel(), "homeAll")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().homed && state().mode == MachineMode::Idle,
                                 kMachineTimeoutMs);
    }

    void theListingOffersTheLine()
    {
        QVERIFY(
            load(writeProgram(QStringLiteral("fromline.nc"), frezka::test::kRunFromLineProgram)));
        const LoadedProgram &whole = m_window->program()->program();
        QVERIFY(whole.runnable());
        QVERIFY(!whole.fromLine);
        wholeEndSteps = whole.unitProgram->commands.back().endSteps;
        ProgramListing *listing = m_window->listing();
        QSignalSpy asked(listing, &ProgramListing::runFromLineRequested);
        // The context menu on a line offers it (the menu is closed again at once).
        QTimer::singleShot(0, listing, [listing] {
            auto *menu = qobject_cast<QMenu *>(QApplication::activePopupWidget());
            QVERIFY(menu);
            QCOMPARE(menu->actions().size(), 1);
            QCOMPARE(menu->actions().front()->text(),
                     ProgramListing::tr("Run from this line (%1)…").arg(1));
            menu->actions().front()->trigger();
            menu->close();
        });
        QContextMenuEvent event(QContextMenuEvent::Mouse, QPoint(5, 2),
                                listing->viewport()->mapToGlobal(QPoint(5, 2)));
        QApplication::sendEvent(listing->viewport(), &event);
        QTRY_COMPARE(asked.size(), 1);
        QCOMPARE(asked.front().front().toInt(), 1);
        QVERIFY(m_window->findChild<QAction *>(QStringLiteral("runFromLine")));
    }

    void aLineInALoopIsRefusedWithTheLineToChoose()
    {
        QVERIFY(load(writeProgram(QStringLiteral("loop.nc"),
                                  "G21 G90 F300\n#1=0\no100 while [#1 LT 2]\nG1 X[#1*10]\n"
                                  "#1=[#1+1]\no100 endwhile\nM2\n")));
        QSignalSpy loaded(m_window->program(), &ProgramSession::loaded);
        emit m_window->listing()->runFromLineRequested(4);
        QVERIFY(loaded.wait(20000));
        const LoadedProgram &p = m_window->program()->program();
        QVERIFY(!p.runnable());
        QVERIFY2(m_window->lastError().contains(QLatin1String("Choose line 3")),
                 qPrintable(m_window->lastError()));
        QVERIFY(m_window->findChild<QAction *>(QStringLiteral("wholeProgram"))->isEnabled());
    }

    void fromTheMiddleEndsOnTheWholeProgramsEnd()
    {
        QVERIFY(
            load(writeProgram(QStringLiteral("fromline.nc"), frezka::test::kRunFromLineProgram)));
        QVERIFY(!m_window->findChild<QAction *>(QStringLiteral("wholeProgram"))->isEnabled());
        QSignalSpy loaded(m_window->program(), &ProgramSession::loaded);
        emit m_window->listing()->runFromLineRequested(frezka::test::kRunFromLine);
        QVERIFY(loaded.wait(20000));
        const LoadedProgram &p = m_window->program()->program();
        QVERIFY2(p.runnable(), qPrintable(m_window->lastError()));
        QVERIFY(p.fromLine);
        QCOMPARE(p.fromLine->line, 18u);
        QCOMPARE(p.unitProgram->commands.back().endSteps, wholeEndSteps);
        // The preview's toolpath opens with the approach on line 18: across, then down at F800.
        const gcode::Toolpath &t = *p.toolpath;
        const double safeZ = p.fromLine->safeZMm;
        const std::size_t n = p.fromLine->approachEntries;
        QVERIFY(n >= 4);
        QCOMPARE(t.kind(n - 1), gcode::MotionKind::Feed);
        QCOMPARE(t.end(n - 1), (gcode::Point4{85, 35, -62, 0}));
        QCOMPARE(t.kind(n - 2), gcode::MotionKind::Rapid);
        QCOMPARE(t.end(n - 2).z, std::max(safeZ, state().positionMm[2]));
        QVERIFY(m_window->findChild<QAction *>(QStringLiteral("wholeProgram"))->isEnabled());

        const auto start = state().positionMm;
        const double lift = std::max(safeZ, start[2]);
        WireTap wire;
        tapWire(wire);
        // Where the machine goes while the job runs, poll by poll.
        QList<std::array<double, 4>> path;
        auto track = connect(m_window->controller(), &driver::MachineController::stateChanged, this,
                             [&path](const driver::MachineState &s) {
                                 if (s.jobActive)
                                     path << s.positionMm;
                             });
        QSignalSpy finished(m_window->workflow(), &session::RunWorkflow::jobFinished);
        button(m_window->runPanel(), "run")->click();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        disconnect(track);
        QVERIFY2(finished.front().front().toBool(), qPrintable(describe()));
        QVERIFY(waitIdle());
        // The unit's counters: exactly where the whole program ends.
        QCOMPARE(state().positionSteps, wholeEndSteps);
        // The spindle (12000 of 24000 rpm: 500 permille) came on before any motion.
        const int spindle = wire.first(QRegularExpression(QStringLiteral("!7V500(,[0-9A-F]{2})?")));
        const int motion = wire.first(QRegularExpression(QStringLiteral("(!0C|!0L|packet of ).*")));
        QVERIFY2(spindle >= 0 && motion > spindle, qPrintable(wire.sent.join(QLatin1Char('|'))));
        // The first motion is the approach: the first poll that finds the tool below the safe
        // height finds it straight above (or on) the line's start, come down there.
        int below = -1;
        for (int i = 0; i < path.size() && below < 0; ++i)
            if (path[i][2] < lift - 0.01)
                below = i;
        QVERIFY2(below > 0, qPrintable(QStringLiteral("%1 polls").arg(path.size())));
        QVERIFY2(std::abs(path[below][0] - 85) < 0.01 && std::abs(path[below][1] - 35) < 0.01,
                 qPrintable(QStringLiteral("below the safe height at X %1 Y %2")
                                .arg(path[below][0])
                                .arg(path[below][1])));
        // The job is done: the program is whole again.
        QTRY_VERIFY_WITH_TIMEOUT(!m_window->program()->program().fromLine &&
                                     m_window->program()->program().runnable(),
                                 20000);
        QCOMPARE(m_window->program()->startLine(), 0u);
    }
};

QTEST_MAIN(WorkflowFromLineTest)
#include "workflow_fromline_test.moc"
