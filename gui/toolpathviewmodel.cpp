#include "toolpathviewmodel.h"

namespace frezka::gui {

QColor ViewColours::colourOf(SegmentClass c) const
{
    switch (c) {
    case SegmentClass::Rapid:
        return rapid;
    case SegmentClass::Arc:
        return arc;
    case SegmentClass::Probe:
        return probe;
    case SegmentClass::Feed:
        break;
    }
    return feed;
}

ToolpathViewModel::ToolpathViewModel(QObject *parent)
    : QObject(parent)
{
    m_camera.setPreset(ViewPreset::Iso);
}

void ToolpathViewModel::setScene(std::shared_ptr<const ToolpathScene> scene)
{
    m_scene = std::move(scene);
    m_cutEntry = kNoneCut;
    fitAll();
    emit sceneChanged();
    emit changed();
}

void ToolpathViewModel::setCutEntry(std::uint32_t entry)
{
    if (entry == m_cutEntry)
        return;
    m_cutEntry = entry;
    emit changed();
}

void ToolpathViewModel::setProvisionalAfter(std::uint32_t entry)
{
    if (entry == m_provisionalAfter)
        return;
    m_provisionalAfter = entry;
    emit changed();
}

std::size_t ToolpathViewModel::firstProvisionalSegment() const
{
    if (!m_scene)
        return 0;
    if (m_provisionalAfter == kNoProvisional)
        return m_scene->segments.size();
    return m_scene->firstSegmentAfter(m_provisionalAfter);
}

void ToolpathViewModel::setToolPosition(const QVector3D &mm)
{
    if (mm == m_tool)
        return;
    m_tool = mm;
    emit changed();
}

void ToolpathViewModel::setTravelBox(const SceneBounds &box)
{
    if (box == m_travel)
        return;
    m_travel = box;
    if (!m_scene || m_scene->isEmpty())
        fitAll();
    emit changed();
}

void ToolpathViewModel::setBoundsOutsideLimits(bool outside)
{
    if (outside == m_outside)
        return;
    m_outside = outside;
    emit changed();
}

void ToolpathViewModel::setPreset(ViewPreset preset)
{
    m_camera.setPreset(preset);
    fitAll();
    emit changed();
}

void ToolpathViewModel::setHeightMap(const gcode::HeightMap &map, const std::vector<bool> &probed)
{
    m_heightMap = map;
    m_heightMapProbed = probed;
    rebuildHeightMap();
}

void ToolpathViewModel::clearHeightMap()
{
    if (!m_heightMap)
        return;
    m_heightMap.reset();
    m_heightMapProbed.clear();
    rebuildHeightMap();
}

void ToolpathViewModel::setHeightMapVisible(bool visible)
{
    if (visible == m_heightMapVisible)
        return;
    m_heightMapVisible = visible;
    emit heightMapChanged();
    emit changed();
}

void ToolpathViewModel::setHeightMapZScale(double scale)
{
    if (scale <= 0 || scale == m_heightMapZScale)
        return;
    m_heightMapZScale = scale;
    rebuildHeightMap();
}

const HeightMapMesh *ToolpathViewModel::shownHeightMap() const
{
    return m_heightMap && m_heightMapVisible ? &m_heightMapMesh : nullptr;
}

void ToolpathViewModel::rebuildHeightMap()
{
    m_heightMapMesh = m_heightMap
                          ? buildHeightMapMesh(*m_heightMap, m_heightMapProbed, m_heightMapZScale)
                          : HeightMapMesh{};
    emit heightMapChanged();
    emit changed();
}

void ToolpathViewModel::fitAll()
{
    SceneBounds b;
    if (m_scene && m_scene->bounds.valid) {
        b = m_scene->bounds;
    } else if (m_travel.valid) {
        b = m_travel;
    }
    if (const HeightMapMesh *mesh = shownHeightMap(); mesh && mesh->bounds.valid) {
        b.include(mesh->bounds.min);
        b.include(mesh->bounds.max);
    }
    if (b.valid) {
        b.include(m_tool);
        m_camera.fit(b.min, b.max);
    }
    emit changed();
}

} // namespace frezka::gui
