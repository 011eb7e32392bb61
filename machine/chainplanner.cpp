// Vertex caps, integer passes and the time-optimal bound (docs/planner.md §3-§5).
#include "machine/chainplanner.h"

#include "machine/chainparts.h"
#include "machine/modalchoice.h"

#include "machine/unitmodel.h"
#include "machine/unitwire.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace frezka::machine::detail {

namespace {

double dot(const Vec4 &a, const Vec4 &b)
{
    return a[0] * b[0] + a[1] * b[1] + a[2] * b[2] + a[3] * b[3];
}

// Path length of a displacement: X/Y/Z length, or |A| for a pure rotary move (feed in °/min).
double pathLength(const Vec4 &delta)
{
    const double xyz = std::sqrt(delta[0] * delta[0] + delta[1] * delta[1] + delta[2] * delta[2]);
    return xyz > 1e-12 ? xyz : std::abs(delta[3]);
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

class RunPlanner
{
public:
    RunPlanner(const std::vector<Move> &moves, const MachineConfig &config,
               const PlanOptions &options, bool vk)
        : m_moves(moves)
        , m_config(config)
        , m_options(options)
        , m_link(config, options)
        , m_vk(vk)
    {}

    // With the link's pace (wireLimited) a vector's wire time includes the B command before it
    // where the plan sends one, which the plan decides: plan without them, then again with the
    // last plan's B bytes spread over each vector's wide neighbourhood (the unit's queue evens
    // them out), a few times: the spread B bytes change little from one plan to the next.
    RunOutcome run()
    {
        derive();
        planOnce();
        if (!m_options.wireLimited || m_config.link.baud <= 0)
            return std::move(m_out);
        m_extraS.assign(m_moves.size(), 0);
        for (int pass = 0; pass < kWirePasses; ++pass) {
            bool changed = false;
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
                changed = changed || extra != m_extraS[k];
                m_extraS[k] = extra;
            }
            if (!changed)
                break;
            planOnce();
        }
        return std::move(m_out);
    }

private:
    static constexpr int kWirePasses = 5;         // plans again at most this often
    static constexpr std::size_t kFlatWindow = 8; // flattenTightCaps: vertices either side

    // One plan of the run: the derived moves, the link's pace over them (with the B bytes of the
    // last plan), caps, bound and passes.
    void planOnce()
    {
        m_out = {};
        m_out.slowLines = m_slowLines;
        m_out.firstFeedCap = m_firstFeedCap;
        m_out.feedCapLines = m_feedCapLines;
        m_d = m_derived;
        wirePace();
        const std::size_t n = m_moves.size();
        m_capUnits.assign(n, 0);
        m_capMm.assign(n, 0);
        for (std::size_t k = 0; k + 1 < n; ++k)
            vertexCaps(k);
        flattenTightCaps();
        bound();
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
        jumpStats();
    }

    // What the moves themselves give, once per run (every plan of it starts from this).
    void derive()
    {
        m_d.resize(m_moves.size());
        for (std::size_t k = 0; k < m_moves.size(); ++k)
            deriveOne(m_moves[k], m_d[k]);
        chooseSpeeds(m_d, m_options, m_link);
        chooseAccels(m_d, m_options, m_link);
        m_derived = m_d;
    }

    // The link's pace (PlanOptions::wireLimited): a vector must last at least the time its bytes
    // take on the wire, or the unit's queue runs dry mid-chain and the machine stops without
    // braking. Its bytes: the largest vector of its neighbourhood, and the neighbourhood's B
    // commands on average. Within a vector the unit accelerates from its entry B toward V and
    // brakes to its exit B, so its fastest speed is at most sqrt((b0² + b1²) / 2 + A·L):
    // capping both Bs at sqrt((L/t)² - A·L) keeps it at L/t. Where even that is below the
    // unit's smallest B (a vector of a step or two), V itself is lowered, which costs a V
    // command (rare). The bound takes the floor as a cruise cap.
    void wirePace()
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
    void sharePacedSpeeds(const std::vector<bool> &lowered)
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

    void deriveOne(const Move &m, Derived &r)
    {
        Vec4 stepMm{};
        for (int i = 0; i < 4; ++i)
            stepMm[i] = m.d[i] / m_config.axes[static_cast<std::size_t>(i)].stepsPerMm;
        r.lengthMm = pathLength(stepMm);
        r.pathLengthMm = pathLength(m.pathDelta);
        r.uPath = normalized(m.pathDelta);
        if (r.pathLengthMm <= 0) // rounding made a step out of a zero-length intent
            r.uPath = normalized(stepMm), r.pathLengthMm = r.lengthMm;
        r.units = speedUnitsLength(m.d, m_vk);
        r.f = r.units / r.lengthMm;
        const double asked = m.rapid ? kInf : m.feedMmPerS * m_options.feedOverride;
        double v = asked;
        double a = kInf;
        FeedCap cap{m.line, asked, 0, 0, 0};
        for (int i = 0; i < 4; ++i) {
            r.uStep[i] = stepMm[i] / r.lengthMm;
            const double u = std::abs(r.uStep[i]);
            if (u < 1e-12)
                continue;
            const AxisConfig &ax = m_config.axes[static_cast<std::size_t>(i)];
            const double axisMax = (m.rapid ? ax.rapidMmPerMin : ax.maxSpeedMmPerMin) / 60.0;
            if (axisMax / u < v)
                cap.limit = kAxisLetters[static_cast<std::size_t>(i)], cap.limitMmPerS = axisMax;
            v = std::min(v, axisMax / u);
            a = std::min(a, ax.accelMmPerS2 / u);
        }
        if (m_config.unit.maxPulseRate / r.f < v)
            cap.limit = 'P', cap.limitMmPerS = m_config.unit.maxPulseRate / r.f;
        v = std::min(v, m_config.unit.maxPulseRate / r.f);
        if (!m.rapid && v < asked * (1 - 1e-9) && m_lastCappedLine != m.line) {
            cap.runMmPerS = v;
            if (m_feedCapLines++ == 0)
                m_firstFeedCap = cap;
            m_lastCappedLine = m.line;
        }
        r.vMm = v;
        r.aMm = a;
        r.speed = std::clamp<std::int64_t>(static_cast<std::int64_t>(floorUnits(v * r.f)),
                                           kMinSpeed, m_config.unit.maxPulseRate);
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
        r.wireBytes = m_link.vectorWireBytes(m.d);
    }

    // Where the vectors are about as short as their bytes on the wire, a B that changes at every
    // vertex (the caps of a wavy path do) costs the link nearly as much as the vector itself, and
    // the link's pace then halves the speed. There the caps are flattened to the least one within
    // kFlatWindow vertices either side: a stretch runs at one B and sends no B inside it.
    void flattenTightCaps()
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

    // Junction-deviation and curvature caps of the path speed at the vertex after move k, mm/s.
    void pathCaps(std::size_t k, const Vec4 &u0, const Vec4 &u1, double &jd, double &curv) const
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
                aj = std::min(aj, m_config.axes[static_cast<std::size_t>(i)].accelMmPerS2 /
                                      std::abs(j[i]));
        }
        const double sinHalfTheta = std::sqrt(0.5 * (1 - cosTheta));
        jd = std::sqrt(aj * m_moves[k + 1].junctionDeviationMm * sinHalfTheta / (1 - sinHalfTheta));
        const double sinHalfPhi = std::sqrt(0.5 * (1 + cosTheta)); // φ: the turn angle
        const double chord = std::min(m_d[k].pathLengthMm, m_d[k + 1].pathLengthMm);
        curv = std::sqrt(aj * chord / (2 * sinHalfPhi));
    }

    // Per-axis speed step at the vertex after move k, per unit of the scalar speed there.
    double jumpPerUnit(std::size_t k, int i) const
    {
        return std::abs(m_d[k].uStep[i] / m_d[k].f - m_d[k + 1].uStep[i] / m_d[k + 1].f);
    }

    void vertexCaps(std::size_t k)
    {
        const Derived &a = m_d[k];
        const Derived &b = m_d[k + 1];
        if (m_moves[k].stopAfter)
            return; // caps stay 0: the program asks for a stop here
        boundCap(k);
        if (m_options.strategy == PlanStrategy::ExactStop)
            return;
        const double fMin = std::min(a.f, b.f);
        double units = static_cast<double>(std::min(a.speed, b.speed));
        double jd = 0, curv = 0;
        // grbl's own caps, unless the baseline is asked to keep every limit of the full plan
        // (then it differs from the full plan only by its short lookahead).
        const bool grbl =
            m_options.strategy == PlanStrategy::GrblJunction && !m_options.grblKeepsAllLimits;
        if (grbl) {
            pathCaps(k, a.uStep, b.uStep, jd, curv); // grbl: geometry of the steps, no curvature
            units = std::min(units, jd * fMin);
        } else {
            pathCaps(k, a.uPath, b.uPath, jd, curv);
            units = std::min({units, jd * fMin, curv * fMin});
        }
        for (int i = 0; i < 4 && !grbl; ++i) {
            const double per = jumpPerUnit(k, i);
            if (per > 1e-15)
                units =
                    std::min(units, m_config.axes[static_cast<std::size_t>(i)].maxJumpMmPerS / per);
        }
        units = std::min({units, a.wireCap, b.wireCap});   // the link's pace (infinite: off)
        units = std::min({units, a.speedCap, b.speedCap}); // V above a vector's own cap
        m_capUnits[k] = static_cast<std::int64_t>(floorUnits(units));
    }

    // The bound's cap at the vertex after move k: the same limits on a continuous path speed.
    void boundCap(std::size_t k)
    {
        const Derived &a = m_d[k];
        const Derived &b = m_d[k + 1];
        double jd = 0, curv = 0;
        pathCaps(k, a.uPath, b.uPath, jd, curv);
        double mm = std::min({a.vMm, b.vMm, jd, curv});
        for (int i = 0; i < 4; ++i) {
            const double per = std::abs(a.uStep[i] - b.uStep[i]);
            if (per > 1e-15)
                mm = std::min(mm, m_config.axes[static_cast<std::size_t>(i)].maxJumpMmPerS / per);
        }
        m_capMm[k] = mm;
    }

    // Integer passes over moves first..last (a chain), then the vectors as they go out.
    void chain(std::size_t first, std::size_t last)
    {
        ++m_out.chains;
        std::vector<std::int64_t> b(last - first + 1, 0);
        for (std::size_t k = first; k < last; ++k)
            b[k - first] = m_capUnits[k];
        b.back() = 0;
        if (m_options.strategy == PlanStrategy::GrblJunction)
            windowedPasses(first, b);
        else
            fullPasses(first, b);
        for (std::size_t k = first; k <= last; ++k) {
            const Derived &r = m_d[k];
            PlannedVector v{r.speed, r.accel, b[k - first], k == last, false};
            if (k == last) // nothing follows: the unit brakes to 0; a short vector cruises at B
                v.brake = r.isShort ? std::min(r.speed, r.ownSpeed) : kMinSpeed;
            v.line = m_options.strategy == PlanStrategy::ExactStop;
            m_out.vectors.push_back(v);
        }
    }

    // True when passing the vertex after move k at the smallest speed (10 pulses/s) keeps every
    // axis's speed step within its limit; else the queue must drain there (a real stop).
    bool softStopAllowed(std::size_t k) const
    {
        for (int i = 0; i < 4; ++i) {
            if (kMinSpeed * jumpPerUnit(k, i) >
                m_config.axes[static_cast<std::size_t>(i)].maxJumpMmPerS)
                return false;
        }
        return true;
    }

    void fullPasses(std::size_t first, std::vector<std::int64_t> &b) const
    {
        const std::size_t n = b.size();
        for (std::size_t k = n - 1; k > 0; --k) {
            const std::int64_t entry = isqrt(b[k] * b[k] + m_d[first + k].twoAU);
            b[k - 1] = std::min(b[k - 1], entry);
        }
        std::int64_t e = 0;
        for (std::size_t k = 0; k + 1 < n; ++k) {
            b[k] = std::min(b[k], isqrt(e * e + m_d[first + k].twoAU));
            e = b[k];
        }
    }

    // grbl: when a block starts, the planner sees only the next `lookahead` blocks and plans
    // the last of them to stop.
    void windowedPasses(std::size_t first, std::vector<std::int64_t> &b) const
    {
        const std::size_t n = b.size();
        const std::size_t window = static_cast<std::size_t>(std::max(2, m_options.grblLookahead));
        const std::vector<std::int64_t> caps = b;
        std::int64_t e = 0;
        for (std::size_t k = 0; k + 1 < n; ++k) {
            const std::size_t end = std::min(n - 1, k + window - 1);
            std::int64_t exit = 0; // the buffer's last block plans a stop
            for (std::size_t j = end; j > k; --j)
                exit = std::min(caps[j - 1], isqrt(exit * exit + m_d[first + j].twoAU));
            b[k] = std::min(exit, isqrt(e * e + m_d[first + k].twoAU));
            e = b[k];
        }
    }

    // Continuous backward/forward passes in mm/s with the bound's caps; closed-form times. The
    // acceleration is each segment's own limit as the unit can take it: A is whole thousands of
    // pulses/s², so an axis at 17 steps/mm and 59 mm/s² gets A 0.99 -> at least 1, and one that
    // allows A 1.9 gets 1 (no plan can do better; property seed 5 was 8 % above a bound that
    // took the fractions).
    void bound()
    {
        const std::size_t n = m_moves.size();
        if (n == 0)
            return;
        std::vector<double> a(n);
        for (std::size_t k = 0; k < n; ++k) {
            const Derived &r = m_d[k];
            const double whole = std::clamp(std::floor(r.aMm * r.f / 1000.0 + 1e-9), 1.0,
                                            static_cast<double>(kMaxAccel));
            a[k] = whole * 1000.0 / r.f;
        }
        std::vector<double> x(m_capMm);
        x[n - 1] = 0;
        for (std::size_t k = n - 1; k > 0; --k) {
            const double entry = std::sqrt(x[k] * x[k] + 2 * a[k] * m_d[k].lengthMm);
            x[k - 1] = std::min(x[k - 1], entry);
        }
        double e = 0;
        for (std::size_t k = 0; k < n; ++k) {
            const Derived &r = m_d[k];
            x[k] = std::min(x[k], std::sqrt(e * e + 2 * a[k] * r.lengthMm));
            m_out.boundS += runVector(e, r.vMm, x[k], a[k], r.lengthMm).timeS;
            e = x[k];
        }
    }

    void jumpStats()
    {
        for (std::size_t k = 0; k + 1 < m_out.vectors.size(); ++k) {
            const PlannedVector &v = m_out.vectors[k];
            if (v.chainEnd)
                continue;
            bool over = false;
            for (int i = 0; i < 4; ++i) {
                const double jump = static_cast<double>(v.brake) * jumpPerUnit(k, i);
                const double limit = m_config.axes[static_cast<std::size_t>(i)].maxJumpMmPerS;
                m_out.maxJumpMmPerS = std::max(m_out.maxJumpMmPerS, jump);
                // A jump below a nanometre per second is rounding noise, not a step (limit 0: none
                // allowed).
                const double ratio = limit > 0 ? jump / limit : (jump > 1e-9 ? kInf : 0);
                m_out.maxJumpRatio = std::max(m_out.maxJumpRatio, ratio);
                over = over || ratio > 1 + 1e-9;
            }
            m_out.jumpOverLimit += over ? 1 : 0;
            curveStats(k, static_cast<double>(v.brake));
        }
    }

    // The axes' acceleration through the turn at the vertex after move k, as the intended path
    // turns: each axis's speed changes by v·Δu_i over the time between the two segments'
    // middles, (L_k + L_k+1) / 2v. On a chorded arc that is v²/r per unit of turn direction.
    void curveStats(std::size_t k, double brake)
    {
        const Derived &a = m_d[k];
        const Derived &b = m_d[k + 1];
        const double v = brake / std::min(a.f, b.f); // the faster side of the vertex, mm/s
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

    const std::vector<Move> &m_moves;
    const MachineConfig &m_config;
    const PlanOptions &m_options;
    LinkTiming m_link;
    bool m_vk;
    std::vector<Derived> m_d;
    std::vector<Derived> m_derived;         // m_d before the link's pace (derive())
    std::vector<std::uint32_t> m_slowLines; // derive(): lines below the unit's slowest speed
    FeedCap m_firstFeedCap;                 // derive(): the first move whose feed is capped
    std::size_t m_feedCapLines = 0;         // ... and how many lines are
    std::uint32_t m_lastCappedLine = 0;
    std::vector<double> m_extraS; // link time of the B, V, A commands before move k (last plan)
    std::vector<std::int64_t> m_capUnits; // B cap at the end of move k, speed units
    std::vector<double> m_capMm;          // the bound's cap there, mm/s
    RunOutcome m_out;
};

} // namespace

RunOutcome planRun(const std::vector<Move> &moves, const MachineConfig &config,
                   const PlanOptions &options, bool vk)
{
    return RunPlanner(moves, config, options, vk).run();
}

} // namespace frezka::machine::detail
