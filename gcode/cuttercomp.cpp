#include "cuttercomp.h"

#include <cmath>
#include <numbers>

namespace frezka::gcode {

namespace {

constexpr double kPi = std::numbers::pi;

// The in-plane (u, v) coordinates of a point (gcode/toolpath.h's arc convention).
void planeUv(const Point4 &p, Plane plane, double *u, double *v)
{
    switch (plane) {
    case Plane::XZ:
        *u = p.z;
        *v = p.x;
        return;
    case Plane::YZ:
        *u = p.y;
        *v = p.z;
        return;
    case Plane::XY:
        break;
    }
    *u = p.x;
    *v = p.y;
}

void setPlaneUv(Point4 *p, Plane plane, double u, double v)
{
    switch (plane) {
    case Plane::XZ:
        p->z = u;
        p->x = v;
        return;
    case Plane::YZ:
        p->y = u;
        p->z = v;
        return;
    case Plane::XY:
        break;
    }
    p->x = u;
    p->y = v;
}

} // namespace

double findTurn(double u1, double v1, double cu, double cv, int turn, double u2, double v2)
{
    if (turn == 0)
        return 0.0;
    double alpha = std::atan2(v1 - cv, u1 - cu);
    double beta = std::atan2(v2 - cv, u2 - cu);
    if (turn > 0) {
        if (beta <= alpha)
            beta += 2 * kPi;
        return beta - alpha + (turn - 1) * 2 * kPi;
    }
    if (alpha <= beta)
        alpha += 2 * kPi;
    return beta - alpha + (turn + 1) * 2 * kPi;
}

CompFault moveQueuedEnds(Toolpath &path, const CutterComp &comp, Plane plane, double offsetU,
                         double offsetV, double u, double v, double radiusTolerance,
                         double arcSlack)
{
    // Check every queued move first, so that a fault leaves the toolpath as it was.
    for (const CompQueued &q : comp.queue) {
        if (path.kind(q.entry) == MotionKind::Arc) {
            const ArcInfo arc = path.arc(q.entry);
            double eu = 0, ev = 0, cu = 0, cv = 0;
            planeUv(path.end(q.entry), plane, &eu, &ev);
            planeUv(arc.centre, plane, &cu, &cv);
            cu -= offsetU;
            cv -= offsetV;
            eu -= offsetU;
            ev -= offsetV;
            const double r1 = std::hypot(eu - cu, ev - cv);
            const double r2 = std::hypot(u - cu, v - cv);
            if (std::fabs(r1 - r2) > radiusTolerance)
                return CompFault::ArcRadiiDiffer;
            const double l2 = findTurn(comp.endU, comp.endV, cu, cv, arc.turns, u, v);
            if (q.originalTurns != 0.0 && comp.endValid &&
                std::fabs(l2) > std::fabs(q.originalTurns) + arcSlack)
                return CompFault::ArcTooLong;
        } else {
            const double dot = q.du * (u - comp.endU) + q.dv * (v - comp.endV);
            if (comp.endValid && dot < 0)
                return CompFault::StraightReversed;
        }
    }
    if (comp.queue.empty())
        return CompFault::None;
    for (const CompQueued &q : comp.queue) {
        Point4 end = path.end(q.entry);
        setPlaneUv(&end, plane, u + offsetU, v + offsetV);
        path.setEnd(q.entry, end);
    }
    for (std::size_t i = comp.queue.front().entry + 1; i < path.size(); ++i) {
        if (!path.isMotion(i))
            path.setEnd(i, path.end(i - 1));
    }
    return CompFault::None;
}

} // namespace frezka::gcode
