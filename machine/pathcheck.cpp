// The path guard's geometry. See pathcheck.h.

#include "machine/pathcheck.h"

#include <algorithm>
#include <cmath>

namespace frezka::machine {

Steps4 plannedBefore(const UnitProgram &program, std::size_t index)
{
    return index == 0 ? program.startSteps
                      : program.commands.endSteps(std::min(index, program.commands.size()) - 1);
}

bool sameSteps(const Steps4 &a, const Steps4 &b, int axes)
{
    for (std::size_t i = 0; i < static_cast<std::size_t>(axes); ++i) {
        if (a[i] != b[i])
            return false;
    }
    return true;
}

std::optional<std::size_t> segmentHolding(const UnitProgram &program, std::size_t from,
                                          std::size_t to, const Steps4 &position)
{
    constexpr double kTolerance = 1.0 + 1e-9; // steps, per axis
    const auto &p = position;
    for (std::size_t i = from; i < to; ++i) {
        const UnitCommand &c = program.commands[i];
        if (c.op != UnitOp::Vector && c.op != UnitOp::Line && c.op != UnitOp::Probe)
            continue;
        // The part t of the segment (0..1) where every axis is within a step of the line.
        double t0 = 0, t1 = 1;
        for (std::size_t a = 0; a < static_cast<std::size_t>(program.axisCount) && t0 <= t1; ++a) {
            const double d = c.d[a];
            const double off = static_cast<double>(p[a] - (c.endSteps[a] - c.d[a]));
            if (d == 0) {
                if (std::abs(off) > kTolerance)
                    t0 = 2;
                continue;
            }
            double u0 = (off - kTolerance) / d, u1 = (off + kTolerance) / d;
            if (u0 > u1)
                std::swap(u0, u1);
            t0 = std::max(t0, u0);
            t1 = std::min(t1, u1);
        }
        if (t0 <= t1)
            return i;
    }
    return std::nullopt;
}

} // namespace frezka::machine
