// The chain planner's run: the figures derived from each move, the integer passes and the
// time-optimal bound (docs/planner.md §3-§5). Vertex caps: chaincaps.cpp; the link's pace:
// chainpace.cpp.
#include "machine/chainplanner.h"

#include "machine/chainparts.h"
#include "machine/chainplanner_internal.h"
#include "machine/modalchoice.h"

#include "machine/unitmodel.h"
#include "machine/unitwire.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <limits>

namespace frezka::machine::detail {

namespace {

// Path length of a displacement: X/Y/Z length, or |A| for a pure rotary move (feed in °/min).
double pathLength(const Vec4 &delta)
{
    const double xyz = std::sqrt(delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2]);
    return xyz > 1e-12 ? xyz : std::abs(delta[3]);
}

// floor(sqrt(x)) for x >= 0, exact in integers.
std::int64_t isqrt(std::int64_t x)
{
    if (x <= 0)
        return 0;
    auto r = static_cast<std::int64_t>(std::sqrt(static_cast<double>(x)));
    while (r * r > x)
        --r;
    while ((r + 1) * (r + 1) <= x)
        ++r;
    return r;
}

// min(cap, floor(sqrt(x))), exact, without the root where the cap is the lesser: floor(sqrt(x))
// is at least cap >= 0 exactly when cap² <= x. Along a chain the caps bind at most vertices, and
// the passes' roots are a chain of dependent steps otherwise (each vertex's speed from the next).
std::int64_t capOrRoot(std::int64_t cap, std::int64_t x)
{
    return cap >= 0 && cap * cap <= x ? cap : std::min(cap, isqrt(x));
}

} // namespace

