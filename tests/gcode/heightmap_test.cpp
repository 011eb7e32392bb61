// HeightMap: interpolation, the file format, and the toolpath bent to the surface.
#include "gcode/heightmap.h"
#include "gcode/interpreter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <random>

using namespace frezka::gcode;

namespace {

HeightMap mapOf(double ox, double oy, double sx, double sy, int nx, int ny,
                const std::function<double(double, double)> &f)
{
    HeightMap m(ox, oy, sx, sy, nx, ny);
    for (int j = 0; j < ny; ++j)
        for (int i = 0; i < nx; ++i)
            m.setZ(i, j, f(m.nodeX(i), m.nodeY(j)));
    return m;
}

Toolpath run(const char *text)
{
    Interpreter interp;
    Result r = interp.run(text);
    EXPECT_TRUE(r.errors.empty());
    return r.toolpath;
}

double plane(double x, double y)
{
    return 0.3 + 0.002 * x - 0.0015 * y;
}

double saddle(double x, double y)
{
    return 0.0004 * (x - 20) * (y - 15);
}

// Every motion point of `bent` lies at the XY of the original path of its line, at the original
// Z there plus the map's height. The original path of a line is a straight feed (tests only).
void expectFollows(const Toolpath &orig, const Toolpath &bent, const HeightMap &map,
                   const std::function<double(double, double)> &surface)
{
    for (std::size_t k = 0; k < bent.size(); ++k) {
        if (!bent.isMotion(k))
            continue;
        std::size_t i = 0;
        while (i < orig.size() && orig.line(i) != bent.line(k))
            ++i;
        ASSERT_LT(i, orig.size()) << "line " << bent.line(k) << " is not the program's";
        const Point4 a = orig.start(i), b = orig.end(i), p = bent.end(k);
        const double dx = b.x - a.x, dy = b.y - a.y, len2 = dx * dx + dy * dy;
        const double t = len2 > 0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / len2 : 1.0;
        ASSERT_GE(t, -1e-9);
        ASSERT_LE(t, 1 + 1e-9);
        EXPECT_NEAR(p.x, a.x + dx * t, 1e-9) << "entry " << k; // on the original XY path
        EXPECT_NEAR(p.y, a.y + dy * t, 1e-9) << "entry " << k;
        const double zOrig = a.z + (b.z - a.z) * t;
        EXPECT_NEAR(p.z, zOrig + surface(p.x, p.y), 1e-9) << "entry " << k;
        EXPECT_NEAR(map.heightAt(p.x, p.y), surface(p.x, p.y), 1e-9);
    }
}

} // namespace

TEST(HeightMap, BilinearReproducesPlaneAndSaddleExactly)
{
    const HeightMap p = mapOf(0, 0, 10, 7.5, 5, 5, plane);
    const HeightMap s = mapOf(0, 0, 10, 7.5, 5, 5, saddle);
    for (double x : {0.0, 3.3, 10.0, 17.2, 39.99, 40.0})
        for (double y : {0.0, 1.1, 7.5, 22.4, 30.0}) {
            EXPECT_NEAR(p.heightAt(x, y), plane(x, y), 1e-12) << x << "," << y;
            EXPECT_NEAR(s.heightAt(x, y), saddle(x, y), 1e-12) << x << "," << y;
        }
    // Outside: the nearest point of the grid.
    EXPECT_NEAR(p.heightAt(-5, 50), plane(0, 30), 1e-12);
    EXPECT_TRUE(p.contains(40, 30));
    EXPECT_FALSE(p.contains(40.01, 30));
}

TEST(HeightMap, FileRoundTripsAndNamesBadLines)
{
    HeightMap m = mapOf(-5, 2.5, 2.5, 5, 4, 3, saddle);
    m.setProbing({2, 3, 50, -12.5});
    QString error;
    const auto back = HeightMap::read(m.write(), &error);
    ASSERT_TRUE(back) << error.toStdString();
    EXPECT_EQ(back->probing(), m.probing());
    for (int j = 0; j < 3; ++j)
        for (int i = 0; i < 4; ++i)
            EXPECT_NEAR(back->z(i, j), m.z(i, j), 5e-5);

    QString text = m.write();
    text.replace(QStringLiteral("-5.0000,2.5000,"), QStringLiteral("-5.0000,2.5000,x"));
    EXPECT_FALSE(HeightMap::read(text, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("line 13"))) << error.toStdString();

    EXPECT_FALSE(HeightMap::read(QStringLiteral("x,y,z\n1,2,3\n"), &error));
    EXPECT_TRUE(error.contains(QStringLiteral("line 1"))) << error.toStdString();

    text = m.write();
    text.replace(QStringLiteral("# count_y: 3"), QStringLiteral("# count_yy: 3"));
    EXPECT_FALSE(HeightMap::read(text, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("line 7"))) << error.toStdString();

    text = m.write();
    text.remove(QStringLiteral("2.5000,12.5000,") + QString::number(m.z(3, 2), 'f', 4) + u'\n');
    EXPECT_FALSE(HeightMap::read(text, &error));
    EXPECT_TRUE(error.contains(QStringLiteral("X 2.5, Y 12.5"))) << error.toStdString();
}

