// The tool table on the whole main window (workflowfixture.h, issue 15 item 1): Machine › Tool
// table… edits the table beside the profile (a bad row is refused with the row named and
// nothing written), saving writes the LinuxCNC .tbl file; a program with T1 M6 G43 then names
// the tool with its comment and length at the change, and cuts at the tool's length: the unit's
// Z counter ends exactly the length higher than programmed; a
// tool the table does not have is the program's error and nothing can run.
#include "workflowfixture.h"

#include "gui/tooltabledialog.h"

#include <QAction>
#include <QTableWidget>

class WorkflowToolsTest : public WorkflowFixture
{
    Q_OBJECT

    QString tablePath() const { return m_dir.filePath(QStringLiteral("tool.tbl")); }

    static void setCell(QTableWidget *grid, int row, int column, const QString &text)
    {
        grid->item(row, column)->setText(text);
    }

private slots:
    void homeFirst()
    {
        button(m_window->jogPanel(), "homeAll")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().homed && state().mode == MachineMode::Idle,
                                 kMachineTimeoutMs);
    }

    void theDialogEditsAndSavesTheTable()
    {
        auto *action = m_window->findChild<QAction *>(QStringLiteral("toolTable"));
        QVERIFY(action);
        action->trigger();
        auto *dlg = m_window->findChild<ToolTableDialog *>();
        QVERIFY(dlg);
        QVERIFY(dlg->isVisible());
        QCOMPARE(dlg->path(), tablePath());
        QTableWidget *grid = dlg->grid();
        QCOMPARE(grid->rowCount(), 0); // no file yet
        button(dlg, "addTool")->click();
        button(dlg, "addTool")->click();
        QCOMPARE(grid->rowCount(), 2);
        QCOMPARE(grid->item(1, ToolTableDialog::ToolColumn)->text(), QStringLiteral("2"));
        setCell(grid, 0, ToolTableDialog::LengthColumn, QStringLiteral("10"));
        setCell(grid, 0, ToolTableDialog::DiameterColumn, QStringLiteral("6"));
        setCell(grid, 0, ToolTableDialog::CommentColumn, QStringLiteral("end mill 6"));
        setCell(grid, 1, ToolTableDialog::LengthColumn, QStringLiteral("long"));
        // A bad row: refused, named, nothing written.
        button(dlg, "saveToolTable")->click();
        QVERIFY2(dlg->errorText().contains(QStringLiteral("Row 2")), qPrintable(dlg->errorText()));
        QVERIFY(!QFile::exists(tablePath()));
        grid->setCurrentCell(1, 0);
        button(dlg, "removeTool")->click();
        QCOMPARE(grid->rowCount(), 1);
        QSignalSpy saved(dlg, &ToolTableDialog::saved);
        button(dlg, "saveToolTable")->click();
        QCOMPARE(saved.size(), 1);
        QVERIFY(dlg->errorText().isEmpty());
        QFile f(tablePath());
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("T1 P1 Z10 D6 ;end mill 6\n"));
        dlg->close();
    }

    void aProgramCutsAtTheToolsLength()
    {
        QVERIFY(load(writeProgram(QStringLiteral("length.nc"),
                                  "G21 G90 G54\nG0 X10 Y10\nT1 M6\nG43\nG0 Z-30\nM2\n")));
        const LoadedProgram &p = m_window->program()->program();
        QVERIFY2(p.runnable(), p.errors.empty() ? "" : qPrintable(p.errors.front().text));
        const session::OffsetState &o = m_window->program()->workOffsets();
        const double z = o.systems[0][2] + o.g92[2] - 30 + 10; // 10 mm of tool 1
        QSignalSpy finished(m_window->workflow(), &session::RunWorkflow::jobFinished);
        button(m_window->runPanel(), "run")->click();
        // M6: the operator is told which tool, with its comment and length from the table.
        QTRY_COMPARE_WITH_TIMEOUT(m_window->holdBanner()->kind(), HoldBanner::Kind::OperatorStop,
                                  kMachineTimeoutMs);
        const QString prompt = m_window->holdBanner()->text();
        QVERIFY2(
            prompt.contains(QStringLiteral("Tool 1: end mill 6 (length 10 mm, diameter 6 mm)")),
            qPrintable(prompt));
        button(m_window->runPanel(), "resume")->click();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY2(finished.front().front().toBool(), qPrintable(describe()));
        QVERIFY(waitIdle());
        QCOMPARE(state().positionSteps[2], steps(2, z));
    }

    void aRunProgramsG10L1IsWrittenBack()
    {
        QVERIFY(load(
            writeProgram(QStringLiteral("g10l1.nc"), "G21 G90\nG10 L1 P1 Z12.5 R4\nG0 X5\nM2\n")));
        QVERIFY(m_window->program()->program().runnable());
        QFile f(tablePath());
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("T1 P1 Z10 D6 ;end mill 6\n")); // checked, not run
        f.close();
        QSignalSpy finished(m_window->workflow(), &session::RunWorkflow::jobFinished);
        button(m_window->runPanel(), "run")->click();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY2(finished.front().front().toBool(), qPrintable(describe()));
        QVERIFY(f.open(QIODevice::ReadOnly));
        QCOMPARE(f.readAll(), QByteArray("T1 P1 Z12.5 D8 ;end mill 6\n"));
        QVERIFY(waitIdle());
    }

    void aToolNotInTheTableIsTheProgramsError()
    {
        QVERIFY(load(writeProgram(QStringLiteral("t5.nc"), "G21\nT5 M6\nM2\n")));
        const LoadedProgram &p = m_window->program()->program();
        QVERIFY(!p.runnable());
        QVERIFY(!p.errors.empty());
        QCOMPARE(p.errors.front().line, 2);
        QVERIFY2(p.errors.front().text.contains(QStringLiteral("Tool 5 is not in the tool table")),
                 qPrintable(p.errors.front().text));
    }
};

QTEST_MAIN(WorkflowToolsTest)
#include "workflow_tools_test.moc"
