// Motion: straight moves, arcs (LinuxCNC's centre and radius formats and its end-radius
// checks), probe moves and the canned cycles G73 G81 G82 G83 G85 G89 expanded into moves
// exactly as rs274ngc's convert_cycle_* does. All geometry is computed in program coordinates
// (mm) in the active plane's (u, v, w) axes and written out in machine coordinates.
#include "interpreter.h"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace frezka::gcode {

namespace {

// LinuxCNC's tolerances (interp_internal.hh), converted to mm.
constexpr double kRadiusToleranceMm = 0.00005 * 25.4;
constexpr double kSpiralAbsToleranceMetricMm = 2 * 0.01 * std::numbers::sqrt2;
constexpr double kSpiralAbsToleranceInchMm = 2 * 0.001 * std::numbers::sqrt2 * 25.4;
constexpr double kSpiralRelTolerance = 0.001;
constexpr double kTiny = 1e-12;
constexpr double kG83RapidDeltaMm = 0.010 * 25.4;
constexpr double kMaxTurns = 1e6; // P of an arc, L of a cycle: bounds against absurd output
constexpr double kMaxRepeats = 1e6;

struct PlaneAxes
{
    int u, v, w;      // indices into x y z
    char ou, ov, bad; // centre offset letters and the letter that does not belong
};

PlaneAxes planeAxes(int plane)
{
    switch (plane) {
    case 180:
        return {2, 0, 1, 'k', 'i', 'j'};
    case 190:
        return {1, 2, 0, 'j', 'k', 'i'};
    default:
        return {0, 1, 2, 'i', 'j', 'k'};
    }
}

Plane toPlane(int plane)
{
    return plane == 180 ? Plane::XZ : plane == 190 ? Plane::YZ : Plane::XY;
}

double &axisRef(Point4 &p, int i)
{
    return i == 0 ? p.x : i == 1 ? p.y : i == 2 ? p.z : p.a;
}

double axisOf(const Point4 &p, int i)
{
    return i == 0 ? p.x : i == 1 ? p.y : i == 2 ? p.z : p.a;
}

std::string fmt4(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4f", v);
    return buf;
}

// The length of an arc from (su, sv) to (eu, ev) around (cu, cv) in its plane, `turns` times
// around (G2: clockwise, motion 20), with `dw` along the plane's third axis: what an inverse-time
// feed (G93) is for.
double arcLength(int motion, double su, double sv, double eu, double ev, double cu, double cv,
                 int turns, double dw)
{
    const double r = std::hypot(su - cu, sv - cv);
    const double a0 = std::atan2(sv - cv, su - cu), a1 = std::atan2(ev - cv, eu - cu);
    double sweep = motion == 30 ? a1 - a0 : a0 - a1;
    while (sweep <= 1e-12)
        sweep += 2 * std::numbers::pi;
    sweep += 2 * std::numbers::pi * (turns - 1);
    return std::hypot(r * sweep, dw);
}

} // namespace

Interpreter::Target Interpreter::targetOf(bool machineCoords) const
{
    Target t{m_pos, m_prog};
    for (int i = 0; i < 4; ++i) {
        const char c = kAxisLetters[i];
        if (!m_block.has(c))
            continue;
        const double v = i < 3 ? lengthWord(c) : m_block.get(c);
        if (machineCoords) {
            axisRef(t.machine, i) = v;
            axisRef(t.prog, i) = v - offset(i);
        } else {
            axisRef(t.prog, i) = m_absolute ? v : axisOf(m_prog, i) + v;
            axisRef(t.machine, i) = axisOf(t.prog, i) + offset(i);
        }
    }
    if (m_block.hasPolar() && !machineCoords)
        polarTarget(&t);
    if (rotation() != 0) {
        // X and Y turn together (interp_rotation.cpp); G53 gives machine X and Y.
        if (machineCoords)
            t.prog = toProgram(t.machine);
        else
            t.machine = toMachine(t.prog);
    }
    return t;
}

