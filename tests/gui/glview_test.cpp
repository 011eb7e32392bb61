// The OpenGL toolpath renderer under xvfb-run (llvmpipe): it must get a context, link its
// shaders and draw the program's colours.
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
};

QTEST_MAIN(GlViewTest)
#include "glview_test.moc"
