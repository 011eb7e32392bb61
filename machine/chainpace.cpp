// The chain planner's link pace: vectors that last at least their bytes on the wire, the
// speeds the pace shares, and flat caps where B commands would cost the link as much as the
// vectors (docs/planner.md §4). Part of RunPlanner (chainplanner_internal.h).
#include "machine/chainplanner_internal.h"

#include <algorithm>
#include <cmath>

namespace frezka::machine::detail {

// The link's pace (PlanOptions::wireLimited): a vector must last at least the time its bytes
// take on the wire, or the unit's queue runs dry mid-chain and the machine stops without
// braking. Its bytes: the largest vector of its neighbourhood, and the neighbourhood's B
// commands on average. Within a vector the unit accelerates from its entry B toward V and
// brakes to its exit B, so its fastest speed is at most sqrt((b0² + b1²) / 2 + A·L):
// capping both Bs at sqrt((L/t)² - A·L) keeps it at L/t. Where even that is below the
// unit's smallest B (a vector of a step or two), V itself is lowered, which costs a V
// command (rare). The bound takes the floor as a cruise cap.
void RunPlanner::wirePace()
{
    if (!m_options.wireLimited || m_config.link.baud <= 0)
        return;
    const std::size_t n = m_d.size();
    std::vector<bool> lowered(n, false); // V itself lowered to keep the pace
    // Prefix sums of the B, V and A commands' link time for their averages.
    std::vector<double> extraPrefix(n + 1, 0.0);
    for (std::size_t k = 0; k < n; ++k)
        extraPrefix[k + 1] = extraPrefix[k] + (m_extraS.size() == n ? m_extraS[k] : 0);
    for (std::size_t k = 0; k < n; ++k) {
        Derived &r = m_d[k];
        const std::size_t from = k > m_link.wireWindow() ? k - m_link.wireWindow() : 0;
        const std::size_t to = std::min(n, k + m_link.wireWindow() + 1);
        double widest = 0;
        for (std::size_t j = from; j < to; ++j)
            widest = std::max(widest, m_d[j].wireBytes);
        const std::size_t bFrom = k > m_link.brakeWindow() ? k - m_link.brakeWindow() : 0;
        const std::size_t bTo = std::min(n, k + m_link.brakeWindow() + 1);
        const double span = static_cast<double>(bTo - bFrom);
        const double wireS =
            m_link.vectorWireS(widest) + (extraPrefix[bTo] - extraPrefix[bFrom]) / span;
        const double fastest = r.units / wireS; // units/s
        r.vMm = std::min(r.vMm, fastest / r.f);
        if (fastest >= static_cast<double>(std::min(r.speed, r.ownSpeed)))
            continue;
        const double room = fastest * fastest - static_cast<double>(r.accel) * 1000.0 * r.units;
        if (room >= static_cast<double>(kMinSpeed * kMinSpeed))
            r.wireCap = std::floor(std::sqrt(room));
        else {
            r.speed = std::clamp<std::int64_t>(static_cast<std::int64_t>(floorUnits(fastest)),
                                               kMinSpeed, r.speed);
            lowered[k] = true;
        }
    }
    sharePacedSpeeds(lowered);
}

// Where the pace lowers V itself, each vector's own V differs from its neighbours' by a few
// units (its window's bytes differ a little), and every V is a round trip outside the
// packets: a slow plunge of two-step vectors sent a V before nearly every vector and the
// unit ran dry at each (property seed 29). A stretch from such a vector shares its least V
// while the time that costs stays below the V commands it saves; vectors the pace did not
// lower join it on the same terms (a plunge that alternates one- and two-step vectors
// lowers only every other V), but the stretch ends at its last lowered vector. A lower V
// only lengthens a vector, so the pace holds; the vertex caps follow V (vertexCaps).
void RunPlanner::sharePacedSpeeds(const std::vector<bool> &lowered)
{
    const double penalty = m_options.speedChangeCost * m_link.modalChangeS();
    const std::size_t n = m_d.size();
    std::size_t k = 0;
    while (k < n) {
        if (!lowered[k]) {
            ++k;
            continue;
        }
        std::int64_t level = m_d[k].speed;
        double units = m_d[k].units;
        double owned = units / static_cast<double>(level);
        std::size_t changes = 0;     // V commands the stretch saves
        std::size_t lastLowered = k; // its last vector the pace lowered
        for (std::size_t j = k + 1; j < n; ++j) {
            const Derived &r = m_d[j];
            const std::int64_t lower = std::min(level, r.speed);
            changes += r.speed != m_d[j - 1].speed ? 1 : 0;
            const double own = r.units / static_cast<double>(r.speed);
            const double loss = (units + r.units) / static_cast<double>(lower) - (owned + own);
            if (loss > penalty * static_cast<double>(changes))
                break;
            level = lower;
            units += r.units;
            owned += own;
            lastLowered = lowered[j] ? j : lastLowered;
        }
        level = m_d[k].speed;
        for (std::size_t j = k + 1; j <= lastLowered; ++j)
            level = std::min(level, m_d[j].speed);
        for (; k <= lastLowered; ++k) {
            Derived &r = m_d[k];
            r.speed = level;
            r.vMm = std::min(r.vMm, static_cast<double>(level) / r.f); // the bound follows
        }
    }
}

// Where the vectors are about as short as their bytes on the wire, a B that changes at every
// vertex (the caps of a wavy path do) costs the link nearly as much as the vector itself, and
// the link's pace then halves the speed. There the caps are flattened to the least one within
// kFlatWindow vertices either side: a stretch runs at one B and sends no B inside it.
void RunPlanner::flattenTightCaps()
{
    if (!m_options.wireLimited || m_config.link.baud <= 0 || m_capUnits.size() < 2)
        return;
    const std::size_t vertices = m_capUnits.size() - 1;
    std::vector<bool> tight(vertices, false);
    for (std::size_t k = 0; k < vertices; ++k) {
        const double cap = static_cast<double>(m_capUnits[k]);
        // With a B before it (B at most V, so at most V's bytes).
        const double withBrake = m_link.vectorWireS(m_d[k].wireBytes) +
                                 m_link.commandS(m_link.brakeWireBytes(m_d[k].speed));
        tight[k] = cap >= kMinSpeed && m_d[k].units < cap * withBrake;
    }
    const std::vector<std::int64_t> caps(m_capUnits.begin(), m_capUnits.end() - 1);
    for (std::size_t k = 0; k < vertices; ++k) {
        if (!tight[k])
            continue;
        std::int64_t least = caps[k];
        for (std::size_t j = k; j > 0 && k - j < kFlatWindow && tight[j - 1]; --j)
            least = std::min(least, caps[j - 1]);
        for (std::size_t j = k + 1; j < vertices && j - k <= kFlatWindow && tight[j]; ++j)
            least = std::min(least, caps[j]);
        m_capUnits[k] = least;
    }
}

} // namespace frezka::machine::detail
