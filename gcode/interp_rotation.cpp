// Coordinate-system rotation (LinuxCNC's G10 L2 P.. R..): each of G54..G59.3 has an angle
// (degrees, counter-clockwise, #5230, #5250, ...) about Z. As rs274ngc and its canon do it,
// the XY plane of the program turns with the G92 offset inside it, the work offset and the tool
// offset outside:
//
//   machine.xy = rotate(program.xy + g92.xy, R) + origin.xy + tool.xy
//   machine.z  = program.z + g92.z + origin.z + tool.z          (A the same way)
//
// Every point the interpreter sends (ends, arc centres, cycle and polar points, G53 and G28
// points read back) goes through toMachine/toProgram; without a rotation they are the plain
// sums of offset(). Arcs outside G17 and cutter radius compensation under a rotation are
// refused (the toolpath has no tilted arc planes; compensation's geometry is in the program
// plane and is not carried through the turn).
#include "interpreter.h"

#include <cmath>
#include <numbers>

namespace frezka::gcode {

namespace {

void rotate(double *x, double *y, double degrees)
{
    const double t = degrees * std::numbers::pi / 180.0;
    const double c = std::cos(t), s = std::sin(t);
    const double xx = *x * c - *y * s;
    *y = *x * s + *y * c;
    *x = xx;
}

} // namespace

Point4 Interpreter::toMachine(const Point4 &prog) const
{
    const double r = rotation();
    if (r == 0)
        return {prog.x + offset(0), prog.y + offset(1), prog.z + offset(2), prog.a + offset(3)};
    double x = prog.x + m_g92[0], y = prog.y + m_g92[1];
    rotate(&x, &y, r);
    return {x + m_origin[m_coord][0] + m_toolOffset[0], y + m_origin[m_coord][1] + m_toolOffset[1],
            prog.z + offset(2), prog.a + offset(3)};
}

Point4 Interpreter::toProgram(const Point4 &machine) const
{
    const double r = rotation();
    if (r == 0)
        return {machine.x - offset(0), machine.y - offset(1), machine.z - offset(2),
                machine.a - offset(3)};
    double x = machine.x - m_origin[m_coord][0] - m_toolOffset[0];
    double y = machine.y - m_origin[m_coord][1] - m_toolOffset[1];
    rotate(&x, &y, -r);
    return {x - m_g92[0], y - m_g92[1], machine.z - offset(2), machine.a - offset(3)};
}

Point4 Interpreter::turnedCentre(double cu, double cv) const
{
    const Point4 c = toMachine({cu, cv, m_prog.z, m_prog.a});
    return {c.x, c.y, m_pos.z, m_pos.a}; // the normal coordinate is the start's (ArcInfo)
}

void Interpreter::shiftProgram(const std::array<double, 4> &oldOffsets, double oldRotationDeg)
{
    if (oldRotationDeg != 0 || rotation() != 0) {
        m_prog = toProgram(m_pos); // rs274ngc's find_current_in_system
        return;
    }
    shiftProgram(oldOffsets);
}

// G10 L2/L20 with the rotation of the system (rs274ngc's convert_setup): L20's X and Y are
// read in the rotated system; when the active system changes, the current point is carried
// over as rs274ngc does (rotated back without the G92 offset, then into the new system).
void Interpreter::setSystemXY(int system, bool l20, double rotationDeg)
{
    const Block &b = m_block;
    auto &origin = m_origin[system];
    if (l20) {
        // The point the current position has in that system, and where the program wants it.
        Point4 current = m_prog;
        if (system != m_coord) {
            const int active = m_coord;
            m_coord = system;
            current = toProgram(m_pos);
            m_coord = active;
        }
        double oldx = current.x, oldy = current.y;
        double x = b.has('x') ? lengthWord('x') : oldx, y = b.has('y') ? lengthWord('y') : oldy;
        rotate(&oldx, &oldy, rotationDeg);
        rotate(&x, &y, rotationDeg);
        origin[0] += oldx - x;
        origin[1] += oldy - y;
    } else {
        if (b.has('x'))
            origin[0] = lengthWord('x');
        if (b.has('y'))
            origin[1] = lengthWord('y');
    }
    m_rotationDeg[system] = rotationDeg;
}

void Interpreter::carryActiveSystem(const std::array<double, 4> &oldOrigin, double oldRotationDeg)
{
    // rs274ngc: rotate(current, old R); += old origin; -= new origin; rotate(current, -new R).
    double x = m_prog.x, y = m_prog.y;
    rotate(&x, &y, oldRotationDeg);
    x += oldOrigin[0] - m_origin[m_coord][0];
    y += oldOrigin[1] - m_origin[m_coord][1];
    rotate(&x, &y, -rotation());
    m_prog.x = x;
    m_prog.y = y;
    m_prog.z += oldOrigin[2] - m_origin[m_coord][2];
    m_prog.a += oldOrigin[3] - m_origin[m_coord][3];
}

bool Interpreter::rotationAllows(int motion, Error *error) const
{
    if (rotation() == 0)
        return true;
    const std::uint32_t col = m_block.hasG(kGMotion) ? m_block.gColumn[kGMotion] : 0;
    if (m_comp.on()) // a system with a rotation chosen while compensating
        return failAt(ErrorCode::UnsupportedRotation, col, "G41/G42", error);
    const bool arcMove = motion == 20 || motion == 30;
    if (arcMove && m_plane != 170)
        return failAt(ErrorCode::UnsupportedRotation, col, gName(m_plane), error);
    return true;
}

} // namespace frezka::gcode