void Interpreter::moveTo(const Target &target)
{
    m_pos = target.machine;
    m_prog = target.prog;
}

double Interpreter::feedFor(double lengthMm) const
{
    return m_inverseTime ? m_feed * lengthMm : m_feedMm;
}

bool Interpreter::executeMotion(int motion, Error *error)
{
    const bool g53 = m_block.hasG(kGNonModal) && m_block.g[kGNonModal] == 530;
    bool ok = true;
    m_motionNext = motion;
    if (m_block.hasPolar() && !polarCheck(error))
        return false;
    if (motion != 0)
        checkFeedUnits();
    if (!rotationAllows(motion, error))
        return false;
    if (motion == 0 || motion == 10)
        ok = straight(motion, targetOf(g53), error);
    else if (motion == 20 || motion == 30)
        ok = arc(motion, targetOf(false), error);
    else if (motion >= 382 && motion <= 385)
        ok = probe(motion, targetOf(false), error);
    else if (motion == 50 || motion == 51)
        ok = spline(motion, targetOf(false), error);
    else if (motion == 52)
        ok = nurbsPoint(targetOf(false), error);
    else
        ok = cycle(motion, error);
    if (ok)
        m_motion = motion;
    if (motion != 730 && !(motion >= 810 && motion <= 890))
        m_cycleIlValid = false;
    return ok;
}

bool Interpreter::straight(int motion, const Target &target, Error *error)
{
    const Point4 &end = target.machine;
    const std::uint32_t col = m_block.hasG(kGMotion) ? m_block.gColumn[kGMotion] : 0;
    m_comp.arcNotAllowed = false;
    if (motion == 10 && m_inverseTime && !m_block.has('f'))
        return failAt(ErrorCode::InverseTimeFeedMissing, col, "G1", error);
    if (motion == 10 && !m_inverseTime && m_feed == 0)
        return failAt(ErrorCode::ZeroFeedRate, col, "G1", error);
    if (m_comp.active())
        return compStraight(motion, target, error);
    if (motion == 0) {
        m_toolpath.appendRapid(end, feedMm(), pathLine());
        moveTo(target);
        return true;
    }
    // The length only matters to an inverse-time feed (G93): no square root per move otherwise.
    const double feed = m_inverseTime ? feedFor(std::sqrt((end.x - m_pos.x) * (end.x - m_pos.x) +
                                                          (end.y - m_pos.y) * (end.y - m_pos.y) +
                                                          (end.z - m_pos.z) * (end.z - m_pos.z)))
                                      : m_feedMm;
    m_toolpath.appendFeed(end, feed, pathLine());
    moveTo(target);
    return true;
}

// Centre from I/J/K (incremental or G90.1 absolute) with LinuxCNC 2.9's end-radius check.
bool Interpreter::arcCentreIjk(double su, double sv, double eu, double ev, std::uint32_t col,
                               double *cu, double *cv, Error *error) const
{
    const PlaneAxes ax = planeAxes(m_plane);
    const double ou = m_block.has(ax.ou) ? lengthWord(ax.ou) : 0.0;
    const double ov = m_block.has(ax.ov) ? lengthWord(ax.ov) : 0.0;
    *cu = m_arcAbsolute ? ou : su + ou;
    *cv = m_arcAbsolute ? ov : sv + ov;
    const double r1 = std::hypot(*cu - su, *cv - sv);
    const double r2 = std::hypot(*cu - eu, *cv - ev);
    auto radii = [&] { return "r1=" + fmt4(r1 / unit()) + " r2=" + fmt4(r2 / unit()); };
    if (r1 < kRadiusToleranceMm || r2 < kRadiusToleranceMm)
        return failAt(ErrorCode::ArcZeroRadius, col, radii(), error);
    const double spiralAbs = m_metric ? kSpiralAbsToleranceMetricMm : kSpiralAbsToleranceInchMm;
    const double absErr = std::fabs(r1 - r2);
    const double relErr = absErr / std::max(r1, r2);
    if (absErr > spiralAbs * 100.0 || (relErr > kSpiralRelTolerance && absErr > spiralAbs))
        return failAt(ErrorCode::ArcRadiusMismatch, col, radii(), error);
    return true;
}