double dot(const Vec4 &a, const Vec4 &b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

Vec4 normalized(const Vec4 &v)
{
    const double n = std::sqrt(dot(v, v));
    Vec4 r{};
    if (n > 0) {
        for (int i = 0; i < 4; ++i)
            r[i] = v[i] / n;
    }
    return r;
}

// With the link's pace (wireLimited) a vector's wire time includes the B command before it
// where the plan sends one, which the plan decides: plan without them, then again with the
// last plan's B, V and A commands spread over each vector's wide neighbourhood (the unit's queue
// evens them out), a few times. They need not settle: where the B commands the pace sets change
// the pace, a plan's commands go back and forth (the spiral of bench_gui_load: its B commands
// near the centre changed in all five re-plans, most of them back to the value of two plans
// before). So a re-plan whose own commands fit what it was paced for within the pace's margin
// (sentFits) is kept: planning again would only trade one such pattern for the next (the spiral:
// 4 plans, not 6; docs/planner.md §4).
RunOutcome RunPlanner::run()
{
    derive();
    planOnce();
    ++m_out.plans;
    if (!m_options.wireLimited || m_config.link.baud <= 0) {
        bound();
        jumpStats();
        return std::move(m_out);
    }
    const std::size_t n = m_moves.size();
    m_extraS.assign(n);
    int plans = 1;
    for (int pass = 0; pass < kWirePasses; ++pass) {
        // The link time of the B, V and A commands the last plan sends before each vector: in the
        // passes' room (free between plans), compared with what that plan assumed (m_extraS).
        std::vector<double> &sent = m_scratch;
        sent.assign(n, 0.0);
        // The run's first B, V and A always count: the unit's modal values are unknown.
        std::int64_t lastB = -1, lastV = -1, lastA = -1;
        for (std::size_t k = 0; k < m_out.vectors.size(); ++k) {
            const PlannedVector &v = m_out.vectors[k];
            double extra = 0;
            if (!v.line && v.brake != lastB)
                extra += m_link.commandS(m_link.brakeWireBytes(v.brake));
            if (v.speed != lastV)
                extra += m_link.nonPacketS(m_link.wireBytes(protocol::cmd::speed(v.speed)));
            if (v.accel != lastA)
                extra += m_link.nonPacketS(m_link.wireBytes(protocol::cmd::accel(v.accel)));
            lastB = v.line ? lastB : v.brake;
            lastV = v.speed;
            lastA = v.accel;
            sent[k] = extra;
        }
        // The first plan assumed no commands at all: it is always planned again.
        if (pass > 0 && sentFits(sent))
            break;
        bool changed = false;
        for (std::size_t k = 0; k < n; ++k) {
            const double extra = sent[k];
            changed = changed || extra != m_extraS[k];
            m_extraS.set(k, extra);
        }
        if (!changed)
            break;
        planOnce();
        ++plans;
    }
    m_out.plans = plans;
    bound();
    jumpStats();
    return std::move(m_out);
}

// Whether the last plan's own B, V and A commands (sent, link time before each vector) fit the
// link time it was paced for (m_extraS): in every window the pace averages over (wirePace's), what
// it sends beyond what it assumed is at most the pace's wire margin's share of the window's
// planned wire time (its vectors, each at its widest neighbour, and the assumed commands). Then a
// plan again would pace for what this one sends and change its B commands once more, where the
// margin pays for the difference already. Exact agreement (the pace settled) always fits.
bool RunPlanner::sentFits(const std::vector<double> &sent) const
{
    const std::size_t n = sent.size();
    const std::size_t window = m_link.brakeWindow();
    const double share = std::max(0.0, m_options.wireMargin - 1);
    // The window [k - window, k + window] slides: sums of the differences and of the planned time.
    double over = 0, planned = 0;
    auto add = [&](std::size_t j, double sign) {
        over += sign * (sent[j] - m_extraS[j]);
        planned += sign * (m_extraS[j] + m_link.vectorWireS(m_d[j].widestBytes));
    };
    for (std::size_t j = 0; j < std::min(n, window); ++j)
        add(j, 1);
    for (std::size_t k = 0; k < n; ++k) {
        if (k + window < n)
            add(k + window, 1);
        if (k > window)
            add(k - window - 1, -1);
        if (over > share * planned)
            return false;
    }
    return true;
}

// One plan of the run: the derived moves, the link's pace over them (with the B bytes of the
// last plan), caps and passes. The bound and the vertex statistics follow from the last plan
// only (run()): the plans before it only tell the next one its B, V and A commands.
void RunPlanner::planOnce()
{
    std::vector<PlannedVector> vectors = std::move(m_out.vectors); // its room, for this plan
    vectors.clear();
    m_out = {};
    m_out.vectors = std::move(vectors);
    m_out.vectors.reserve(m_d.size());
    m_out.slowLines = m_slowLines;
    m_out.firstFeedCap = m_firstFeedCap;
    m_out.feedCapLines = m_feedCapLines;
    wirePace(); // starts each move again from m_paceStart as it goes
    paceModalChanges();
    capVertices(); // the vertex caps, flattened where the vectors are as short as their bytes
    const std::size_t n = m_moves.size();
    std::size_t first = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const bool exact = m_options.strategy == PlanStrategy::ExactStop;
        if (k + 1 < n && !exact && m_capUnits[k] < kMinSpeed && softStopAllowed(k)) {
            // A sharp corner ends the chain at the unit's smallest speed; the queue keeps
            // running, so the unit neither rests nor pauses T there.
            m_capUnits[k] = kMinSpeed;
            ++m_out.chains;
        } else if (k + 1 == n || m_capUnits[k] < kMinSpeed) {
            chain(first, k);
            first = k + 1;
        }
    }
}

