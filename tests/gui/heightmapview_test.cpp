// The height map in the toolpath view (issue 19 item 3): the mesh's geometry (nodes at their
// probed Z in the view's machine coordinates, the dialog's colour scale, faces and grid lines
// only between probed nodes, the Z scale), the model's show / hide / remove, and the QPainter
// view drawing a marker at every node that is not there without the map.

#include "gui/heightmapmesh.h"
#include "gui/toolpathrenderers.h"
#include "gui/toolpathview.h"

#include <QSignalSpy>
#include <QtTest>

using namespace frezka;
using namespace frezka::gui;

namespace {

// 4 x 3 nodes from machine X10 Y20, 5 mm in X and 10 mm in Y; the surface 20.5 mm below the
// machine's zero at the first node, tilted and with one node raised.
gcode::HeightMap sampleMap()
{
    gcode::HeightMap map(10, 20, 5, 10, 4, 3);
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i)
            map.setZ(i, j, 0.01 * i + 0.02 * j);
    map.setZ(2, 1, 0.3);  // the highest
    map.setZ(1, 2, -0.1); // the lowest
    gcode::HeightMapProbing probing;
    probing.referenceZMm = -20.5;
    map.setProbing(probing);
    return map;
}

QPoint projected(const ToolpathViewModel &model, const QVector3D &p, const QSize &size)
{
    const QVector3D n = model.camera().viewProjection(size).map(p);
    return {int(std::lround(size.width() / 2.0 + n.x() * size.width() / 2.0)),
            int(std::lround(size.height() / 2.0 - n.y() * size.height() / 2.0))};
}

} // namespace

class HeightMapViewTest : public QObject
{
    Q_OBJECT

private slots:
    void meshHasTheNodesAtTheirProbedZ()
    {
        const gcode::HeightMap map = sampleMap();
        const HeightMapMesh mesh = buildHeightMapMesh(map);
        QCOMPARE(mesh.countX, 4);
        QCOMPARE(mesh.countY, 3);
        QCOMPARE(mesh.nodes.size(), std::size_t(12));
        for (int j = 0; j < 3; ++j) {
            for (int i = 0; i < 4; ++i) {
                const QVector3D p = mesh.nodes[mesh.index(i, j)];
                QCOMPARE(p.x(), float(10 + 5 * i));
                QCOMPARE(p.y(), float(20 + 10 * j));
                QCOMPARE(p.z(), float(-20.5 + map.z(i, j)));
            }
        }
        QCOMPARE(mesh.triangles.size(), std::size_t(3 * 2 * 3 * 2)); // 3 x 2 cells, 2 each
        QCOMPARE(mesh.edges.size(), std::size_t(3 * 3 + 4 * 2));
        for (const auto k : mesh.triangles)
            QVERIFY(k < 12);
        // The dialog's scale: the lowest node blue, the highest red, over the map's range.
        QCOMPARE(mesh.colours[mesh.index(1, 2)], heightMapColour(0));
        QCOMPARE(mesh.colours[mesh.index(2, 1)], heightMapColour(1));
        QCOMPARE(mesh.colours[mesh.index(0, 0)], heightMapColour(0.1 / 0.4));
        QVERIFY(heightMapColour(0).hueF() > heightMapColour(1).hueF());
        QCOMPARE(mesh.bounds.min, QVector3D(10, 20, float(-20.5 - 0.1)));
        QCOMPARE(mesh.bounds.max, QVector3D(25, 40, float(-20.5 + 0.3)));
    }

    void zScaleExaggeratesOnlyTheHeights()
    {
        const gcode::HeightMap map = sampleMap();
        const HeightMapMesh mesh = buildHeightMapMesh(map, {}, 10);
        QCOMPARE(mesh.zScale, 10.f);
        QCOMPARE(mesh.nodes[mesh.index(2, 1)], QVector3D(20, 30, float(-20.5 + 3.0)));
        QCOMPARE(mesh.nodes[mesh.index(0, 0)], QVector3D(10, 20, -20.5f)); // the reference stays
    }

