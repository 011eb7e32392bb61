// applyHeightMap: the toolpath bent to a probed surface (docs/height-map.md, "Applying").
#include "heightmap.h"

#include <QCoreApplication>

#include <algorithm>
#include <cmath>

namespace frezka::gcode {

namespace {

struct Bender
{
    const HeightMap &map;
    double maxSegmentMm;
    Toolpath out;
    std::uint32_t refusedLine = 0;
    Point4 refusedAt;

    // The piece from a to b (uncorrected points), split and raised, appended as feeds or rapids.
    // False when a cutting piece leaves the map.
    bool segment(const Point4 &a, const Point4 &b, bool rapid, double feed, std::uint32_t line)
    {
        const double len = std::hypot(b.x - a.x, b.y - a.y);
        const auto n =
            static_cast<std::size_t>(std::max(1.0, std::ceil(len / maxSegmentMm - 1e-9)));
        if (!rapid && !map.contains(a.x, a.y))
            return refuse(a, line);
        for (std::size_t k = 1; k <= n; ++k) {
            const double t = static_cast<double>(k) / static_cast<double>(n);
            Point4 p = k == n ? b
                              : Point4{a.x + (b.x - a.x) * t, a.y + (b.y - a.y) * t,
                                       a.z + (b.z - a.z) * t, a.a + (b.a - a.a) * t};
            if (!rapid && !map.contains(p.x, p.y))
                return refuse(p, line);
            p.z += map.heightAt(p.x, p.y);
            if (rapid)
                out.appendRapid(p, feed, line);
            else
                out.appendFeed(p, feed, line);
        }
        return true;
    }

    bool refuse(const Point4 &p, std::uint32_t line)
    {
        refusedLine = line;
        refusedAt = p;
        return false;
    }

    bool entry(const Toolpath &path, std::size_t i)
    {
        const double feed = path.feedMmPerMin(i);
        const std::uint32_t line = path.line(i);
        switch (path.kind(i)) {
        case MotionKind::Rapid:
        case MotionKind::Feed:
            return segment(path.start(i), path.end(i), path.kind(i) == MotionKind::Rapid, feed,
                           line);
        case MotionKind::Arc: {
            Point4 from = path.start(i);
            for (const Point4 &p : chordArc(from, path.end(i), path.arc(i))) {
                if (!segment(from, p, false, feed, line))
                    return false;
                from = p;
            }
            return true;
        }
        case MotionKind::Probe:
            out.appendProbe(path.end(i), path.probe(i), feed, line);
            return true;
        case MotionKind::Dwell:
        case MotionKind::Event:
            out.appendEvent(path.event(i), feed, line);
            return true;
        }
        return true;
    }
};

} // namespace

HeightMapApplied applyHeightMap(const Toolpath &path, const HeightMap &map, double maxSegmentMm)
{
    HeightMapApplied result;
    const double grid = std::min(map.spacingX(), map.spacingY());
    const double step = maxSegmentMm > 0 ? std::min(maxSegmentMm, grid) : grid;
    Bender bender{map, step, {}, 0, {}};
    bender.out.setOrigin(path.origin());
    bender.out.reserve(path.size());
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (!bender.entry(path, i)) {
            result.refusedLine = bender.refusedLine;
            result.error =
                QCoreApplication::translate(
                    "frezka::gcode::HeightMap",
                    "Line %1 cuts at X %2, Y %3, outside the height map (X %4 to %5, Y %6 to "
                    "%7). Probe a grid that covers the whole program, or run it without the "
                    "height map.")
                    .arg(bender.refusedLine)
                    .arg(bender.refusedAt.x, 0, 'f', 3)
                    .arg(bender.refusedAt.y, 0, 'f', 3)
                    .arg(map.originX(), 0, 'f', 3)
                    .arg(map.endX(), 0, 'f', 3)
                    .arg(map.originY(), 0, 'f', 3)
                    .arg(map.endY(), 0, 'f', 3);
            return result;
        }
    }
    result.path = std::move(bender.out);
    return result;
}

} // namespace frezka::gcode
