// The height map in the window's toolpath view (issue 19 item 3): a map loaded in Machine ›
// Height map appears as a mesh in the view at its machine coordinates — the frame the program's
// toolpath is drawn in, every work offset applied — and after Apply the bent program's cut runs
// 0.1 mm under the mesh's nodes; View › Height map hides it (remembered), its Z scale
// exaggerates the heights only, Remove takes it away.

#include "gui/heightmapdialog.h"
#include "gui/mainwindow.h"
#include "gui/toolpathview.h"

#include "windowtest.h"

#include <QAction>
#include <QSettings>
#include <QStandardPaths>
#include <QtTest>

#include <cmath>

using namespace frezka;
using namespace frezka::gui;

namespace {

// Nodes from machine X10 Y10 every 10 mm, 5 x 4, the top 20.5 mm below the machine's zero at
// the first node: tilted 0.01 / 0.02 mm per mm with a bump in the middle.
const char kMap[] = "# frezka-height-map 1\n"
                    "# origin_x_mm: 10\n# origin_y_mm: 10\n"
                    "# spacing_x_mm: 10\n# spacing_y_mm: 10\n"
                    "# count_x: 5\n# count_y: 4\n"
                    "# reference_z_mm: -20.5\n";

double height(int i, int j)
{
    return 0.1 * i + 0.2 * j + (i == 2 && j == 2 ? 0.15 : 0.0);
}

int countColour(const QImage &img, const QColor &c)
{
    int n = 0;
    for (int y = 0; y < img.height(); ++y)
        for (int x = 0; x < img.width(); ++x)
            n += (img.pixel(x, y) & 0xFFFFFF) == (c.rgb() & 0xFFFFFF);
    return n;
}

} // namespace

class HeightMapWindowViewTest : public QObject
{
    Q_OBJECT

private slots:
    void initTestCase()
    {
        QVERIFY(m_dir.isValid());
        // The window's own link stays unconnected (test::unconnectedWindow).
        m_window = test::unconnectedWindow(m_dir, QStringLiteral("FrezkaHeightMapWindowViewTest"));
        QVERIFY(m_window);
    }

    void theMapShowsWhereTheProgramCuts();

    void cleanupTestCase() { m_window.reset(); }

private:
    QTemporaryDir m_dir;
    std::unique_ptr<MainWindow> m_window;
};

