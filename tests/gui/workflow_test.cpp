// The operator's workflows of issue 6 on the whole main window against the emulated unit in real
// time (offscreen, software view): the built-in (in-process) emulator, or with
// FREZKA_WORKFLOW_UNIT=pty gve-emu on a pty connected through the profile's port as a typed path,
// exactly like hardware. One window for the whole run, like an operator's day:
// connect -> open -> check -> home -> run; pause -> tool lift -> resume; jog and soft-limit
// refusal; spindle/coolant; feed override; a program with an error; EEPROM write/read back.
// Never sleeps: every wait is QTRY_* / QSignalSpy::wait on the machine's own signals.
#include "gui/consolewidget.h"
#include "gui/drowidget.h"
#include "gui/holdbanner.h"
#include "gui/iopanel.h"
#include "gui/jogpanel.h"
#include "gui/mainwindow.h"
#include "gui/outputspanel.h"
#include "gui/programsession.h"
#include "gui/runpanel.h"
#include "gui/settingsdialog.h"
#include "gui/toolpathview.h"
#include "gui/unitconfigdialog.h"

#include "windowtest.h"

#include "driver/link/machinecontroller.h"
#include "session/runworkflow.h"

#include <QApplication>
#include <QCheckBox>
#include <QDir>
#include <QLabel>
#include <QMessageBox>
#include <QPointer>
#include <QProcess>
#include <QPushButton>
#include <QRadioButton>
#include <QRegularExpression>
#include <QScopeGuard>
#include <QSettings>
#include <QSlider>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

using namespace frezka;
using namespace frezka::gui;
using driver::MachineMode;

namespace {
constexpr int kMachineTimeoutMs = 60000;
}

class WorkflowTest : public QObject
{
    Q_OBJECT

private:
    const driver::MachineState &state() const { return m_window->controller()->state(); }
    QString describe() const
    {
        const auto &s = state();
        return QStringLiteral("mode %1 pos %2 %3 %4 line %5 error: %6 | gui: %7")
            .arg(driver::machineModeName(s.mode))
            .arg(s.positionMm[0])
            .arg(s.positionMm[1])
            .arg(s.positionMm[2])
            .arg(s.sourceLine)
            .arg(s.lastError ? QString::fromStdString(s.lastError->message) : QString())
            .arg(m_window->lastError());
    }

    QString writeProgram(const QString &name, const QByteArray &text)
    {
        return test::writeProgram(m_dir, name, text);
    }

    bool load(const QString &path) { return test::openAndWait(m_window.get(), path); }

    QPushButton *button(QWidget *parent, const char *name) { return test::button(parent, name); }

    bool waitIdle()
    {
        QTest::qWaitFor([&] { return state().mode == MachineMode::Idle; }, kMachineTimeoutMs);
        if (state().mode != MachineMode::Idle)
            qWarning("not idle: %s", qPrintable(describe()));
        return state().mode == MachineMode::Idle;
    }

    // Records every command the driver puts on the wire ("> " lines of its log), in order.
    struct WireTap
    {
        QStringList sent;
        QMetaObject::Connection connection;
        ~WireTap() { QObject::disconnect(connection); }
        // The first / last command that the pattern matches whole (-1: none).
        int first(const QRegularExpression &re) const { return int(sent.indexOf(re)); }
        int last(const QRegularExpression &re) const { return int(sent.lastIndexOf(re)); }
    };
    void tapWire(WireTap &tap)
    {
        tap.connection = connect(m_window->controller(), &driver::MachineController::logLine, this,
                                 [&tap](const QString &line) {
                                     if (line.startsWith(QLatin1String("> ")))
                                         tap.sent << line.mid(2);
                                 });
    }

    // Steps of a position in mm, as the planner rounds them.
    std::int64_t steps(int axis, double mm) const
    {
        return std::llround(mm * m_window->profile().axes[std::size_t(axis)].stepsPerMm);
    }

    // What gve-emu received on its pty ("pc>" lines of --verbose), joined.
    QByteArray emulatorReceived()
    {
        m_emuLog += m_emu.readAllStandardError();
        QByteArray in;
        for (const QByteArray &line : m_emuLog.split('\n')) {
            const int at = line.indexOf(" pc> ");
            if (at >= 0)
                in += line.mid(at + 5).replace("\\r", "\r");
        }
        return in;
    }

