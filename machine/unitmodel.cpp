#include "machine/unitmodel.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace frezka::machine {

double speedUnitsLength(const std::array<std::int32_t, 4> &d, bool vk)
{
    if (vk) {
        const double x = d[0], y = d[1], z = d[2];
        return std::sqrt(x * x + y * y + z * z);
    }
    std::int64_t major = 0;
    for (std::int32_t c : d)
        major = std::max<std::int64_t>(major, std::llabs(c));
    return static_cast<double>(major);
}

namespace {

// Accelerate (or decelerate) from e toward c over at most n; returns {time, speed, distance}.
struct Ramp
{
    double t, v, d;
};
Ramp rampToward(double e, double c, double a, double n)
{
    const double d = std::abs(c * c - e * e) / (2 * a);
    if (d <= n)
        return {std::abs(c - e) / a, c, d};
    const double v = std::sqrt(std::max(0.0, e * e + (c > e ? 2 : -2) * a * n));
    return {std::abs(v - e) / a, v, n};
}

} // namespace

VectorRun runVector(double e, double c, double x, double a, double n)
{
    VectorRun r;
    const double eps = 1e-9 * (e * e + x * x + 2 * a * n) + 1e-12;
    if (e > x && e * e - x * x > 2 * a * n + eps) {
        // Cannot brake in time (whatever the cruise target): decelerates all the way.
        r.violation = true;
        r.exit = std::sqrt(e * e - 2 * a * n);
        r.timeS = (e - r.exit) / a;
        return r;
    }
    if (e <= c) {
        if (x * x >= e * e + 2 * a * n || c < x) {
            // The exit target is out of reach: ramp toward c, cruise, arrive slower than x.
            const Ramp up = rampToward(e, c, a, n);
            r.exit = up.v;
            r.timeS = up.t + (up.d < n ? (n - up.d) / up.v : 0);
            return r;
        }
        const double peak = std::min(c, std::sqrt((e * e + x * x + 2 * a * n) / 2));
        const double d1 = (peak * peak - e * e) / (2 * a);
        const double d3 = (peak * peak - x * x) / (2 * a);
        const double cruise = std::max(0.0, n - d1 - d3);
        r.exit = x;
        r.timeS = (peak - e) / a + (peak > 0 ? cruise / peak : 0) + (peak - x) / a;
        r.peak = peak;
        return r;
    }
    // e > c: slow down to the cruise target first.
    const Ramp down = rampToward(e, c, a, n);
    if (c < x || down.d >= n) {
        r.exit = down.v;
        r.timeS = down.t + (down.d < n ? (n - down.d) / down.v : 0);
        return r;
    }
    const double d3 = (c * c - x * x) / (2 * a);
    r.exit = x;
    r.timeS = down.t + std::max(0.0, n - down.d - d3) / c + (c - x) / a;
    return r;
}

namespace {

struct Pending
{
    double n, a, v, b;
    bool isShort;
    bool isLine;
};

std::int64_t majorSteps(const std::array<std::int32_t, 4> &d)
{
    std::int64_t major = 0;
    for (std::int32_t c : d)
        major = std::max<std::int64_t>(major, std::llabs(c));
    return major;
}

class Model
{
public:
    Model(bool vk)
        : m_vk(vk)
    {}

    void command(const UnitCommand &c)
    {
        switch (c.op) {
        case UnitOp::SpeedModeVk:
            m_vk = true;
            break;
        case UnitOp::SpeedModeVn:
            m_vk = false;
            break;
        case UnitOp::Accel:
            m_a = static_cast<double>(c.value) * 1000;
            break;
        case UnitOp::Speed:
            m_v = static_cast<double>(c.value);
            break;
        case UnitOp::Brake:
            m_b = static_cast<double>(c.value);
            break;
        case UnitOp::ShortThreshold:
            m_short = c.value;
            break;
        case UnitOp::Pause:
            m_pauseS = static_cast<double>(c.value) / 1000.0;
            break;
        case UnitOp::Vector:
            m_chain.push_back(
                {speedUnitsLength(c.d, m_vk), m_a, m_v, m_b, majorSteps(c.d) < m_short, false});
            break;
        case UnitOp::Line:
            flush();
            m_chain.push_back({speedUnitsLength(c.d, m_vk), m_a, m_v, 0, false, true});
            flush();
            break;
        case UnitOp::Dwell:
            flush();
            m_result.waitS += static_cast<double>(c.value) / 1000.0;
            m_sinceRest += static_cast<double>(c.value) / 1000.0;
            break;
        case UnitOp::Output:
        case UnitOp::Spindle:
            break;
        default:
            flush();
            break;
        }
    }

    ModelResult finish()
    {
        flush();
        return m_result;
    }

private:
    // Runs the queued vectors from rest to rest (a chain: the queue never runs dry inside).
    void flush()
    {
        if (m_chain.empty())
            return;
        ++m_result.chains;
        if (m_restedBefore) // the unit waits T after coming to rest (PC-side waits overlap it)
            m_result.waitS += std::max(0.0, m_pauseS - m_sinceRest);
        double e = 0;
        for (std::size_t k = 0; k < m_chain.size(); ++k) {
            const Pending &p = m_chain[k];
            const bool last = k + 1 == m_chain.size();
            const double cruise = p.isShort ? std::min(p.v, p.b) : p.v;
            const double exit = last || p.isLine ? 0 : std::min(p.b, cruise);
            const VectorRun r = runVector(e, cruise, exit, p.a, p.n);
            m_result.motionS += r.timeS;
            m_result.brakeViolations += r.violation ? 1 : 0;
            m_result.peakSpeed = std::max({m_result.peakSpeed, e, r.exit, r.peak});
            m_result.vertexSpeeds.push_back(r.exit);
            m_result.vectorTimes.push_back(r.timeS);
            ++m_result.vectors;
            e = r.exit;
        }
        m_chain.clear();
        m_restedBefore = true;
        m_sinceRest = 0;
    }

    bool m_vk;
    double m_a = 20000, m_v = 1000, m_b = 35000, m_pauseS = kInitialPauseS;
    std::int64_t m_short = 512;
    bool m_restedBefore = false;
    double m_sinceRest = 0;
    std::vector<Pending> m_chain;
    ModelResult m_result;
};

} // namespace

ModelResult runUnitModel(const UnitProgram &program, bool speedModeVk)
{
    Model model(speedModeVk);
    for (const UnitCommand &c : program.commands)
        model.command(c);
    return model.finish();
}

} // namespace frezka::machine
