#pragma once
// ToolpathScene: what the toolpath view draws, built from a Toolpath off the GUI thread.
//
// The scene is for the eyes only: arcs are chorded and runs of tiny collinear-ish segments are
// merged so that a multi-million-line program stays interactive. The machine always gets the
// full toolpath; nothing here feeds back into planning.
//
// Vertices form one polyline per "run" (consecutive entries of the same colour class); each
// vertex remembers the toolpath entry it ends, so the view can colour what was already cut.

#include "gcode/toolpath.h"

#include <QVector3D>

#include <atomic>
#include <cstdint>
#include <functional>
#include <vector>

namespace frezka::gui {

enum class SegmentClass : std::uint8_t { Rapid, Feed, Arc, Probe };

struct SceneBounds
{
    QVector3D min;
    QVector3D max;
    bool valid = false;
    void include(const QVector3D &p);
    QVector3D centre() const { return (min + max) * 0.5f; }
    float diagonal() const { return valid ? (max - min).length() : 0.f; }
    friend bool operator==(const SceneBounds &, const SceneBounds &) = default;
};

struct SceneSegment
{
    QVector3D from;
    QVector3D to;
    std::uint32_t entry = 0; // toolpath entry this piece belongs to
    SegmentClass cls = SegmentClass::Feed;
};

struct ToolpathScene
{
    std::vector<SceneSegment> segments; // in program order (entry non-decreasing)
    SceneBounds bounds;                 // of the motion (all points, before decimation)
    // The segments as OpenGL line vertices (x, y, z, class; two per segment), built off the GUI
    // thread when SceneOptions::glVertices is set, so the upload is a single copy.
    std::vector<float> glVertices;
    std::size_t sourceEntries = 0;
    bool isEmpty() const { return segments.empty(); }
    // Index of the first segment whose entry is > entry (segments before it are cut).
    std::size_t firstSegmentAfter(std::uint32_t entry) const;
};

struct SceneOptions
{
    // Segments shorter than this fraction of the bounds diagonal are merged with neighbours
    // of the same class while the direction stays within ~3 degrees.
    double mergeFraction = 1.0 / 4000.0;
    std::size_t maxSegments = 1'500'000; // hard cap: decimation coarsens until below
    bool glVertices = false;             // also fill ToolpathScene::glVertices
};

// Builds the display scene. progress(done, total) is called now and then from the calling
// thread; cancel, when set, aborts early (the result is then incomplete and must be dropped).
ToolpathScene buildScene(const gcode::Toolpath &path, const SceneOptions &options = {},
                         const std::function<void(std::size_t, std::size_t)> &progress = {},
                         const std::atomic_bool *cancel = nullptr);

} // namespace frezka::gui
