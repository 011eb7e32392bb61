// Executing a block's non-motion codes in LinuxCNC's order: feed mode, F, S, T, M6,
// M3/M4/M5, M7/M8/M9, G4, then the modal groups (plane, units, G40, tool length, work offset,
// path control, distance modes, retract mode), the non-modal G10/G28/G30/G92 family and finally
// (after the motion) M0/M1/M2/M30.
#include "interpreter.h"

#include <cmath>
#include <cstdio>

namespace frezka::gcode {

void Interpreter::event(EventKind kind, double value, double p, double q)
{
    m_toolpath.appendEvent({kind, value, p, q}, feedMm(), pathLine());
}

namespace {

// "6", "0.2362", "152.4": a feed in a message.
std::string feedText(double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, "%.4f", v);
    std::string s = buf;
    while (s.back() == '0')
        s.pop_back();
    if (s.back() == '.')
        s.pop_back();
    return s;
}

} // namespace

void Interpreter::checkFeedUnits()
{
    if (m_inverseTime || m_feedUnitsWarned || m_feed == 0 || m_feedMetric == m_metric)
        return;
    m_feedUnitsWarned = true;
    const char *setIn = m_feedMetric ? "mm/min" : "in/min";
    const char *now = m_metric ? "mm/min" : "in/min";
    const double inNow = m_feedMm / unit(); // the same feed in the new units
    const double meantMm = m_feed * unit(); // F read in the new units, in mm/min
    const double meantInSet = meantMm / (m_feedMetric ? 1.0 : 25.4);
    const char sep = kDetailSeparator;
    warn(ErrorCode::FeedUnitsChanged, m_unitsLine, m_unitsColumn,
         feedText(m_feed) + sep + setIn + sep + std::to_string(m_feedLine) + sep + feedText(inNow) +
             sep + now + sep + feedText(meantInSet));
}

// The non-motion words of a block in rs274ngc's order of execution (G93/G94, F, S, T, M6, M3-M5,
// M7-M9, G4): kept whole (over 60 lines) so that the order, which the result depends on, reads
// top to bottom as in the NGC manual's table.
bool Interpreter::executeModes(Error *error)
{
    const Block &b = m_block;
    if (b.hasG(kGFeedMode)) {
        // rs274ngc: any G93/G94 word resets the feed rate (an F on the same line sets it again).
        m_inverseTime = b.g[kGFeedMode] == 930;
        m_feed = 0;
        m_feedMm = 0;
    }
    if (b.has('f')) {
        if (b.get('f') < 0)
            return fail(ErrorCode::NegativeValue, 'f', "F", error);
        // In the units in force before this block's G20/G21, which LinuxCNC executes later.
        m_feed = b.get('f');
        m_feedMm = m_feed * unit();
        m_feedMetric = m_metric;
        m_feedLine = m_line;
        m_feedUnitsWarned = false;
    }
    if (b.has('s')) {
        if (b.get('s') < 0)
            return fail(ErrorCode::NegativeValue, 's', "S", error);
        const bool changed = b.get('s') != m_speed;
        m_speed = b.get('s');
        const bool startsSpindle = b.hasM(kMSpindle) && b.m[kMSpindle] != 5;
        if (changed && m_spindle != 0 && !startsSpindle)
            event(EventKind::SpindleSpeed, m_speed);
    }
    if (!selectTool(error))
        return false;
    if (b.hasM(kMSpindle)) {
        const int m = b.m[kMSpindle];
        m_spindle = m == 3 ? 1 : m == 4 ? -1 : 0;
        event(m == 3   ? EventKind::SpindleCw
              : m == 4 ? EventKind::SpindleCcw
                       : EventKind::SpindleOff,
              m == 5 ? 0 : m_speed);
    }
    if (b.hasM(kMCoolant)) {
        const int m = b.m[kMCoolant];
        if (m == 7)
            m_mist = true;
        else if (m == 8)
            m_flood = true;
        else
            m_mist = m_flood = false;
        event(m == 7   ? EventKind::CoolantMist
              : m == 8 ? EventKind::CoolantFlood
                       : EventKind::CoolantOff);
    }
    if (b.hasG(kGNonModal) && b.g[kGNonModal] == 40) {
        const double p = b.get('p');
        if (p < 0)
            return fail(ErrorCode::NegativeValue, 'p', "P", error);
        // Mach3/UCCNC posts may mean milliseconds: a whole P of 100 s or more is suspect.
        if (p >= 100 && p == std::floor(p)) {
            const char sep = kDetailSeparator;
            warnAt(ErrorCode::DwellLooksLikeMilliseconds, b.col('p'),
                   feedText(p) + sep + feedText(p / 60) + " min" + sep + feedText(p / 1000));
        }
        m_toolpath.appendEvent({EventKind::Dwell, b.get('p'), 0, 0}, feedMm(), pathLine());
    }
    return executeModalGroups(error);
}