// Centre from R (rs274ngc's arc_data_r): negative R takes the arc longer than a half circle.
bool Interpreter::arcCentreR(int motion, double su, double sv, double eu, double ev, double *cu,
                             double *cv, Error *error) const
{
    if (eu == su && ev == sv)
        return fail(ErrorCode::ArcEndEqualsStart, 'r', {}, error);
    const double radius = lengthWord('r');
    const double absRadius = std::fabs(radius);
    const double mu = (eu + su) / 2.0, mv = (ev + sv) / 2.0;
    double half = std::hypot(mu - eu, mv - ev);
    if (half - absRadius > kRadiusToleranceMm)
        return fail(ErrorCode::ArcRadiusTooSmall, 'r', "R" + fmt4(radius / unit()), error);
    if (half / absRadius > 1 - kTiny)
        half = absRadius;
    const double chord = std::atan2(ev - sv, eu - su);
    const bool minus = (motion == 20 && radius > 0) || (motion == 30 && radius < 0);
    const double theta = chord + (minus ? -std::numbers::pi / 2 : std::numbers::pi / 2);
    const double dist = absRadius * std::cos(std::asin(half / absRadius));
    *cu = mu + dist * std::cos(theta);
    *cv = mv + dist * std::sin(theta);
    return true;
}

bool Interpreter::arc(int motion, const Target &target, Error *error)
{
    const Point4 &end = target.machine;
    const Block &b = m_block;
    const std::uint32_t col = b.hasG(kGMotion) ? b.gColumn[kGMotion] : 0;
    const char *name = motion == 20 ? "G2" : "G3";
    const bool ijk = b.has('i') || b.has('j') || b.has('k');
    const bool rForm = b.has('r');
    const PlaneAxes ax = planeAxes(m_plane);
    if (m_comp.arcNotAllowed)
        return failAt(ErrorCode::CompArcAfterExit, col, {}, error);
    if (!rForm && !ijk)
        return failAt(ErrorCode::ArcMissingCentre, col, {}, error);
    if (rForm && ijk)
        return fail(ErrorCode::ArcMixedRAndIjk, 'r', {}, error);
    if (m_inverseTime && !b.has('f'))
        return failAt(ErrorCode::InverseTimeFeedMissing, col, name, error);
    if (!m_inverseTime && m_feed == 0)
        return failAt(ErrorCode::ZeroFeedRate, col, name, error);
    if (ijk) {
        if (b.has(ax.bad) && b.get(ax.bad) != 0)
            return fail(ErrorCode::ArcWrongPlaneWord, ax.bad, std::string(1, ax.bad - 32), error);
        if (b.has(ax.bad)) { // K0 on a G17 arc (FreeCAD's grbl post): no effect
            const char *plane = m_plane == 180 ? "XZ" : m_plane == 190 ? "YZ" : "XY";
            warnAt(ErrorCode::IgnoredArcWord, b.col(ax.bad),
                   std::string(1, ax.bad - 32) + "0" + kDetailSeparator + plane);
        }
        if (m_arcAbsolute && (!b.has(ax.ou) || !b.has(ax.ov))) {
            const char missing = b.has(ax.ou) ? ax.ov : ax.ou;
            return failAt(ErrorCode::ArcMissingAbsoluteCentre, col, std::string(1, missing - 32),
                          error);
        }
    } else if (!b.has(kAxisLetters[ax.u]) && !b.has(kAxisLetters[ax.v]) && !b.hasPolar()) {
        return fail(ErrorCode::ArcMissingEndWords, 'r', {}, error);
    }
    int turns = 1;
    if (b.has('p')) {
        const double p = b.get('p');
        const double rounded = std::round(p);
        if (rounded < 1 || rounded > kMaxTurns || std::fabs(p - rounded) > 0.0001)
            return fail(ErrorCode::ArcBadTurns, 'p', fmt4(p), error);
        turns = static_cast<int>(rounded);
    }
    if (m_comp.active())
        return compArc(motion, target, turns, error);

    // Program coordinates in the plane.
    const double su = axisOf(m_prog, ax.u), sv = axisOf(m_prog, ax.v);
    const double eu = axisOf(target.prog, ax.u), ev = axisOf(target.prog, ax.v);
    double cu = 0, cv = 0;
    const bool ok = ijk ? arcCentreIjk(su, sv, eu, ev, col, &cu, &cv, error)
                        : arcCentreR(motion, su, sv, eu, ev, &cu, &cv, error);
    if (!ok)
        return false;
    ArcInfo info;
    info.plane = toPlane(m_plane);
    info.turns = motion == 20 ? -turns : turns;
    info.centre = m_pos;
    axisRef(info.centre, ax.u) = cu + offset(ax.u);
    axisRef(info.centre, ax.v) = cv + offset(ax.v);
    if (rotation() != 0) // G17 only (rotationAllows)
        info.centre = turnedCentre(cu, cv);

    double feed = m_feedMm;
    if (m_inverseTime)
        feed = feedFor(arcLength(motion, su, sv, eu, ev, cu, cv, turns,
                                 axisOf(end, ax.w) - axisOf(m_pos, ax.w)));
    m_toolpath.appendArc(end, info, feed, pathLine());
    moveTo(target);
    return true;
}

