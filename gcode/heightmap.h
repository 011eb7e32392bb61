#pragma once
// HeightMap: a probed surface on a regular XY grid, and the program bent to it.
//
// The grid has countX x countY nodes at originX + i * spacingX, originY + j * spacingY
// (machine coordinates, mm). z(i, j) is the surface's height there relative to the reference
// (the machine Z that height 0 stands for, the first probed point when probe-grid wrote it).
// Between the nodes the height is bilinear; it reproduces a plane exactly.
// The file format (CSV-friendly, versioned) is docs/height-map.md.

#include <QString>

#include <cstdint>
#include <optional>
#include <vector>

#include "toolpath.h"

namespace frezka::gcode {

struct HeightMapProbing // how the map was probed (informational; written and read back)
{
    double clearanceMm = 0;
    double depthMm = 0;
    double feedMmPerMin = 0;
    double referenceZMm = 0; // machine Z of height 0
    friend bool operator==(const HeightMapProbing &, const HeightMapProbing &) = default;
};

class HeightMap
{
public:
    static constexpr int kFormatVersion = 1;

    HeightMap() = default;
    // countX, countY >= 2, spacings > 0; every height starts at 0.
    HeightMap(double originX, double originY, double spacingX, double spacingY, int countX,
              int countY);

    double originX() const { return m_originX; }
    double originY() const { return m_originY; }
    double spacingX() const { return m_spacingX; }
    double spacingY() const { return m_spacingY; }
    int countX() const { return m_countX; }
    int countY() const { return m_countY; }
    double endX() const { return m_originX + m_spacingX * (m_countX - 1); }
    double endY() const { return m_originY + m_spacingY * (m_countY - 1); }
    bool isValid() const { return m_countX >= 2 && m_countY >= 2; }

    double nodeX(int i) const { return m_originX + m_spacingX * i; }
    double nodeY(int j) const { return m_originY + m_spacingY * j; }
    double z(int i, int j) const { return m_z[static_cast<std::size_t>(j * m_countX + i)]; }
    void setZ(int i, int j, double zMm) { m_z[static_cast<std::size_t>(j * m_countX + i)] = zMm; }
    double minZ() const;
    double maxZ() const;

    const HeightMapProbing &probing() const { return m_probing; }
    void setProbing(const HeightMapProbing &p) { m_probing = p; }

    // Whether (x, y) lies on the grid (edges included, within 1 micrometre).
    bool contains(double x, double y) const;
    // Bilinear height at (x, y); outside the grid, at the nearest point of the grid.
    double heightAt(double x, double y) const;

    // The file's text (docs/height-map.md) and back. read() returns an empty optional and sets
    // *error to a translated message naming the line and what to do.
    QString write() const;
    static std::optional<HeightMap> read(const QString &text, QString *error);
    bool save(const QString &path, QString *error) const;
    static std::optional<HeightMap> load(const QString &path, QString *error);

    friend bool operator==(const HeightMap &, const HeightMap &) = default;

private:
    double m_originX = 0, m_originY = 0, m_spacingX = 1, m_spacingY = 1;
    int m_countX = 0, m_countY = 0;
    std::vector<double> m_z;
    HeightMapProbing m_probing;
};

struct HeightMapApplied
{
    std::optional<Toolpath> path; // empty when refused
    std::uint32_t refusedLine = 0;
    QString error; // translated, names the line and what to do
};

// Bends the toolpath to the map (docs/height-map.md, "Applying"): feed moves and arcs (chorded)
// are split into pieces no longer than maxSegmentMm in XY (0: the smaller grid spacing) and each
// point's Z is raised by the height there; rapids are split and raised the same way (the height
// clamped to the map's edge outside it) so they keep their programmed clearance over the
// surface; probes, dwells and events are kept as they are. Every piece keeps its source line.
// A feed move or arc that leaves the map refuses the program, naming the first such line.
HeightMapApplied applyHeightMap(const Toolpath &path, const HeightMap &map,
                                double maxSegmentMm = 0);

} // namespace frezka::gcode
