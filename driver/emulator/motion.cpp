#include "motion.h"

#include "readings.h"

#include <algorithm>
#include <cmath>

namespace frezka::emulator {
namespace {

// Homing travel has no ramp in the model: it starts and stops at its speed at once.
constexpr double kHomingAccel = 1e12;
// Relative slack when comparing speeds and path positions computed in floating point.
constexpr double kRel = 1e-12;
// Path distance below which a boundary counts as reached (far below one step).
constexpr double kSnapSteps = 1e-7;

double sq(double x)
{
    return x * x;
}

} // namespace

double MotionVector::lengthSteps() const
{
    if (velocityCorrection) {
        const double e =
            std::sqrt(sq(double(steps[0])) + sq(double(steps[1])) + sq(double(steps[2])));
        if (e > 0)
            return e;
        return std::abs(double(steps[3]));
    }
    double major = 0;
    for (auto s : steps)
        major = std::max(major, std::abs(double(s)));
    return major;
}

double MotionEngine::cruiseFor(const MotionVector &v) const
{
    const double length = v.lengthSteps();
    double major = 0;
    for (auto s : v.steps)
        major = std::max(major, std::abs(double(s)));
    if (length <= 0 || major <= 0)
        return 0;
    const double rateCap = m_limits.maxPulseRate * length / major;
    if (v.isHoming)
        return std::min(v.speedPulsesPerS, rateCap);
    double vlCap = kNever;
    for (int i = 0; i < kMaxAxes; ++i) {
        const double limit = m_limits.velocityLimitPulsesPerS[i];
        if (v.steps[i] != 0 && limit > 0)
            vlCap = std::min(vlCap, limit * length / std::abs(double(v.steps[i])));
    }
    const double base = readings::cruiseSpeed(v.isShort, v.speedPulsesPerS, v.brakePulsesPerS);
    return std::min(readings::multipliedSpeed(base, m_limits.xmPercent, vlCap), rateCap);
}

double MotionEngine::exitTarget() const
{
    const MotionVector &head = m_queue.front();
    if (head.isLine || head.isHoming || m_committedToZero || m_queue.size() < 2)
        return 0;
    const MotionVector &next = m_queue[1];
    if (next.isLine || next.isHoming)
        return 0;
    return std::min(head.brakePulsesPerS, cruiseFor(head));
}

MotionEngine::Segment MotionEngine::currentSegment() const
{
    const MotionVector &head = m_queue.front();
    const double length = head.lengthSteps();
    const double a = head.isHoming ? kHomingAccel : head.accelPulsesPerS2;
    const double remaining = std::max(0.0, length - m_s);
    const double v2 = sq(m_v);
    if (length <= 0)
        return {0, 0, m_v, false}; // a zero vector passes the speed through
    if (m_stopping) {
        const double stopDistance = v2 / (2 * a);
        if (stopDistance >= remaining)
            return {-a, length, std::sqrt(std::max(0.0, v2 - 2 * a * remaining)), false};
        return {-a, m_s + stopDistance, 0, false};
    }
    const double c = cruiseFor(head);
    const double e = std::min(exitTarget(), c);
    // Rounding noise is judged against the scale of the whole vector, not the (possibly tiny)
    // speed left near its end.
    const double tol = 1e-9 * std::max({v2, sq(c), a * length}) + 1e-9;
    // Cannot brake in time: brake all the way and arrive too fast (a brake violation).
    if (v2 - 2 * a * remaining > sq(e) + tol)
        return {-a, length, std::sqrt(v2 - 2 * a * remaining), true};
    // Cannot even reach the exit speed: accelerate all the way.
    if (v2 + 2 * a * remaining <= sq(e))
        return {a, length, std::sqrt(v2 + 2 * a * remaining), false};
    if (m_v > c * (1 + kRel) + 1e-9) // entered faster than this vector's cruise speed
        return {-a, m_s + (v2 - sq(c)) / (2 * a), c, false};
    const double peak = std::min(c, std::sqrt((v2 + sq(e)) / 2 + a * remaining));
    if (m_v < peak * (1 - kRel) - 1e-9)
        return {a, m_s + (sq(peak) - v2) / (2 * a), peak, false};
    const double brakeDistance = std::max(0.0, (v2 - sq(e)) / (2 * a));
    if (remaining - brakeDistance > kRel * length + 1e-9)
        return {0, length - brakeDistance, m_v, false};
    return {-a, length, e, true};
}

double MotionEngine::timeTo(double sTarget, const Segment &seg) const
{
    const double distance = sTarget - m_s;
    if (distance <= kSnapSteps)
        return 0; // closer than rounding noise: the boundary is here

    const double disc = sq(m_v) + 2 * seg.accel * distance;
    const double denom = m_v + std::sqrt(std::max(0.0, disc));
    if (denom <= 0)
        return kNever;
    return 2 * distance / denom;
}

std::int64_t MotionEngine::partial(const MotionVector &v, double s, int axis) const
{
    const std::int64_t d = v.steps[axis];
    if (d == 0)
        return 0;
    const double length = v.lengthSteps();
    const std::int64_t mag = d < 0 ? -d : d;
    if (s >= length)
        return d;
    // One rounding rule: steps done = floor(|d| * s / L) (slack absorbs the rounding of s).
    auto done = static_cast<std::int64_t>(std::floor(double(mag) * s / length + 1e-6));
    done = std::clamp<std::int64_t>(done, 0, mag);
    return d < 0 ? -done : done;
}

double MotionEngine::nextWatchProgress() const
{
    const MotionVector &head = m_queue.front();
    const double length = head.lengthSteps();
    double best = kNever;
    for (const Watch &w : m_watches) {
        const std::int64_t d = head.steps[w.axis];
        if (d == 0)
            continue;
        const std::int64_t base = m_base[w.axis];
        const std::int64_t done = std::abs(partial(head, m_s, w.axis));
        // Steps after which the counter reaches threshold (upward) or threshold-1 (downward).
        const std::int64_t k = d > 0 ? w.threshold - base : base - w.threshold + 1;
        const std::int64_t mag = d < 0 ? -d : d;
        if (k > done && k <= mag)
            best = std::min(best, std::max(m_s, double(k) * length / double(mag)));
    }
    return best;
}

double MotionEngine::dwellRemaining() const
{
    if (!m_queue.empty() && m_queue.front().isHoming)
        return 0; // homing travel is one move: no T pause between its legs
    return std::max(0.0, m_restSince + m_pauseS - m_now);
}

double MotionEngine::nextEventIn() const
{
    if (m_queue.empty() || m_held)
        return kNever;
    if (!m_started)
        return dwellRemaining();
    const Segment seg = currentSegment();
    return timeTo(std::min(seg.sEnd, nextWatchProgress()), seg);
}

void MotionEngine::step(double dt)
{
    if (m_queue.empty() || m_held) {
        m_now += dt;
        return;
    }
    if (!m_started) {
        const double rest = dwellRemaining();
        m_now += dt;
        if (dt + 1e-15 < rest)
            return;
        m_started = true;
        const MotionVector &head = m_queue.front();
        if (!head.isLine && !head.isHoming && m_prevEndedDry) {
            ++m_stats.starvationStops;
            if (m_stats.starvationAtS.size() < MotionStats::kStarvationTimes)
                m_stats.starvationAtS.push_back(m_now);
        }
        m_prevEndedDry = false;
        record();
        if (onVectorStart)
            onVectorStart(head);
        return;
    }
    const Segment seg = currentSegment();
    if (seg.finalBrake && !m_queue.front().isLine && exitTarget() == 0)
        m_committedToZero = true; // braking to zero has begun: a late C no longer helps
    const double sNext = std::min(seg.sEnd, nextWatchProgress());
    const double tEnd = timeTo(sNext, seg);
    if (dt >= tEnd) {
        if (sNext >= seg.sEnd)
            m_v = seg.vEnd;
        else
            m_v = std::sqrt(std::max(0.0, sq(m_v) + 2 * seg.accel * (sNext - m_s)));
        m_s = sNext;
        dt = tEnd;
    } else {
        m_s = std::min(sNext, m_s + m_v * dt + 0.5 * seg.accel * dt * dt);
        m_v = std::max(0.0, m_v + seg.accel * dt);
    }
    m_now += dt;
    m_stats.movingTimeS += dt;
    notePeak();
    const double length = m_queue.front().lengthSteps();
    const bool reachedEnd = m_s >= length;
    if (m_stopping && m_v <= 0 && dt == tEnd) {
        m_v = 0;
        if (reachedEnd)
            completeHead(); // may already finish the stop when nothing follows
        if (m_stopping)
            finishStop();
        return;
    }
    if (reachedEnd)
        completeHead();
    else if (dt == tEnd)
        record();
}

void MotionEngine::finishStop()
{
    m_v = 0;
    m_stopping = false;
    m_held = true;
    m_restSince = m_now;
    m_started = false;
    m_prevEndedDry = false;
    record();
    if (onStopped)
        onStopped();
}

void MotionEngine::completeHead()
{
    const MotionVector head = m_queue.front();
    // A stop (H) brakes along the ramp across whatever is queued; it is within the ramp as long
    // as a C is there to brake into. Running off the queue (or into an L) while still moving
    // stops dead: the same fault as a vector too short to brake (docs/gve-protocol.md §7).
    double allowed = kNever;
    if (m_stopping) {
        const bool brakesOn = m_queue.size() > 1 && !m_queue[1].isLine && !m_queue[1].isHoming;
        if (!brakesOn && !head.isHoming)
            allowed = 0;
    } else if (head.lengthSteps() > 0) {
        allowed = std::min(exitTarget(), cruiseFor(head));
    }
    for (int i = 0; i < kMaxAxes; ++i)
        m_base[i] += head.steps[i];
    m_queue.pop_front();
    m_s = 0;
    m_committedToZero = false;
    if (!head.isHoming) {
        ++m_stats.vectorsExecuted;
        const double excess = m_v - allowed;
        if (excess > readings::kBrakeViolationTolerance + 1e-9 * allowed) {
            ++m_stats.brakeViolations;
            if (m_stats.brakeViolationAtS.size() < MotionStats::kStarvationTimes)
                m_stats.brakeViolationAtS.push_back(m_now);
            m_stats.worstBrakeExcessPulsesPerS =
                std::max(m_stats.worstBrakeExcessPulsesPerS, excess);
        }
    }
    const bool continues =
        !m_queue.empty() && m_v > 0 && !m_queue.front().isLine && !m_queue.front().isHoming;
    if (continues) {
        m_started = true;
        if (onVectorStart)
            onVectorStart(m_queue.front());
    } else {
        m_v = 0; // an arrival above zero with nothing to continue into stops dead
        m_restSince = m_now;
        m_started = false;
        m_prevEndedDry = !head.isLine && !head.isHoming && !m_stopping;
    }
    record();
    if (onVectorDone)
        onVectorDone(head);
    if (m_stopping && !continues)
        finishStop();
}

void MotionEngine::notePeak()
{
    if (m_queue.empty())
        return;
    const MotionVector &head = m_queue.front();
    if (head.isHoming)
        return;
    const double length = head.lengthSteps();
    if (length <= 0)
        return;
    for (int i = 0; i < kMaxAxes; ++i) {
        const double axisSpeed = m_v * std::abs(double(head.steps[i])) / length;
        m_stats.peakAxisSpeedPulsesPerS[i] =
            std::max(m_stats.peakAxisSpeedPulsesPerS[i], axisSpeed);
        if (m_axisMax[i] > 0 && axisSpeed > m_axisMax[i] + readings::kAxisOverMaxTolerance &&
            head.serial != m_overMaxSerial) {
            m_overMaxSerial = head.serial;
            ++m_stats.axisOverMax;
        }
    }
}

std::array<std::int64_t, kMaxAxes> MotionEngine::headEnd() const
{
    auto end = m_base;
    if (!m_queue.empty()) {
        for (int i = 0; i < kMaxAxes; ++i)
            end[i] += m_queue.front().steps[i];
    }
    return end;
}

void MotionEngine::record()
{
    if (m_traceEnabled)
        m_trace.push_back({m_now, position(), m_v});
}

void MotionEngine::reset()
{
    MotionEngine fresh;
    fresh.m_now = m_now;
    fresh.m_stats = m_stats;
    fresh.m_trace = std::move(m_trace);
    fresh.m_traceEnabled = m_traceEnabled;
    fresh.m_watches = std::move(m_watches);
    fresh.m_limits.maxPulseRate = m_limits.maxPulseRate;
    fresh.onStopped = std::move(onStopped);
    fresh.onVectorDone = std::move(onVectorDone);
    fresh.onVectorStart = std::move(onVectorStart);
    fresh.m_axisMax = m_axisMax;
    fresh.m_overMaxSerial = m_overMaxSerial;
    *this = std::move(fresh);
}

void MotionEngine::enqueue(const MotionVector &v)
{
    if (readings::kZeroVectorDoneAtOnce && m_queue.empty() && !m_held && v.lengthSteps() == 0) {
        if (!v.isHoming)
            ++m_stats.vectorsExecuted;
        m_prevEndedDry = false;
        if (onVectorDone)
            onVectorDone(v);
        return;
    }
    m_queue.push_back(v);
}

void MotionEngine::requestStop()
{
    // H at rest with nothing queued changes nothing about how the last vector ended: the C that
    // starts after it (a chain the driver held at its start) still restarts a unit that ran dry.
    if (!m_queue.empty() || m_v > 0)
        m_prevEndedDry = false;
    if (m_queue.empty() || m_held || !m_started || m_v <= 0) {
        m_held = true;
        m_stopping = false;
        m_v = 0;
        if (m_started)
            m_restSince = m_now;
        m_started = false;
        if (onStopped)
            onStopped();
        return;
    }
    m_stopping = true;
}

void MotionEngine::release()
{
    m_held = false;
}

void MotionEngine::clear()
{
    if (!m_queue.empty()) {
        for (int i = 0; i < kMaxAxes; ++i)
            m_base[i] += partial(m_queue.front(), m_s, i);
    }
    m_queue.clear();
    m_s = 0;
    m_v = 0;
    m_started = false;
    m_stopping = false;
    m_committedToZero = false;
    m_prevEndedDry = false;
}

void MotionEngine::abortHead()
{
    if (m_queue.empty())
        return;
    for (int i = 0; i < kMaxAxes; ++i)
        m_base[i] += partial(m_queue.front(), m_s, i);
    m_queue.pop_front();
    m_s = 0;
    m_v = 0;
    m_started = false;
    m_committedToZero = false;
    m_restSince = m_now;
    record();
}

MotionEngine::Saved MotionEngine::takeQueue()
{
    Saved saved{m_queue, m_s};
    clear();
    return saved;
}

void MotionEngine::restoreQueue(Saved saved)
{
    clear();
    if (saved.queue.empty())
        return;
    m_queue = std::move(saved.queue);
    m_s = saved.headProgress;
    for (int i = 0; i < kMaxAxes; ++i)
        m_base[i] -= partial(m_queue.front(), m_s, i);
}

std::array<std::int64_t, kMaxAxes> MotionEngine::position() const
{
    auto pos = m_base;
    if (!m_queue.empty() && m_s > 0) {
        for (int i = 0; i < kMaxAxes; ++i)
            pos[i] += partial(m_queue.front(), m_s, i);
    }
    return pos;
}

void MotionEngine::setPosition(int axis, std::int64_t value)
{
    const std::int64_t current = position()[axis];
    m_base[axis] += value - current;
}

} // namespace frezka::emulator
