#include "viewcamera.h"

#include <algorithm>
#include <cmath>

namespace frezka::gui {

void ViewCamera::setPreset(ViewPreset preset)
{
    switch (preset) {
    case ViewPreset::Top:
        m_yawDeg = 0.f;
        m_pitchDeg = 90.f;
        break;
    case ViewPreset::Front:
        m_yawDeg = 0.f;
        m_pitchDeg = 0.f;
        break;
    case ViewPreset::Side:
        m_yawDeg = 90.f; // from +X, Y to the right
        m_pitchDeg = 0.f;
        break;
    case ViewPreset::Iso:
        m_yawDeg = 45.f; // from front-right, above
        m_pitchDeg = 35.264f;
        break;
    }
}

void ViewCamera::fit(const QVector3D &min, const QVector3D &max)
{
    m_target = (min + max) * 0.5f;
    const float r = std::max(1.f, (max - min).length() * 0.5f);
    m_halfHeightMm = r * 1.1f;
}

void ViewCamera::orbit(float dxPixels, float dyPixels)
{
    m_yawDeg = std::fmod(m_yawDeg + dxPixels * 0.4f, 360.f);
    m_pitchDeg = std::clamp(m_pitchDeg + dyPixels * 0.4f, -90.f, 90.f);
}

void ViewCamera::pan(float dxPixels, float dyPixels, const QSize &viewport)
{
    const float s = scaleMmPerPixel(viewport);
    const QMatrix4x4 inv = view().inverted();
    const QVector3D right = inv.mapVector({1, 0, 0});
    const QVector3D up = inv.mapVector({0, 1, 0});
    m_target -= right * (dxPixels * s);
    m_target += up * (dyPixels * s);
}

void ViewCamera::zoom(float steps, const QPointF &atPixel, const QSize &viewport)
{
    const float factor = std::pow(0.85f, steps);
    // Keep the point under the cursor fixed.
    const float s = scaleMmPerPixel(viewport);
    const float cx = float(atPixel.x() - viewport.width() / 2.0);
    const float cy = float(atPixel.y() - viewport.height() / 2.0);
    const QMatrix4x4 inv = view().inverted();
    const QVector3D right = inv.mapVector({1, 0, 0});
    const QVector3D up = inv.mapVector({0, 1, 0});
    const QVector3D under = m_target + right * (cx * s) - up * (cy * s);
    m_halfHeightMm = std::clamp(m_halfHeightMm * factor, 0.01f, 1e6f);
    const float s2 = scaleMmPerPixel(viewport);
    m_target = under - right * (cx * s2) + up * (cy * s2);
}

QMatrix4x4 ViewCamera::view() const
{
    QMatrix4x4 v;
    // Camera looks along -Y at yaw 0 / pitch 0 (front view), Z up; pitch 90 looks down.
    v.rotate(-90.f + m_pitchDeg, 1, 0, 0);
    v.rotate(-m_yawDeg, 0, 0, 1);
    v.translate(-m_target);
    return v;
}

float ViewCamera::scaleMmPerPixel(const QSize &viewport) const
{
    return 2.f * m_halfHeightMm / float(std::max(1, viewport.height()));
}

QMatrix4x4 ViewCamera::viewProjection(const QSize &viewport) const
{
    const float aspect =
        float(std::max(1, viewport.width())) / float(std::max(1, viewport.height()));
    const float h = m_halfHeightMm;
    const float depth = std::max(1000.f, h * 20.f);
    QMatrix4x4 p;
    p.ortho(-h * aspect, h * aspect, -h, h, -depth, depth);
    return p * view();
}

} // namespace frezka::gui
