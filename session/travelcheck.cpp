#include "travelcheck.h"

#include "machine/softlimits.h"

#include <algorithm>
#include <limits>

namespace frezka::session {
namespace {

double coordinate(const gcode::Point4 &p, int axis)
{
    return axis == 0 ? p.x : axis == 1 ? p.y : axis == 2 ? p.z : p.a;
}

struct Bounds
{
    std::array<double, 4> min, max;
    bool any = false;
};

class Walker
{
public:
    Walker(const machine::MachineConfig &config, const gcode::Point4 &origin)
        : m_config(config)
        , m_origin(origin)
    {
        m_bounds.min.fill(std::numeric_limits<double>::infinity());
        m_bounds.max.fill(-std::numeric_limits<double>::infinity());
        m_own.min = m_bounds.min;
        m_own.max = m_bounds.max;
    }

    void visit(const gcode::Point4 &p, std::uint32_t line)
    {
        m_bounds.any = true;
        for (int a = 0; a < 4; ++a) {
            const machine::AxisConfig &axis = m_config.axes[std::size_t(a)];
            const double v = coordinate(p, a);
            m_bounds.min[std::size_t(a)] = std::min(m_bounds.min[std::size_t(a)], v);
            m_bounds.max[std::size_t(a)] = std::max(m_bounds.max[std::size_t(a)], v);
            if (m_moved[std::size_t(a)] || v != coordinate(m_origin, a)) {
                m_moved[std::size_t(a)] = m_own.any = true;
                m_own.min[std::size_t(a)] = std::min(m_own.min[std::size_t(a)], v);
                m_own.max[std::size_t(a)] = std::max(m_own.max[std::size_t(a)], v);
            }
            if (!axis.present || machine::withinSoftLimits(axis, v))
                continue;
            const bool above = v > axis.softMaxMm;
            note(a, above, line, v, above ? axis.softMaxMm : axis.softMinMm);
        }
    }

    TravelFit result() const
    {
        TravelFit fit;
        fit.moves = m_own.any;
        for (std::size_t a = 0; a < 4; ++a) { // an axis never moved: where it stands
            fit.minMm[a] = m_moved[a] ? m_own.min[a] : coordinate(m_origin, int(a));
            fit.maxMm[a] = m_moved[a] ? m_own.max[a] : coordinate(m_origin, int(a));
        }
        for (const auto &e : m_found)
            if (e.firstLine != 0)
                fit.excursions.push_back(e);
        std::stable_sort(fit.excursions.begin(), fit.excursions.end(),
                         [](const auto &l, const auto &r) { return l.firstLine < r.firstLine; });
        for (std::size_t a = 0; a < 4 && m_bounds.any; ++a) {
            const machine::AxisConfig &axis = m_config.axes[a];
            if (!axis.present)
                continue;
            const double lo = m_bounds.min[a], hi = m_bounds.max[a];
            if (hi - lo > axis.softMaxMm - axis.softMinMm + 1e-9)
                fit.fitsElsewhere = false;
            else if (hi > axis.softMaxMm)
                fit.shiftMm[a] = axis.softMaxMm - hi;
            else if (lo < axis.softMinMm)
                fit.shiftMm[a] = axis.softMinMm - lo;
        }
        return fit;
    }

private:
    void note(int axis, bool above, std::uint32_t line, double v, double limit)
    {
        TravelExcursion &e = m_found[std::size_t(axis * 2 + (above ? 1 : 0))];
        const double beyond = above ? v - limit : limit - v;
        if (e.firstLine == 0) {
            e = {axis, above, line, v, beyond, line, v, beyond, limit};
        } else if (beyond > e.farthestBeyondMm) {
            e.farthestLine = line;
            e.farthestValueMm = v;
            e.farthestBeyondMm = beyond;
        }
    }

    const machine::MachineConfig &m_config;
    gcode::Point4 m_origin; // where the program starts: the machine's position, not the program's
    Bounds m_bounds, m_own; // every motion's / the program's own (per axis from its first move)
    std::array<bool, 4> m_moved{};
    std::array<TravelExcursion, 8> m_found{};
};

} // namespace

TravelFit checkTravel(const gcode::Toolpath &path, const machine::MachineConfig &config)
{
    Walker walker(config, path.origin());
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (!path.isMotion(i))
            continue;
        if (path.kind(i) == gcode::MotionKind::Arc) {
            for (const gcode::Point4 &p : gcode::chordArc(path.start(i), path.end(i), path.arc(i)))
                walker.visit(p, path.line(i));
        } else {
            walker.visit(path.end(i), path.line(i));
        }
    }
    return walker.result();
}

} // namespace frezka::session
