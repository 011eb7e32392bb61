// The operator's keyboard shortcuts (issue 16 item 4) on the whole main window
// (workflowfixture.h): listed in Help › Keyboard shortcuts; each key does what its button does
// when its button would, asserted on the wire and on the machine (R runs, P pauses with H, S
// resumes, + / - / 0 set the feed override XM, L lifts the tool while paused, Esc holds,
// Shift+Esc drops the job with D, Ctrl+Home homes with W); a key never acts through the focus
// (no machine button takes it, a text field keeps its letters).

#include "workflowfixture.h"

#include "gui/shortcuteditor.h"
#include "gui/shortcuts.h"

#include <QAbstractButton>
#include <QAction>
#include <QDialog>
#include <QKeySequenceEdit>
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
    // Each jog key jogs its axis by the chosen step: the L on the wire, the unit's counters there.
    void jogByKey(OperatorAction action, int axis, double mm)
    {
        QVERIFY(waitIdle());
        const std::int64_t from = state().positionSteps[std::size_t(axis)];
        WireTap wire;
        tapWire(wire);
        press(keyOf(action));
        QTRY_VERIFY2_WITH_TIMEOUT(state().positionSteps[std::size_t(axis)] ==
                                      from + steps(axis, mm),
                                  qPrintable(describe()), kMachineTimeoutMs);
        QVERIFY2(wire.first(jogCommand(axis, mm)) >= 0,
                 qPrintable(wire.sent.join(QLatin1Char('|'))));
        QVERIFY(waitIdle());
    }
    QKeySequence keyOf(OperatorAction action) const
    {
        return shortcutKey(operatorShortcut(action));
    }
    // A jog of 1 mm: "!0Lx,y,z" with the axis' steps (the A component may follow).
    QRegularExpression jogCommand(int axis, double mm) const
    {
        std::array<std::int64_t, 3> d{};
        d[std::size_t(axis)] = steps(axis, mm);
        return command(QStringLiteral("!0L%1,%2,%3(,0)?").arg(d[0]).arg(d[1]).arg(d[2]));
    }
    // Any jog that moves ("!0L" with a component other than 0; L0,0,0 only asks for the queue).
    static QRegularExpression anyMovingJog()
    {
        return QRegularExpression(QStringLiteral("^!0L(?!0,0,0(,0)?(,[0-9A-F]{2})?$).*"));
    }
    void focusTheWindow()
    {
        m_window->activateWindow();
        QVERIFY(QTest::qWaitForWindowActive(m_window.get()));
        if (QWidget *focus = QApplication::focusWidget())
            focus->clearFocus();
        QTRY_VERIFY(!QApplication::focusWidget() ||
                    !qobject_cast<QLineEdit *>(QApplication::focusWidget()));
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
            // A jog key acts while held (key press and release), the others are QShortcuts.
            QVERIFY2(bool(m_window->findChild<QShortcut *>(QLatin1String(s.name))) == !s.held,
                     s.name);
        }
        QCOMPARE(keyOf(OperatorAction::Run), QKeySequence(Qt::Key_R)); // AXIS's keys
        QCOMPARE(keyOf(OperatorAction::Pause), QKeySequence(Qt::Key_P));
        QCOMPARE(keyOf(OperatorAction::Resume), QKeySequence(Qt::Key_S));
        QCOMPARE(keyOf(OperatorAction::Stop), QKeySequence(Qt::Key_Escape));
        QCOMPARE(keyOf(OperatorAction::JogXPlus), QKeySequence(Qt::Key_Right));
        QCOMPARE(keyOf(OperatorAction::JogZPlus), QKeySequence(Qt::Key_PageUp));
        QCOMPARE(keyOf(OperatorAction::Spindle), QKeySequence(Qt::Key_F9));
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

    // The jog keys (AXIS's: arrows X/Y, Page Up/Down Z) jog by the step, F9 switches the spindle
    // (address 7 on the wire, the emulator's spindle turns), Shift+X zeroes X here: the DRO
    // reads 0 and G0 X0 in the console comes back to that point on the unit's counters.
    void theJogZeroAndSpindleKeysReachTheUnit()
    {
        focusTheWindow();
        m_window->jogPanel()->setStepMm(1.0);
        jogByKey(OperatorAction::JogXPlus, 0, 1.0);
        if (QTest::currentTestFailed())
            return;
        jogByKey(OperatorAction::JogXMinus, 0, -1.0);
        if (QTest::currentTestFailed())
            return;
        jogByKey(OperatorAction::JogYPlus, 1, 1.0);
        if (QTest::currentTestFailed())
            return;
        jogByKey(OperatorAction::JogYMinus, 1, -1.0);
        if (QTest::currentTestFailed())
            return;
        jogByKey(OperatorAction::JogZMinus, 2, -1.0);
        if (QTest::currentTestFailed())
            return;
        jogByKey(OperatorAction::JogZPlus, 2, 1.0);
        if (QTest::currentTestFailed())
            return;
        jogByKey(OperatorAction::JogXPlus, 0, 1.0);
        if (QTest::currentTestFailed())
            return;
        const std::int64_t zeroAt = state().positionSteps[0];
        press(keyOf(OperatorAction::ZeroX));
        QTRY_COMPARE(m_window->dro()->findChild<QLabel *>(QStringLiteral("droWorkX"))->text(),
                     QStringLiteral("0.000"));
        jogByKey(OperatorAction::JogXPlus, 0, 1.0);
        if (QTest::currentTestFailed())
            return;
        QTRY_COMPARE(m_window->dro()->findChild<QLabel *>(QStringLiteral("droWorkX"))->text(),
                     QStringLiteral("1.000"));
        m_window->executeManualLine(QStringLiteral("G0 X0"));
        QTRY_COMPARE_WITH_TIMEOUT(state().positionSteps[0], zeroAt, kMachineTimeoutMs);
        QVERIFY(waitIdle());
        // F9: the spindle on (!7V on the wire, the emulator's spindle turns), F9 again: off.
        WireTap wire;
        tapWire(wire);
        press(keyOf(OperatorAction::Spindle));
        QTRY_VERIFY_WITH_TIMEOUT(state().spindleOn, 10000);
        QVERIFY(wire.first(command(QStringLiteral("!7V[1-9][0-9]*"))) >= 0);
        press(keyOf(OperatorAction::Spindle));
        QTRY_VERIFY_WITH_TIMEOUT(!state().spindleOn, 10000);
        QVERIFY(wire.first(command(QStringLiteral("!7V0"))) >= 0);
        m_window->setWorkZero(-1); // leave the work zero where the day goes on
        QTRY_VERIFY(m_window->workOffsets()[std::size_t(m_window->activeOffset())][0] ==
                    state().positionMm[0]);
    }

    // A jog key never acts while a text field has the focus (Page Up in the console) nor while
    // a job runs (no moving L on the wire; the job runs on).
    void theJogKeysWaitForTheirMoment()
    {
        QVERIFY(waitIdle());
        auto *line = m_window->console()->findChild<QLineEdit *>();
        line->setFocus();
        QTRY_VERIFY(line->hasFocus());
        WireTap wire;
        tapWire(wire);
        press(keyOf(OperatorAction::JogZPlus));
        press(keyOf(OperatorAction::JogXPlus)); // the line edit's cursor key
        QTest::qWait(500);
        QCOMPARE(wire.first(anyMovingJog()), -1);
        focusTheWindow();
        QVERIFY(
            load(writeProgram(QStringLiteral("jogkeys.nc"), "G21 G90\nG1 X60 F300\nG1 X0\nM2\n")));
        const std::int64_t y0 = state().positionSteps[1], z0 = state().positionSteps[2];
        button(m_window->runPanel(), "run")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Running, kMachineTimeoutMs);
        const int from = int(wire.sent.size());
        press(keyOf(OperatorAction::JogYPlus));
        press(keyOf(OperatorAction::JogZMinus));
        QVERIFY(waitIdle());
        QCOMPARE(wire.sent.mid(from).indexOf(anyMovingJog()), -1);
        QCOMPARE(state().positionSteps[1], y0);
        QCOMPARE(state().positionSteps[2], z0);
    }

    // Every key can be changed in Settings › Shortcuts (stored in QSettings, applied at once);
    // a key another action has is refused with a message naming that action; Reset to defaults
    // brings the AXIS keys back. One operator's visit to the editor and back at the machine, in
    // order (each step needs the keys the one before left): longer than a slot usually is.
    void theKeysAreEditableInTheSettings()
    {
        QVERIFY(waitIdle());
        SettingsDialog *settings = m_window->openSettings();
        ShortcutEditor *editor = settings->shortcutEditor();
        QVERIFY(editor);
        QString why;
        QVERIFY(editor->assign(OperatorAction::JogXPlus, QKeySequence(Qt::Key_D), &why));
        QCOMPARE(QSettings().value(QStringLiteral("shortcuts/shortcutJogXPlus")).toString(),
                 QStringLiteral("D"));
        QVERIFY(editor->assign(OperatorAction::Spindle, QKeySequence(Qt::Key_F8), &why));
        // Typed into the key field: P is Pause's, refused, the field shows Shift+Y again.
        auto *field = editor->findChild<QKeySequenceEdit *>(QStringLiteral("keyZeroY"));
        QVERIFY(field);
        field->setKeySequence(QKeySequence(Qt::Key_P));
        QMetaObject::invokeMethod(field, "editingFinished");
        QVERIFY2(editor->message().contains(QStringLiteral("Pause")),
                 qPrintable(editor->message()));
        QCOMPARE(field->keySequence(), QKeySequence(Qt::SHIFT | Qt::Key_Y));
        QCOMPARE(keyOf(OperatorAction::ZeroY), QKeySequence(Qt::SHIFT | Qt::Key_Y));
        QVERIFY(!editor->assign(OperatorAction::JogYPlus, QKeySequence(Qt::Key_R), &why));
        QVERIFY2(why.contains(QStringLiteral("Run the program")), qPrintable(why));
        // A menu command's key (File › Reload program) is refused too.
        QVERIFY(!editor->assign(OperatorAction::ZeroAll, QKeySequence(Qt::CTRL | Qt::Key_R), &why));
        QVERIFY2(why.contains(QStringLiteral("Reload program")), qPrintable(why));
        QCOMPARE(keyOf(OperatorAction::ZeroAll), QKeySequence(Qt::Key_End));
        settings->close();
        focusTheWindow();
        // D jogs X+ now, the arrow no longer; F8 switches the spindle.
        jogByKey(OperatorAction::JogXPlus, 0, 1.0);
        if (QTest::currentTestFailed())
            return;
        QCOMPARE(keyOf(OperatorAction::JogXPlus), QKeySequence(Qt::Key_D));
        WireTap wire;
        tapWire(wire);
        QTest::keyClick(m_window.get(), Qt::Key_Right);
        QTest::qWait(500);
        QCOMPARE(wire.first(anyMovingJog()), -1);
        QTest::keyClick(m_window.get(), Qt::Key_F8);
        QTRY_VERIFY_WITH_TIMEOUT(state().spindleOn, 10000);
        QTest::keyClick(m_window.get(), Qt::Key_F8);
        QTRY_VERIFY_WITH_TIMEOUT(!state().spindleOn, 10000);
        // Help › Keyboard shortcuts lists the key in use.
        showShortcutsDialog(m_window.get());
        auto *table = m_window->findChild<QTableWidget *>(QStringLiteral("shortcutsTable"));
        QVERIFY(!table->findItems(QStringLiteral("D"), Qt::MatchExactly).isEmpty());
        m_window->findChild<QDialog *>(QStringLiteral("shortcutsDialog"))->close();
        // Reset to defaults: the arrow jogs again, D does nothing.
        settings = m_window->openSettings();
        button(settings->shortcutEditor(), "resetShortcuts")->click();
        QVERIFY(!QSettings().contains(QStringLiteral("shortcuts/shortcutJogXPlus")));
        settings->close();
        focusTheWindow();
        QCOMPARE(keyOf(OperatorAction::JogXPlus), QKeySequence(Qt::Key_Right));
        jogByKey(OperatorAction::JogXMinus, 0, -1.0);
        if (QTest::currentTestFailed())
            return;
        const int from = int(wire.sent.size());
        QTest::keyClick(m_window.get(), Qt::Key_D);
        QTest::qWait(500);
        QCOMPARE(wire.sent.mid(from).indexOf(anyMovingJog()), -1);
    }
};

QTEST_MAIN(WorkflowShortcutsTest)
#include "workflow_shortcuts_test.moc"