TEST(HeightMap, FeedsSplitToGridAndFollowTiltedPlane)
{
    const HeightMap map = mapOf(0, 0, 10, 10, 5, 4, plane);
    const Toolpath orig = run("G0 X0 Y0 Z2\nG1 Z-0.1 F100\nG1 X40 Y30\nG1 X0\nG0 Z2\n");
    const HeightMapApplied a = applyHeightMap(orig, map);
    ASSERT_TRUE(a.path) << a.error.toStdString();
    expectFollows(orig, *a.path, map, plane);
    // Line 3 (50 mm) is split into pieces of at most 10 mm: 5 of them; line 4 (40 mm) into 4.
    int line3 = 0, line4 = 0;
    for (std::size_t k = 0; k < a.path->size(); ++k) {
        line3 += a.path->line(k) == 3;
        line4 += a.path->line(k) == 4;
        EXPECT_NE(a.path->kind(k), MotionKind::Arc);
    }
    EXPECT_EQ(line3, 5);
    EXPECT_EQ(line4, 4);
    EXPECT_NEAR(a.path->last().z, 2 + plane(0, 30), 1e-12);
}

TEST(HeightMap, ArcsAreChordedSplitAndFollowSaddle)
{
    const HeightMap map = mapOf(0, 0, 10, 7.5, 5, 5, saddle);
    const Toolpath orig = run("G0 X30 Y15 Z1\nG1 Z-0.1 F100\nG3 X10 Y15 I-10 J0\nG3 X30 I10\n");
    const HeightMapApplied a = applyHeightMap(orig, map, 1.0);
    ASSERT_TRUE(a.path) << a.error.toStdString();
    for (std::size_t k = 0; k < a.path->size(); ++k) {
        const Point4 p = a.path->end(k), s = a.path->start(k);
        if (a.path->line(k) >= 3 && a.path->isMotion(k)) {
            EXPECT_EQ(a.path->kind(k), MotionKind::Feed);
            EXPECT_NEAR(std::hypot(p.x - 20, p.y - 15), 10, 1e-6); // on the circle
            EXPECT_LE(std::hypot(p.x - s.x, p.y - s.y), 1.0 + 1e-9);
            EXPECT_NEAR(p.z, -0.1 + saddle(p.x, p.y), 1e-12);
        }
    }
}

TEST(HeightMap, CutOutsideTheMapIsRefusedNamingTheLine)
{
    const HeightMap map = mapOf(0, 0, 10, 10, 3, 3, plane);
    // The rapids outside are allowed (raised by the edge's height); line 4 cuts beyond X 20.
    const Toolpath orig = run("G0 X-10 Y-10 Z5\nG0 X5 Y5\nG1 Z-0.1 F100\nG1 X25\nG1 Y10\n");
    const HeightMapApplied a = applyHeightMap(orig, map);
    EXPECT_FALSE(a.path);
    EXPECT_EQ(a.refusedLine, 4u);
    EXPECT_TRUE(a.error.contains(QStringLiteral("Line 4"))) << a.error.toStdString();
    EXPECT_NEAR(applyHeightMap(run("G0 X-10 Y-10 Z5\n"), map).path->last().z, 5 + plane(0, 0),
                1e-12);
}

TEST(HeightMap, RandomMapsAndProgramsKeepXYAndAddTheHeight)
{
    std::mt19937 rng(19);
    std::uniform_real_distribution<double> u(0, 1);
    for (int round = 0; round < 40; ++round) {
        const int nx = 2 + int(u(rng) * 6), ny = 2 + int(u(rng) * 6);
        const double sx = 1 + u(rng) * 20, sy = 1 + u(rng) * 20;
        const double ox = -50 + u(rng) * 100, oy = -50 + u(rng) * 100;
        HeightMap map(ox, oy, sx, sy, nx, ny);
        for (int j = 0; j < ny; ++j)
            for (int i = 0; i < nx; ++i)
                map.setZ(i, j, -1 + 2 * u(rng));
        const auto surface = [&map](double x, double y) { return map.heightAt(x, y); };
        std::string text = "F500\n";
        for (int n = 0; n < 30; ++n) {
            const double x = ox + u(rng) * sx * (nx - 1), y = oy + u(rng) * sy * (ny - 1);
            text += (n == 0 || u(rng) < 0.2 ? "G0" : "G1") + std::string(" X") + std::to_string(x) +
                    " Y" + std::to_string(y) + " Z" + std::to_string(-2 + 4 * u(rng)) + "\n";
        }
        const Toolpath orig = run(text.c_str());
        const HeightMapApplied a = applyHeightMap(orig, map, 0.5 + u(rng) * 5);
        ASSERT_TRUE(a.path) << a.error.toStdString();
        // The first rapid comes from the origin, perhaps outside the map: its points are
        // raised by the edge's height, which heightAt gives there too.
        expectFollows(orig, *a.path, map, surface);
    }
}
