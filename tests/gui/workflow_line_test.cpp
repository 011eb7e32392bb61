// Two GVE114 units on one line in the main window (issue 20, Deliver 1): a profile whose
// line.units lists the mill (address 0, this profile) and an engraver (address 1, its own
// profile with other scales) on the built-in emulator in real time. The window runs a job on
// the mill while the Units panel jogs the engraver; asserted on what reached the wire (commands
// to each address, taking turns), on both units' counters as they report them (the mill exactly
// at the program's end, the engraver exactly the jog), and on what the panel shows. With
// FREZKA_WORKFLOW_UNIT=pty the line is gve-emu --units 0:gve114,1:gve114 on a pty, opened by its
// path like hardware (the engraver's move then also in what gve-emu received).
#include "gui/mainwindow.h"
#include "gui/runpanel.h"
#include "gui/unitspanel.h"

#include "windowtest.h"

#include "driver/link/machinecontroller.h"
#include "session/runworkflow.h"

#include <QApplication>
#include <QComboBox>
#include <QProcess>
#include <QPushButton>
#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <optional>

using namespace frezka;
using namespace frezka::gui;
using driver::MachineMode;

class WorkflowLineTest : public QObject
{
    Q_OBJECT

    static constexpr int kTimeoutMs = 60000;
    static constexpr double kEngraverStepsPerMm = 160; // the mill's: 400 (GVE114 default)

    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
    QProcess m_emu;
    QByteArray m_emuLog;
    bool m_pty = false;

