// LinuxCNC's splines: G5.1 (quadratic B-spline: I J the control point relative to the start),
// G5 (cubic: I J the first control point relative to the start, P Q the second relative to the
// end; I J left out continue the previous G5 smoothly) and G5.2 .. G5.3 (a NURBS: G5.2 X Y P L
// and lines of X Y P, each P the point's weight, L the order; G5.3 cuts it), with rs274ngc's
// rules and errors (convert_spline, convert_nurbs, check_g_codes). rs274 prints a spline as
// NURBS_FEED without coordinates; LinuxCNC's motion cuts the curve (as biarcs), Frezka as
// chords within Options::splineToleranceMm (gcode/spline.h), each a feed move of the spline's
// line, so planning, preview, soft limits and streaming see ordinary moves.
//
// Where LinuxCNC takes a program silently along another path, Frezka refuses it instead: a
// G5.2 curve not ended by G5.3 (LinuxCNC drops it), a control point without a positive weight
// (LinuxCNC takes -1), Z or A words on G5.2 lines (LinuxCNC ignores them), G5.2 outside G17
// (LinuxCNC cuts it in XY all the same), G5.2 with cutter compensation or in G93.
#include "interpreter.h"

#include <cmath>
#include <cstdio>

namespace frezka::gcode {

namespace {

std::string number(double v) // a word's value as the user wrote it, near enough
{
    char buf[32];
    std::snprintf(buf, sizeof buf, "%.6g", v);
    return buf;
}

constexpr double kMinWeight = 1e-6, kMaxWeight = 1e6;

} // namespace

bool Interpreter::splineAllowed(int motion, Error *error) const
{
    const std::uint32_t col = m_block.hasG(kGMotion) ? m_block.gColumn[kGMotion] : 0;
    const std::string name = gName(motion);
    if (m_comp.on())
        return failAt(ErrorCode::CompNotAllowed, col, name, error);
    if (motion == 52 && m_inverseTime)
        return failAt(ErrorCode::NurbsInverseTime, col, {}, error);
    if (m_inverseTime && !m_block.has('f'))
        return failAt(ErrorCode::InverseTimeFeedMissing, col, name, error);
    if (!m_inverseTime && m_feed == 0)
        return failAt(ErrorCode::ZeroFeedRate, col, name, error);
    if (m_plane != 170)
        return failAt(ErrorCode::SplinePlane, col, name + kDetailSeparator + gName(m_plane), error);
    for (char c : {'z', 'a'}) {
        if (m_block.has(c))
            return fail(ErrorCode::SplineAxisWord, c,
                        name + kDetailSeparator + std::string(1, char(c - 32)), error);
    }
    return true;
}

bool Interpreter::nurbsPending(int motion, Error *error)
{
    if (m_nurbs.empty() || motion == 52)
        return true;
    const std::uint32_t col = m_block.hasG(kGMotion) ? m_block.gColumn[kGMotion]
                              : m_block.hasM(kMStop) ? m_block.mColumn[kMStop]
                                                     : 0;
    failAt(ErrorCode::NurbsNotEnded, col, std::to_string(m_nurbsLine), error);
    m_nurbs.clear(); // check mode goes on without the curve: no follow-on errors
    return false;
}

bool Interpreter::spline(int motion, const Target &end, Error *error)
{
    const Block &b = m_block;
    const std::uint32_t col = b.hasG(kGMotion) ? b.gColumn[kGMotion] : 0;
    const std::string name = gName(motion);
    if (!splineAllowed(motion, error))
        return false;
    const double sx = m_prog.x, sy = m_prog.y, ex = end.prog.x, ey = end.prog.y;
    std::vector<SplinePoint> points{{sx, sy, 1}};
    if (motion == 51) {
        if (!b.has('i') || !b.has('j'))
            return failAt(ErrorCode::SplineMissingWords, col, name + kDetailSeparator + "I, J",
                          error);
        points.push_back({sx + lengthWord('i'), sy + lengthWord('j'), 1});
    } else {
        // rs274ngc keeps -P, -Q as written: after G20/G21 they count in the new units.
        double i = m_splineI * unit(), j = m_splineJ * unit();
        if (b.has('i') != b.has('j'))
            return failAt(ErrorCode::SplineMissingWords, col, name + kDetailSeparator + "I, J",
                          error);
        if (b.has('i')) {
            i = lengthWord('i');
            j = lengthWord('j');
        }
        if (!b.has('p') || !b.has('q'))
            return failAt(ErrorCode::SplineMissingWords, col, name + kDetailSeparator + "P, Q",
                          error);
        const double p = lengthWord('p'), q = lengthWord('q');
        points.push_back({sx + i, sy + j, 1});
        points.push_back({ex + p, ey + q, 1});
        m_splineI = -b.get('p');
        m_splineJ = -b.get('q');
    }
    points.push_back({ex, ey, 1});
    appendSpline(points, unsigned(points.size()), end.machine);
    moveTo(end);
    return true;
}

bool Interpreter::nurbsPoint(const Target &end, Error *error)
{
    const Block &b = m_block;
    if (!splineAllowed(52, error))
        return false;
    if (m_motion != 52)
        m_nurbs.clear(); // a new G5.2 starts a new curve (rs274ngc's convert_nurbs)
    const bool xy = b.has('x') && b.has('y');
    if (b.has('x') != b.has('y'))
        return fail(ErrorCode::NurbsMissingXy, b.has('x') ? 'x' : 'y', b.has('x') ? "Y" : "X",
                    error);
    if (!xy && b.has('p') && !m_nurbs.empty())
        return fail(ErrorCode::NurbsMissingXy, 'p', "X, Y", error);
    // A weight: LinuxCNC wants it positive; bounded here so that the curve's denominators
    // stay far from 0 and from overflow.
    const auto badWeight = [](double w) { return !(w >= kMinWeight && w <= kMaxWeight); };
    if (xy && !b.has('p'))
        return fail(ErrorCode::NurbsBadWeight, 'x', "-", error);
    if (b.has('p') && badWeight(b.get('p')))
        return fail(ErrorCode::NurbsBadWeight, 'p', number(b.get('p')), error);
    unsigned order = m_nurbs.empty() ? 3 : m_nurbsOrder;
    if (b.has('l')) {
        const double l = b.get('l');
        if (l != std::floor(l) || l > kMaxSplineOrder)
            return fail(ErrorCode::NurbsBadOrder, 'l', number(l), error);
        if (l > 3) // rs274ngc: L3 or less (or none) keeps the order
            order = unsigned(l);
    }
    if (m_nurbs.empty()) {
        m_nurbs.push_back({m_prog.x, m_prog.y, !xy && b.has('p') ? b.get('p') : 1.0});
        m_nurbsLine = m_line;
    }
    m_nurbsOrder = order;
    if (xy)
        m_nurbs.push_back({end.prog.x, end.prog.y, b.get('p')});
    return true;
}

bool Interpreter::nurbsEndAlone(Error *error) const
{
    // Only a new G5.2 may share G5.3's block (rs274ngc's check_g_codes); axis words there would
    // be taken as a control point of the curve just ended.
    const int mode1 = m_block.hasG(kGMotion) ? m_block.g[kGMotion] : -1;
    if (mode1 != -1 && mode1 != 52)
        return failAt(ErrorCode::NurbsOnlyControlPoints, m_block.gColumn[kGMotion], gName(mode1),
                      error);
    for (char c : kAxisLetters) {
        if (mode1 == -1 && m_block.has(c))
            return fail(ErrorCode::WordNotUsed, c, std::string(1, char(c - 32)), error);
    }
    return true;
}

bool Interpreter::nurbsEnd(Error *error)
{
    const std::uint32_t col = m_block.gColumn[kGNonModal];
    if (m_motion != 52 || m_nurbs.empty())
        return failAt(ErrorCode::NurbsNotStarted, col, {}, error);
    if (m_nurbs.size() < m_nurbsOrder) {
        failAt(ErrorCode::NurbsTooFewPoints, col,
               std::to_string(m_nurbs.size()) + kDetailSeparator + std::to_string(m_nurbsOrder),
               error);
        m_nurbs.clear(); // the curve is dropped: check mode goes on without follow-on errors
        m_motion = 800;
        return false;
    }
    checkFeedUnits();
    m_prog.x = m_nurbs.back().x;
    m_prog.y = m_nurbs.back().y;
    m_pos = toMachine(m_prog);
    appendSpline(m_nurbs, m_nurbsOrder, m_pos);
    m_nurbs.clear();
    m_motion = 800; // rs274ngc: no motion mode after G5.3 (axis words alone are an error)
    return true;
}

void Interpreter::appendSpline(const std::vector<SplinePoint> &points, unsigned order,
                               const Point4 &endMachine)
{
    const std::vector<PlanePoint> chords =
        flattenSpline(points, order, m_options.splineToleranceMm);
    std::vector<Point4> ends;
    ends.reserve(chords.size());
    for (std::size_t k = 0; k + 1 < chords.size(); ++k)
        ends.push_back(toMachine({chords[k][0], chords[k][1], m_prog.z, m_prog.a}));
    ends.push_back(endMachine);
    double feed = m_feedMm;
    if (m_inverseTime) { // the whole spline takes 1/F minutes
        double length = 0;
        Point4 from = m_toolpath.last();
        for (const Point4 &p : ends) {
            length += std::hypot(p.x - from.x, p.y - from.y);
            from = p;
        }
        feed = feedFor(length);
    }
    for (const Point4 &p : ends)
        m_toolpath.appendFeed(p, feed, pathLine());
}

} // namespace frezka::gcode