    bool homedMarksShown(std::uint8_t axes) const
    {
        for (int a = 0; a < 3; ++a) {
            if (m_window->dro()->homedShown(a) != bool((axes >> a) & 1))
                return false;
        }
        return true;
    }

private slots:
    void initTestCase()
    {
        QStandardPaths::setTestModeEnabled(true);
        QVERIFY(m_dir.isValid());
        QSettings::setDefaultFormat(QSettings::IniFormat);
        QSettings::setPath(QSettings::IniFormat, QSettings::UserScope, m_dir.path());
        QCoreApplication::setOrganizationName(QStringLiteral("FrezkaWorkflowTest"));
        machine::MachineConfig profile = machine::defaultMachineConfig(protocol::Variant::Gve64);
        m_pty = qgetenv("FREZKA_WORKFLOW_UNIT") == "pty";
        if (m_pty) {
            // gve-emu with home switches where a GVE64 mill has them, on a pty opened by its
            // path like hardware.
            m_emu.setProgram(QStringLiteral(FREZKA_GVE_EMU));
            m_emu.setArguments({QStringLiteral("--variant"), QStringLiteral("gve64"),
                                QStringLiteral("--home"), QStringLiteral("X=0"),
                                QStringLiteral("--home"), QStringLiteral("Y=0"),
                                QStringLiteral("--home"), QStringLiteral("Z=0,+"),
                                QStringLiteral("--verbose")}); // what it receives, on stderr
            m_emu.start();
            QVERIFY(m_emu.waitForStarted());
            QTRY_VERIFY_WITH_TIMEOUT(m_emu.canReadLine(), 10000);
            const QString pty = QString::fromLocal8Bit(m_emu.readLine()).trimmed();
            QVERIFY2(pty.startsWith(QLatin1Char('/')), qPrintable(pty));
            profile.link.port = pty.toStdString();
        } else {
            profile.link.port = "emulator"; // the built-in emulator, in real time
        }
        const QString profilePath = m_dir.filePath(QStringLiteral("machine.json"));
        QVERIFY(!machine::saveMachineConfig(profile, profilePath.toStdString()));
        QSettings().setValue(QStringLiteral("lastProfile"), profilePath);
        MainWindowOptions options;
        options.view = MainWindowOptions::View::Software;
        options.restoreLayout = false;
        m_window = std::make_unique<MainWindow>(options);
        m_window->show();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Idle, 20000);
        QVERIFY(!state().firmware.empty());
    }

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

    void spindleAndCoolantReachTheUnit()
    {
        QVERIFY(waitIdle());
        auto *spindle = button(m_window->outputsPanel(), "spindle");
        spindle->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().spindlePermille > 0, 10000);
        QTRY_VERIFY(m_window->ioPanel()->outputLed(0));
        button(m_window->outputsPanel(), "coolant")->click();
        const std::uint8_t bit =
            machine::outputBit(m_window->profile(), machine::OutputFunction::Coolant);
        QVERIFY(bit != 0);
        QTRY_VERIFY_WITH_TIMEOUT((state().outputs & bit) == 0, 10000); // active low: on
        spindle->click();
        QTRY_COMPARE_WITH_TIMEOUT(state().spindlePermille, 0, 10000);
        button(m_window->outputsPanel(), "coolant")->click();
        QTRY_VERIFY_WITH_TIMEOUT((state().outputs & bit) != 0, 10000);
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

    void feedOverrideReachesTheUnit()
    {
        auto *slider =
            m_window->outputsPanel()->findChild<QSlider *>(QStringLiteral("feedOverride"));
        slider->setValue(150);
        emit slider->sliderReleased();
        QTRY_COMPARE_WITH_TIMEOUT(state().overridePercent, 150, 10000);
        button(m_window->outputsPanel(), "feedDown")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().overridePercent < 150, 10000);
        button(m_window->outputsPanel(), "feedReset")->click();
        QTRY_COMPARE_WITH_TIMEOUT(state().overridePercent, 100, 10000);
    }

    void programWithAnErrorShowsItAndRunsNothing()
    {
        QVERIFY(waitIdle());
        const QString path =
            writeProgram(QStringLiteral("bad.nc"), "G21 G90\nG0 X10\nG1 X20 Q\nM30\n");
        QSignalSpy errors(m_window.get(), &MainWindow::errorShown);
        QVERIFY(load(path));
        QVERIFY(!m_window->program()->program().ok());
        QVERIFY(errors.count() >= 1);
        QVERIFY2(m_window->lastError().contains(QStringLiteral("bad.nc:3:")),
                 qPrintable(m_window->lastError()));
        QVERIFY(!button(m_window->runPanel(), "run")->isEnabled());
        const auto before = state().positionSteps;
        m_window->runProgram();
        QVERIFY(m_window->lastError().contains(QStringLiteral("bad.nc:3:")));
        QTest::qWait(0);
        QCOMPARE(state().mode, MachineMode::Idle);
        QCOMPARE(state().positionSteps, before);
    }

    void programOutsideTheSoftLimitsIsRedAndRefused()
    {
        const QString path =
            writeProgram(QStringLiteral("far.nc"), "G21 G90\nG0 X10 Y10\nG1 X450 F1000\nM30\n");
        QVERIFY(load(path));
        const LoadedProgram &p = m_window->program()->program();
        QVERIFY(!p.runnable());
        QVERIFY(m_window->toolpathView()->model()->boundsOutsideLimits());
        QVERIFY2(m_window->lastError().contains(QStringLiteral("far.nc:3:")),
                 qPrintable(m_window->lastError()));
        QVERIFY(!button(m_window->runPanel(), "run")->isEnabled());
    }

    // A feed above what the axes allow (the GVE64's X runs at most 4000 mm/min) is told once,
    // with its line and both feeds, among the check results in the console; the program runs.
    void feedAboveTheAxesIsToldInTheCheckResults()
    {
        const QString path = writeProgram(QStringLiteral("fast.nc"),
                                          "G21 G90\nG0 X10 Y10 Z-1\nG1 X20 F12000\nG1 Y20\nM30\n");
        QVERIFY(load(path));
        QVERIFY(m_window->program()->program().runnable());
        int told = 0;
        for (const LogEntry &e : m_window->console()->entries()) {
            const QString line = QString::fromUtf8(e.bytes);
            if (line.contains(QStringLiteral("fast.nc:3:")) &&
                line.contains(QStringLiteral("F12000 mm/min")) &&
                line.contains(QStringLiteral("4000 mm/min")))
                ++told;
        }
        QCOMPARE(told, 1);
    }

    void eepromWriteAndReadBack()
    {
        QVERIFY(waitIdle());
        UnitConfigDialog *dlg = m_window->openUnitConfig();
        QSignalSpy finished(dlg, &UnitConfigDialog::finished);
        dlg->readUnit();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(dlg->statusText()));
        for (const auto &r : dlg->rows())
            QVERIFY(r.unit.has_value());
        machine::MachineConfig changed = m_window->profile();
        changed.eeprom.polarity = 0x5A;
        changed.axes[1].stepsPerMm = 250;
        dlg->setProfile(changed);
        dlg->readUnit();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY(dlg->differences() >= 2);
        dlg->writeUnit(false);
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY2(finished.last().at(0).toBool(), qPrintable(dlg->statusText()));
        QCOMPARE(dlg->differences(), 0);
        dlg->readUnit(); // a fresh read agrees
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QCOMPARE(dlg->differences(), 0);
        dlg->close();
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

    void languageSwitch()
    {
        auto *run = button(m_window->runPanel(), "run");
        QCOMPARE(run->text(), QStringLiteral("Run"));
        SettingsDialog *settings = m_window->openSettings();
        settings->chooseLanguage(QStringLiteral("cs"));
        QTRY_COMPARE(run->text(), QStringLiteral("Spustit"));
        QCOMPARE(QSettings().value(QStringLiteral("language")).toString(), QStringLiteral("cs"));
        settings->chooseLanguage(QStringLiteral("en"));
        QTRY_COMPARE(run->text(), QStringLiteral("Run"));
        settings->close();
    }

    // A failed step must not leave the machine held for the next one.
    void cleanup()
    {
        if (state().mode != MachineMode::Idle) {
            m_window->controller()->abort();
            waitIdle();
        }
    }

    void cleanupTestCase()
    {
        m_window.reset();
        m_emu.terminate();
        m_emu.waitForFinished(5000);
    }

private:
    QTemporaryDir m_dir;
    QProcess m_emu;
    QByteArray m_emuLog; // gve-emu's --verbose log read so far
    bool m_pty = false;  // the unit is gve-emu on a pty
    std::unique_ptr<MainWindow> m_window;
};

QTEST_MAIN(WorkflowTest)
#include "workflow_test.moc"