// What the moves themselves give, once per run (every plan of it starts from this): the
// figures of each move, the caps of each vertex that its two directions set, and each move's
// widest neighbour on the wire.
void RunPlanner::derive()
{
    const std::size_t n = m_moves.size();
    m_d.clear();
    m_d.reserve(n); // each move's figures made where they are derived: no walk to make them first
    const std::size_t vertices = n > 0 ? n - 1 : 0;
    m_geoCap.assign(vertices, 0);
    m_softStop.assign(vertices, true);
    m_stopAfter.assign(n, false);
    if (m_options.strategy == PlanStrategy::GrblJunction && !m_options.grblKeepsAllLimits)
        m_planGeoCap.assign(vertices, 0);
    // Each move's widest neighbour on the wire within the window either side, as the pace charges
    // it: a sliding maximum, taken in the same walk that derives the moves, `window` moves behind
    // it (the candidates, their bytes falling from front to back, in a ring).
    const bool paced = m_options.wireLimited && m_config.link.baud > 0;
    const std::size_t window = m_link.wireWindow();
    std::array<std::size_t, kWidestRing> widest{};
    static_assert(kWidestRing >= 2 * 16 + 2, "LinkTiming::wireWindow() is at most 16");
    std::size_t front = 0, back = 0; // the ring's candidates [front, back)
    auto widestOf = [&](std::size_t k) {
        while (widest[front % kWidestRing] + window < k)
            ++front;
        m_d[k].widestBytes = m_d[widest[front % kWidestRing]].wireBytes;
    };
    Directions before;
    for (std::size_t k = 0; k < n; ++k) {
        const Directions dir = directions(m_moves[k]);
        Derived &r = m_d.emplace_back();
        deriveOne(m_moves[k], m_moves.modes(k), dir, r);
        m_stopAfter[k] = m_moves.modes(k).stopAfter;
        if (k > 0) {
            vertexGeometry(k - 1, before, dir);
            r.restBefore = m_stopAfter[k - 1] || !softStopAllowed(k - 1);
        } else {
            r.restBefore = true;
        }
        before = dir;
        if (!paced)
            continue;
        while (back > front && m_d[widest[(back - 1) % kWidestRing]].wireBytes <= r.wireBytes)
            --back;
        widest[back++ % kWidestRing] = k;
        if (k >= window)
            widestOf(k - window);
    }
    for (std::size_t k = n > window ? n - window : 0; paced && k < n; ++k)
        widestOf(k);
    chooseSpeeds(m_d, m_options, m_link);
    chooseAccels(m_d, m_geoCap, m_options, m_link);
    m_paceStart.resize(m_d.size());
    for (std::size_t k = 0; k < m_d.size(); ++k) {
        const Derived &r = m_d[k];
        m_paceStart[k] = {r.vMm, static_cast<std::int32_t>(r.speed),
                          static_cast<std::int32_t>(r.accel)};
    }
}

Directions RunPlanner::directions(const Move &m) const
{
    Directions r;
    Vec4 stepMm{};
    for (int i = 0; i < 4; ++i)
        stepMm[i] = m.d[i] / m_config.axes[static_cast<std::size_t>(i)].stepsPerMm;
    r.lengthMm = pathLength(stepMm);
    r.pathLengthMm = pathLength(m.pathDelta);
    r.uPath = normalized(m.pathDelta);
    if (r.pathLengthMm <= 0) // rounding made a step out of a zero-length intent
        r.uPath = normalized(stepMm), r.pathLengthMm = r.lengthMm;
    for (int i = 0; i < 4; ++i)
        r.uStep[i] = stepMm[i] / r.lengthMm;
    return r;
}

