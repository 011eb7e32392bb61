// Programs that probe for themselves run from the main window (issue 19 item 4): the built-in
// emulator in real time with a tilted work top (FREZKA_EMULATOR_SURFACE), Run pressed as the
// operator would. The window's Run follows each probe (session::ProbeFollow): asserted on what
// reached the unit (the probe input armed once per probe on the wire, the serial trace), the
// unit's counters (the cut at the probed surface − 0.1 within a step; every point of the
// autolevel grid's cut 0.1 below the tilted surface), the job ending finished without
// ProbeTrippedElsewhere; and on the preview: provisional after the first probe when loaded,
// from the next probe after each one followed, none after the last. Run from a line and a height
// map are refused with the probe's line.

#include "gui/jogpanel.h"
#include "gui/mainwindow.h"
#include "gui/runpanel.h"
#include "gui/toolpathview.h"

#include "../session/probefollow_programs.h"
#include "windowtest.h"

#include "driver/emulator/serialtrace.h"
#include "driver/link/machinecontroller.h"
#include "session/workoffsets.h"

#include <QRegularExpression>
#include <QSettings>
#include <QStandardPaths>
#include <QStatusBar>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>

using namespace frezka;
using namespace frezka::gui;
using driver::MachineMode;

namespace {

namespace window = frezka::gui::test; // windowtest.h
namespace programs = frezka::test;    // probefollow_programs.h

constexpr double kStepsPerMm = 200; // the GVE64's default profile, X Y Z
constexpr int kTimeoutMs = 120000;

} // namespace

class ProbeFollowWindowTest : public QObject
{
    Q_OBJECT

    const driver::MachineState &state() const { return m_window->controller()->state(); }
    const LoadedProgram &program() const { return m_window->program()->program(); }
    ToolpathViewModel *view() const { return m_window->toolpathView()->model(); }

    // The probe moves that reached the unit since the trace was cleared: the probe input (IN15,
    // bit 7 of status register 1) armed for each, on the serial trace.
    int probesOnTheWire()
    {
        const QString path = m_dir.filePath(QStringLiteral("run.trace"));
        QString error;
        if (!m_window->saveSerialTrace(path, &error))
            return -1;
        QFile f(path);
        if (!f.open(QIODevice::ReadOnly))
            return -1;
        emulator::SerialTrace trace;
        emulator::TraceMessage bad;
        if (!emulator::parseTrace(f.readAll().toStdString(), trace, bad))
            return -1;
        static const QRegularExpression arm(QStringLiteral("SW1,([0-9A-Fa-f]+)"));
        int armed = 0;
        for (const emulator::TraceEntry &e : trace.entries) {
            if (e.direction != emulator::TraceDirection::ToUnit)
                continue;
            auto it = arm.globalMatch(QString::fromStdString(e.bytes));
            while (it.hasNext())
                armed += (it.next().captured(1).toInt(nullptr, 16) & 0x80) != 0;
        }
        return armed;
    }