    void onlyProbedNodesAreDrawn()
    {
        const gcode::HeightMap map = sampleMap();
        std::vector<bool> probed(12, false);
        for (const int k : {0, 1, 2, 3, 7, 6}) // row 0, then row 1 from the right: serpentine
            probed[std::size_t(k)] = true;
        const HeightMapMesh mesh = buildHeightMapMesh(map, probed);
        QCOMPARE(mesh.nodes.size(), std::size_t(12));
        QCOMPARE(mesh.triangles.size(), std::size_t(6)); // the one cell with four probed corners
        QCOMPARE(mesh.edges.size(), std::size_t(3 + 1 + 2)); // row 0, row 1's, two uprights
        QCOMPARE(mesh.bounds.min.x(), 10.f);
        QCOMPARE(mesh.bounds.max.y(), 30.f);
        QVERIFY(buildHeightMapMesh(map, std::vector<bool>(12, false)).isEmpty());
        // The colours over the probed nodes' range: (2, 1) is the highest of them as well.
        QCOMPARE(mesh.colours[mesh.index(2, 1)], heightMapColour(1));
        QCOMPARE(mesh.colours[mesh.index(0, 0)], heightMapColour(0));
    }

    void modelShowsHidesAndRemovesTheMap()
    {
        ToolpathViewModel model;
        QSignalSpy changed(&model, &ToolpathViewModel::heightMapChanged);
        QVERIFY(!model.shownHeightMap());
        model.setHeightMap(sampleMap());
        QVERIFY(model.hasHeightMap());
        QVERIFY(model.shownHeightMap());
        QCOMPARE(model.shownHeightMap()->nodes.size(), std::size_t(12));
        model.setHeightMapVisible(false);
        QVERIFY(!model.shownHeightMap());
        QVERIFY(model.hasHeightMap()); // kept while hidden
        model.setHeightMapVisible(true);
        model.setHeightMapZScale(100);
        QCOMPARE(model.shownHeightMap()->nodes[4].z(), float(-20.5 + 100 * 0.02));
        model.clearHeightMap();
        QVERIFY(!model.shownHeightMap());
        QVERIFY(!model.hasHeightMap());
        QCOMPARE(changed.count(), 5);
    }

    void softwareViewMarksEveryNode()
    {
        ToolpathView view(nullptr, ToolpathView::Backend::Software);
        view.resize(400, 300);
        gcode::Toolpath p;
        p.setOrigin({5, 15, -18, 0}); // across the map, its bounds' box outside the nodes
        p.appendFeed({30, 45, -20.6, 0}, 300, 1);
        view.model()->setScene(std::make_shared<ToolpathScene>(buildScene(p)));
        view.model()->setPreset(ViewPreset::Top);
        const QSize size(400, 300);
        auto render = [&] {
            return static_cast<SoftwareToolpathRenderer *>(view.renderer())->renderImage(size);
        };
        const QRgb node = view.model()->colours().heightMapNode.rgb() & 0xFFFFFF;
        const QRgb bg = view.model()->colours().background.rgb() & 0xFFFFFF;
        const gcode::HeightMap map = sampleMap();
        // A node away from the program's line: (3, 0) at X25 Y20.
        const QVector3D at(25, 20, float(-20.5 + map.z(3, 0)));
        const QImage without = render();
        const QPoint px = projected(*view.model(), at, size);
        QCOMPARE(without.pixel(px) & 0xFFFFFF, bg);
        view.model()->setHeightMap(map);
        const QImage with = render();
        int marked = 0;
        const HeightMapMesh &mesh = *view.model()->shownHeightMap();
        for (const QVector3D &n : mesh.nodes) {
            const QPoint q = projected(*view.model(), n, size);
            // The marker's cross covers its node's pixel or a neighbour (rounding).
            bool found = false;
            for (int dy = -1; dy <= 1 && !found; ++dy)
                for (int dx = -1; dx <= 1 && !found; ++dx)
                    found = (with.pixel(q + QPoint(dx, dy)) & 0xFFFFFF) == node;
            marked += found;
        }
        QCOMPARE(marked, 12);
        // Inside a cell, away from its lines: the face, semi-transparent over the background.
        const QPoint face = projected(*view.model(), QVector3D(17.5, 25, -20.5f), size);
        QVERIFY((with.pixel(face) & 0xFFFFFF) != bg);
        QVERIFY((with.pixel(face) & 0xFFFFFF) != (without.pixel(face) & 0xFFFFFF));
        // The program's line is drawn over the mesh in its own colour.
        const QRgb feed = view.model()->colours().feed.rgb() & 0xFFFFFF;
        int feedPixels = 0;
        for (int y = 0; y < with.height(); ++y)
            for (int x = 0; x < with.width(); ++x)
                feedPixels += (with.pixel(x, y) & 0xFFFFFF) == feed;
        QVERIFY2(feedPixels > 50, qPrintable(QString::number(feedPixels)));
        view.model()->setHeightMapVisible(false);
        const QImage hidden = render();
        QCOMPARE(hidden.pixel(px) & 0xFFFFFF, bg);
        QCOMPARE(hidden, without);
    }
};

QTEST_MAIN(HeightMapViewTest)
#include "heightmapview_test.moc"
