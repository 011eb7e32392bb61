// LinuxCNC's polar coordinates: the @ (radius) and ^ (angle, degrees) words around the program
// origin in the XY plane, for straight moves, arcs and canned cycles (rs274ngc's find_ends and
// CYCLE_MACRO), with its errors.
#include "interpreter.h"

#include <cmath>
#include <numbers>

namespace frezka::gcode {

// LinuxCNC's polar coordinates (find_ends): @ radius and ^ angle (degrees) around the program
// origin in the XY plane; in G91 @ adds to the radius and ^ turns by the angle.
void Interpreter::polarTarget(Target *t) const
{
    const Block &b = m_block;
    const bool hasR = b.hasWord(Block::kRadius), hasA = b.hasWord(Block::kAngle);
    const double r = hasR ? b.value[Block::kRadius] * unit() : 0.0;
    const double a = hasA ? b.value[Block::kAngle] * std::numbers::pi / 180 : 0.0;
    double px = t->prog.x, py = t->prog.y;
    if (m_absolute) {
        const double radius = hasR ? r : std::hypot(py, px);
        const double theta = hasA ? a : std::atan2(py, px);
        px = radius * std::cos(theta);
        py = radius * std::sin(theta);
    } else {
        if (hasR) {
            const double theta = std::atan2(py, px), radius = std::hypot(py, px) + r;
            px = radius * std::cos(theta);
            py = radius * std::sin(theta);
        }
        if (hasA) {
            const double theta = std::atan2(py, px) + a, radius = std::hypot(py, px);
            px = radius * std::cos(theta);
            py = radius * std::sin(theta);
        }
    }
    t->prog.x = px;
    t->prog.y = py;
    t->machine.x = px + offset(0);
    t->machine.y = py + offset(1); // targetOf turns it when a rotation is set
}

bool Interpreter::polarCheck(Error *error) const
{
    const Block &b = m_block;
    const int word = b.hasWord(Block::kRadius) ? Block::kRadius : Block::kAngle;
    const std::uint32_t col = b.column[word];
    if (m_plane != 170)
        return failAt(ErrorCode::PolarNotAllowed, col, gName(m_plane), error);
    if (b.has('x') || b.has('y'))
        return failAt(ErrorCode::PolarNotAllowed, col, b.has('x') ? "X" : "Y", error);
    if (b.hasG(kGNonModal) && b.g[kGNonModal] == 530)
        return failAt(ErrorCode::PolarNotAllowed, col, "G53", error);
    const bool onlyRadius = !b.hasWord(Block::kAngle);
    if (m_prog.x == 0 && m_prog.y == 0 && (!m_absolute || onlyRadius) &&
        !(m_motionNext == 730 || (m_motionNext >= 810 && m_motionNext <= 890)))
        return failAt(ErrorCode::PolarNotAllowed, col, "X0 Y0", error);
    return true;
}

// G91 polar words in a cycle: each repeat adds @ to the radius and turns by ^ (LinuxCNC's
// CYCLE_MACRO).
bool Interpreter::cyclePolarStep(double *aa, double *bb, Error *error) const
{
    const Block &b = m_block;
    const int word = b.hasWord(Block::kRadius) ? Block::kRadius : Block::kAngle;
    if (*aa == 0 && *bb == 0)
        return failAt(ErrorCode::PolarNotAllowed, b.column[word], "X0 Y0", error);
    if (b.hasWord(Block::kRadius)) {
        const double theta = std::atan2(*bb, *aa);
        const double radius = std::hypot(*bb, *aa) + b.value[Block::kRadius] * unit();
        *aa = radius * std::cos(theta);
        *bb = radius * std::sin(theta);
    }
    if (b.hasWord(Block::kAngle)) {
        const double theta = std::atan2(*bb, *aa) + b.value[Block::kAngle] * std::numbers::pi / 180;
        const double radius = std::hypot(*bb, *aa);
        *aa = radius * std::cos(theta);
        *bb = radius * std::sin(theta);
    }
    return true;
}

} // namespace frezka::gcode
