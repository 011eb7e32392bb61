// The operator's keyboard shortcuts (issue 16 item 4) on the whole main window
// (workflowfixture.h): listed in Help › Keyboard shortcuts; each key does what its button does
// when its button would, asserted on the wire and on the machine (R runs, P pauses with H, S
// resumes, + / - / 0 set the feed override XM, L lifts the tool while paused, Esc holds,
// Shift+Esc drops the job with D, Ctrl+Home homes with W); a key never acts through the focus
// (no machine button takes it, a text field keeps its letters).

#include "workflowfixture.h"

#include "gui/shortcuts.h"

#include <QAbstractButton>
#include <QAction>
#include <QDialog>
#include <QLineEdit>
#include <QShortcut>
#include <QTableWidget>

class WorkflowShortcutsTest : public WorkflowFixture
{
    Q_OBJECT

    void press(QKeySequence key)
    {
        const QKeyCombination k = key[0];
        QTest::keyClick(m_window.get(), k.key(), k.keyboardModifiers());
    }
    QKeySequence keyOf(OperatorAction action) const
    {
        for (const OperatorShortcut &s : operatorShortcuts())
            if (s.action == action)
                return s.key;
        return {};
    }
    static QRegularExpression command(const QString &pattern)
    {
        return QRegularExpression(
            QRegularExpression::anchoredPattern(pattern + QStringLiteral("(,[0-9A-F]{2})?")));
    }

private slots:
    void activateTheWindow()
    {
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    }

    void theShortcutsAreListedInHelp()
    {
        QAction *help = m_window->findChild<QAction *>(QStringLiteral("keyboardShortcuts"));
        QVERIFY(help);
        help->trigger();
        auto *dialog = m_window->findChild<QDialog *>(QStringLiteral("shortcutsDialog"));
        QVERIFY(dialog && dialog->isVisible());
        QVERIFY(!dialog->isModal());
        auto *table = dialog->findChild<QTableWidget *>(QStringLiteral("shortcutsTable"));
        QCOMPARE(table->rowCount(), int(operatorShortcuts().size()));
        QStringList keys;
        for (int row = 0; row < table->rowCount(); ++row)
            keys << table->item(row, 1)->text();
        for (const OperatorShortcut &s : operatorShortcuts()) {
            QVERIFY2(keys.contains(s.key.toString(QKeySequence::NativeText)), s.name);
            QVERIFY2(m_window->findChild<QShortcut *>(QLatin1String(s.name)), s.name);
        }
        QCOMPARE(keyOf(OperatorAction::Run), QKeySequence(Qt::Key_R)); // AXIS's keys
        QCOMPARE(keyOf(OperatorAction::Pause), QKeySequence(Qt::Key_P));
        QCOMPARE(keyOf(OperatorAction::Resume), QKeySequence(Qt::Key_S));
        QCOMPARE(keyOf(OperatorAction::Stop), QKeySequence(Qt::Key_Escape));
        dialog->close();
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
    }

