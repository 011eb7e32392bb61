// Machine › Height map (issue 19), the done-when in the window: the dialog probes a grid on the
// emulator's warped work top (session::SimLink on the virtual clock, its surface 0.3 mm out of
// flat over 100 mm), shows the heights, Apply loads the program again bent to the map (the
// listing keeps its lines) with the work's Z zero on the first point; the window's plan run on
// the emulator keeps the tool tip 0.08 .. 0.12 mm below the surface wherever it cuts (the
// unit's counters sampled every 2 ms of the virtual clock), and after Remove it does not. The
// toolpath view shows the map node by node as it is probed.

#include "gui/heightmapdialog.h"
#include "gui/mainwindow.h"
#include "gui/toolpathview.h"

#include "windowtest.h"

#include "driver/link/emulatorport.h"
#include "driver/link/machinecontroller.h"
#include "session/programplanner.h"
#include "session/runworkflow.h"
#include "session/simlink.h"

#include <QDoubleSpinBox>
#include <QSettings>
#include <QStandardPaths>
#include <QTableWidget>
#include <QTemporaryDir>
#include <QtTest>

#include <algorithm>
#include <cmath>

using namespace frezka;
using namespace frezka::gui;
using driver::MachineMode;

namespace {

// A tilt of 0.24 mm over the 80 mm work plus a 0.05 mm sine: about 0.3 mm over 100 mm.
const char kWarp[] = "warp:-20,0.002,0.001,0.05,100";

struct Depth
{
    int samples = 0;
    double min = 1e9, max = -1e9;
};

} // namespace

class HeightMapTest : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // The window's own link stays unconnected (test::unconnectedWindow).
        m_window = test::unconnectedWindow(m_dir, QStringLiteral("FrezkaHeightMapTest"));
        QVERIFY(m_window);
    }

    void probeApplyAndRunKeepTheDepth();

    void cleanupTestCase() { m_window.reset(); }

private:
    // Moves the simulated machine to the machine's zero (where the window plans from).
    bool returnToZero(session::SimLink &link, const machine::MachineConfig &config);
    // Runs the window's plan on the link; the tool's depth below the surface while it cuts.
    Depth runSampled(session::SimLink &link, const emulator::ProbeSurface &surface);

    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

bool HeightMapTest::returnToZero(session::SimLink &link, const machine::MachineConfig &config)
{
    session::InterpretRequest request;
    request.text = "G21 G90\nG0 Z0\nG0 X0 Y0\n";
    request.startMm = link.state().positionMm;
    const auto interpreted = session::interpretProgram(request);
    if (!interpreted.toolpath || !interpreted.errors.empty())
        return false;
    const auto plan = session::planProgram(*interpreted.toolpath, config, QStringLiteral("zero"));
    if (!plan.ok())
        return false;
    bool finished = false;
    auto c = connect(&link, &session::MachineLink::jobFinished, this, [&] { finished = true; });
    link.run(*plan.program);
    link.runUntil([&] { return finished && link.state().mode == MachineMode::Idle; }, 120);
    disconnect(c);
    return link.port().unit().position() == std::array<std::int64_t, 4>{};
}

Depth HeightMapTest::runSampled(session::SimLink &link, const emulator::ProbeSurface &surface)
{
    Depth depth;
    bool finished = false, ok = false;
    auto c = connect(&link, &session::MachineLink::jobFinished, this, [&](bool o) {
        finished = true;
        ok = o;
    });
    link.run(*m_window->program()->program().unitProgram);
    auto last = link.port().unit().position();
    while (!finished && link.now() < 3600) {
        link.runFor(0.002);
        const auto at = link.port().unit().position();
        const bool movedXY = at[0] != last[0] || at[1] != last[1];
        last = at;
        const double x = at[0] / 200.0, y = at[1] / 200.0, z = at[2] / 200.0;
        const double below = surface.heightMm(x, y) - z;
        if (!movedXY || below < -0.5) // a cut: moving in X/Y at the work, not above it
            continue;
        ++depth.samples;
        depth.min = std::min(depth.min, below);
        depth.max = std::max(depth.max, below);
    }
    disconnect(c);
    if (!ok)
        depth.samples = -1;
    return depth;
}