bool Interpreter::executeModalGroups(Error *error)
{
    const Block &b = m_block;
    if (b.hasG(kGPlane) && m_comp.on() && b.g[kGPlane] != m_plane)
        return failAt(ErrorCode::CompNotAllowed, b.gColumn[kGPlane], gName(b.g[kGPlane]), error);
    if (b.hasG(kGPlane))
        m_plane = b.g[kGPlane];
    if (b.hasG(kGUnits) && m_metric != (b.g[kGUnits] == 210)) {
        m_metric = b.g[kGUnits] == 210;
        m_unitsLine = m_line;
        m_unitsColumn = m_parser.columnAt(b.gColumn[kGUnits]);
    }
    if (b.hasG(kGCutterComp) && !(b.g[kGCutterComp] == 400 ? compOff(error) : compOn(error)))
        return false;
    if (!compAllows(error))
        return false;
    if (b.hasG(kGToolLength) && !toolLengthOffset(error))
        return false;
    if (b.hasG(kGCoordSystem)) {
        const int g = b.g[kGCoordSystem];
        const auto before = offsets();
        const double oldRotation = rotation();
        m_coord = g < 590 ? (g - 540) / 10 : 5 + (g - 590);
        shiftProgram(before, oldRotation);
    }
    if (b.hasG(kGPathControl)) {
        const int g = b.g[kGPathControl];
        m_pathMode = g == 610 ? 0 : g == 611 ? 1 : 2;
        m_pathP = g == 640 && b.has('p') ? lengthWord('p') : 0;
        m_pathQ = g == 640 && b.has('q') ? lengthWord('q') : 0;
        event(EventKind::PathMode, m_pathMode, m_pathP, m_pathQ);
    }
    if (b.hasG(kGDistance))
        m_absolute = b.g[kGDistance] == 900;
    if (b.hasG(kGArcDistance))
        m_arcAbsolute = b.g[kGArcDistance] == 901;
    if (b.hasG(kGRetract))
        m_retractToR = b.g[kGRetract] == 990;
    return true;
}

bool Interpreter::executeNonModal(Error *error)
{
    if (!m_block.hasG(kGNonModal))
        return true;
    const int g = m_block.g[kGNonModal];
    switch (g) {
    case 53:
        return nurbsEnd(error);
    case 100:
        return setOffsets(error);
    case 280:
    case 300:
        return homeMove(g == 300, error);
    case 281:
        m_g28 = {m_pos.x, m_pos.y, m_pos.z, m_pos.a};
        return true;
    case 301:
        m_g30 = {m_pos.x, m_pos.y, m_pos.z, m_pos.a};
        return true;
    case 920: {
        // rs274ngc: offset = current + offset - value, and the current position becomes value.
        double *prog = &m_prog.x;
        for (int i = 0; i < 4; ++i) {
            const char c = kAxisLetters[i];
            if (!m_block.has(c))
                continue;
            const double v = i < 3 ? lengthWord(c) : m_block.get(c);
            m_g92[i] = prog[i] + m_g92[i] - v;
            prog[i] = v;
        }
        m_g92Saved = m_g92;
        m_g92Enabled = true;
        return true;
    }
    case 921:
    case 922:
    case 923: {
        const auto before = offsets();
        m_g92 = g == 923 ? m_g92Saved : std::array<double, 4>{};
        if (g == 921)
            m_g92Saved = {};
        m_g92Enabled = g == 923;
        shiftProgram(before);
        return true;
    }
    default: // G4 (executed with the modes), G53 (with the motion)
        return true;
    }
}