bool Interpreter::probe(int motion, const Target &target, Error *error)
{
    const Point4 &end = target.machine;
    const std::uint32_t col = m_block.hasG(kGMotion) ? m_block.gColumn[kGMotion] : 0;
    if (m_comp.on())
        return failAt(ErrorCode::CompNotAllowed, col, gName(motion), error);
    if (m_inverseTime)
        return failAt(ErrorCode::ProbeInverseTime, col, {}, error);
    if (m_feed == 0)
        return failAt(ErrorCode::ZeroFeedRate, col, gName(motion), error);
    if (end == m_pos)
        return failAt(ErrorCode::ProbeNoMotion, col, {}, error);
    const auto kind = static_cast<ProbeKind>(motion - 382);
    const std::size_t n = m_probes++;
    if (n < m_options.probeResults.size()) { // it has run: the rest goes on from where it stopped
        const ProbeResult &r = m_options.probeResults[n];
        m_toolpath.appendProbe(r.machineMm, kind, m_feedMm, pathLine());
        moveTo({r.machineMm, toProgram(r.machineMm)});
        m_probe = m_prog;
        m_probed = r.tripped;
        return true;
    }
    if (m_provisionalEntry == Result::kNoEntry) {
        m_provisionalEntry = m_toolpath.size();
        m_provisionalLine = pathLine();
    }
    m_toolpath.appendProbe(end, kind, m_feedMm, pathLine());
    moveTo(target);
    m_probe = m_prog;
    m_probed = true;
    return true;
}

void Interpreter::cycleTraverse(int plane, double aa, double bb, double cc)
{
    const PlaneAxes ax = planeAxes(plane);
    Target t{m_pos, m_prog};
    axisRef(t.prog, ax.u) = aa;
    axisRef(t.prog, ax.v) = bb;
    axisRef(t.prog, ax.w) = cc;
    for (int i : {ax.u, ax.v, ax.w})
        axisRef(t.machine, i) = axisOf(t.prog, i) + offset(i);
    if (rotation() != 0)
        t.machine = toMachine(t.prog);
    m_toolpath.appendRapid(t.machine, m_feedMm, pathLine());
    moveTo(t);
}