// One operator's sequence: load the program and the map, apply, hide, scale, remove.
void HeightMapWindowViewTest::theMapShowsWhereTheProgramCuts()
{
    ToolpathViewModel *model = m_window->toolpathView()->model();
    QVERIFY(!model->shownHeightMap());
    // The work's zero at machine X10 Y10 Z-20: the program's X0 Y0 is the map's first node.
    m_window->offsets()->setSystem(0, {10, 10, -20, 0});
    m_window->selectWorkOffset(0);
    const QByteArray program = "G21 G90 G94\nG0 Z2\nG0 X0 Y0\nG1 Z-0.1 F100\nG1 X40 F600\n"
                               "G1 Y20\nG0 Z2\nM2\n";
    QVERIFY(test::openAndWait(m_window.get(),
                              test::writeProgram(m_dir, QStringLiteral("cut.nc"), program)));
    QVERIFY2(m_window->program()->program().runnable(), qPrintable(m_window->lastError()));

    QByteArray text = kMap;
    text += "x_mm,y_mm,z_mm\n";
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 5; ++i)
            text += QByteArray::number(10 + 10 * i) + ',' + QByteArray::number(10 + 10 * j) + ',' +
                    QByteArray::number(height(i, j), 'f', 4) + '\n';
    const QString file = test::writeProgram(m_dir, QStringLiteral("map.csv"), text);
    HeightMapDialog *dialog = m_window->openHeightMap();
    QVERIFY(dialog->loadFrom(file));

    // Loaded: the mesh, every node at its machine X, Y and probed Z.
    const HeightMapMesh *mesh = model->shownHeightMap();
    QVERIFY(mesh);
    QCOMPARE(mesh->nodes.size(), std::size_t(20));
    QCOMPARE(mesh->triangles.size(), std::size_t(4 * 3 * 2 * 3));
    for (int j = 0; j < 4; ++j)
        for (int i = 0; i < 5; ++i)
            QCOMPARE(
                mesh->nodes[mesh->index(i, j)],
                QVector3D(float(10 + 10 * i), float(10 + 10 * j), float(-20.5 + height(i, j))));
    const QColor node = model->colours().heightMapNode;
    QVERIFY(countColour(m_window->toolpathView()->grabFrame(), node) > 20 * 4);

    // Applied, with the work's Z zero on the surface at the first node: the bent program's cut
    // along the first row of nodes (work Y0 = machine Y10) passes 0.1 mm under each of them,
    // in the view's frame.
    QSignalSpy reloaded(m_window->program(), &ProgramSession::loaded);
    test::button(dialog, "applyMap")->click();
    QTRY_VERIFY_WITH_TIMEOUT(!m_window->program()->isLoading() && reloaded.count() > 0, 20000);
    mesh = model->shownHeightMap();
    QVERIFY(mesh);
    const auto scene = model->scene();
    QVERIFY(scene && !scene->isEmpty());
    int under = 0;
    for (int i = 0; i < 5; ++i) {
        const QVector3D n = mesh->nodes[mesh->index(i, 0)];
        for (const SceneSegment &s : scene->segments) {
            if (s.cls == SegmentClass::Feed && std::abs(s.to.x() - n.x()) < 1e-3f &&
                std::abs(s.to.y() - n.y()) < 1e-3f) {
                QVERIFY2(std::abs(n.z() - s.to.z() - 0.1f) < 1e-4f,
                         qPrintable(QStringLiteral("node %1: %2 over %3")
                                        .arg(i)
                                        .arg(double(n.z()))
                                        .arg(double(s.to.z()))));
                ++under;
            }
        }
    }
    QCOMPARE(under, 5); // the plunge at the first node, then every node along X

    // View › Height map off: hidden and remembered; on again.
    auto *toggle = m_window->findChild<QAction *>(QStringLiteral("viewHeightMap"));
    QVERIFY(toggle && toggle->isCheckable() && toggle->isChecked());
    QVERIFY(!toggle->text().isEmpty());
    toggle->trigger();
    QVERIFY(!model->shownHeightMap());
    QCOMPARE(countColour(m_window->toolpathView()->grabFrame(), node), 0);
    QCOMPARE(QSettings().value(QStringLiteral("view/heightMap")).toBool(), false);
    toggle->trigger();
    QVERIFY(model->shownHeightMap());
    QCOMPARE(QSettings().value(QStringLiteral("view/heightMap")).toBool(), true);

    // The Z scale: the heights only, about the reference; the program is not scaled.
    auto *scale10 = m_window->findChild<QAction *>(QStringLiteral("viewHeightMapScale10"));
    QVERIFY(scale10);
    scale10->trigger();
    QCOMPARE(model->shownHeightMap()->nodes[model->shownHeightMap()->index(2, 2)].z(),
             float(-20.5 + 10 * height(2, 2)));
    QCOMPARE(QSettings().value(QStringLiteral("view/heightMapZScale")).toDouble(), 10.0);
    QCOMPARE(model->scene(), scene);
    m_window->findChild<QAction *>(QStringLiteral("viewHeightMapScale1"))->trigger();

    // Remove: the program as written and no map in the view.
    reloaded.clear();
    test::button(dialog, "removeMap")->click();
    QTRY_VERIFY_WITH_TIMEOUT(!m_window->program()->isLoading() && reloaded.count() > 0, 20000);
    QVERIFY(!model->hasHeightMap());
    QVERIFY(!model->shownHeightMap());
    QCOMPARE(countColour(m_window->toolpathView()->grabFrame(), node), 0);
}

QTEST_MAIN(HeightMapWindowViewTest)
#include "heightmap_window_view_test.moc"
