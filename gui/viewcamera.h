#pragma once
// ViewCamera: orthographic orbit camera for the toolpath view (Z up, machine coordinates, mm).
// Value type; both the OpenGL and the software view render through the same matrices.

#include <QMatrix4x4>
#include <QPointF>
#include <QSize>
#include <QVector3D>

namespace frezka::gui {

enum class ViewPreset { Top, Front, Side, Iso };

class ViewCamera
{
public:
    void setPreset(ViewPreset preset);
    // Frames the box centre..halfSize in the current orientation.
    void fit(const QVector3D &min, const QVector3D &max);
    void orbit(float dxPixels, float dyPixels);
    void pan(float dxPixels, float dyPixels, const QSize &viewport);
    void zoom(float steps, const QPointF &atPixel, const QSize &viewport);

    // World -> clip space for a viewport of the given size (aspect preserved).
    QMatrix4x4 viewProjection(const QSize &viewport) const;
    float yawDeg() const { return m_yawDeg; }
    float pitchDeg() const { return m_pitchDeg; }
    float scaleMmPerPixel(const QSize &viewport) const;
    friend bool operator==(const ViewCamera &, const ViewCamera &) = default;

private:
    QMatrix4x4 view() const;
    QVector3D m_target;
    float m_yawDeg = 45.f;
    float m_pitchDeg = 35.264f;
    float m_halfHeightMm = 100.f; // half the visible height
};

} // namespace frezka::gui
