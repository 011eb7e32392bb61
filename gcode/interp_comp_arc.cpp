// Arcs under cutter radius compensation (rs274ngc's convert_arc_comp1 and convert_arc_comp2):
// the tool follows an arc of the same centre one radius larger (outside) or smaller (inside);
// the entry arc is the arc through the tool's position that ends one radius beside the
// programmed end. See interp_comp.cpp.
#include "comp_internal.h"
#include "interpreter.h"

#include <cmath>

namespace frezka::gcode {

using namespace comp;

bool Interpreter::compArc(int motion, const Target &target, int turns, Error *error)
{
    return m_comp.firstMove ? compArcFirst(motion, target, turns, error)
                            : compArcNext(motion, target, turns, error);
}

bool Interpreter::compArcFirst(int motion, const Target &target, int turns, Error *error)
{
    const Axes ax = compAxes(m_plane);
    const std::uint32_t col = m_block.hasG(kGMotion) ? m_block.gColumn[kGMotion] : 0;
    const double cu = get(m_pos, ax.u) - offset(ax.u), cv = get(m_pos, ax.v) - offset(ax.v);
    double eu = get(target.prog, ax.u), ev = get(target.prog, ax.v);
    const double r = m_comp.radius;
    const int turn = motion == 20 ? -turns : turns;
    const bool inside = toolInsideArc(m_comp.side, turn);
    const std::string radius = fmt4(r / unit());
    if (std::hypot(eu - cu, ev - cv) <= r)
        return failAt(ErrorCode::CompEntryTooShort, col, radius, error);
    if (m_block.has('r') && inside && std::fabs(lengthWord('r')) <= r)
        return failAt(ErrorCode::CompToolTooBig, col, radius, error);
    double ccu = 0, ccv = 0;
    const bool ok = m_block.has('r') ? arcCentreR(motion, cu, cv, eu, ev, &ccu, &ccv, error)
                                     : arcCentreIjk(cu, cv, eu, ev, col, &ccu, &ccv, error);
    if (!ok)
        return false;
    if (inside && std::hypot(ccu - cu, ccv - cv) <= r)
        return failAt(ErrorCode::CompToolTooBig, col, radius, error);
    // The tool ends one radius from the programmed end, toward the centre when inside.
    const double gamma = inside ? std::atan2(ccv - ev, ccu - eu) : std::atan2(ev - ccv, eu - ccu);
    m_comp.firstMove = false;
    eu += r * std::cos(gamma);
    ev += r * std::sin(gamma);
    // The centre of the arc from the tool to there: on the line from the end to the old centre,
    // as far from the end as from the start.
    const double halfChord = std::hypot(cv - ev, cu - eu) / 2.0;
    const double toCentre = std::atan2(ccv - ev, ccu - eu);
    const double corner = std::atan2(cv - ev, cu - eu) - toCentre;
    if (std::fabs(std::cos(corner)) < kCompEqualTolerance)
        return failAt(ErrorCode::CompToolTooBig, col, radius, error);
    const double length = halfChord / std::cos(corner);
    ccu = eu + length * std::cos(toCentre);
    ccv = ev + length * std::sin(toCentre);
    const double spiral = m_metric ? kSpiralAbsToleranceMetricMm : kSpiralAbsToleranceInchMm;
    if (std::fabs(std::hypot(ccu - eu, ccv - ev) - std::hypot(ccu - cu, ccv - cv)) > spiral)
        return failAt(ErrorCode::CompToolTooBig, col, radius, error);
    const double pw = get(target.machine, ax.w);
    ArcInfo arc;
    arc.centre = compPoint(ccu, ccv, get(m_pos, ax.w), target.machine.a);
    arc.plane = planeOf(m_plane);
    arc.turns = turn;
    const double sweep = findTurn(cu, cv, ccu, ccv, turn, eu, ev);
    const double feed = feedFor(
        std::hypot(std::fabs(sweep) * std::hypot(ccu - eu, ccv - ev), pw - get(m_pos, ax.w)));
    const Point4 end = compPoint(eu, ev, pw, target.machine.a);
    compEnqueue(MotionKind::Arc, end, feed, 0, 0, &arc, sweep);
    m_pos = end;
    m_prog = target.prog;
    return true;
}

// Kept whole (a little over 60 lines) so that it reads side by side with convert_arc_comp2.
bool Interpreter::compArcNext(int motion, const Target &target, int turns, Error *error)
{
    const Axes ax = compAxes(m_plane);
    const std::uint32_t col = m_block.hasG(kGMotion) ? m_block.gColumn[kGMotion] : 0;
    const double ou = get(m_prog, ax.u), ov = get(m_prog, ax.v);
    const double cu = get(m_pos, ax.u) - offset(ax.u), cv = get(m_pos, ax.v) - offset(ax.v);
    const double eu = get(target.prog, ax.u), ev = get(target.prog, ax.v);
    double ccu = 0, ccv = 0;
    const bool ok = m_block.has('r') ? arcCentreR(motion, ou, ov, eu, ev, &ccu, &ccv, error)
                                     : arcCentreIjk(ou, ov, eu, ev, col, &ccu, &ccv, error);
    if (!ok)
        return false;
    const int turn = motion == 20 ? -turns : turns;
    const bool left = m_comp.side == CompSide::Left;
    const double r = m_comp.radius;
    const double arcRadius = std::hypot(ccu - eu, ccv - ev);
    double theta = std::atan2(cv - ov, cu - ou);
    theta = left ? theta - kPi / 2 : theta + kPi / 2; // the direction of the last cut
    double delta = std::atan2(ccv - ov, ccu - ou);
    const double alpha = motion == 30 ? delta - kPi / 2 : delta + kPi / 2; // the arc's start
    double beta = left ? theta - alpha : alpha - theta;
    beta = beta > 1.5 * kPi ? beta - 2 * kPi : beta < -kPi / 2 ? beta + 2 * kPi : beta;
    double gamma = 0;
    if ((left && motion == 30) || (!left && motion == 20)) { // the tool inside the arc
        gamma = std::atan2(ccv - ev, ccu - eu);
        if (arcRadius <= r)
            return failAt(ErrorCode::CompToolTooBig, col, fmt4(r / unit()), error);
    } else {
        gamma = std::atan2(ev - ccv, eu - ccu);
        delta += kPi;
    }
    const double neu = eu + r * std::cos(gamma), nev = ev + r * std::sin(gamma);
    const double pw = get(target.machine, ax.w), a = target.machine.a;
    const double w = get(m_pos, ax.w);
    ArcInfo arc;
    arc.centre = compPoint(ccu, ccv, w, a);
    arc.plane = planeOf(m_plane);
    arc.turns = turn;
    const double sweep = findTurn(ou, ov, ccu, ccv, turn, eu, ev);
    const double feed = feedFor(std::hypot(std::fabs(sweep) * arcRadius, pw - w));
    const double small = kCompConcaveTolerance;
    const bool concave = beta < -small || beta > kPi + small ||
                         (std::fabs(beta - kPi) < small && !toolInsideArc(m_comp.side, turn));
    if (concave) {
        if (!compArcCorner(beta, theta, ccu, ccv, arcRadius, turn, error))
            return false;
    } else if (beta > small) { // outside corner: an arc around it first
        const double mu = ou + r * std::cos(delta), mv = ov + r * std::sin(delta);
        m_comp.dequeue();
        ArcInfo corner;
        corner.centre = compPoint(ou, ov, w, a);
        corner.plane = arc.plane;
        corner.turns = left ? -1 : 1;
        compEnqueue(MotionKind::Arc, compPoint(mu, mv, w, a), feed, 0, 0, &corner, 0);
        m_comp.dequeue();
        m_comp.setEndpoint(mu, mv);
    } else {
        m_comp.dequeue();
        m_comp.setEndpoint(cu, cv);
    }
    const Point4 end = compPoint(neu, nev, pw, a);
    compEnqueue(MotionKind::Arc, end, feed, 0, 0, &arc, sweep);
    m_pos = end;
    m_prog = target.prog;
    return true;
}

// An inside corner before an arc: the queued move ends where its offset path meets the arc's.
bool Interpreter::compArcCorner(double beta, double theta, double ccu, double ccv, double arcRadius,
                                int turn, Error *error)
{
    const Axes ax = compAxes(m_plane);
    const std::uint32_t col = m_block.hasG(kGMotion) ? m_block.gColumn[kGMotion] : 0;
    const double r = m_comp.radius;
    const bool inside = toolInsideArc(m_comp.side, turn);
    const std::string radius = fmt4(r / unit());
    if (m_comp.queue.empty() || m_toolpath.kind(m_comp.queue.front().entry) != MotionKind::Arc) {
        const double across = arcRadius * std::sin(beta - kPi / 2);
        const double fromCentre = inside ? arcRadius - r : arcRadius + r;
        const double l = (inside ? across + r : across - r) / fromCentre;
        if (l > 1.0 || l < -1.0)
            return failAt(ErrorCode::CompGouge, col, radius, error);
        double angle = 0;
        if (inside)
            angle = turn > 0 ? theta + std::asin(l) : theta - std::asin(l);
        else
            angle = turn > 0 ? theta + kPi - std::asin(l) : theta + kPi + std::asin(l);
        return compFlush(ccu + fromCentre * std::cos(angle), ccv + fromCentre * std::sin(angle),
                         error);
    }
    const QueuedArc prev = queuedArc(m_toolpath, m_comp.queue.front().entry, planeOf(m_plane),
                                     offset(ax.u), offset(ax.v));
    const double oldRadius = std::hypot(prev.cv - prev.ev, prev.cu - prev.eu);
    const double newRadius = inside ? arcRadius - r : arcRadius + r;
    const double centres = std::hypot(prev.cv - ccv, prev.cu - ccu);
    if (oldRadius == 0 || centres == 0)
        return failAt(ErrorCode::CompGouge, col, radius, error);
    const double c = (oldRadius * oldRadius + centres * centres - newRadius * newRadius) /
                     (2 * oldRadius * centres);
    if (c > 1.0 || c < -1.0)
        return failAt(ErrorCode::CompGouge, col, radius, error);
    const double pullback = std::acos(c);
    const double toCentre = std::atan2(ccv - prev.cv, ccu - prev.cu);
    const bool plus = toolInsideArc(m_comp.side, prev.turn) ? turn > 0 : turn <= 0;
    const double dir = plus ? toCentre + pullback : toCentre - pullback;
    return compFlush(prev.cu + oldRadius * std::cos(dir), prev.cv + oldRadius * std::sin(dir),
                     error);
}

} // namespace frezka::gcode