// One operator's sequence from the program's load to the two runs, in order (hence its length).
void HeightMapTest::probeApplyAndRunKeepTheDepth()
{
    // The work's zero at machine X10 Y10, its top near Z -20 (before probing: a guess).
    m_window->offsets()->setSystem(0, {10, 10, -20, 0});
    m_window->selectWorkOffset(0);
    QByteArray text = "G21 G90 G94\nM3 S10000\nG0 Z2\n";
    for (int k = 0; k <= 4; ++k) { // PCB-isolation style: 0.1 mm deep, 5 passes each way
        const QByteArray c = QByteArray::number(k * 20);
        text += "G0 X0 Y" + c + "\nG1 Z-0.1 F100\nG1 X80 F900\nG0 Z2\n";
        text += "G0 X" + c + " Y0\nG1 Z-0.1 F100\nG1 Y80 F900\nG0 Z2\n";
    }
    text += "M5\nM2\n";
    QVERIFY(test::openAndWait(m_window.get(),
                              test::writeProgram(m_dir, QStringLiteral("pcb.nc"), text)));
    QVERIFY2(m_window->program()->program().runnable(), qPrintable(m_window->lastError()));
    const std::uint32_t lines = std::uint32_t(m_window->program()->program().text->lineCount());

    const machine::MachineConfig config = m_window->profile();
    emulator::UnitOptions unit = driver::unitOptionsFor(config);
    QVERIFY(driver::setProbeSurface(unit, kWarp, config));
    session::SimLink link(config, unit, driver::WireOptions{}, driver::CoreOptions{});
    link.connectTo(session::RunWorkflow::connectionFor(config));
    QVERIFY(link.runUntil([&] { return link.state().mode == MachineMode::Idle; }, 30));

    HeightMapDialog *dialog = m_window->openHeightMap(&link);
    QVERIFY(dialog);
    QVERIFY(dialog->isVisible());
    test::button(dialog, "areaFromProgram")->click();
    QCOMPARE(dialog->findChild<QDoubleSpinBox *>(QStringLiteral("areaX1"))->value(), 80.0);
    dialog->findChild<QDoubleSpinBox *>(QStringLiteral("spacing"))->setValue(10);
    dialog->findChild<QDoubleSpinBox *>(QStringLiteral("clearance"))->setValue(1);
    dialog->findChild<QDoubleSpinBox *>(QStringLiteral("depth"))->setValue(2);
    QVERIFY(test::button(dialog, "probe")->isEnabled());
    test::button(dialog, "probe")->click();
    QVERIFY2(dialog->isProbing(), qPrintable(dialog->errorText()));
    // The view shows the map as it is probed: the nodes probed so far, a cell once its four
    // corners are (row 0, then row 1 from the right: the 11th node closes the first cell).
    const ToolpathViewModel *view = m_window->toolpathView()->model();
    auto probedInView = [view] {
        const HeightMapMesh *mesh = view->shownHeightMap();
        return mesh ? int(std::count(mesh->probed.begin(), mesh->probed.end(), true)) : 0;
    };
    QVERIFY(link.runUntil([&] { return probedInView() >= 11; }, 3600));
    QVERIFY(dialog->isProbing());
    QVERIFY(probedInView() < 81);
    QCOMPARE(view->shownHeightMap()->triangles.size(), std::size_t(6));
    QVERIFY(link.runUntil([&] { return !dialog->isProbing(); }, 3600));
    QVERIFY2(dialog->map().has_value(), qPrintable(dialog->errorText()));
    QCOMPARE(dialog->table()->rowCount(), 9);
    QCOMPARE(dialog->table()->columnCount(), 9);
    // The table's top-right cell is the node at the work's X80 Y80 (the highest Y on top).
    const gcode::HeightMap map = *dialog->map();
    QCOMPARE(dialog->table()->item(0, 8)->text(), QString::number(map.z(8, 8), 'f', 3));
    QVERIFY(map.maxZ() - map.minZ() > 0.2); // 0.24 mm: the tilt over the nodes, the sine between
    QCOMPARE(probedInView(), 81);
    QCOMPARE(view->shownHeightMap()->nodes[80],
             QVector3D(float(map.nodeX(8)), float(map.nodeY(8)),
                       float(map.probing().referenceZMm + map.z(8, 8))));

    // Save and load give the same map back.
    const QString file = m_dir.filePath(QStringLiteral("map.csv"));
    QVERIFY(dialog->saveTo(file));
    QVERIFY(dialog->loadFrom(file));

    QSignalSpy reloaded(m_window->program(), &ProgramSession::loaded);
    test::button(dialog, "applyMap")->click();
    QTRY_VERIFY_WITH_TIMEOUT(!m_window->program()->isLoading() && reloaded.count() > 0, 20000);
    const LoadedProgram &bent = m_window->program()->program();
    QVERIFY2(bent.runnable(), qPrintable(m_window->lastError()));
    QCOMPARE(std::uint32_t(m_window->program()->program().text->lineCount()), lines);
    QVERIFY(std::abs(m_window->offsets()->systems()[0][2] - map.probing().referenceZMm) < 1e-9);
    QVERIFY(test::button(dialog, "removeMap")->isEnabled());
    // The listing names the program's lines: every piece of the bent path is on one of them.
    for (std::size_t i = 0; i < bent.toolpath->size(); ++i)
        QVERIFY(bent.toolpath->line(i) >= 1 && bent.toolpath->line(i) <= lines);

    QVERIFY(returnToZero(link, config));
    const Depth withMap = runSampled(link, unit.surface);
    qInfo("with the map: %d samples, %.4f .. %.4f mm below the surface", withMap.samples,
          withMap.min, withMap.max);
    QVERIFY2(withMap.samples > 1000 && withMap.min >= 0.08 && withMap.max <= 0.12,
             qPrintable(QStringLiteral("%1 samples, %2 .. %3 mm")
                            .arg(withMap.samples)
                            .arg(withMap.min)
                            .arg(withMap.max)));

    reloaded.clear();
    test::button(dialog, "removeMap")->click();
    QTRY_VERIFY_WITH_TIMEOUT(!m_window->program()->isLoading() && reloaded.count() > 0, 20000);
    QVERIFY(!m_window->program()->heightMap());
    QVERIFY(returnToZero(link, config));
    const Depth without = runSampled(link, unit.surface);
    qInfo("without it: %d samples, %.4f .. %.4f mm below the surface", without.samples, without.min,
          without.max);
    QVERIFY(without.samples > 0);
    QVERIFY2(without.min < 0.08 || without.max > 0.12,
             qPrintable(QStringLiteral("%1 .. %2 mm").arg(without.min).arg(without.max)));
}

QTEST_MAIN(HeightMapTest)
#include "heightmap_test.moc"
