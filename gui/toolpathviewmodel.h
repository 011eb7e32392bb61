#pragma once
// ToolpathViewModel: what both toolpath renderers show — the scene, the camera, the tool
// marker, how far the program has been cut, the machine travel box, the program bounds and the
// height map's mesh (gui/heightmapmesh.h).

#include "heightmapmesh.h"
#include "toolpathscene.h"
#include "viewcamera.h"

#include <QColor>
#include <QObject>

#include <memory>
#include <optional>
#include <vector>

namespace frezka::gui {

struct ViewColours
{
    QColor background{30, 32, 36};
    QColor rapid{230, 160, 40};
    QColor feed{70, 160, 255};
    QColor arc{60, 210, 140};
    QColor probe{220, 80, 220};
    QColor cut{120, 120, 120};
    // The path after a probe not run yet (a program that probes for itself): dim, dashed in
    // the QPainter view.
    QColor provisional{125, 110, 150};
    QColor tool{255, 60, 60};
    QColor travel{110, 110, 120};
    QColor boundsOk{90, 200, 90};
    QColor boundsBad{255, 40, 40};
    QColor heightMapNode{245, 245, 245}; // the probed nodes' markers
    int heightMapFillAlpha = 90;         // the mesh's faces: the toolpath shows through
    int heightMapLineAlpha = 200;        // its grid lines
    QColor colourOf(SegmentClass c) const;
};

class ToolpathViewModel : public QObject
{
    Q_OBJECT

public:
    explicit ToolpathViewModel(QObject *parent = nullptr);

    void setScene(std::shared_ptr<const ToolpathScene> scene);
    const std::shared_ptr<const ToolpathScene> &scene() const { return m_scene; }

    // Entries up to and including this one are drawn as cut; kNoneCut = nothing cut.
    static constexpr std::uint32_t kNoneCut = 0xFFFFFFFFu;
    void setCutEntry(std::uint32_t entry);
    std::uint32_t cutEntry() const { return m_cutEntry; }

    // Entries after this one depend on a probe that has not run (session::ProbeFollow) and are
    // drawn as provisional; kNoProvisional = none.
    static constexpr std::uint32_t kNoProvisional = 0xFFFFFFFFu;
    void setProvisionalAfter(std::uint32_t entry);
    std::uint32_t provisionalAfter() const { return m_provisionalAfter; }
    // The first scene segment drawn as provisional (the scene's size: none).
    std::size_t firstProvisionalSegment() const;

    void setToolPosition(const QVector3D &mm);
    QVector3D toolPosition() const { return m_tool; }

    void setTravelBox(const SceneBounds &box);
    const SceneBounds &travelBox() const { return m_travel; }
    // Red bounds when the program leaves the soft limits.
    void setBoundsOutsideLimits(bool outside);
    bool boundsOutsideLimits() const { return m_outside; }

    // The height map drawn over the path (docs/height-map.md, "In the 3D view"); probed: one
    // flag per node, empty = all probed. The mesh is rebuilt at once; the camera stays.
    void setHeightMap(const gcode::HeightMap &map, const std::vector<bool> &probed = {});
    void clearHeightMap();
    bool hasHeightMap() const { return m_heightMap.has_value(); }
    // View › Height map: shown or hidden (kept while hidden).
    void setHeightMapVisible(bool visible);
    bool heightMapVisible() const { return m_heightMapVisible; }
    // The heights' exaggeration in the view (1: true scale; the path is never scaled).
    void setHeightMapZScale(double scale);
    double heightMapZScale() const { return m_heightMapZScale; }
    // The mesh to draw: null when there is no map or it is hidden.
    const HeightMapMesh *shownHeightMap() const;

    ViewCamera &camera() { return m_camera; }
    const ViewCamera &camera() const { return m_camera; }
    void setPreset(ViewPreset preset);
    void fitAll();
    void notifyCameraChanged() { emit changed(); }

    const ViewColours &colours() const { return m_colours; }

signals:
    void changed();
    void sceneChanged();
    void heightMapChanged(); // the shown mesh changed (appeared, went, rebuilt)

private:
    std::shared_ptr<const ToolpathScene> m_scene;
    std::uint32_t m_cutEntry = kNoneCut;
    std::uint32_t m_provisionalAfter = kNoProvisional;
    QVector3D m_tool;
    SceneBounds m_travel;
    bool m_outside = false;
    ViewCamera m_camera;
    ViewColours m_colours;
    std::optional<gcode::HeightMap> m_heightMap;
    std::vector<bool> m_heightMapProbed;
    HeightMapMesh m_heightMapMesh;
    bool m_heightMapVisible = true;
    double m_heightMapZScale = 1.0;

    void rebuildHeightMap();
};

} // namespace frezka::gui
