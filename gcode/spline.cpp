// LinuxCNC's splines evaluated and flattened.
//
// The knot vector is LinuxCNC's knot_vector_creator(n, k) for n + 1 control points of order k:
// k zeros, then 1 .. n - k + 1, then k times n - k + 2 (clamped, uniform, integer knots), so the
// curve starts at the first control point and ends at the last. LinuxCNC evaluates the basis
// with the Cox-de Boor recursion (Nmix); de Boor's algorithm below gives the same rational curve
// with order^2 operations a point instead of 2^order. LinuxCNC's motion then cuts the curve as
// 4 x count biarcs; Frezka cuts it as chords within the profile's chord tolerance, which is
// within that tolerance of the curve itself.
//
// Flattening: each knot span is cut into a few pieces first (so that an S-curve whose middle
// happens to lie on the chord is not taken for straight), then every piece is bisected until the
// curve's points at a quarter, the half and three quarters of its parameter are all within the
// tolerance of its chord.
#include "spline.h"

#include <algorithm>
#include <cmath>

namespace frezka::gcode {

namespace {

constexpr int kPiecesPerSpan = 4;
constexpr int kMaxDepth = 14; // at most 4 x 2^14 chords a span (a 1 m circle needs ~2 000)

double knot(std::size_t i, std::size_t n, unsigned k)
{
    if (i < k)
        return 0;
    if (i <= n)
        return double(i - k + 1);
    return double(n - k + 2);
}

double distanceToChord(const PlanePoint &p, const PlanePoint &a, const PlanePoint &b)
{
    const double dx = b[0] - a[0], dy = b[1] - a[1];
    const double len2 = dx * dx + dy * dy;
    double t = len2 > 0 ? ((p[0] - a[0]) * dx + (p[1] - a[1]) * dy) / len2 : 0.0;
    t = std::clamp(t, 0.0, 1.0);
    return std::hypot(p[0] - (a[0] + t * dx), p[1] - (a[1] + t * dy));
}

struct Flattener
{
    const std::vector<SplinePoint> &points;
    unsigned order;
    double tol;
    std::vector<PlanePoint> out;

    PlanePoint at(double u) const { return splinePoint(points, order, u); }

    void piece(double u0, const PlanePoint &p0, double u1, const PlanePoint &p1, int depth)
    {
        const double um = (u0 + u1) / 2;
        const PlanePoint pm = at(um);
        const PlanePoint q1 = at((u0 + um) / 2), q3 = at((um + u1) / 2);
        const bool flat = distanceToChord(pm, p0, p1) <= tol &&
                          distanceToChord(q1, p0, p1) <= tol && distanceToChord(q3, p0, p1) <= tol;
        if (flat || depth >= kMaxDepth) {
            out.push_back(p1);
            return;
        }
        piece(u0, p0, um, pm, depth + 1);
        piece(um, pm, u1, p1, depth + 1);
    }
};

} // namespace

double splineParameterEnd(std::size_t count, unsigned order)
{
    return double(count) - double(order) + 1;
}

PlanePoint splinePoint(const std::vector<SplinePoint> &points, unsigned order, double u)
{
    const std::size_t n = points.size() - 1;
    const unsigned p = order - 1; // degree
    const double uMax = splineParameterEnd(points.size(), order);
    u = std::clamp(u, 0.0, uMax);
    // The span s with knot(s) <= u < knot(s + 1), p <= s <= n (the last span includes uMax).
    std::size_t s = std::min<std::size_t>(n, p + std::size_t(std::floor(u)));
    // Homogeneous de Boor points d[j] = (w x, w y, w) for j = s - p .. s.
    std::array<std::array<double, 3>, kMaxSplineOrder> d{};
    for (unsigned j = 0; j <= p; ++j) {
        const SplinePoint &c = points[s - p + j];
        d[j] = {c.w * c.x, c.w * c.y, c.w};
    }
    for (unsigned r = 1; r <= p; ++r) {
        for (unsigned j = p; j >= r; --j) {
            const std::size_t i = s - p + j;
            const double lo = knot(i, n, order), hi = knot(i + p + 1 - r, n, order);
            const double alpha = hi > lo ? (u - lo) / (hi - lo) : 0.0;
            for (int c = 0; c < 3; ++c)
                d[j][c] = (1 - alpha) * d[j - 1][c] + alpha * d[j][c];
        }
    }
    return {d[p][0] / d[p][2], d[p][1] / d[p][2]};
}

std::vector<PlanePoint> flattenSpline(const std::vector<SplinePoint> &points, unsigned order,
                                      double toleranceMm)
{
    Flattener f{points, order, std::max(toleranceMm, 1e-9), {}};
    const double uMax = splineParameterEnd(points.size(), order);
    const int pieces = int(std::lround(uMax)) * kPiecesPerSpan;
    PlanePoint prev = f.at(0);
    for (int i = 1; i <= pieces; ++i) {
        const double u0 = uMax * (i - 1) / pieces, u1 = uMax * i / pieces;
        const PlanePoint next = f.at(u1);
        f.piece(u0, prev, u1, next, 0);
        prev = next;
    }
    // The end exactly as programmed (the evaluation may differ in the last bits).
    f.out.back() = {points.back().x, points.back().y};
    return f.out;
}

} // namespace frezka::gcode
