// ToolpathScene decimation and the software renderer: colours per class, cut part, bounds.
#include "gui/toolpathrenderers.h"
#include "gui/toolpathscene.h"
#include "gui/toolpathview.h"

#include <QtTest>

using namespace frezka;
using namespace frezka::gui;

namespace {

gcode::Toolpath square(double size, int repeats)
{
    gcode::Toolpath p;
    p.appendRapid({0, 0, 5, 0}, 0, 1);
    p.appendFeed({0, 0, -1, 0}, 300, 2);
    std::uint32_t line = 3;
    for (int r = 0; r < repeats; ++r) {
        p.appendFeed({size, 0, -1, 0}, 600, line++);
        p.appendFeed({size, size, -1, 0}, 600, line++);
        p.appendFeed({0, size, -1, 0}, 600, line++);
        p.appendFeed({0, 0, -1, 0}, 600, line++);
    }
    p.appendRapid({0, 0, 5, 0}, 0, line++);
    return p;
}

int countColour(const QImage &img, const QColor &c)
{
    int n = 0;
    for (int y = 0; y < img.height(); ++y) {
        const auto *row = reinterpret_cast<const QRgb *>(img.constScanLine(y));
        for (int x = 0; x < img.width(); ++x)
            n += (row[x] & 0xFFFFFF) == (c.rgb() & 0xFFFFFF);
    }
    return n;
}

} // namespace

class ToolpathViewTest : public QObject
{
    Q_OBJECT

private slots:
    void sceneKeepsClassesAndBounds()
    {
        const auto path = square(50, 1);
        const auto scene = buildScene(path);
        QVERIFY(scene.bounds.valid);
        QCOMPARE(scene.bounds.min, QVector3D(0, 0, -1));
        QCOMPARE(scene.bounds.max, QVector3D(50, 50, 5));
        // 2 rapids + 5 feeds, nothing merged at this scale.
        QCOMPARE(scene.segments.size(), std::size_t(7));
        QCOMPARE(scene.segments.front().cls, SegmentClass::Rapid);
        QCOMPARE(scene.segments[1].cls, SegmentClass::Feed);
        QCOMPARE(scene.segments.back().cls, SegmentClass::Rapid);
        QCOMPARE(scene.firstSegmentAfter(2), std::size_t(3));
    }

    void sceneDecimatesTinySegmentsButKeepsEnds()
    {
        gcode::Toolpath p;
        p.appendFeed({100, 0, 0, 0}, 100, 1);
        // 100 000 tiny steps back along x: far below the merge length of a 100 mm part.
        for (int i = 1; i <= 100000; ++i)
            p.appendFeed({100 - i * 0.001, 0.0, 0.0, 0.0}, 100, std::uint32_t(i + 1));
        p.appendRapid({0, 0, 10, 0}, 0, 100002);
        const auto scene = buildScene(p);
        QVERIFY(scene.segments.size() < 5000); // merge length = diagonal / 4000
        // The last feed point and the rapid are exact.
        const auto &lastFeed = scene.segments[scene.segments.size() - 2];
        QCOMPARE(lastFeed.cls, SegmentClass::Feed);
        QVERIFY(qAbs(lastFeed.to.x() - 0.f) < 1e-3f);
        QCOMPARE(scene.segments.back().to, QVector3D(0, 0, 10));
    }

    void sceneCapIsHonoured()
    {
        gcode::Toolpath p;
        for (int i = 0; i < 200000; ++i)
            p.appendFeed({double(i % 2) * 10, double(i) * 0.01, 0, 0}, 100, std::uint32_t(i + 1));
        SceneOptions o;
        o.maxSegments = 5000;
        const auto scene = buildScene(p, o);
        QVERIFY(scene.segments.size() <= 5000);
        QVERIFY(!scene.segments.empty());
    }

    void arcsAreChorded()
    {
        gcode::Toolpath p;
        p.setOrigin({10, 0, 0, 0});
        gcode::ArcInfo arc;
        arc.centre = {0, 0, 0, 0};
        arc.turns = 1;
        p.appendArc({-10, 0, 0, 0}, arc, 100, 1); // half circle CCW through +Y
        const auto scene = buildScene(p);
        QVERIFY(scene.segments.size() > 10);
        QCOMPARE(scene.segments.front().cls, SegmentClass::Arc);
        QVERIFY(scene.bounds.max.y() > 9.9f);
    }

    void softwareRendererDrawsClassesAndCutPart()
    {
        ToolpathView view(nullptr, ToolpathView::Backend::Software);
        QVERIFY(!view.usesOpenGl());
        view.resize(400, 300);
        auto scene = std::make_shared<ToolpathScene>(buildScene(square(50, 1)));
        view.model()->setScene(scene);
        view.model()->setPreset(ViewPreset::Top);
        const auto &c = view.model()->colours();
        QImage img =
            static_cast<SoftwareToolpathRenderer *>(view.renderer())->renderImage({400, 300});
        QVERIFY(countColour(img, c.feed) > 100);
        QCOMPARE(countColour(img, c.cut), 0);
        view.model()->setCutEntry(4); // rapid, plunge, first two sides cut
        img = static_cast<SoftwareToolpathRenderer *>(view.renderer())->renderImage({400, 300});
        QVERIFY(countColour(img, c.cut) > 100);
        QVERIFY(countColour(img, c.feed) > 50);
    }

