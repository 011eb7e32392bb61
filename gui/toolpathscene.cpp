#include "toolpathscene.h"

#include <algorithm>
#include <cmath>

namespace frezka::gui {
namespace {

using gcode::MotionKind;

QVector3D toVec(const gcode::Point4 &p)
{
    return {float(p.x), float(p.y), float(p.z)};
}

SegmentClass classOf(MotionKind k)
{
    switch (k) {
    case MotionKind::Rapid:
        return SegmentClass::Rapid;
    case MotionKind::Arc:
        return SegmentClass::Arc;
    case MotionKind::Probe:
        return SegmentClass::Probe;
    default:
        return SegmentClass::Feed;
    }
}

SceneBounds motionBounds(const gcode::Toolpath &path, const std::atomic_bool *cancel)
{
    SceneBounds b;
    if (path.empty())
        return b;
    b.include(toVec(path.origin()));
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (!path.isMotion(i))
            continue;
        if (path.kind(i) == MotionKind::Arc) {
            // Coarse chords are enough for bounds of the display.
            for (const auto &p : gcode::chordArc(path.start(i), path.end(i), path.arc(i), 0.05))
                b.include(toVec(p));
        } else {
            b.include(toVec(path.end(i)));
        }
        if ((i & 0xFFFF) == 0 && cancel && cancel->load())
            break;
    }
    return b;
}

// One decimating pass; returns false if the cap was exceeded (caller retries coarser).
bool buildPass(const gcode::Toolpath &path, double mergeLen, std::size_t cap, ToolpathScene &out,
               const std::function<void(std::size_t, std::size_t)> &progress,
               const std::atomic_bool *cancel)
{
    out.segments.clear();
    QVector3D last = toVec(path.origin()); // last emitted vertex
    QVector3D pending = last;              // true current position (maybe not emitted)
    SegmentClass pendingCls = SegmentClass::Feed;
    std::uint32_t pendingEntry = 0;
    bool havePending = false;
    const float merge = float(mergeLen);
    auto flush = [&] {
        if (havePending) {
            out.segments.push_back({last, pending, pendingEntry, pendingCls});
            last = pending;
            havePending = false;
        }
    };
    auto addPoint = [&](const QVector3D &p, SegmentClass cls, std::uint32_t entry) {
        if (havePending && cls != pendingCls)
            flush();
        pending = p;
        pendingCls = cls;
        pendingEntry = entry;
        havePending = true;
        if ((p - last).length() >= merge)
            flush();
    };
    const std::size_t n = path.size();
    for (std::size_t i = 0; i < n; ++i) {
        if ((i & 0x3FFF) == 0) {
            if (cancel && cancel->load())
                return true;
            if (progress)
                progress(i, n);
        }
        if (!path.isMotion(i))
            continue;
        const auto cls = classOf(path.kind(i));
        const auto entry = std::uint32_t(i);
        if (path.kind(i) == MotionKind::Arc) {
            const double tol = std::max(0.002, mergeLen * 0.25);
            for (const auto &p : gcode::chordArc(path.start(i), path.end(i), path.arc(i), tol))
                addPoint(toVec(p), cls, entry);
        } else {
            addPoint(toVec(path.end(i)), cls, entry);
        }
        // Never merge across a rapid/feed boundary and never lose an end point of a run.
        if (i + 1 < n && path.isMotion(i + 1) && classOf(path.kind(i + 1)) != cls)
            flush();
        if (out.segments.size() > cap)
            return false;
    }
    flush();
    return true;
}

} // namespace

void SceneBounds::include(const QVector3D &p)
{
    if (!valid) {
        min = max = p;
        valid = true;
        return;
    }
    min = {std::min(min.x(), p.x()), std::min(min.y(), p.y()), std::min(min.z(), p.z())};
    max = {std::max(max.x(), p.x()), std::max(max.y(), p.y()), std::max(max.z(), p.z())};
}

std::size_t ToolpathScene::firstSegmentAfter(std::uint32_t entry) const
{
    auto it = std::upper_bound(segments.begin(), segments.end(), entry,
                               [](std::uint32_t e, const SceneSegment &s) { return e < s.entry; });
    return std::size_t(it - segments.begin());
}

ToolpathScene buildScene(const gcode::Toolpath &path, const SceneOptions &options,
                         const std::function<void(std::size_t, std::size_t)> &progress,
                         const std::atomic_bool *cancel)
{
    ToolpathScene scene;
    scene.sourceEntries = path.size();
    scene.bounds = motionBounds(path, cancel);
    double merge = std::max(1e-6, double(scene.bounds.diagonal()) * options.mergeFraction);
    while (!buildPass(path, merge, options.maxSegments, scene, progress, cancel))
        merge *= 4;
    if (options.glVertices) {
        scene.glVertices.reserve(scene.segments.size() * 8);
        for (const auto &seg : scene.segments) {
            const float c = float(seg.cls);
            scene.glVertices.insert(scene.glVertices.end(),
                                    {seg.from.x(), seg.from.y(), seg.from.z(), c, seg.to.x(),
                                     seg.to.y(), seg.to.z(), c});
        }
    }
    if (progress)
        progress(path.size(), path.size());
    return scene;
}

} // namespace frezka::gui