void Interpreter::cycleFeed(int plane, double aa, double bb, double cc)
{
    const PlaneAxes ax = planeAxes(plane);
    Target t{m_pos, m_prog};
    axisRef(t.prog, ax.u) = aa;
    axisRef(t.prog, ax.v) = bb;
    axisRef(t.prog, ax.w) = cc;
    for (int i : {ax.u, ax.v, ax.w})
        axisRef(t.machine, i) = axisOf(t.prog, i) + offset(i);
    if (rotation() != 0)
        t.machine = toMachine(t.prog);
    m_toolpath.appendFeed(t.machine, m_feedMm, pathLine());
    moveTo(t);
}

void Interpreter::cycleBody(int motion, double aa, double bb, double r, double clear, double cc,
                            double dwell, double peck)
{
    switch (motion) {
    case 810:
        cycleFeed(m_plane, aa, bb, cc);
        cycleTraverse(m_plane, aa, bb, clear);
        break;
    case 820:
        cycleFeed(m_plane, aa, bb, cc);
        event(EventKind::Dwell, dwell);
        cycleTraverse(m_plane, aa, bb, clear);
        break;
    case 730: // chip breaking: back off a little after each peck
    case 830: // peck: out to R after each peck
        for (double depth = r - peck; depth > cc; depth -= peck) {
            cycleFeed(m_plane, aa, bb, depth);
            if (motion == 830)
                cycleTraverse(m_plane, aa, bb, r);
            cycleTraverse(m_plane, aa, bb, depth + kG83RapidDeltaMm);
        }
        cycleFeed(m_plane, aa, bb, cc);
        cycleTraverse(m_plane, aa, bb, clear);
        break;
    case 850:
        cycleFeed(m_plane, aa, bb, cc);
        cycleFeed(m_plane, aa, bb, r);
        cycleTraverse(m_plane, aa, bb, clear);
        break;
    case 890:
        cycleFeed(m_plane, aa, bb, cc);
        event(EventKind::Dwell, dwell);
        cycleFeed(m_plane, aa, bb, clear);
        break;
    default:
        break;
    }
}

// The words of a cycle block, with the sticky values of the previous cycle block (same cycle)
// where a word is left out, as rs274ngc's convert_cycle does.
bool Interpreter::cycleWords(int motion, CycleWords *w, Error *error) const
{
    const Block &b = m_block;
    const std::uint32_t col = b.hasG(kGMotion) ? b.gColumn[kGMotion] : 0;
    const std::string name = gName(motion);
    const char wc = kAxisLetters[planeAxes(m_plane).w];
    if (m_comp.on())
        return failAt(ErrorCode::CompNotAllowed, col, name, error);
    if (m_inverseTime)
        return failAt(ErrorCode::CycleInverseTime, col, {}, error);
    if (m_feed == 0)
        return failAt(ErrorCode::ZeroFeedRate, col, name, error);
    const bool same = m_motion == motion;
    w->r = m_cycleR;
    if (b.has('r'))
        w->r = lengthWord('r');
    else if (!same)
        return failAt(ErrorCode::CycleMissingR, col, name, error);
    w->repeats = 1;
    if (b.has('l')) {
        const double l = b.get('l');
        if (l < 1 || l > kMaxRepeats || l != std::floor(l))
            return fail(ErrorCode::CycleBadL, 'l', {}, error);
        w->repeats = static_cast<int>(l);
    }
    if (!same && !b.has(wc))
        return failAt(ErrorCode::CycleMissingDepth, col, name, error);
    w->depth = b.has(wc) ? lengthWord(wc) : m_cycleCC;
    w->dwell = m_cycleP;
    w->peck = m_cycleQ;
    if (motion == 820 || motion == 890) {
        if (!same && !b.has('p'))
            return failAt(ErrorCode::CycleMissingP, col, name, error);
        if (b.has('p'))
            w->dwell = b.get('p');
    }
    if (motion == 730 || motion == 830) {
        if (!same && !b.has('q'))
            return failAt(ErrorCode::CycleMissingQ, col, name, error);
        if (b.has('q'))
            w->peck = lengthWord('q');
        if (w->peck <= 0)
            return fail(ErrorCode::CycleBadQ, b.has('q') ? 'q' : 0, {}, error);
    }
    return true;
}

