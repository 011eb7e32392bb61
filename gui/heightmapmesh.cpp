// The height map's mesh for the toolpath view. See heightmapmesh.h.

#include "heightmapmesh.h"

#include <algorithm>

namespace frezka::gui {

QColor heightMapColour(double t)
{
    t = std::clamp(t, 0.0, 1.0);
    return QColor::fromHsvF(float((1 - t) * 240.0 / 360.0), 0.45f, 1.0f);
}

HeightMapMesh buildHeightMapMesh(const gcode::HeightMap &map, const std::vector<bool> &probed,
                                 double zScale)
{
    HeightMapMesh mesh;
    if (!map.isValid())
        return mesh;
    mesh.countX = map.countX();
    mesh.countY = map.countY();
    mesh.zScale = float(zScale > 0 ? zScale : 1.0);
    const std::size_t n = std::size_t(mesh.countX) * std::size_t(mesh.countY);
    mesh.probed = probed.size() == n ? probed : std::vector<bool>(n, true);
    double lo = 0, hi = 0;
    bool any = false;
    for (int j = 0; j < mesh.countY; ++j) {
        for (int i = 0; i < mesh.countX; ++i) {
            if (!mesh.probed[mesh.index(i, j)])
                continue;
            lo = any ? std::min(lo, map.z(i, j)) : map.z(i, j);
            hi = any ? std::max(hi, map.z(i, j)) : map.z(i, j);
            any = true;
        }
    }
    const double reference = map.probing().referenceZMm;
    mesh.nodes.reserve(n);
    mesh.colours.reserve(n);
    for (int j = 0; j < mesh.countY; ++j) {
        for (int i = 0; i < mesh.countX; ++i) {
            const QVector3D p(float(map.nodeX(i)), float(map.nodeY(j)),
                              float(reference + double(mesh.zScale) * map.z(i, j)));
            mesh.nodes.push_back(p);
            mesh.colours.push_back(heightMapColour(hi > lo ? (map.z(i, j) - lo) / (hi - lo) : 0.5));
            if (mesh.probed[mesh.index(i, j)])
                mesh.bounds.include(p);
        }
    }
    auto done = [&](int i, int j) { return bool(mesh.probed[mesh.index(i, j)]); };
    auto id = [&](int i, int j) { return std::uint32_t(mesh.index(i, j)); };
    for (int j = 0; j < mesh.countY; ++j) {
        for (int i = 0; i < mesh.countX; ++i) {
            if (!done(i, j))
                continue;
            if (i + 1 < mesh.countX && done(i + 1, j))
                mesh.edges.push_back({id(i, j), id(i + 1, j)});
            if (j + 1 < mesh.countY && done(i, j + 1))
                mesh.edges.push_back({id(i, j), id(i, j + 1)});
            if (i + 1 < mesh.countX && j + 1 < mesh.countY && done(i + 1, j) && done(i, j + 1) &&
                done(i + 1, j + 1))
                mesh.triangles.insert(mesh.triangles.end(),
                                      {id(i, j), id(i + 1, j), id(i + 1, j + 1), id(i, j),
                                       id(i + 1, j + 1), id(i, j + 1)});
        }
    }
    return mesh;
}

} // namespace frezka::gui
