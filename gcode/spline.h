#pragma once
// LinuxCNC's splines as curves in the plane: G5.1 (a quadratic Bezier), G5 (a cubic Bezier) and
// G5.2/G5.3 (a NURBS of order L over a clamped uniform knot vector with integer knots, the knot
// vector of LinuxCNC's nurbs_additional_functions.cc), evaluated with de Boor's algorithm in
// homogeneous coordinates and flattened into chords for the toolpath. Pure math, no state.

#include <array>
#include <cstddef>
#include <vector>

namespace frezka::gcode {

struct SplinePoint
{
    double x = 0, y = 0; // program coordinates, mm
    double w = 1;        // weight (> 0)
};

using PlanePoint = std::array<double, 2>;

// The highest order a NURBS may have here (LinuxCNC has no bound; its recursive basis costs
// 2^order a point, so L above 10 is impractical there too).
inline constexpr unsigned kMaxSplineOrder = 10;

// The curve's parameter runs from 0 to splineParameterEnd(count, order) = count - order + 1
// (LinuxCNC's umax = n - k + 2 with n = count - 1). Needs 2 <= order <= count.
double splineParameterEnd(std::size_t count, unsigned order);

// The point at parameter u (clamped to the range) of the NURBS of `order` (degree order - 1)
// through `points` (the first is the start, the last the end).
PlanePoint splinePoint(const std::vector<SplinePoint> &points, unsigned order, double u);

// Points along the curve from its start (excluded) to its end (included, exactly the last control
// point) such that no chord is farther than toleranceMm from the curve between its ends (checked
// at the chord's middle and quarter parameters, bisected until it holds).
std::vector<PlanePoint> flattenSpline(const std::vector<SplinePoint> &points, unsigned order,
                                      double toleranceMm);

} // namespace frezka::gcode