    // A program that probes for itself (issue 19 item 4): the path after the probe not run yet
    // in the dim provisional colour, dashed (background between the dashes), the rest as before;
    // a cut part stays the cut colour.
    void softwareRendererDrawsTheProvisionalPartDimAndDashed()
    {
        ToolpathView view(nullptr, ToolpathView::Backend::Software);
        view.resize(400, 300);
        view.model()->setScene(std::make_shared<ToolpathScene>(buildScene(square(50, 1))));
        view.model()->setPreset(ViewPreset::Top);
        const auto &c = view.model()->colours();
        auto render = [&] {
            return static_cast<SoftwareToolpathRenderer *>(view.renderer())
                ->renderImage({400, 300});
        };
        QCOMPARE(view.model()->firstProvisionalSegment(), view.model()->scene()->segments.size());
        const int allFeed = countColour(render(), c.feed);
        QCOMPARE(countColour(render(), c.provisional), 0);
        view.model()->setProvisionalAfter(2); // after the first side: three sides provisional
        QVERIFY(view.model()->firstProvisionalSegment() < view.model()->scene()->segments.size());
        const QImage img = render();
        const int provisional = countColour(img, c.provisional), feed = countColour(img, c.feed);
        QVERIFY2(provisional > 100, qPrintable(QString::number(provisional)));
        QVERIFY2(feed > 50 && feed < allFeed / 2, qPrintable(QString::number(feed)));
        // Dashed: along the far side (y = 50 mm, the top row of the square) what lies under it
        // (the background, the bounds box) shows between the dashes.
        int row = -1, best = 0;
        for (int y = 0; y < img.height(); ++y) {
            int n = 0;
            for (int x = 0; x < img.width(); ++x)
                n += (img.pixel(x, y) & 0xFFFFFF) == (c.provisional.rgb() & 0xFFFFFF);
            if (n > best)
                best = n, row = y;
        }
        QVERIFY(row >= 0);
        int first = img.width(), last = -1, gaps = 0;
        for (int x = 0; x < img.width(); ++x) {
            if ((img.pixel(x, row) & 0xFFFFFF) == (c.provisional.rgb() & 0xFFFFFF))
                first = std::min(first, x), last = x;
        }
        for (int x = first; x <= last; ++x)
            gaps += (img.pixel(x, row) & 0xFFFFFF) != (c.provisional.rgb() & 0xFFFFFF);
        QVERIFY2(gaps > 10, qPrintable(QString::number(gaps)));
        view.model()->setCutEntry(5); // cut past the probe: the cut colour wins
        QVERIFY(countColour(render(), c.provisional) < provisional);
        QVERIFY(countColour(render(), c.cut) > 100);
        view.model()->setProvisionalAfter(ToolpathViewModel::kNoProvisional);
        QCOMPARE(countColour(render(), c.provisional), 0);
    }

    void boundsTurnRedOutsideLimits()
    {
        ToolpathView view(nullptr, ToolpathView::Backend::Software);
        view.resize(400, 300);
        view.model()->setScene(std::make_shared<ToolpathScene>(buildScene(square(50, 1))));
        auto render = [&] {
            return static_cast<SoftwareToolpathRenderer *>(view.renderer())
                ->renderImage({400, 300});
        };
        const QColor bad = view.model()->colours().boundsBad;
        QCOMPARE(countColour(render(), bad), 0);
        view.model()->setBoundsOutsideLimits(true);
        QVERIFY(countColour(render(), bad) > 20);
    }

    void cameraPresetsAndZoom()
    {
        ViewCamera cam;
        cam.setPreset(ViewPreset::Top);
        cam.fit({0, 0, 0}, {100, 100, 0});
        const QSize vp(400, 400);
        // Top view: +X to the right, +Y up on screen.
        const QMatrix4x4 m = cam.viewProjection(vp);
        QVERIFY(m.map(QVector3D(100, 50, 0)).x() > m.map(QVector3D(0, 50, 0)).x());
        QVERIFY(m.map(QVector3D(50, 100, 0)).y() > m.map(QVector3D(50, 0, 0)).y());
        cam.setPreset(ViewPreset::Front);
        const QMatrix4x4 f = cam.viewProjection(vp);
        QVERIFY(f.map(QVector3D(50, 50, 10)).y() > f.map(QVector3D(50, 50, 0)).y());
        const float before = cam.scaleMmPerPixel(vp);
        cam.zoom(2, QPointF(200, 200), vp);
        QVERIFY(cam.scaleMmPerPixel(vp) < before);
    }
};

QTEST_MAIN(ToolpathViewTest)
#include "toolpathview_test.moc"
