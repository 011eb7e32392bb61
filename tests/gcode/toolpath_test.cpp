#include "gcode/toolpath.h"

#include <gtest/gtest.h>

#include <cmath>

using namespace frezka::gcode;

TEST(Toolpath, EntriesKeepOrderAndPosition)
{
    Toolpath tp;
    tp.appendRapid({0, 0, 5, 0}, 0, 1);
    tp.appendFeed({10, 0, 5, 0}, 600, 2);
    tp.appendEvent({EventKind::Dwell, 0.5}, 600, 3);
    ASSERT_EQ(tp.size(), 3u);
    EXPECT_EQ(tp.start(1), (Point4{0, 0, 5, 0}));
    EXPECT_EQ(tp.end(2), (Point4{10, 0, 5, 0})); // a dwell does not move
    EXPECT_EQ(tp.kind(2), MotionKind::Dwell);
    EXPECT_EQ(tp.event(2).value, 0.5);
    EXPECT_EQ(tp.line(1), 2u);
}

TEST(Toolpath, ChordArcHonoursToleranceAndEndsExactly)
{
    // Quarter circle radius 10, CCW from (10,0) to (0,10) about the origin.
    const Point4 s{10, 0, 0, 0};
    const Point4 e{0, 10, -1, 0};
    const ArcInfo arc{{0, 0, 0, 0}, Plane::XY, 1};
    const auto pts = chordArc(s, e, arc, 0.002);
    ASSERT_GT(pts.size(), 10u);
    EXPECT_EQ(pts.back(), e);
    Point4 prev = s;
    for (const auto &p : pts) {
        // Sagitta of each chord: radius minus the distance from the centre to the chord midpoint.
        const double mx = (prev.x + p.x) / 2, my = (prev.y + p.y) / 2;
        EXPECT_LE(10 - std::hypot(mx, my), 0.002 + 1e-9);
        EXPECT_GE(std::atan2(p.y, p.x), std::atan2(prev.y, prev.x) - 1e-12); // CCW
        prev = p;
    }
}

TEST(Toolpath, ChordArcFullTurns)
{
    // Two full clockwise circles in XZ ending where they start.
    const Point4 s{5, 0, 0, 0};
    const ArcInfo arc{{0, 0, 0, 0}, Plane::XZ, -2};
    const auto pts = chordArc(s, s, arc, 0.01);
    const double step = 2 * std::acos(1 - 0.01 / 5);
    EXPECT_EQ(pts.size(), static_cast<std::size_t>(std::ceil(4 * M_PI / step)));
}
