// The chain planner's vertex caps (junction deviation, curvature, the axes' speed steps) and
// the plan's vertex statistics (docs/planner.md §3). Part of RunPlanner (chainplanner_internal.h).
#include "machine/chainplanner_internal.h"

#include <algorithm>
#include <cmath>

namespace frezka::machine::detail {

// Junction-deviation and curvature caps of the path speed at the vertex after move k, mm/s;
// chordMm: the shorter of the two segments.
void RunPlanner::pathCaps(std::size_t k, const Vec4 &u0, const Vec4 &u1, double chordMm, double &jd,
                          double &curv) const
{
    const double cosTheta = -dot(u0, u1);
    jd = kInf;
    curv = kInf;
    if (cosTheta < -0.999999)
        return; // straight on
    if (cosTheta > 0.999999) {
        jd = curv = 0; // reversal
        return;
    }
    Vec4 j{};
    for (int i = 0; i < 4; ++i)
        j[i] = u1[i] - u0[i];
    j = normalized(j);
    double aj = kInf;
    for (int i = 0; i < 4; ++i) {
        if (std::abs(j[i]) > 1e-12)
            aj = std::min(aj,
                          m_config.axes[static_cast<std::size_t>(i)].accelMmPerS2 / std::abs(j[i]));
    }
    const double sinHalfTheta = std::sqrt(0.5 * (1 - cosTheta));
    jd = std::sqrt(aj * m_moves.modes(k + 1).junctionDeviationMm * sinHalfTheta /
                   (1 - sinHalfTheta));
    const double sinHalfPhi = std::sqrt(0.5 * (1 + cosTheta)); // φ: the turn angle
    curv = std::sqrt(aj * chordMm / (2 * sinHalfPhi));
}

// The caps at the vertex after move k that only its two directions set (derive(), once per
// run): junction deviation, curvature and the axes' speed steps on the scalar speed, and
// whether passing it at the unit's smallest speed keeps every axis's speed step within its
// limit (else the queue must drain there: a real stop).
void RunPlanner::vertexGeometry(std::size_t k, const Directions &a, const Directions &b)
{
    const double fMin = std::min(m_d[k].f, m_d[k + 1].f);
    const double chord = std::min(a.pathLengthMm, b.pathLengthMm);
    double jd = 0, curv = 0;
    pathCaps(k, a.uPath, b.uPath, chord, jd, curv);
    double units = std::min(jd, curv) * fMin;
    bool soft = true;
    for (int i = 0; i < 4; ++i) {
        // A speed step of rounding size is none (collinear vectors of different lengths give
        // 1e-19, and an axis whose jump limit is 0 would rest there).
        const double per = jumpPerUnit(k, a, b, i);
        const double limit = m_config.axes[static_cast<std::size_t>(i)].maxJumpMmPerS;
        if (per > 1e-15) {
            units = std::min(units, limit / per);
            soft = soft && !(kMinSpeed * per > limit);
        }
    }
    m_geoCap[k] = units;
    m_softStop[k] = soft;
    if (m_options.strategy == PlanStrategy::GrblJunction && !m_options.grblKeepsAllLimits) {
        // grbl's own caps: geometry of the steps, no curvature, no speed steps (unless the
        // baseline is asked to keep every limit of the full plan: then it differs from the full
        // plan only by its short lookahead).
        pathCaps(k, a.uStep, b.uStep, chord, jd, curv);
        m_planGeoCap[k] = jd * fMin;
    }
}

// The bound's cap at the vertex after move k: the same limits on a continuous speed in the
// unit's own speed units (the scalar the unit carries across a vertex), without the plan's
// integers, its V sharing or its flattening (docs/planner.md §7).
double RunPlanner::boundCap(std::size_t k) const
{
    if (m_stopAfter[k])
        return 0; // the program asks for a stop here
    const Derived &a = m_d[k];
    const Derived &b = m_d[k + 1];
    double units = std::min({a.vMm * a.f, b.vMm * b.f, m_geoCap[k]});
    // The unit moves at 10 pulses/s at least: a corner whose geometric caps lie below that is
    // passed at that speed where the jump limits allow it, by any plan (planOnce's soft stop);
    // a crawl below it is no plan this unit can run (property seed 72 lay 8 % above the plan).
    if (units < kMinSpeed && softStopAllowed(k))
        units = kMinSpeed;
    return units;
}

// The plan's vertex statistics, once for the run's final plan: the directions are derived again
// from the moves (two at a time) rather than kept for every move.
void RunPlanner::jumpStats()
{
    const std::size_t n = m_out.vectors.size();
    if (n < 2)
        return;
    Directions a = directions(m_moves[0]);
    for (std::size_t k = 0; k + 1 < n; ++k) {
        const Directions b = directions(m_moves[k + 1]);
        const PlannedVector &v = m_out.vectors[k];
        if (!v.chainEnd) {
            bool over = false;
            for (int i = 0; i < 4; ++i) {
                const double jump = static_cast<double>(v.brake) * jumpPerUnit(k, a, b, i);
                const double limit = m_config.axes[static_cast<std::size_t>(i)].maxJumpMmPerS;
                m_out.maxJumpMmPerS = std::max(m_out.maxJumpMmPerS, jump);
                // A jump below a nanometre per second is rounding noise, not a step (limit 0:
                // none allowed).
                const double ratio = limit > 0 ? jump / limit : (jump > 1e-9 ? kInf : 0);
                m_out.maxJumpRatio = std::max(m_out.maxJumpRatio, ratio);
                over = over || ratio > 1 + 1e-9;
            }
            m_out.jumpOverLimit += over ? 1 : 0;
            curveStats(k, a, b, static_cast<double>(v.brake));
        }
        a = b;
    }
}

// The axes' acceleration through the turn at the vertex after move k, as the intended path
// turns: each axis's speed changes by v·Δu_i over the time between the two segments'
// middles, (L_k + L_k+1) / 2v. On a chorded arc that is v²/r per unit of turn direction.
void RunPlanner::curveStats(std::size_t k, const Directions &a, const Directions &b, double brake)
{
    const double v = brake / std::min(m_d[k].f, m_d[k + 1].f); // the faster side, mm/s
    const double span = 0.5 * (a.pathLengthMm + b.pathLengthMm);
    bool over = false;
    for (int i = 0; i < 4; ++i) {
        const double accel = v * v * std::abs(b.uPath[i] - a.uPath[i]) / span;
        const double ratio = accel / m_config.axes[static_cast<std::size_t>(i)].accelMmPerS2;
        m_out.maxCurveAccelRatio = std::max(m_out.maxCurveAccelRatio, ratio);
        over = over || ratio > 1 + 1e-6;
    }
    m_out.curveAccelOverLimit += over ? 1 : 0;
}

} // namespace frezka::machine::detail
