#pragma once
// Helpers shared by the cutter radius compensation files of the interpreter (interp_comp.cpp,
// interp_comp_arc.cpp): the plane's axes and the queued arc in program coordinates.

#include "gcode/toolpath.h"

#include <cstdio>
#include <numbers>
#include <string>

namespace frezka::gcode::comp {

constexpr double kPi = std::numbers::pi;
constexpr double kSpiralAbsToleranceMetricMm = 2 * 0.01 * std::numbers::sqrt2;
constexpr double kSpiralAbsToleranceInchMm = 2 * 0.001 * std::numbers::sqrt2 * 25.4;

struct Axes
{
    int u, v, w; // indices into x y z of the plane's axes (XZ: u = z, v = x)
};

inline Axes compAxes(int plane)
{
    return plane == 180 ? Axes{2, 0, 1} : Axes{0, 1, 2};
}

inline Plane planeOf(int plane)
{
    return plane == 180 ? Plane::XZ : Plane::XY;
}

inline double &at(Point4 &p, int i)
{
    return i == 0 ? p.x : i == 1 ? p.y : p.z;
}

inline double get(const Point4 &p, int i)
{
    return i == 0 ? p.x : i == 1 ? p.y : p.z;
}

inline std::string fmt4(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4f", v);
    return buf;
}

// A queued compensated arc in program coordinates: centre, end and turns.
struct QueuedArc
{
    double cu = 0, cv = 0, eu = 0, ev = 0;
    int turn = 0;
};

inline QueuedArc queuedArc(const Toolpath &path, std::size_t entry, Plane plane, double offU,
                           double offV)
{
    const ArcInfo arc = path.arc(entry);
    const Point4 end = path.end(entry);
    QueuedArc q;
    q.turn = arc.turns;
    if (plane == Plane::XZ) {
        q.cu = arc.centre.z - offU;
        q.cv = arc.centre.x - offV;
        q.eu = end.z - offU;
        q.ev = end.x - offV;
    } else {
        q.cu = arc.centre.x - offU;
        q.cv = arc.centre.y - offV;
        q.eu = end.x - offU;
        q.ev = end.y - offV;
    }
    return q;
}

} // namespace frezka::gcode::comp