bool Interpreter::setOffsets(Error *error)
{
    const Block &b = m_block;
    const std::uint32_t col = b.gColumn[kGNonModal];
    if (!b.has('l'))
        return failAt(ErrorCode::G10BadL, col, "without L", error);
    const double l = b.get('l');
    if (l == 1 || l == 10 || l == 11)
        return setToolEntry(static_cast<int>(l), error);
    if (l != 2 && l != 20)
        return fail(ErrorCode::G10BadL, 'l', "L" + std::to_string(l), error);
    if (!b.has('p'))
        return failAt(ErrorCode::G10BadP, col, "none", error);
    const double p = b.get('p');
    if (p < 0 || p > 9 || p != std::floor(p))
        return fail(ErrorCode::G10BadP, 'p', std::to_string(p), error);
    const int system = p == 0 ? m_coord : static_cast<int>(p) - 1;
    if (b.has('r') && l == 20)
        return fail(ErrorCode::WordNotUsed, 'r', "R", error); // rs274: R not allowed in G10 L20
    const double rotationDeg = b.has('r') ? b.get('r') : m_rotationDeg[system];
    const auto before = offsets();
    const auto active = m_origin[m_coord];
    const double oldRotation = rotation();
    const bool rotated = b.has('r') || m_rotationDeg[system] != 0;
    if (rotated) {
        // X and Y with the system's rotation (interp_rotation.cpp), then Z and A as below.
        if (system == m_coord && m_comp.on())
            return failAt(ErrorCode::CompNotAllowed, col, "G10 L2 R", error);
        setSystemXY(system, l == 20, rotationDeg);
    }
    const double *prog = &m_prog.x;
    for (int i = rotated ? 2 : 0; i < 4; ++i) {
        const char c = kAxisLetters[i];
        if (!b.has(c))
            continue;
        const double v = i < 3 ? lengthWord(c) : b.get(c);
        // L20: the offset that makes the current position read v.
        m_origin[system][i] = l == 2 ? v : prog[i] + active[i] - v;
    }
    if (system != m_coord)
        return true;
    if (oldRotation != 0 || rotation() != 0)
        carryActiveSystem(active, oldRotation);
    else
        shiftProgram(before);
    return true;
}

bool Interpreter::homeMove(bool g30, Error *error)
{
    (void)error;
    // Rapid to the intermediate point (program coordinates, G90/G91 honoured), then to the
    // stored position: all axes when none is given, else only the given ones.
    const Target mid = targetOf(false);
    m_toolpath.appendRapid(mid.machine, feedMm(), pathLine());
    moveTo(mid);
    const std::array<double, 4> &home = g30 ? m_g30 : m_g28;
    const bool all = !(m_block.letters & kAxisBits);
    double *p = &m_pos.x;
    double *prog = &m_prog.x;
    for (int i = 0; i < 4; ++i) {
        if (all || m_block.has(kAxisLetters[i])) {
            p[i] = home[i];
            prog[i] = home[i] - offset(i);
        }
    }
    if (rotation() != 0) {
        // rs274ngc's convert_home: the axes given take the stored point's program coordinates
        // in the turned system, so a G28 X0 moves machine Y as well.
        const Point4 homeProg = toProgram({home[0], home[1], home[2], home[3]});
        m_prog = mid.prog;
        for (int i = 0; i < 4; ++i) {
            if (all || m_block.has(kAxisLetters[i]))
                prog[i] = (&homeProg.x)[i];
        }
        m_pos = toMachine(m_prog);
    }
    m_toolpath.appendRapid(m_pos, feedMm(), pathLine());
    return true;
}

bool Interpreter::executeStops(Error *error)
{
    if (!m_block.hasM(kMStop))
        return true;
    const int m = m_block.m[kMStop];
    // The queued move ends where it is; M2 and M30 turn the compensation off.
    if (((m == 2 || m == 30) && !nurbsPending(-1, error)) || !compFlushHere(error) ||
        ((m == 2 || m == 30) && !compOff(error)))
        return false;
    if (m == 0) {
        event(EventKind::Pause);
    } else if (m == 1) {
        event(EventKind::OptionalPause);
    } else {
        event(EventKind::ProgramEnd);
        m_ended = true;
    }
    return true;
}

} // namespace frezka::gcode
