#pragma once
// HeightMapMesh: the probed surface of a height map as the toolpath view draws it (issue 19) —
// the grid's nodes at their probed Z, coloured by height on the dialog's colour scale, two
// triangles per cell (drawn semi-transparent), the grid's lines and a marker at every probed
// node. Built from a gcode::HeightMap in the view's coordinates: machine mm, as the toolpath
// (interpreted with every work offset applied), the tool marker and the travel box are; a node
// stands at X = nodeX(i), Y = nodeY(j), Z = reference_z_mm + zScale * height, so at zScale 1 the
// mesh is the probed surface where the machine found it. A value type; no GL here.

#include "toolpathscene.h"

#include "gcode/heightmap.h"

#include <QColor>
#include <QVector3D>

#include <array>
#include <cstdint>
#include <vector>

namespace frezka::gui {

// The colour of a height at t in [0, 1] of the map's range: blue (lowest) through green to red
// (highest). The dialog's table and the view's mesh share it.
QColor heightMapColour(double t);

struct HeightMapMesh
{
    int countX = 0;
    int countY = 0;
    float zScale = 1.f;                   // Z exaggeration of the heights (1: true scale)
    std::vector<QVector3D> nodes;         // node (i, j) at j * countX + i, view coordinates (mm)
    std::vector<QColor> colours;          // per node, by its height over the probed nodes' range
    std::vector<bool> probed;             // per node: probed (drawn and marked)
    std::vector<std::uint32_t> triangles; // node indices, 3 per triangle (cells with
                                          // four probed corners)
    std::vector<std::array<std::uint32_t, 2>> edges; // grid lines between probed neighbours
    SceneBounds bounds;                              // of the probed nodes
    bool isEmpty() const { return !bounds.valid; }   // no node probed yet
    std::size_t index(int i, int j) const { return std::size_t(j) * std::size_t(countX) + i; }
};

// The mesh of the map. probed: one flag per node (j * countX + i), empty = every node probed
// (a loaded or finished map); zScale > 0 multiplies the heights (the reference stays).
HeightMapMesh buildHeightMapMesh(const gcode::HeightMap &map, const std::vector<bool> &probed = {},
                                 double zScale = 1.0);

} // namespace frezka::gui
