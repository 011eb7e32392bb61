// Cutter radius compensation as LinuxCNC's rs274ngc does it (interp_convert.cc's
// convert_straight_comp1/comp2, convert_arc_comp1/comp2 and interp_queue.cc's
// move_endpoint_and_flush, read for their behaviour): the tool's centre kept one radius to the
// left (G41) or right (G42) of the programmed path in the XY (G17) or XZ (G18) plane. The entry
// move goes straight (or along an arc) to the point one radius beside the first programmed end;
// an outside corner is rounded with an arc around the programmed corner (a rapid goes straight
// to the same point), an inside corner ends both moves where their offset paths meet (a
// following Z-only move stays there too), and G40 leaves the tool where the last move put it,
// so the move after G40 is the exit move (it must be straight). The geometry is computed in
// program coordinates, mm, in the plane's (u, v) and written out in machine coordinates.
#include "comp_internal.h"
#include "interpreter.h"

#include <cmath>

namespace frezka::gcode {

using namespace comp;

Point4 Interpreter::compPoint(double u, double v, double w, double a) const
{
    const Axes ax = compAxes(m_plane);
    Point4 p;
    at(p, ax.u) = u + offset(ax.u);
    at(p, ax.v) = v + offset(ax.v);
    at(p, ax.w) = w; // machine coordinates already
    p.a = a;
    return p;
}

void Interpreter::compEnqueue(MotionKind kind, const Point4 &end, double feed, double du, double dv,
                              const ArcInfo *arc, double originalTurns)
{
    const std::size_t entry = m_toolpath.size();
    if (kind == MotionKind::Arc)
        m_toolpath.appendArc(end, *arc, feed, pathLine());
    else if (kind == MotionKind::Rapid)
        m_toolpath.appendRapid(end, feed, pathLine());
    else
        m_toolpath.appendFeed(end, feed, pathLine());
    m_comp.queue.push_back({entry, du, dv, originalTurns});
}

bool Interpreter::compOn(Error *error)
{
    const Block &b = m_block;
    const int g = b.g[kGCutterComp];
    const std::uint32_t col = b.gColumn[kGCutterComp];
    if (m_plane != 170 && m_plane != 180)
        return failAt(ErrorCode::CompPlane, col, gName(g), error);
    if (m_comp.on())
        return failAt(ErrorCode::CompAlreadyOn, col, gName(g), error);
    if (rotation() != 0) // interp_rotation.cpp
        return failAt(ErrorCode::UnsupportedRotation, col, gName(g), error);
    CompSide side = g == 410 || g == 411 ? CompSide::Left : CompSide::Right;
    double radius = 0;
    if (g == 411 || g == 421) { // D is the diameter
        if (!b.has('d'))
            return failAt(ErrorCode::CompMissingD, col, gName(g), error);
        radius = lengthWord('d') / 2;
    } else { // D names a tool of the table, the one in the spindle without D (or D0)
        ToolEntry e = spindleTool();
        int tool = 0;
        if (b.has('d') &&
            (!toolNumber('d', &tool, error) || (tool != 0 && !findTool(tool, 'd', &e, error))))
            return false;
        const char sep = kDetailSeparator;
        if (e.orientation != 0 && e.orientation != 9)
            return failAt(ErrorCode::CutterCompensation, col,
                          gName(g) + sep + std::to_string(e.tool) + sep +
                              std::to_string(e.orientation),
                          error);
        radius = e.diameterMm / 2;
        if (radius == 0)
            warnAt(ErrorCode::CompZeroRadius, col, gName(g) + sep + std::to_string(e.tool));
    }
    if (radius < 0) { // a negative diameter (wear): the other side, as in rs274ngc
        radius = -radius;
        side = side == CompSide::Left ? CompSide::Right : CompSide::Left;
    }
    m_comp.side = side;
    m_comp.radius = radius;
    m_comp.onLine = m_line;
    return true;
}

bool Interpreter::compFlush(double u, double v, Error *error)
{
    if (m_comp.queue.empty())
        return true;
    const Axes ax = compAxes(m_plane);
    const double radiusTolerance = m_metric ? 0.01 : 0.01 * 25.4;
    const double arcSlack = m_metric ? 0.0254 : 0.001 * 25.4;
    const CompFault fault = moveQueuedEnds(m_toolpath, m_comp, planeOf(m_plane), offset(ax.u),
                                           offset(ax.v), u, v, radiusTolerance, arcSlack);
    if (fault != CompFault::None) {
        const std::uint32_t col = m_block.hasG(kGMotion) ? m_block.gColumn[kGMotion] : 0;
        return failAt(ErrorCode::CompGouge, col, fmt4(m_comp.radius / unit()), error);
    }
    m_comp.dequeue();
    m_comp.setEndpoint(u, v);
    return true;
}

bool Interpreter::compFlushHere(Error *error)
{
    const Axes ax = compAxes(m_plane);
    if (!compFlush(get(m_pos, ax.u) - offset(ax.u), get(m_pos, ax.v) - offset(ax.v), error))
        return false;
    m_comp.dequeue();
    return true;
}

bool Interpreter::compOff(Error *error)
{
    if (m_comp.active() && !m_comp.firstMove) {
        if (!compFlushHere(error))
            return false;
        // rs274ngc: the programmed point becomes the current one; the next move (the exit
        // move, straight) starts where the tool is.
        m_pos = {m_prog.x + offset(0), m_prog.y + offset(1), m_prog.z + offset(2), m_pos.a};
        m_comp.arcNotAllowed = true;
    }
    m_comp.side = CompSide::Off;
    m_comp.firstMove = true;
    return true;
}

bool Interpreter::compAllows(Error *error) const
{
    if (!m_comp.on())
        return true;
    const Block &b = m_block;
    for (int group : {kGCoordSystem, kGPathControl, kGRetract}) {
        if (b.hasG(group))
            return failAt(ErrorCode::CompNotAllowed, b.gColumn[group], gName(b.g[group]), error);
    }
    if (!b.hasG(kGNonModal))
        return true;
    const int g = b.g[kGNonModal];
    bool refused = g == 280 || g == 281 || g == 300 || g == 301 || (g >= 920 && g <= 923);
    if (g == 100 && b.has('l') && (b.get('l') == 2 || b.get('l') == 20) && b.has('p')) {
        const int p = static_cast<int>(b.get('p') + 0.0001);
        refused = p == 0 || p - 1 == m_coord; // the active system
    }
    if (refused)
        return failAt(ErrorCode::CompNotAllowed, b.gColumn[kGNonModal], gName(g), error);
    return true;
}

// An outside corner between two straight moves: an arc around the programmed corner (ou, ov)
// to (mu, mv), where the next move starts, at that move's feed (in G93 the rate LinuxCNC sets
// for the next move, as rs274 does); a rapid goes there straight.
void Interpreter::compCorner(int motion, double ou, double ov, double mu, double mv,
                             const Point4 &end, double feed)
{
    const Axes ax = compAxes(m_plane);
    const double w = get(m_pos, ax.w); // the corner is made at the current height
    const Point4 mid = compPoint(mu, mv, w, end.a);
    if (motion == 10) {
        ArcInfo arc;
        arc.centre = compPoint(ou, ov, w, end.a);
        arc.plane = planeOf(m_plane);
        arc.turns = m_comp.side == CompSide::Left ? -1 : 1;
        compEnqueue(MotionKind::Arc, mid, feed, 0, 0, &arc, 0);
    } else {
        compEnqueue(MotionKind::Rapid, mid, feedMm(), 0, 0, nullptr, 0);
    }
    m_comp.dequeue();
    m_comp.setEndpoint(mu, mv);
}

// An inside corner before a straight move: the queued move ends where the offset paths meet.
bool Interpreter::compInsideCorner(double beta, double theta, double gamma, double pu, double pv,
                                   double ou, double ov, Error *error)
{
    const Axes ax = compAxes(m_plane);
    const double r = m_comp.radius;
    const double cu = get(m_pos, ax.u) - offset(ax.u), cv = get(m_pos, ax.v) - offset(ax.v);
    const std::uint32_t col = m_block.hasG(kGMotion) ? m_block.gColumn[kGMotion] : 0;
    const std::string radius = fmt4(r / unit());
    if (m_comp.queue.empty() || m_toolpath.kind(m_comp.queue.front().entry) != MotionKind::Arc) {
        const double half = (beta + kPi) / 2; // half the inside corner's angle
        if (half == 0.0)
            return failAt(ErrorCode::CompGouge, col, radius, error);
        const double retreat = r / std::tan(half);
        return compFlush(cu + retreat * std::cos(theta + gamma),
                         cv + retreat * std::sin(theta + gamma), error);
    }
    // Arc, then straight: where the line's offset meets the arc's (the queued arc is the
    // compensated one).
    const QueuedArc prev = queuedArc(m_toolpath, m_comp.queue.front().entry, planeOf(m_plane),
                                     offset(ax.u), offset(ax.v));
    const double oldRadius = std::hypot(prev.cv - prev.ev, prev.cu - prev.eu);
    const double base = std::atan2(pv - ov, pu - ou);
    const double th = prev.turn > 0 ? base + kPi / 2 : base - kPi / 2;
    const double phi = std::atan2(prev.cv - ov, prev.cu - ou);
    const bool inside = toolInsideArc(m_comp.side, prev.turn);
    const double programmed = inside ? oldRadius + r : oldRadius - r;
    const double d = programmed * std::cos(th - phi);
    const double l = (inside ? d - r : d + r) / oldRadius;
    if (l > 1.0 || l < -1.0)
        return failAt(ErrorCode::CompGouge, col, radius, error);
    const double sign = (prev.turn > 0) == inside ? -1.0 : 1.0;
    const double angle = sign * std::acos(l) + th + kPi;
    return compFlush(prev.cu + oldRadius * std::cos(angle), prev.cv + oldRadius * std::sin(angle),
                     error);
}

// rs274ngc's convert_straight_comp1 (entry move) and convert_straight_comp2, kept whole (a little
// over 60 lines) so that it reads side by side with them.
bool Interpreter::compStraight(int motion, const Target &target, Error *error)
{
    const Axes ax = compAxes(m_plane);
    const std::uint32_t col = m_block.hasG(kGMotion) ? m_block.gColumn[kGMotion] : 0;
    if (m_block.hasG(kGNonModal) && m_block.g[kGNonModal] == 530)
        return failAt(ErrorCode::CompNotAllowed, m_block.gColumn[kGNonModal], "G53", error);
    const double pu = get(target.prog, ax.u), pv = get(target.prog, ax.v);
    const double pw = get(target.machine, ax.w), a = target.machine.a;
    const double cu = get(m_pos, ax.u) - offset(ax.u), cv = get(m_pos, ax.v) - offset(ax.v);
    const double ou = get(m_prog, ax.u), ov = get(m_prog, ax.v);
    const double r = m_comp.radius;
    const bool left = m_comp.side == CompSide::Left;
    const MotionKind kind = motion == 0 ? MotionKind::Rapid : MotionKind::Feed;
    const Point4 &p = target.prog;
    const double feed = motion == 0
                            ? feedMm()
                            : feedFor(std::hypot(p.x - m_prog.x, p.y - m_prog.y, p.z - m_prog.z));
    double eu = cu, ev = cv;
    if (m_comp.firstMove) {
        if (std::hypot(pu - cu, pv - cv) <= r)
            return failAt(ErrorCode::CompEntryTooShort, col, fmt4(r / unit()), error);
        const double alpha = std::atan2(pv - cv, pu - cu) + (left ? kPi / 2 : -kPi / 2);
        eu = pu + r * std::cos(alpha);
        ev = pv + r * std::sin(alpha);
        m_comp.setEndpoint(cu, cv);
        compEnqueue(kind, compPoint(eu, ev, pw, a), feed, std::cos(alpha), std::sin(alpha), nullptr,
                    0);
        m_comp.firstMove = false;
    } else if (pu == ou && pv == ov) { // no motion in the plane
        compEnqueue(kind, compPoint(cu, cv, pw, a), feed, 0, 0, nullptr, 0);
    } else {
        double theta = std::atan2(cv - ov, cu - ou); // from the programmed point to the tool
        double alpha = std::atan2(pv - ov, pu - ou); // the programmed direction
        if (left && theta < alpha)
            theta += 2 * kPi;
        if (!left && alpha < theta)
            alpha += 2 * kPi;
        const double beta = left ? theta - alpha - kPi / 2 : alpha - theta - kPi / 2;
        const double gamma = left ? kPi / 2 : -kPi / 2;
        eu = pu + r * std::cos(alpha + gamma);
        ev = pv + r * std::sin(alpha + gamma);
        const double small = kCompConcaveTolerance;
        bool concave = beta < -small || beta > kPi + small;
        if (!concave && beta > kPi - small && !m_comp.queue.empty() &&
            m_toolpath.kind(m_comp.queue.front().entry) == MotionKind::Arc) {
            // An "h": coming back along the arc's round, the tool stays on the outside.
            const int turn = m_toolpath.arc(m_comp.queue.front().entry).turns;
            concave = (!left && turn > 0) || (left && turn < 0);
        }
        if (concave) {
            if (!compInsideCorner(beta, theta, gamma, pu, pv, ou, ov, error))
                return false;
        } else if (beta > small) {
            if (!compFlush(cu, cv, error))
                return false;
            compCorner(motion, ou, ov, ou + r * std::cos(alpha + gamma),
                       ov + r * std::sin(alpha + gamma), target.machine, feed);
        } else { // straight on (or tangent after an arc)
            m_comp.dequeue();
            m_comp.setEndpoint(cu, cv);
        }
        compEnqueue(kind, compPoint(eu, ev, pw, a), feed, pu - ou, pv - ov, nullptr, 0);
    }
    m_pos = compPoint(eu, ev, pw, a);
    m_prog = target.prog;
    return true;
}

} // namespace frezka::gcode