// LinuxCNC's convert_cycle_xy/_yz/_zx in one, its variables (aa, bb, cc, r, old_cc, current_cc)
// under their names: kept whole (over 60 lines) so that it reads side by side with rs274ngc's.
bool Interpreter::cycle(int motion, Error *error)
{
    const Block &b = m_block;
    const std::uint32_t col = b.hasG(kGMotion) ? b.gColumn[kGMotion] : 0;
    const PlaneAxes ax = planeAxes(m_plane);
    const char uc = kAxisLetters[ax.u], vc = kAxisLetters[ax.v];
    CycleWords words;
    if (!cycleWords(motion, &words, error))
        return false;
    const double rWord = words.r, ccWord = words.depth, p = words.dwell, q = words.peck;
    const int repeats = words.repeats;

    const Point4 prog = programPosition();
    // LinuxCNC 2.9: the initial level is remembered over consecutive cycle blocks.
    double currentCc = axisOf(prog, ax.w);
    if (!m_cycleIlValid) {
        m_cycleIl = currentCc;
        m_cycleIlValid = true;
    }
    double oldCc = m_cycleIl;
    double aa = 0, bb = 0, aaInc = 0, bbInc = 0, r = 0, cc = 0;
    if (m_absolute) {
        r = rWord;
        cc = ccWord;
        aa = b.has(uc) ? lengthWord(uc) : axisOf(prog, ax.u);
        bb = b.has(vc) ? lengthWord(vc) : axisOf(prog, ax.v);
        if (b.hasPolar()) { // G17 only (polarCheck)
            Target t{m_pos, prog};
            polarTarget(&t);
            aa = t.prog.x;
            bb = t.prog.y;
        }
    } else {
        aaInc = b.has(uc) ? lengthWord(uc) : 0.0;
        bbInc = b.has(vc) ? lengthWord(vc) : 0.0;
        r = rWord + oldCc;
        cc = r + ccWord;
        aa = axisOf(prog, ax.u);
        bb = axisOf(prog, ax.v);
    }
    if (r < cc)
        return failAt(ErrorCode::CycleRBelowDepth, b.has('r') ? b.col('r') : col, {}, error);
    if (oldCc < r) { // below the R plane: straight up to it first
        cycleTraverse(m_plane, axisOf(prog, ax.u), axisOf(prog, ax.v), r);
        oldCc = r;
        currentCc = oldCc;
    }
    const double clear = m_retractToR ? r : oldCc;
    if (m_pathMode != 0)
        event(EventKind::PathMode, 0, 0, 0);
    for (int n = 0; n < repeats; ++n) {
        aa += aaInc;
        bb += bbInc;
        if (!m_absolute && b.hasPolar() && !cyclePolarStep(&aa, &bb, error))
            return false;
        if (n == 0 && currentCc > r) {
            cycleTraverse(m_plane, aa, bb, currentCc);
            cycleTraverse(m_plane, aa, bb, r);
        } else {
            cycleTraverse(m_plane, aa, bb, clear);
            if (clear > r)
                cycleTraverse(m_plane, aa, bb, r);
        }
        cycleBody(motion, aa, bb, r, clear, cc, p, q);
    }
    if (m_pathMode != 0)
        event(EventKind::PathMode, m_pathMode, m_pathP, m_pathQ);
    m_cycleCC = ccWord;
    m_cycleR = rWord;
    m_cycleP = p;
    m_cycleQ = q;
    return true;
}

} // namespace frezka::gcode