    driver::MachineController *controller() const { return m_window->controller(); }
    driver::MachineState unit(int i) const
    {
        const auto &states = controller()->unitStates();
        return i < int(states.size()) ? states[std::size_t(i)] : driver::MachineState{};
    }
    QString describe() const
    {
        return QStringLiteral("mill %1 %2,%3 | engraver %4 %5 | %6")
            .arg(driver::machineModeName(unit(0).mode))
            .arg(unit(0).positionSteps[0])
            .arg(unit(0).positionSteps[1])
            .arg(driver::machineModeName(unit(1).mode))
            .arg(
                QStringLiteral("%1,%2").arg(unit(1).positionSteps[0]).arg(unit(1).positionSteps[1]))
            .arg(m_window->lastError());
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("FrezkaWorkflowLineTest"));
        machine::MachineConfig engraver = machine::defaultMachineConfig(protocol::Variant::Gve114);
        engraver.name = "Engraver";
        engraver.axes[0].stepsPerMm = kEngraverStepsPerMm;
        // Y slow (the panel jogs at half the maximum: 0.5 mm/s), so that Stop meets a jog of
        // 10 mm under way.
        engraver.axes[1].maxSpeedMmPerMin = engraver.axes[1].rapidMmPerMin = 60;
        QVERIFY(!machine::saveMachineConfig(
            engraver, m_dir.filePath(QStringLiteral("engraver.json")).toStdString()));
        machine::MachineConfig mill = machine::defaultMachineConfig(protocol::Variant::Gve114);
        mill.name = "Mill";
        mill.link.port = "emulator";
        m_pty = qgetenv("FREZKA_WORKFLOW_UNIT") == "pty";
        if (m_pty) {
            m_emu.setProgram(QStringLiteral(FREZKA_GVE_EMU));
            m_emu.setArguments({QStringLiteral("--units"), QStringLiteral("0:gve114,1:gve114"),
                                QStringLiteral("--verbose")});
            m_emu.start();
            QVERIFY(m_emu.waitForStarted());
            QTRY_VERIFY_WITH_TIMEOUT(m_emu.canReadLine(), 10000);
            const QString pty = QString::fromLocal8Bit(m_emu.readLine()).trimmed();
            QVERIFY2(pty.startsWith(QLatin1Char('/')), qPrintable(pty));
            mill.link.port = pty.toStdString();
        }
        mill.motion.runBeforeHoming = true;
        using machine::LineUnitRole;
        mill.line.units = {
            {0, protocol::Variant::Gve114, "Mill", LineUnitRole::Machine, {}},
            {1, protocol::Variant::Gve114, "Engraver", LineUnitRole::Auxiliary, "engraver.json"}};
        const QString path = m_dir.filePath(QStringLiteral("mill.json"));
        QVERIFY(!machine::saveMachineConfig(mill, path.toStdString()));
        QSettings().setValue(QStringLiteral("lastProfile"), path);
        MainWindowOptions options;
        options.view = MainWindowOptions::View::Software;
        options.restoreLayout = false;
        m_window = std::make_unique<MainWindow>(options);
        m_window->show();
        QTRY_VERIFY2_WITH_TIMEOUT(unit(0).mode == MachineMode::Idle &&
                                      unit(1).mode == MachineMode::Idle,
                                  qPrintable(describe()), 20000);
        QCOMPARE(controller()->state().mode, MachineMode::Idle); // the window's machine
    }

    void cleanupTestCase()
    {
        m_window.reset();
        m_emu.terminate();
        m_emu.waitForFinished(5000);
    }

    // The panel lists both units with their identity as read at connect.
    void panelShowsBothUnits()
    {
        UnitsPanel *panel = m_window->unitsPanel();
        QVERIFY(panel);
        QCOMPARE(panel->unitCount(), 2);
        QCOMPARE(panel->text(0, UnitsPanel::Address), QStringLiteral("0"));
        QCOMPARE(panel->text(1, UnitsPanel::Address), QStringLiteral("1"));
        QVERIFY(panel->text(0, UnitsPanel::Name).contains(QStringLiteral("Mill")));
        QCOMPARE(panel->text(1, UnitsPanel::Name), QStringLiteral("Engraver"));
        QCOMPARE(panel->text(1, UnitsPanel::Type), QStringLiteral("GVE114"));
        QVERIFY(!unit(1).firmware.empty());
        QVERIFY(panel->text(1, UnitsPanel::Identity)
                    .startsWith(QString::fromStdString(unit(1).firmware)));
        QCOMPARE(panel->text(1, UnitsPanel::State),
                 session::RunWorkflow::modeText(MachineMode::Idle));
        QCOMPARE(panel->jogUnit(), 1); // only the other unit is offered to the jog
    }

    void jobOnTheMillWhileTheEngraverJogs()
    {
        const QString program =
            test::writeProgram(m_dir, QStringLiteral("line.nc"),
                               "G21 G90\nG1 X30 Y5 F600\nG1 X10 Y10\nG1 X0 Y10\nM2\n");
        QVERIFY(test::openAndWait(m_window.get(), program));
        QStringList sent;
        // The mill's mode as the window saw it when the engraver's move went on the wire.
        std::optional<MachineMode> millAtEngraverMove;
        const auto tap = connect(controller(), &driver::MachineController::logLine, this,
                                 [&](const QString &line) {
                                     if (!line.startsWith(QLatin1String("> ")))
                                         return;
                                     sent << line.mid(2);
                                     static const QRegularExpression move(
                                         QStringLiteral("^(packet of .* starting ')?!1(C|B|L)"));
                                     if (!millAtEngraverMove && move.match(sent.back()).hasMatch())
                                         millAtEngraverMove = unit(0).mode;
                                 });
        const auto untap = qScopeGuard([&] { disconnect(tap); });
        QSignalSpy finished(controller(), &driver::MachineController::jobFinished);
        test::button(m_window->runPanel(), "run")->click();
        QTRY_VERIFY2_WITH_TIMEOUT(unit(0).mode == MachineMode::Running, qPrintable(describe()),
                                  20000);
        UnitsPanel *panel = m_window->unitsPanel();
        QTRY_COMPARE(panel->text(0, UnitsPanel::State),
                     session::RunWorkflow::modeText(MachineMode::Running));
        // The engraver jogs X +1 mm from the panel while the mill runs.
        const int sentBeforeJog = int(sent.size());
        panel->setJogUnit(1);
        panel->setJogAxis(0);
        panel->setJogStepMm(1);
        auto *plus = panel->findChild<QPushButton *>(QStringLiteral("unitsJogPlus"));
        QVERIFY(plus && plus->isEnabled());
        plus->click();
        QTRY_VERIFY2_WITH_TIMEOUT(unit(1).mode == MachineMode::Jogging ||
                                      unit(1).positionSteps[0] != 0,
                                  qPrintable(describe()), 20000);
        QTRY_VERIFY2_WITH_TIMEOUT(unit(1).mode == MachineMode::Idle &&
                                      unit(1).positionSteps[0] == kEngraverStepsPerMm,
                                  qPrintable(describe()), kTimeoutMs);
        QVERIFY2(finished.wait(kTimeoutMs), qPrintable(describe()));
        QCOMPARE(finished.at(0).at(0).toBool(), true);

        // The mill's counters exactly at the program's end; the engraver's exactly the jog.
        const auto &plan = m_window->program()->program().unitProgram;
        QVERIFY(plan && !plan->commands.empty());
        const machine::Steps4 end = plan->commands.back().endSteps;
        QCOMPARE(end[1], 10 * 400);
        QTRY_VERIFY2_WITH_TIMEOUT(unit(0).positionSteps[0] == end[0] &&
                                      unit(0).positionSteps[1] == end[1] &&
                                      unit(0).positionSteps[2] == end[2],
                                  qPrintable(describe()), 10000);
        const std::array<std::int64_t, 4> jogged{std::int64_t(kEngraverStepsPerMm), 0, 0, 0};
        QCOMPARE(unit(1).positionSteps, jogged);

        // On the wire: every command to address 0, 1 or the spindle's 7; the engraver's move
        // among the mill's job (the line taken in turns), the engraver polled during the job.
        // (a packet is logged as "packet of N commands starting '!0B…'").
        const QRegularExpression addressed(QStringLiteral("^(packet of .* starting ')?!([0-7])"));
        const QRegularExpression millJob(QStringLiteral("^(packet of .* starting ')?!0(C|B|L)"));
        const QRegularExpression engraverMove(
            QStringLiteral("^(packet of .* starting ')?!1(C|B|L)"));
        int firstJob = -1, lastJob = -1, engraverMoveAt = -1, engraverPolls = 0;
        for (int i = 0; i < sent.size(); ++i) {
            const auto m = addressed.match(sent[i]);
            QVERIFY2(m.hasMatch() && QStringList({"0", "1", "7"}).contains(m.captured(2)),
                     qPrintable(sent[i]));
            if (millJob.match(sent[i]).hasMatch()) {
                firstJob = firstJob < 0 ? i : firstJob;
                lastJob = i;
            }
            if (engraverMove.match(sent[i]).hasMatch() && engraverMoveAt < 0)
                engraverMoveAt = i;
            if (i > sentBeforeJog && sent[i].startsWith(QLatin1String("!1P")))
                ++engraverPolls;
        }
        // The jog was asked while the mill ran (sentBeforeJog), and the engraver's move went on
        // the wire while the mill was still running its job: both on the line at once, in
        // turns. (The mill's last vectors may all be queued in its unit by then on a loaded
        // machine: the job still runs, and is polled, on the same line.)
        QVERIFY2(firstJob >= 0 && engraverMoveAt > sentBeforeJog &&
                     millAtEngraverMove == MachineMode::Running,
                 qPrintable(QStringLiteral("job %1..%2, jog asked at %3, engraver's move %4: %5")
                                .arg(firstJob)
                                .arg(lastJob)
                                .arg(sentBeforeJog)
                                .arg(engraverMoveAt)
                                .arg(sent.mid(std::max(0, engraverMoveAt - 5), 10).join('|'))));
        QVERIFY(engraverPolls > 0);
        if (m_pty) { // gve-emu received the engraver's move
            const QByteArray in = test::emulatorReceived(m_emu, m_emuLog);
            QVERIFY2(in.contains("!1L160,0,0,0"), in.right(500).constData());
        }

        // The panel: both positions in each unit's own scale, both idle.
        QTRY_COMPARE(panel->text(1, UnitsPanel::X), QStringLiteral("1.000"));
        QTRY_COMPARE(panel->text(0, UnitsPanel::Y), QStringLiteral("10.000"));
        QTRY_COMPARE(panel->text(0, UnitsPanel::X), QString::number(end[0] / 400.0, 'f', 3));
        QCOMPARE(panel->text(1, UnitsPanel::State),
                 session::RunWorkflow::modeText(MachineMode::Idle));
        QTRY_COMPARE(panel->text(0, UnitsPanel::State),
                     session::RunWorkflow::modeText(MachineMode::Idle));
    }

    // Stop on the panel ends the engraver's jog only; the mill stays as it is.
    void stopEndsTheOtherUnitsJog()
    {
        UnitsPanel *panel = m_window->unitsPanel();
        panel->setJogUnit(1);
        panel->setJogAxis(1);
        panel->setJogStepMm(10);
        panel->findChild<QPushButton *>(QStringLiteral("unitsJogPlus"))->click();
        // Under way: Y has left 0 (0.5 mm/s: 20 s for the 10 mm).
        QTRY_VERIFY2_WITH_TIMEOUT(unit(1).mode == MachineMode::Jogging &&
                                      unit(1).positionSteps[1] > 0,
                                  qPrintable(describe()), 20000);
        panel->findChild<QPushButton *>(QStringLiteral("unitsStop"))->click();
        QTRY_VERIFY2_WITH_TIMEOUT(unit(1).mode == MachineMode::Idle, qPrintable(describe()), 20000);
        // Stopped short of the 10 mm (at 400 steps/mm in Y).
        QVERIFY2(unit(1).positionSteps[1] > 0 && unit(1).positionSteps[1] < 10 * 400,
                 qPrintable(describe()));
        QCOMPARE(controller()->state().mode, MachineMode::Idle);
    }

    // With every unit idle, the engraver becomes the window's machine: the window shows it and
    // jogs it in its own scale (the line stays connected, the mill keeps its counters).
    void anotherUnitBecomesTheWindowsMachine()
    {
        UnitsPanel *panel = m_window->unitsPanel();
        panel->setJogUnit(1);
        auto *choose = panel->findChild<QPushButton *>(QStringLiteral("unitsMakeMachine"));
        QVERIFY(choose);
        QTRY_VERIFY2(choose->isEnabled(), qPrintable(describe()));
        choose->click();
        QTRY_COMPARE(QString::fromStdString(m_window->profile().name), QStringLiteral("Engraver"));
        QCOMPARE(panel->machineIndex(), 1);
        QCOMPARE(panel->jogUnit(), 0);
        QCOMPARE(m_window->profile().unit.address, 1);
        QCOMPARE(m_window->profile().axes[0].stepsPerMm, kEngraverStepsPerMm);
        QTRY_COMPARE(controller()->state().positionSteps, unit(1).positionSteps);
        const auto mill = unit(0).positionSteps;
        const auto engraver = unit(1).positionSteps;
        QStringList sent;
        // The mill's mode as the window saw it when the engraver's move went on the wire.
        std::optional<MachineMode> millAtEngraverMove;
        const auto tap = connect(controller(), &driver::MachineController::logLine, this,
                                 [&](const QString &line) {
                                     if (!line.startsWith(QLatin1String("> ")))
                                         return;
                                     sent << line.mid(2);
                                     static const QRegularExpression move(
                                         QStringLiteral("^(packet of .* starting ')?!1(C|B|L)"));
                                     if (!millAtEngraverMove && move.match(sent.back()).hasMatch())
                                         millAtEngraverMove = unit(0).mode;
                                 });
        const auto untap = qScopeGuard([&] { disconnect(tap); });
        m_window->jogStep(0, 1.0, 600); // the window's jog: now the engraver's X
        QTRY_VERIFY2_WITH_TIMEOUT(unit(1).mode == MachineMode::Idle &&
                                      unit(1).positionSteps[0] ==
                                          engraver[0] + std::int64_t(kEngraverStepsPerMm),
                                  qPrintable(describe()), 20000);
        QCOMPARE(unit(0).positionSteps, mill);
        QVERIFY(sent.indexOf(QRegularExpression(QStringLiteral("^!1(L|C|\\*S).*"))) >= 0);
        QCOMPARE(sent.indexOf(QRegularExpression(QStringLiteral("^!0(L|C|\\*S).*"))), -1);
        // The next connect sets up the same line with the engraver as the machine.
        QCOMPARE(m_window->profile().line.units.size(), std::size_t(2));
        QVERIFY(machine::validateMachineConfig(m_window->profile()).empty());
    }
};

QTEST_MAIN(WorkflowLineTest)
#include "workflow_line_test.moc"
