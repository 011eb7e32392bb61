// The OpenGL toolpath renderer under xvfb-run (llvmpipe): it must get a context, link its
// shaders and draw the program's colours, and the height map's mesh (issue 19) under the path.
#include "gui/heightmapmesh.h"
#include "gui/toolpathrenderers.h"
#include "gui/toolpathscene.h"
#include "gui/toolpathview.h"

#include <QtTest>

using namespace frezka;
using namespace frezka::gui;

class GlViewTest : public QObject
{
    Q_OBJECT

private slots:
    void rendersWithOpenGl()
    {
        QVERIFY2(openGlUsable(), "no OpenGL context (run under xvfb-run)");
        ToolpathView view(nullptr, ToolpathView::Backend::Auto);
        QVERIFY(view.usesOpenGl());
        view.resize(400, 300);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        gcode::Toolpath p;
        p.appendRapid({0, 0, 5, 0}, 0, 1);
        p.appendFeed({50, 0, 0, 0}, 600, 2);
        p.appendFeed({50, 50, 0, 0}, 600, 3);
        p.appendFeed({0, 50, 0, 0}, 600, 4);
        view.model()->setScene(std::make_shared<ToolpathScene>(buildScene(p)));
        view.model()->setPreset(ViewPreset::Top);
        const QImage img = view.grabFrame();
        QVERIFY(static_cast<GlToolpathRenderer *>(view.renderer())->isReady());
        const QRgb feed = view.model()->colours().feed.rgb() & 0xFFFFFF;
        const QRgb bg = view.model()->colours().background.rgb() & 0xFFFFFF;
        int feedPixels = 0, bgPixels = 0;
        for (int y = 0; y < img.height(); ++y) {
            for (int x = 0; x < img.width(); ++x) {
                const QRgb px = img.pixel(x, y) & 0xFFFFFF;
                feedPixels += px == feed;
                bgPixels += px == bg;
            }
        }
        QVERIFY2(feedPixels > 100, qPrintable(QString::number(feedPixels)));
        QVERIFY(bgPixels > img.width() * img.height() / 2);
    }

    // The path after a probe not run yet (issue 19 item 4) in the dim provisional colour.
    void drawsTheProvisionalPartDim()
    {
        QVERIFY2(openGlUsable(), "no OpenGL context (run under xvfb-run)");
        ToolpathView view(nullptr, ToolpathView::Backend::Auto);
        QVERIFY(view.usesOpenGl());
        view.resize(400, 300);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        gcode::Toolpath p;
        p.appendRapid({0, 0, 5, 0}, 0, 1);
        p.appendFeed({50, 0, 0, 0}, 600, 2);
        p.appendFeed({50, 50, 0, 0}, 600, 3);
        p.appendFeed({0, 50, 0, 0}, 600, 4);
        view.model()->setScene(std::make_shared<ToolpathScene>(buildScene(p)));
        view.model()->setPreset(ViewPreset::Top);
        const QRgb feed = view.model()->colours().feed.rgb() & 0xFFFFFF;
        const QRgb dim = view.model()->colours().provisional.rgb() & 0xFFFFFF;
        auto count = [](const QImage &img, QRgb colour) {
            int n = 0;
            for (int y = 0; y < img.height(); ++y)
                for (int x = 0; x < img.width(); ++x)
                    n += (img.pixel(x, y) & 0xFFFFFF) == colour;
            return n;
        };
        const QImage before = view.grabFrame();
        QCOMPARE(count(before, dim), 0);
        view.model()->setProvisionalAfter(1); // the first side as written, two provisional
        const QImage after = view.grabFrame();
        QVERIFY2(count(after, dim) > 100, qPrintable(QString::number(count(after, dim))));
        QVERIFY(count(after, feed) > 50 && count(after, feed) < count(before, feed) / 2);
    }

    // The mesh's node markers at their projected pixels, its faces blended over the background,
    // the path drawn over it in its own colour; nothing of it once hidden.
    void drawsTheHeightMap()
    {
        ToolpathView view(nullptr, ToolpathView::Backend::OpenGl);
        view.resize(400, 300);
        view.show();
        QVERIFY(QTest::qWaitForWindowExposed(&view));
        gcode::Toolpath p;
        p.setOrigin({-5, -5, 1, 0});
        p.appendFeed({45, 35, -0.1, 0}, 600, 1);
        view.model()->setScene(std::make_shared<ToolpathScene>(buildScene(p)));
        view.model()->setToolPosition({-5, -5, 1}); // the red cone off the nodes
        view.model()->setPreset(ViewPreset::Top);
        gcode::HeightMap map(0, 0, 10, 10, 5, 4);
        for (int j = 0; j < 4; ++j)
            for (int i = 0; i < 5; ++i)
                map.setZ(i, j, 0.01 * i * j);
        const QImage without = view.grabFrame();
        view.model()->setHeightMap(map);
        const QImage with = view.grabFrame();
        QVERIFY(static_cast<GlToolpathRenderer *>(view.renderer())->isReady());
        const QSize size = with.size();
        const QMatrix4x4 mvp = view.model()->camera().viewProjection(size);
        auto pixelOf = [&](const QVector3D &v) {
            const QVector3D n = mvp.map(v);
            return QPoint(int(std::lround(size.width() / 2.0 + n.x() * size.width() / 2.0)),
                          int(std::lround(size.height() / 2.0 - n.y() * size.height() / 2.0)));
        };
        const QRgb node = view.model()->colours().heightMapNode.rgb() & 0xFFFFFF;
        const QRgb bg = view.model()->colours().background.rgb() & 0xFFFFFF;
        int marked = 0;
        for (const QVector3D &n : view.model()->shownHeightMap()->nodes) {
            const QPoint q = pixelOf(n);
            bool found = false;
            for (int dy = -1; dy <= 1 && !found; ++dy)
                for (int dx = -1; dx <= 1 && !found; ++dx)
                    found = (with.pixel(q + QPoint(dx, dy)) & 0xFFFFFF) == node;
            marked += found;
            if (!found)
                qWarning("node %g %g at %d %d: %s", n.x(), n.y(), q.x(), q.y(),
                         qPrintable(with.pixelColor(q).name()));
            QVERIFY((without.pixel(q) & 0xFFFFFF) != node);
        }
        QCOMPARE(marked, 20);
        // A face (cell i 3, j 0; the path is far from it): blended, neither background nor opaque.
        const QPoint face = pixelOf(QVector3D(35, 5, 0.f));
        QCOMPARE(without.pixel(face) & 0xFFFFFF, bg);
        const QColor blended = with.pixelColor(face);
        QVERIFY2((blended.rgb() & 0xFFFFFF) != bg, qPrintable(blended.name()));
        QVERIFY(blended.red() < 200 && blended.blue() < 200); // the background shows through
        const QRgb feed = view.model()->colours().feed.rgb() & 0xFFFFFF;
        int feedPixels = 0;
        for (int y = 0; y < with.height(); ++y)
            for (int x = 0; x < with.width(); ++x)
                feedPixels += (with.pixel(x, y) & 0xFFFFFF) == feed;
        QVERIFY2(feedPixels > 100, qPrintable(QString::number(feedPixels)));
        view.model()->setHeightMapVisible(false);
        const QImage hidden = view.grabFrame();
        QCOMPARE(hidden.pixel(face) & 0xFFFFFF, bg);
        QCOMPARE(hidden, without);
    }
};

QTEST_MAIN(GlViewTest)
#include "glview_test.moc"