    // Presses Run and waits for the job's end; the positions the unit reported meanwhile and
    // what the status bar said.
    bool runToTheEnd(std::vector<std::array<std::int64_t, 4>> *seen, bool *ok)
    {
        m_messages.clear();
        QSignalSpy finished(m_window->workflow(), &session::RunWorkflow::jobFinished);
        auto said = connect(m_window->statusBar(), &QStatusBar::messageChanged, this,
                            [this](const QString &m) { m_messages += m + QLatin1Char('\n'); });
        auto sample =
            connect(m_window->controller(), &driver::MachineController::stateChanged, this,
                    [seen](const driver::MachineState &s) { seen->push_back(s.positionSteps); });
        const emulator::Stats before = window::emulatorStats(m_window.get());
        const session::OffsetState offsetsBefore = m_window->offsets()->state();
        QSignalSpy reloaded(m_window->program(), &ProgramSession::loaded);
        window::button(m_window->runPanel(), "run")->click();
        const bool ended = finished.wait(kTimeoutMs);
        // Offsets the program set are kept, and the program is loaded again with them.
        if (ended && !(m_window->offsets()->state() == offsetsBefore) && reloaded.isEmpty() &&
            !reloaded.wait(20000))
            return false;
        disconnect(sample);
        disconnect(said);
        // What the unit did: it ran, never cut without the spindle at speed, never kept it
        // turning while held, and braked on its ramp every time.
        const emulator::Stats after = window::emulatorStats(m_window.get());
        m_unitRan = after.motion.vectorsExecuted > before.motion.vectorsExecuted &&
                    after.safety == before.safety &&
                    after.motion.brakeViolations == before.motion.brakeViolations;
        if (!m_unitRan)
            qWarning("the unit: %lld vectors, %lld cuts without the spindle, %lld held with "
                     "it on, %lld brake violations",
                     qlonglong(after.motion.vectorsExecuted - before.motion.vectorsExecuted),
                     qlonglong(after.safety.cutWithoutSpindle - before.safety.cutWithoutSpindle),
                     qlonglong(after.safety.spindleOnWhileHeld - before.safety.spindleOnWhileHeld),
                     qlonglong(after.motion.brakeViolations - before.motion.brakeViolations));
        if (!ended)
            return false;
        *ok = finished.front().front().toBool();
        QTest::qWait(50); // a second jobFinished would be a run that ended twice
        return finished.size() == 1 &&
               QTest::qWaitFor([&] { return state().mode == MachineMode::Idle; }, kTimeoutMs);
    }

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        m_window = window::emulatorWindow(m_dir, "plane:-2,0.02,-0.015",
                                          QStringLiteral("FrezkaProbeFollowWindowTest"));
        QVERIFY(m_window);
        window::button(m_window->jogPanel(), "homeAll")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().homed && state().mode == MachineMode::Idle, kTimeoutMs);
    }

    // G38.2 Z-10 F50 over X10 Y10, G10 L20 P1 Z0 there, a cut 0.1 deep to X20.
    void touchOffThenCutRunsWithTheProbesResult()
    {
        m_window->selectWorkOffset(0);
        const QString path =
            window::writeProgram(m_dir, QStringLiteral("touchoff.ngc"), programs::kTouchOff);
        QVERIFY(window::openAndWait(m_window.get(), path));
        QVERIFY2(program().runnable(),
                 qPrintable(program().errors.empty() ? QString() : program().errors[0].text));
        // Loaded: provisional after the probe on line 3, in the preview too.
        QCOMPARE(program().provisionalLine, 3u);
        QVERIFY(program().followRequest);
        QCOMPARE(view()->provisionalAfter(), std::uint32_t(program().provisionalEntry));
        QVERIFY(view()->firstProvisionalSegment() < view()->scene()->segments.size());
        // Check says so.
        QSignalSpy checked(m_window.get(), &MainWindow::programChecked);
        window::button(m_window->runPanel(), "check")->click();
        QVERIFY(checked.wait(20000));
        QVERIFY(m_window->statusBar()->currentMessage().contains(
            QStringLiteral("After line 3 the path depends on the probe's result")));

        QSignalSpy followed(m_window->workflow(), &session::RunWorkflow::probeFollowed);
        std::vector<std::uint32_t> provisionalAfter;
        const auto shown = connect(m_window->program(), &ProgramSession::probeFollowShown, this,
                                   [&] { provisionalAfter.push_back(view()->provisionalAfter()); });
        const int probesBefore = probesOnTheWire();
        std::vector<std::array<std::int64_t, 4>> seen;
        bool ok = false;
        QVERIFY(runToTheEnd(&seen, &ok));
        disconnect(shown);
        QVERIFY2(ok, qPrintable(m_window->lastError()));
        QVERIFY(m_unitRan);
        QVERIFY(!state().lastError ||
                state().lastError->reason.code != driver::DriverCode::ProbeTrippedElsewhere);
        QCOMPARE(m_window->workflow()->probesFollowed(), 1);
        QCOMPARE(followed.size(), 1);
        QCOMPARE(followed.front().front().value<std::uint32_t>(), 3u);
        QCOMPARE(probesOnTheWire() - probesBefore, 1);
        // The preview after the probe: the re-interpreted program, nothing provisional.
        QCOMPARE(provisionalAfter.front(), ToolpathViewModel::kNoProvisional);
        QCOMPARE(view()->scene()->sourceEntries, program().toolpath->size());
        QVERIFY2(m_messages.contains(QStringLiteral("Line 3: the probe's result was followed")),
                 qPrintable(m_messages));
        // The unit: the probe touched the work top at X10 Y10 (Z -1.95), the cut ends 0.1
        // below that, within a step.
        const double surfaceMm = programs::tilted(10, 10);
        QCOMPARE(state().positionSteps[0], std::int64_t(20 * kStepsPerMm));
        QCOMPARE(state().positionSteps[1], std::int64_t(10 * kStepsPerMm));
        QVERIFY2(std::abs(double(state().positionSteps[2]) - (surfaceMm - 0.1) * kStepsPerMm) <= 1,
                 qPrintable(QString::number(state().positionSteps[2])));
        std::int64_t lowest = 0;
        for (const auto &p : seen)
            lowest = std::min(lowest, p[2]);
        QVERIFY(double(lowest) >= (surfaceMm - 0.1) * kStepsPerMm - 1);
        // The window keeps the Z zero the program's G10 L20 set at the trip point (the next
        // program starts from it), and the console says so.
        QVERIFY2(std::abs(m_window->offsets()->systems()[0][2] - surfaceMm) <= 1 / kStepsPerMm,
                 qPrintable(QString::number(m_window->offsets()->systems()[0][2])));
        QCOMPARE(m_window->offsets()->systems()[0][0], 0.0);
    }

    // pcb2gcode's autolevel shape: a zero probe, a 3 × 3 grid into #500..#508, the cut's Z
    // interpolated from them; the work top tilted.
    void autolevelGridCutFollowsTheTiltedSurface()
    {
        // The test before left the tool in the work at the end of its cut: up first.
        m_window->executeManualLine(QStringLiteral("G53 G0 Z0"));
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Idle && state().positionSteps[2] == 0,
                                 kTimeoutMs);
        m_window->offsets()->setSystem(0, {0, 0, 0, 0});
        const std::string text = programs::autolevelProgram(60, 600);
        const QString path =
            window::writeProgram(m_dir, QStringLiteral("autolevel.ngc"), text.c_str());
        QVERIFY(window::openAndWait(m_window.get(), path));
        QVERIFY2(program().runnable(),
                 qPrintable(program().errors.empty() ? QString() : program().errors[0].text));
        QCOMPARE(program().provisionalLine, 4u);
        QCOMPARE(view()->provisionalAfter(), std::uint32_t(program().provisionalEntry));

        std::vector<std::uint32_t> lines, provisionalLines;
        std::vector<bool> viewMatches;
        const auto shown =
            connect(m_window->program(), &ProgramSession::probeFollowShown, this, [&] {
                lines.push_back(program().provisionalLine);
                viewMatches.push_back(
                    view()->provisionalAfter() == (program().provisional()
                                                       ? std::uint32_t(program().provisionalEntry)
                                                       : ToolpathViewModel::kNoProvisional) &&
                    view()->scene()->sourceEntries == program().toolpath->size() &&
                    program().estimatedS > 0);
            });
        const int probesBefore = probesOnTheWire();
        std::vector<std::array<std::int64_t, 4>> seen;
        bool ok = false;
        QVERIFY(runToTheEnd(&seen, &ok));
        disconnect(shown);
        QVERIFY2(ok, qPrintable(m_window->lastError()));
        QVERIFY(m_unitRan);
        QCOMPARE(m_window->workflow()->probesFollowed(), 10);
        QCOMPARE(probesOnTheWire() - probesBefore, 10);
        // The provisional part starts at the next grid probe (lines 8, 12 .. 40), none after.
        std::vector<std::uint32_t> expected;
        for (std::uint32_t l = 8; l <= 40; l += 4)
            expected.push_back(l);
        expected.push_back(0);
        QCOMPARE(lines, expected);
        QCOMPARE(viewMatches, std::vector<bool>(10, true));
        QVERIFY2(m_messages.contains(QStringLiteral("Line 40: the probe's result was followed")),
                 qPrintable(m_messages));
        // Every point the unit reported more than 0.05 below the surface is a cut point, 0.1
        // below it within 1.5 steps; at X4 Y3 the tool may be on its way down (the plunge: the
        // window polls in real time), never deeper.
        int cutPoints = 0;
        for (const auto &p : seen) {
            const double x = p[0] / kStepsPerMm, y = p[1] / kStepsPerMm, z = p[2] / kStepsPerMm;
            const double depth = programs::tilted(x, y) - z;
            if (depth < 0.05)
                continue;
            if (p[0] == std::int64_t(4 * kStepsPerMm) && p[1] == std::int64_t(3 * kStepsPerMm)) {
                QVERIFY2(depth <= 0.1 + 1.5 / kStepsPerMm, qPrintable(QString::number(depth)));
                continue;
            }
            ++cutPoints;
            QVERIFY2(std::abs(depth - 0.1) <= 1.5 / kStepsPerMm,
                     qPrintable(QStringLiteral("%1 at %2 %3 %4").arg(depth).arg(x).arg(y).arg(z)));
        }
        QVERIFY2(cutPoints >= 5, qPrintable(QString::number(cutPoints)));
        // The program's G10 L20 made the first probe's trip point (X0 Y0) G54's Z zero: kept,
        // and the program loaded again with it, provisional after its first probe again.
        QVERIFY2(std::abs(m_window->offsets()->systems()[0][2] - programs::tilted(0, 0)) <=
                     1 / kStepsPerMm,
                 qPrintable(QString::number(m_window->offsets()->systems()[0][2])));
        QVERIFY(!m_window->program()->restoreAsLoaded()); // nothing followed is shown any more
        QCOMPARE(program().provisionalLine, 4u);
        QCOMPARE(view()->provisionalAfter(), std::uint32_t(program().provisionalEntry));
    }

    // Run from a line and a height map would run the provisional path: refused, naming the line.
    void runFromALineAndAHeightMapAreRefusedWithTheProbesLine()
    {
        const QString path =
            window::writeProgram(m_dir, QStringLiteral("touchoff2.ngc"), programs::kTouchOff);
        QVERIFY(window::openAndWait(m_window.get(), path));
        QSignalSpy loaded(m_window->program(), &ProgramSession::loaded);
        m_window->runFromLine(7);
        QVERIFY(loaded.wait(20000));
        QVERIFY(!program().runnable());
        QVERIFY(!program().errors.empty());
        QCOMPARE(program().errors.front().line, 7);
        QVERIFY2(program().errors.front().text.contains(QStringLiteral("after line 3")),
                 qPrintable(program().errors.front().text));
        m_window->runWholeProgram();
        QVERIFY(loaded.wait(20000));
        QVERIFY(program().runnable());

        const QString map = window::writeProgram(m_dir, QStringLiteral("map.csv"),
                                                 "# frezka-height-map 1\n# origin_x_mm: 0\n"
                                                 "# origin_y_mm: 0\n# spacing_x_mm: 30\n"
                                                 "# spacing_y_mm: 30\n# count_x: 2\n# count_y: 2\n"
                                                 "0,0,0\n30,0,0\n0,30,0\n30,30,0\n");
        QString error;
        QVERIFY2(m_window->applyHeightMapFile(map, &error), qPrintable(error));
        QVERIFY(loaded.wait(20000));
        QVERIFY(!program().runnable());
        QCOMPARE(program().errors.front().line, 3);
        QVERIFY2(program().errors.front().text.contains(QStringLiteral("height map")),
                 qPrintable(program().errors.front().text));
    }

    void cleanupTestCase() { m_window.reset(); }

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
    QString m_messages;
    bool m_unitRan = false; // the last run: the unit moved, safely (runToTheEnd)
};

QTEST_MAIN(ProbeFollowWindowTest)
#include "probefollow_window_test.moc"
