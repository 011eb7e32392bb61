// The live view on a dense job (issue 16 item 3): between the position polls of the wire-bound
// bundled raster at 8 ms latency, the window's DRO, tool marker and line highlight follow the
// driver's model of the unit, on the emulator's virtual clock (session::SimLink): the main window
// (offscreen, software view, its own link left unconnected) renders the states the simulated link
// publishes, exactly as it renders its controller's.

#include "gui/drowidget.h"
#include "gui/mainwindow.h"
#include "gui/programlisting.h"
#include "gui/toolpathview.h"
#include "gui/toolpathviewmodel.h"

#include "windowtest.h"

#include "driver/link/emulatorport.h"
#include "driver/link/machinecontroller.h"
#include "session/runworkflow.h"
#include "session/simlink.h"

#include <QSettings>
#include <QStandardPaths>
#include <QTemporaryDir>
#include <QtTest>

#include <cmath>
#include <map>

using namespace frezka;
using namespace frezka::gui;
using driver::MachineMode;

class LiveViewTest : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // The window's own link stays unconnected (test::unconnectedWindow).
        m_window = test::unconnectedWindow(m_dir, QStringLiteral("FrezkaLiveViewTest"));
        QVERIFY(m_window);
    }

    // At least 20 distinct DRO figures in every whole virtual second of the job; every modelled
    // figure shown in the DRO (marked as such), the tool marker and the listing, lies on a command
    // the unit accepted and within one vector of where the emulated unit is at that moment.
    void droFollowsTheModelOnTheWireBoundRaster();

    void cleanupTestCase() { m_window.reset(); }

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

void LiveViewTest::droFollowsTheModelOnTheWireBoundRaster()
{
    // The raster's stock-relative coordinates, where the default GVE64 profile's travel holds them.
    m_window->offsets()->setSystem(0, {60, 60, -60, 0});
    m_window->selectWorkOffset(0);
    QVERIFY(test::openAndWait(m_window.get(), QStringLiteral(FREZKA_SOURCE_DIR) +
                                                  "/tests/bench/planner/programs/surface.nc"));
    const LoadedProgram &loaded = m_window->program()->program();
    QVERIFY2(loaded.runnable(), qPrintable(m_window->lastError()));
    const machine::UnitProgram &program = *loaded.unitProgram;
    const machine::MachineConfig config = m_window->profile();

    driver::WireOptions wire;
    wire.latencyS = 0.008; // the profile's link.latencyMs: the job is wire-bound
    session::SimLink link(config, driver::unitOptionsFor(config), wire, driver::CoreOptions{});
    connect(&link, &session::MachineLink::stateChanged, m_window->controller(),
            &driver::MachineController::stateChanged);
    int modelled = 0, fresh = 0, ahead = 0, unmarked = 0, elsewhere = 0, offPath = 0;
    double worst = 0; // in vectors
    // After the window has rendered the state (connected after it), with the emulated unit where
    // it is at that moment.
    connect(&link, &session::MachineLink::stateChanged, this, [&](const driver::MachineState &s) {
        if (!s.jobActive || s.mode != MachineMode::Running)
            return;
        DroWidget *dro = m_window->dro();
        if (!s.live.modelled) {
            unmarked += dro->modelledShown() ? 1 : 0; // a read figure is not marked modelled
            return;
        }
        ++modelled;
        ahead += s.live.command >= s.commandsAcked ? 1 : 0;
        unmarked += dro->modelledShown() ? 0 : 1;
        const QVector3D tool = m_window->toolpathView()->model()->toolPosition();
        for (int a = 0; a < 3; ++a) {
            elsewhere += dro->machineText(a) != QString::number(s.live.mm[a], 'f', 3) ? 1 : 0;
            elsewhere += std::abs(tool[a] - s.live.mm[a]) > 1e-3 ? 1 : 0;
        }
        elsewhere += m_window->listing()->currentLine() != int(s.live.sourceLine) ? 1 : 0;
        if (s.live.atS != link.now())
            return; // published again for another change: the figure of an earlier moment
        ++fresh;
        // One vector: the longest motion from the command modelled to those beside it.
        double vectorMm = 1e-3; // the DRO's last digit
        const auto k = std::size_t(s.live.command);
        for (std::size_t j = k > 0 ? k - 1 : 0; j <= k + 1 && j < program.commands.size(); ++j) {
            double d2 = 0;
            for (int a = 0; a < 3; ++a) {
                const double mm = program.commands[j].d[a] / config.axes[a].stepsPerMm;
                d2 += mm * mm;
            }
            vectorMm = std::max(vectorMm, std::sqrt(d2));
        }
        double off2 = 0;
        for (int a = 0; a < 3; ++a) {
            const double unitMm =
                double(link.port().unit().position()[a]) / config.axes[a].stepsPerMm;
            const double shownMm = dro->machineText(a).toDouble();
            off2 += (shownMm - unitMm) * (shownMm - unitMm);
        }
        const double off = std::sqrt(off2);
        worst = std::max(worst, off / vectorMm);
        offPath += off > vectorMm + 1e-3 ? 1 : 0;
    });
    link.connectTo(session::RunWorkflow::connectionFor(config));
    QVERIFY(link.runUntil([&] { return link.state().mode == MachineMode::Idle; }, 30));
    bool finished = false, ok = false;
    connect(&link, &session::MachineLink::jobFinished, this, [&](bool o) {
        finished = true;
        ok = o;
    });
    link.run(program);

    // The DRO as the operator sees it every 5 ms of virtual time: its changes in each whole second
    // in which the emulated unit moved at every sample (not the spindle's spin-up at the start).
    struct Second
    {
        int changes = 0, samples = 0, moving = 0;
    };
    std::map<int, Second> seconds;
    QString last;
    auto unitWas = link.port().unit().position();
    while (!finished && link.now() < 300) {
        link.runFor(0.005);
        Second &second = seconds[int(link.now())];
        ++second.samples;
        const auto unit = link.port().unit().position();
        second.moving += unit != unitWas ? 1 : 0;
        unitWas = unit;
        if (link.state().mode != MachineMode::Running)
            continue;
        QString shown;
        for (int a = 0; a < 3; ++a)
            shown += m_window->dro()->workText(a) + QLatin1Char(' ');
        second.changes += shown != last ? 1 : 0;
        last = shown;
    }
    QVERIFY(finished && ok);
    int moving = 0;
    for (const auto &[at, second] : seconds) {
        if (second.samples < 190 || second.moving < second.samples)
            continue;
        ++moving;
        QVERIFY2(
            second.changes >= 20,
            qPrintable(QStringLiteral("second %1: %2 DRO figures").arg(at).arg(second.changes)));
    }
    QVERIFY2(moving > 30, "the raster moves for about 40 s");
    QVERIFY(modelled > 20 * 30);
    QVERIFY(fresh > 20 * 30);
    QCOMPARE(ahead, 0);
    QCOMPARE(unmarked, 0);
    QCOMPARE(elsewhere, 0);
    // Within one vector of the emulated unit at the figure's moment, but for a few just after a
    // poll where the unit accelerates through a row's turn (LiveModel.WireBoundRaster...).
    QVERIFY2(offPath <= fresh / 100 && worst <= 4.0,
             qPrintable(QStringLiteral("%1 of %2 figures more than a vector away, worst %3 vectors")
                            .arg(offPath)
                            .arg(fresh)
                            .arg(worst)));
}

QTEST_MAIN(LiveViewTest)
#include "liveview_test.moc"
