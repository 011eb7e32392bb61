#include "gcode/toolpath.h"

#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <cstdint>
#include <vector>

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

// Issue 17: the feed is kept as runs of equal values and the aux index only for the entries that
// have one; every entry reads back exactly what was appended, in any mix of kinds.
TEST(Toolpath, FeedsAndAuxReadBackExactlyPerEntry)
{
    Toolpath tp;
    std::vector<double> feeds;
    for (int i = 0; i < 2000; ++i) {
        const double f = i % 7 == 0 ? 100.0 + i : (i % 3 == 0 ? -0.0 : 600.0 / 7);
        const Point4 end{double(i), double(i % 5), 1, 0};
        switch (i % 11) {
        case 3:
            tp.appendArc(end, ArcInfo{{0, 0, 1, 0}, Plane::XY, i % 4 + 1}, f, i + 1);
            break;
        case 5:
            tp.appendProbe(end, ProbeKind::Away, f, i + 1);
            break;
        case 8:
            tp.appendEvent({EventKind::Dwell, double(i)}, f, i + 1);
            break;
        default:
            i % 2 ? tp.appendFeed(end, f, i + 1) : tp.appendRapid(end, f, i + 1);
        }
        feeds.push_back(f);
    }
    ASSERT_EQ(tp.size(), feeds.size());
    for (std::size_t i = 0; i < tp.size(); ++i) {
        EXPECT_EQ(std::bit_cast<std::uint64_t>(tp.feedMmPerMin(i)),
                  std::bit_cast<std::uint64_t>(feeds[i]))
            << i;
        if (i % 11 == 3) {
            EXPECT_EQ(tp.arc(i).turns, int(i % 4 + 1)) << i;
        } else if (i % 11 == 5) {
            EXPECT_EQ(tp.probe(i), ProbeKind::Away) << i;
        } else if (i % 11 == 8) {
            EXPECT_EQ(tp.event(i).value, double(i)) << i;
        }
    }
    Toolpath copy;
    copy.appendEntries(tp, 100, 1500);
    for (std::size_t i = 0; i < copy.size(); ++i)
        EXPECT_EQ(copy.feedMmPerMin(i), tp.feedMmPerMin(i + 100)) << i;
    EXPECT_EQ(copy.event(7).value, tp.event(107).value); // entry 107: a dwell (107 % 11 == 8)
}

// A program of straight moves at one feed: the position (4 doubles), the line and the kind, 37
// bytes an entry; 49 when every entry kept its feed and an aux index.
TEST(Toolpath, StraightMovesAtOneFeedTakeNoFeedOrAuxPerEntry)
{
    Toolpath tp;
    constexpr std::size_t n = 100000;
    tp.reserve(n);
    for (std::size_t i = 0; i < n; ++i)
        tp.appendFeed({double(i), 0, 0, 0}, 1200, static_cast<std::uint32_t>(i + 1));
    EXPECT_LE(tp.memoryBytes(), n * (4 * sizeof(double) + sizeof(std::uint32_t) + 1) + 4096);
    EXPECT_EQ(tp.feedMmPerMin(n - 1), 1200);
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
