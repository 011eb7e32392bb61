// The chain planner's link pace: vectors that last at least their bytes on the wire, the
// speeds the pace shares, and flat caps where B commands would cost the link as much as the
// vectors (docs/planner.md §4). Part of RunPlanner (chainplanner_internal.h).
#include "machine/chainplanner_internal.h"
#include "machine/modalchoice.h"

#include <algorithm>
#include <array>
#include <cmath>

namespace frezka::machine::detail {

namespace {
// paceModalChanges: how many times a stretch is slowed toward the time a change needs (from rest
// a lower V lengthens the acceleration less than the cruise, so one step may fall short).
constexpr int kSlowTries = 4;
} // namespace

// Move k as derive() left it, before the link's pace and the modal choices of a plan change it.
void RunPlanner::restart(std::size_t k)
{
    const PaceStart &from = m_paceStart[k];
    Derived &r = m_d[k];
    r.vMm = from.vMm;
    r.wireCap = kNoCap;
    r.speed = from.speed;
    if (r.accel != from.accel) // twoAU follows A and the move's length (setAccel): as A, so it
        setAccel(r, from.accel, m_options);
}

// The link's pace (PlanOptions::wireLimited): a vector must last at least the time its bytes
// take on the wire, or the unit's queue runs dry mid-chain and the machine stops without
// braking. Its bytes: the largest vector of its neighbourhood, and the neighbourhood's B
// commands on average. Within a vector the unit accelerates from its entry B toward V and
// brakes to its exit B, so its fastest speed is at most sqrt((b0² + b1²) / 2 + A·L):
// capping both Bs at sqrt((L/t)² - A·L) keeps it at L/t. Where even that is below the
// unit's smallest B (a vector of a step or two), V itself is lowered, which costs a V
// command (rare). The bound takes the floor as a cruise cap.
//
// Each move starts again here from what derive() left it (m_paceStart) before the pace takes it:
// one walk over the moves' figures instead of two, in each of the run's plans.
void RunPlanner::wirePace()
{
    const std::size_t n = m_d.size();
    if (!m_options.wireLimited || m_config.link.baud <= 0) {
        for (std::size_t k = 0; k < n; ++k)
            restart(k);
        return;
    }
    std::vector<bool> lowered(n, false); // V itself lowered to keep the pace
    // Prefix sums of the B, V and A commands' link time for their averages.
    std::vector<double> &extraPrefix = m_scratch;
    extraPrefix.resize(n + 1); // every sum written below: no zeroing walk first
    extraPrefix[0] = 0;
    for (std::size_t k = 0; k < n; ++k)
        extraPrefix[k + 1] = extraPrefix[k] + (m_extraS.size() == n ? m_extraS[k] : 0);
    const std::size_t window = m_link.brakeWindow();
    for (std::size_t k = 0; k < n; ++k) {
        restart(k);
        Derived &r = m_d[k];
        const std::size_t bFrom = k > window ? k - window : 0;
        const std::size_t bTo = std::min(n, k + window + 1);
        const double span = static_cast<double>(bTo - bFrom);
        const double wireS =
            m_link.vectorWireS(r.widestBytes) + (extraPrefix[bTo] - extraPrefix[bFrom]) / span;
        const double fastest = r.units / wireS; // units/s
        r.vMm = std::min(r.vMm, fastest / r.f);
        if (fastest >= static_cast<double>(std::min(r.speed, r.ownSpeed)))
            continue;
        const double room = fastest * fastest - static_cast<double>(r.accel) * 1000.0 * r.units;
        if (room >= static_cast<double>(kMinSpeed * kMinSpeed))
            r.wireCap = static_cast<std::int32_t>(std::floor(std::sqrt(room))); // below V
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
// only lengthens a vector, so the pace holds; the vertex caps follow V (vertexCap).
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
            const std::int64_t lower = std::min<std::int64_t>(level, r.speed);
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
            level = std::min<std::int64_t>(level, m_d[j].speed);
        for (; k <= lastLowered; ++k) {
            Derived &r = m_d[k];
            r.speed = level;
            r.vMm = std::min(r.vMm, static_cast<double>(level) / r.f); // the bound follows
        }
    }
}

// Where V or A changes inside a chain, the packets stop while the change's own round trip goes
// out (V and A cannot travel in a packet, docs/gve-protocol.md §2.2), then the packet with the
// next vectors follows: meanwhile the unit runs on what it holds (the job streams before it
// polls, and the pace's margins pay for the polls, §4). At a chain's start it holds only what went
// out since the rest, so a chain of a few short vectors with a V or an A between them ran dry at
// nearly every change (property seed 4, GVE84 at 9.6 ms: V4925, V9230 and V3220 over three vectors
// of a Z plunge, 24 starvation stops in the job). The walk follows the motion the unit holds (each
// vector at least its cruise time, units / V; the link's pace keeps it at least its wire time) and
// where a change would find too little, the stretch before it runs slower, by just the time
// missing; the queue holds at most its capacity of vectors. The cost is bounded by the round trips
// per change, and only where a stretch is shorter than them.
void RunPlanner::paceModalChanges()
{
    if (!m_options.wireLimited || m_config.link.baud <= 0 ||
        m_options.strategy != PlanStrategy::Full)
        return;
    const std::size_t n = m_d.size();
    const std::size_t queue = m_link.queueVectors();
    // Prefix sums of the vectors' cruise times, each written as the walk reaches it.
    std::vector<double> &timeS = m_scratch;
    timeS.resize(n + 1);
    timeS[0] = 0;
    auto cruise = [this](std::size_t j) {
        return m_d[j].units / static_cast<double>(std::max<std::int64_t>(m_d[j].speed, 1));
    };
    // The time of stretch [a, b): from rest at least its acceleration (cruise alone under-counts
    // it, and the stretch was slowed more than it needed).
    auto stretchS = [&](std::size_t a, std::size_t b) {
        return m_d[a].restBefore ? fromRestS(timeS[b] - timeS[a], a, b) : timeS[b] - timeS[a];
    };
    double held = 0; // motion the unit holds when stretch [first, k) has gone out
    std::size_t first = 0;
    // The stretch's wire time: a round trip and its vectors' bare wire times, summed in their
    // order as the walk passes them (not again over the stretch when it closes: a run without a
    // change is one stretch, and that was a second walk over all its moves).
    double wire = m_link.roundTripS();
    for (std::size_t k = 0; k <= n; ++k) {
        if (k > 0)
            wire += m_link.bareVectorWireS(m_d[k - 1].wireBytes);
        if (k < n)
            timeS[k + 1] = timeS[k] + cruise(k);
        const bool chainStart = k < n && k > 0 && !softStopAllowed(k - 1);
        const bool changes = k < n && k > 0 &&
                             (m_d[k].speed != m_d[k - 1].speed || m_d[k].accel != m_d[k - 1].accel);
        if (k > first && (k == n || chainStart || changes)) {
            // Stretch [first, k) has gone out: the unit gained its motion less its wire time,
            // and the packet cut short at the change costs a round trip of its own.
            const std::size_t from = k > queue ? k - queue : 0;
            held = std::min(held + stretchS(first, k) - wire, timeS[k] - timeS[from]);
            held = std::max(held, 0.0);
            if (k < n && changes && !chainStart) {
                const int commands = (m_d[k].speed != m_d[k - 1].speed ? 1 : 0) +
                                     (m_d[k].accel != m_d[k - 1].accel ? 1 : 0);
                // The packet after the change must arrive (LinkTiming::changeLeadS).
                const double need = commands * m_link.modalChangeS() +
                                    m_link.changeLeadS(static_cast<double>(m_d[k].wireBytes));
                if (held < need) {
                    // Either the stretch before runs slower by the time missing, or the two
                    // stretches share one V and A (no change to send): whichever costs less.
                    if (mergeCostS(first, k, need - held) <= need - held) {
                        mergeStretches(first, k);
                        for (std::size_t j = first; j <= k; ++j)
                            timeS[j + 1] = timeS[j] + cruise(j);
                        continue; // one stretch now, going on past k
                    }
                    // What slowing gains is measured as the stretch's own time: from rest
                    // that is its acceleration, which a lower V lengthens less than its cruise
                    // (property seed 95: a chain's first vector counted 40 ms it did not gain,
                    // and the unit ran dry behind the V after it).
                    for (int tries = 0; tries < kSlowTries && held < need; ++tries) {
                        // From rest the stretch may last longer than its cruise time: the
                        // cruise must outlast that (seed 343: V 589 -> 209 gained nothing on a
                        // vector that never reached either).
                        const double before = stretchS(first, k);
                        slowStretch(first, k, need - held + before - (timeS[k] - timeS[first]));
                        // Through k: timeS[k + 1] was summed from the old timeS[k], and
                        // every later stretch's time would lack what this one gained (the
                        // walk then found nothing held at each change and slowed every
                        // stretch of the bundled engrave at 19 200 Bd, each by more).
                        for (std::size_t j = first; j <= k && j < n; ++j)
                            timeS[j + 1] = timeS[j] + cruise(j);
                        const double gained = stretchS(first, k) - before;
                        if (!(gained > 0))
                            break;
                        held += gained;
                    }
                }
                held = std::max(0.0, held - commands * m_link.modalChangeS()); // spent on them
            }
            first = k;
            wire = m_link.roundTripS();
        }
        if (chainStart)
            held = 0;
    }
}

// The end of the stretch that begins at k: the vectors after it with its V and A, within the
// chain.
std::size_t RunPlanner::stretchEnd(std::size_t k) const
{
    std::size_t end = k + 1;
    while (end < m_d.size() && softStopAllowed(end - 1) && m_d[end].speed == m_d[k].speed &&
           m_d[end].accel == m_d[k].accel)
        ++end;
    return end;
}

// What running the stretches [first, k) and the one from k at one V and one A (the lesser of
// each) costs in time: cruise at the lower V, and for a lower A the estimate of chooseAccels
// (each vector as if all acceleration, t ~ 1/sqrt(A)), or, where more, each vector's time
// between the fastest speeds its corners allow (vectorTimeS) at the shared V and A less at its
// own. The first alone counted nothing where the corners are slow and the vectors never reach V
// (property seed 157: A 1 merged over vectors whose own was 5, each twice as long); the second
// alone misses what a lower A costs the corners of a chain of short vectors (the bundled engrave
// 0.3 % slower). Summed only until it exceeds limitS (the caller asks whether it stays within).
double RunPlanner::mergeCostS(std::size_t first, std::size_t k, double limitS) const
{
    const std::size_t end = stretchEnd(k);
    const double v = static_cast<double>(std::min(m_d[first].speed, m_d[k].speed));
    const double a = static_cast<double>(std::min(m_d[first].accel, m_d[k].accel));
    double cost = 0;
    for (std::size_t j = first; j < end; ++j) {
        const Derived &r = m_d[j];
        const double own = r.units / static_cast<double>(r.speed);
        const double slower = r.units / v;
        const double scaled = slower * std::sqrt(static_cast<double>(r.accel) / a) - own;
        const double paced = r.vMm * r.f; // the link's pace, as wirePace left it
        const double between = vectorTimeS(m_d, m_geoCap, j, static_cast<std::int64_t>(v),
                                           static_cast<std::int64_t>(a), paced) -
                               vectorTimeS(m_d, m_geoCap, j, r.speed, r.accel, paced);
        cost += std::max(scaled, between);
        if (cost > limitS)
            break; // each term is at least 0: the merge costs more than the limit already
    }
    return cost;
}

void RunPlanner::mergeStretches(std::size_t first, std::size_t k)
{
    const std::size_t end = stretchEnd(k);
    const std::int64_t v = std::min(m_d[first].speed, m_d[k].speed);
    const std::int64_t a = std::min(m_d[first].accel, m_d[k].accel);
    for (std::size_t j = first; j < end; ++j) {
        m_d[j].speed = v;
        if (m_d[j].accel != a)
            setAccel(m_d[j], a, m_options);
    }
}

// How long vectors [first, last), one V and one A, from rest, keep the unit moving before it must
// begin to brake to a stop if nothing more arrives: what the next packet must beat. Up to V and
// down again the brake point is where half the distance is covered, sqrt(units / A) from the
// start; where the vectors reach V it lies units / V from the start (cruiseS: at V throughout).
// Not the time to their end: a chain's first vector of six steps from rest braked from its
// midpoint, and the vector after the V and A behind it arrived 5 ms after that (property seed
// 343, a stop at nearly every chain's start once the A and V were no longer merged there).
double RunPlanner::fromRestS(double cruiseS, std::size_t first, std::size_t last) const
{
    double units = 0;
    for (std::size_t j = first; j < last; ++j)
        units += m_d[j].units;
    const double a = 1000.0 * static_cast<double>(std::max<std::int64_t>(m_d[first].accel, 1));
    const double v = static_cast<double>(std::max<std::int64_t>(m_d[first].speed, 1));
    const double t = units < v * v / a ? std::sqrt(units / a) : units / v;
    return std::max(cruiseS, t);
}

// Lowers the V of vectors [first, last) so that they last `missingS` longer at cruise; returns
// the time gained (less where V reaches the unit's smallest speed).
double RunPlanner::slowStretch(std::size_t first, std::size_t last, double missingS)
{
    double units = 0, now = 0;
    for (std::size_t j = first; j < last; ++j) {
        units += m_d[j].units;
        now += m_d[j].units / static_cast<double>(m_d[j].speed);
    }
    const std::int64_t level = std::max<std::int64_t>(
        kMinSpeed, static_cast<std::int64_t>(std::floor(units / (now + missingS))));
    double gained = -now;
    for (std::size_t j = first; j < last; ++j) {
        Derived &r = m_d[j];
        r.speed = static_cast<std::int32_t>(std::min<std::int64_t>(r.speed, level));
        gained += r.units / static_cast<double>(r.speed);
    }
    return std::max(0.0, gained);
}

// The plan's B cap at the vertex after move k, speed units (0 where the program stops there).
// Here beside its one caller, capVertices, which takes it at every vertex of every plan.
inline std::int32_t RunPlanner::vertexCap(std::size_t k) const
{
    const Derived &a = m_d[k];
    const Derived &b = m_d[k + 1];
    if (m_stopAfter[k] || m_options.strategy == PlanStrategy::ExactStop)
        return 0; // the program asks for a stop here (or every vertex is one)
    double units = static_cast<double>(std::min(a.speed, b.speed));
    units = std::min(units, m_planGeoCap.empty() ? m_geoCap[k] : m_planGeoCap[k]);
    units = std::min({units, static_cast<double>(a.wireCap),
                      static_cast<double>(b.wireCap)}); // the link's pace (kNoCap: off)
    units = std::min({units, static_cast<double>(a.speedCap),
                      static_cast<double>(b.speedCap)}); // V above a vector's own cap
    return static_cast<std::int32_t>(floorUnits(units)); // units <= V <= the pulse rate
}

// Where the vectors are about as short as their bytes on the wire, a B that changes at every
// vertex (the caps of a wavy path do) costs the link nearly as much as the vector itself, and
// the link's pace then halves the speed. There the caps are flattened to the least one within
// kFlatWindow vertices either side: a stretch runs at one B and sends no B inside it. The vertex
// caps themselves (vertexCap) are taken in the same walk that finds the tight vertices.
void RunPlanner::capVertices()
{
    const std::size_t n = m_d.size();
    m_capUnits.resize(n); // every vertex's cap is written below, and the run's end is 0
    if (n > 0)
        m_capUnits[n - 1] = 0;
    if (!m_options.wireLimited || m_config.link.baud <= 0 || n < 2) {
        for (std::size_t k = 0; k + 1 < n; ++k)
            m_capUnits[k] = vertexCap(k);
        return;
    }
    const std::size_t vertices = n - 1;
    // The caps before flattening, a tight vertex's own and -1 at every other: a flattened cap
    // reads only the tight vertices of its own stretch.
    std::vector<std::int32_t> &caps = m_scratchUnits;
    caps.resize(vertices);
    for (std::size_t k = 0; k < vertices; ++k) {
        const std::int32_t own = vertexCap(k);
        m_capUnits[k] = own;
        const double cap = static_cast<double>(own);
        // With a B before it (B at most V, so at most V's bytes).
        const double withBrake = m_link.vectorWireS(m_d[k].wireBytes) +
                                 m_link.commandS(m_link.brakeWireBytes(m_d[k].speed));
        const bool tight = cap >= kMinSpeed && m_d[k].units < cap * withBrake;
        caps[k] = tight ? own : -1;
    }
    // Each tight vertex takes the least cap of the tight vertices within kFlatWindow either side
    // in its stretch of tight vertices: a sliding minimum over each stretch (the candidates,
    // their caps rising from front to back), one walk instead of 2 x kFlatWindow reads a vertex.
    std::array<std::size_t, 2 * kFlatWindow + 2> least{}; // a ring of candidate vertices
    std::size_t k = 0;
    while (k < vertices) {
        if (caps[k] < 0) {
            ++k;
            continue;
        }
        std::size_t end = k; // the stretch [k, end) of tight vertices
        while (end < vertices && caps[end] >= 0)
            ++end;
        std::size_t front = 0, back = 0, next = k; // ring [front, back), next vertex to enter
        for (std::size_t j = k; j < end; ++j) {
            for (; next < std::min(end, j + kFlatWindow + 1); ++next) {
                while (back > front && caps[least[(back - 1) % least.size()]] >= caps[next])
                    --back;
                least[back++ % least.size()] = next;
            }
            while (least[front % least.size()] + kFlatWindow < j)
                ++front;
            m_capUnits[j] = caps[least[front % least.size()]];
        }
        k = end;
    }
}

} // namespace frezka::machine::detail
