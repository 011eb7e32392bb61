#include "lineapproach.h"

#include <algorithm>
#include <cmath>

namespace frezka::machine {
namespace {

constexpr double kSameMm = 1e-9;

bool same(const gcode::Point4 &a, const gcode::Point4 &b)
{
    return std::abs(a.x - b.x) < kSameMm && std::abs(a.y - b.y) < kSameMm &&
           std::abs(a.z - b.z) < kSameMm && std::abs(a.a - b.a) < kSameMm;
}

} // namespace

double approachSafeZ(const MachineConfig &config, const gcode::Toolpath &program,
                     const gcode::Point4 &fromMm, const gcode::Point4 &toMm)
{
    double top = toMm.z + config.motion.toolLiftMm;
    for (std::size_t i = 0; i < program.size(); ++i) {
        if (program.isMotion(i)) // events stand where the machine is (before the first move:
            top = std::max(top, program.end(i).z); // wherever it started)
    }
    top = std::min(top, config.axis(Axis::Z).softMaxMm);
    return std::max(top, fromMm.z);
}

std::vector<ApproachMove> lineApproach(const gcode::Point4 &fromMm, const gcode::Point4 &toMm,
                                       double safeZMm)
{
    std::vector<ApproachMove> moves;
    gcode::Point4 at = fromMm;
    auto move = [&](const gcode::Point4 &to, bool feed) {
        if (!same(at, to))
            moves.push_back({to, feed});
        at = to;
    };
    const double lift = std::max(safeZMm, fromMm.z);
    move({at.x, at.y, lift, at.a}, false);
    move({toMm.x, toMm.y, lift, toMm.a}, false);
    move(toMm, toMm.z < lift);
    return moves;
}

} // namespace frezka::machine