void RunPlanner::deriveOne(const Move &m, const MoveModes &modes, const Directions &dir, Derived &r)
{
    r.units = speedUnitsLength(m.d, m_vk);
    r.f = r.units / dir.lengthMm;
    const double asked = modes.rapid ? kInf : modes.feedMmPerS * m_options.feedOverride;
    double v = asked;
    double a = kInf;
    FeedCap cap{m.line, asked, 0, 0, 0};
    for (int i = 0; i < 4; ++i) {
        const double u = std::abs(dir.uStep[i]);
        if (u < 1e-12)
            continue;
        const AxisConfig &ax = m_config.axes[static_cast<std::size_t>(i)];
        const double axisMax = (modes.rapid ? ax.rapidMmPerMin : ax.maxSpeedMmPerMin) / 60.0;
        if (axisMax / u < v)
            cap.limit = kAxisLetters[static_cast<std::size_t>(i)], cap.limitMmPerS = axisMax;
        v = std::min(v, axisMax / u);
        a = std::min(a, ax.accelMmPerS2 / u);
    }
    if (m_config.unit.maxPulseRate / r.f < v)
        cap.limit = 'P', cap.limitMmPerS = m_config.unit.maxPulseRate / r.f;
    v = std::min(v, m_config.unit.maxPulseRate / r.f);
    if (!modes.rapid && v < asked * (1 - 1e-9) && m_lastCappedLine != m.line) {
        cap.runMmPerS = v;
        if (m_feedCapLines++ == 0)
            m_firstFeedCap = cap;
        m_lastCappedLine = m.line;
    }
    r.vMm = v;
    r.aMm = a;
    r.speed = std::clamp<std::int64_t>(static_cast<std::int64_t>(floorUnits(v * r.f)), kMinSpeed,
                                       m_config.unit.maxPulseRate);
    r.ownSpeed = r.speed;
    if (v * r.f < kMinSpeed) { // the unit cannot go slower: the move runs faster than asked
        r.vMm = kMinSpeed / r.f;
        if (m_slowLines.empty() || m_slowLines.back() != m.line)
            m_slowLines.push_back(m.line);
    }
    std::int64_t major = 0;
    for (std::int32_t c : m.d)
        major = std::max<std::int64_t>(major, std::abs(c));
    r.isShort = major < m_options.shortThreshold; // the unit compares major-axis steps
    r.wireBytes = static_cast<std::uint8_t>(m_link.vectorWireBytes(m.d)); // under 70
}

// Integer passes over moves first..last (a chain), then the vectors as they go out.
void RunPlanner::chain(std::size_t first, std::size_t last)
{
    ++m_out.chains;
    std::vector<std::int32_t> &b = m_scratchUnits; // at most the caps: 32 bits
    b.resize(last - first + 1);
    if (m_options.strategy != PlanStrategy::GrblJunction) {
        fullPasses(first, b); // takes the caps and sends the vectors out as it goes
        return;
    }
    for (std::size_t k = first; k < last; ++k)
        b[k - first] = m_capUnits[k];
    b.back() = 0;
    windowedPasses(first, b);
    for (std::size_t k = first; k <= last; ++k)
        outputVector(m_d[k], b[k - first], k == last);
}

// The speeds are at most the caps (32 bits); their squares and the sums are taken in 64. The
// backward pass takes each vertex's cap as it reaches it, and the forward pass sends each vector
// out as soon as its exit is known: two walks over the chain's figures instead of four (a spiral
// of 5 M vectors is one chain, walked in each of the link's pace's plans).
void RunPlanner::fullPasses(std::size_t first, std::vector<std::int32_t> &b)
{
    const std::size_t n = b.size();
    b[n - 1] = 0;
    for (std::size_t k = n - 1; k > 0; --k) {
        const std::int64_t exit = b[k];
        b[k - 1] = static_cast<std::int32_t>(
            capOrRoot(m_capUnits[first + k - 1], exit * exit + m_d[first + k].twoAU));
    }
    std::int64_t e = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const Derived &r = m_d[first + k];
        if (k + 1 < n)
            b[k] = static_cast<std::int32_t>(capOrRoot(b[k], e * e + r.twoAU));
        e = b[k];
        outputVector(r, b[k], k + 1 == n);
    }
}

// Vector k of a chain as it goes out, its exit B planned (the chain's last: nothing follows).
void RunPlanner::outputVector(const Derived &r, std::int32_t brake, bool chainEnd)
{
    PlannedVector v{static_cast<std::int32_t>(r.speed), brake, static_cast<std::int32_t>(r.accel),
                    chainEnd, false};
    if (chainEnd) // nothing follows: the unit brakes to 0; a short vector cruises at B
        v.brake = static_cast<std::int32_t>(r.isShort ? std::min(r.speed, r.ownSpeed) : kMinSpeed);
    v.line = m_options.strategy == PlanStrategy::ExactStop;
    m_out.vectors.push_back(v);
}