    void ctrlHomeHomes()
    {
        WireTap wire;
        tapWire(wire);
        press(keyOf(OperatorAction::HomeAll));
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Homing, 10000);
        QTRY_VERIFY_WITH_TIMEOUT(state().homed && state().mode == MachineMode::Idle,
                                 kMachineTimeoutMs);
        QVERIFY(wire.first(command(QStringLiteral("!0W.*"))) >= 0);
    }

    void theRunKeysActAsTheirButtons()
    {
        QVERIFY(load(writeProgram(QStringLiteral("keys.nc"),
                                  "G21 G90\nG1 Z-2 F600\nG1 X80 Y5 F300\nG1 X1\nG0 Z0\nM2\n")));
        WireTap wire;
        tapWire(wire);
        QSignalSpy started(m_window->workflow(), &session::RunWorkflow::jobStarted);
        press(keyOf(OperatorAction::Run));
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running, kMachineTimeoutMs);
        QCOMPARE(started.size(), 1);
        // Feed override: - (6.25 % down), + (back up), 0 (100 %): XM on the wire.
        press(keyOf(OperatorAction::FeedDown));
        QTRY_VERIFY_WITH_TIMEOUT(state().overridePercent < 100, 10000);
        QVERIFY(wire.first(command(QStringLiteral("!0XM.*"))) >= 0);
        press(keyOf(OperatorAction::FeedDown));
        QTRY_VERIFY_WITH_TIMEOUT(state().overridePercent < 90, 10000);
        press(keyOf(OperatorAction::FeedUp));
        QTRY_VERIFY_WITH_TIMEOUT(state().overridePercent > 90, 10000);
        press(keyOf(OperatorAction::Feed100));
        QTRY_COMPARE_WITH_TIMEOUT(state().overridePercent, 100, 10000);
        // P pauses (H along the ramp), S resumes.
        int from = int(wire.sent.size());
        press(keyOf(OperatorAction::Pause));
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Paused, 10000);
        QVERIFY(wire.sent.mid(from).indexOf(command(QStringLiteral("!0H"))) >= 0);
        QVERIFY(state().jobActive);
        press(keyOf(OperatorAction::Resume));
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running, 10000);
        // Paused, L lifts the tool (the job held with its queue kept); lowered, the job runs on.
        press(keyOf(OperatorAction::ToolLift));
        QTest::qWait(300);
        QCOMPARE(state().mode, MachineMode::Running); // as its button: only while paused
        press(keyOf(OperatorAction::Pause));
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Paused, 10000);
        from = int(wire.sent.size());
        press(keyOf(OperatorAction::ToolLift));
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::ToolLifted, 20000);
        QVERIFY(wire.sent.mid(from).indexOf(command(QStringLiteral("!0K"))) >= 0); // queue kept
        m_window->workflow()->lowerTool(0, true);
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running, 30000);
        // Esc holds; Shift+Esc drops the job (H, D).
        press(keyOf(OperatorAction::Stop));
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Paused, 10000);
        QVERIFY(state().jobActive);
        from = int(wire.sent.size());
        press(keyOf(OperatorAction::Abort));
        QVERIFY(waitIdle());
        QVERIFY(!state().jobActive);
        QVERIFY(wire.sent.mid(from).indexOf(command(QStringLiteral("!0D"))) >= 0);
    }

    // A key never acts through the focus: no button that acts on the machine takes it, and a
    // text field with the focus keeps the letters (R typed into the console runs nothing).
    void noKeyActsThroughTheFocus()
    {
        QVERIFY(waitIdle());
        for (QWidget *panel :
             {static_cast<QWidget *>(m_window->runPanel()),
              static_cast<QWidget *>(m_window->outputsPanel()),
              static_cast<QWidget *>(m_window->jogPanel()), static_cast<QWidget *>(m_window->dro()),
              static_cast<QWidget *>(m_window->holdBanner())}) {
            for (QAbstractButton *b : panel->findChildren<QAbstractButton *>())
                QVERIFY2(b->focusPolicy() == Qt::NoFocus, qPrintable(b->objectName()));
        }
        auto *line = m_window->console()->findChild<QLineEdit *>();
        QVERIFY(line);
        line->setFocus();
        QTRY_VERIFY(line->hasFocus());
        QSignalSpy started(m_window->workflow(), &session::RunWorkflow::jobStarted);
        WireTap wire;
        tapWire(wire);
        QTest::keyClicks(line, QStringLiteral("rps0"));
        QTest::keyClick(line, Qt::Key_Space);
        QCOMPARE(line->text(), QStringLiteral("rps0 "));
        QTest::qWait(500);
        QCOMPARE(started.size(), 0);
        QCOMPARE(state().mode, MachineMode::Idle);
        QCOMPARE(wire.first(command(QStringLiteral("!0(\\*S|C|XM).*"))), -1);
        line->clear();
    }
};

QTEST_MAIN(WorkflowShortcutsTest)
#include "workflow_shortcuts_test.moc"