// grbl: when a block starts, the planner sees only the next `lookahead` blocks and plans
// the last of them to stop.
void RunPlanner::windowedPasses(std::size_t first, std::vector<std::int32_t> &b) const
{
    const std::size_t n = b.size();
    const std::size_t window = static_cast<std::size_t>(std::max(2, m_options.grblLookahead));
    const std::vector<std::int32_t> caps = b;
    std::int64_t e = 0;
    for (std::size_t k = 0; k + 1 < n; ++k) {
        const std::size_t end = std::min(n - 1, k + window - 1);
        std::int64_t exit = 0; // the buffer's last block plans a stop
        for (std::size_t j = end; j > k; --j)
            exit = std::min<std::int64_t>(caps[j - 1], isqrt(exit * exit + m_d[first + j].twoAU));
        b[k] = static_cast<std::int32_t>(std::min(exit, isqrt(e * e + m_d[first + k].twoAU)));
        e = b[k];
    }
}

// Continuous backward/forward passes over the bound's caps; closed-form times. The speed is
// the unit's own scalar (speed units: VK step length, VN major-axis steps, per second), which
// the unit carries across a vertex whatever the two vectors' units per mm: a continuous speed
// in mm is not what it can do with unequal axis scales (property seed 127: such a "bound" lay
// 31 % above the plan the unit ran). The acceleration is each segment's own limit as the unit
// can take it: A is whole thousands of pulses/s², so an axis at 17 steps/mm and 59 mm/s² gets
// A 0.99 -> at least 1, and one that allows A 1.9 gets 1 (no plan can do better; property seed
// 5 was 8 % above a bound that took the fractions).
void RunPlanner::bound()
{
    const std::size_t n = m_moves.size();
    if (n == 0)
        return;
    // Segment k's acceleration, computed where it is used rather than kept (8 bytes a move at the
    // plan's peak, which the bound is otherwise: 40 MB at 5 M moves).
    auto accelOf = [this](std::size_t k) {
        const Derived &r = m_d[k];
        return 1000.0 * std::clamp(std::floor(r.aMm * r.f / 1000.0 + 1e-9), 1.0,
                                   static_cast<double>(kMaxAccel));
    };
    // Segment k's cruise cap. V is a whole number of speed units: a vector that cruises (or, if
    // short, runs at its B, a whole number too) does so at most at floor(cap). Only a vector whose
    // V lies above its cap and whose peak stays below the cap without reaching V could go faster
    // than floor(cap), and its peak is at least sqrt(A·units) with A at least 1000 pulses/s²: where
    // that lies above the cap, the floor is the cap (property seed 70: a 10 285-unit move at a cap
    // of 13.9 runs at V 13, 51 s longer than a bound at 13.9 said). Its exit is at most its cruise.
    auto cruiseOf = [this](std::size_t k) {
        const Derived &r = m_d[k];
        const double c = r.vMm * r.f;
        return 1000.0 * r.units > c * c ? floorUnits(c) : c;
    };
    std::vector<double> &x = m_scratch; // the vertex speeds: the passes' room, no longer needed
    x.assign(n, 0.0);
    for (std::size_t k = 0; k + 1 < n; ++k)
        x[k] = std::min(boundCap(k), cruiseOf(k));
    for (std::size_t k = n - 1; k > 0; --k) {
        const double entry = std::sqrt(x[k] * x[k] + 2 * accelOf(k) * m_d[k].units);
        x[k - 1] = std::min(x[k - 1], entry);
    }
    double e = 0;
    for (std::size_t k = 0; k < n; ++k) {
        const Derived &r = m_d[k];
        const double a = accelOf(k);
        x[k] = std::min(x[k], std::sqrt(e * e + 2 * a * r.units));
        m_out.boundS += runVector(e, cruiseOf(k), x[k], a, r.units).timeS;
        e = x[k];
    }
}

RunOutcome planRun(const Moves &moves, const MachineConfig &config, const PlanOptions &options,
                   bool vk)
{
    return RunPlanner(moves, config, options, vk).run();
}

} // namespace frezka::machine::detail
