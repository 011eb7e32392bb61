#pragma once
// Motion engine of the emulated unit: the vector queue and the trapezoid model of
// docs/gve-protocol.md §4.2, stepped analytically from event to event.
//
// A vector runs along a path of length `lengthSteps` (VN: major-axis steps, VK: Euclidean length
// of the XYZ step vector). The path speed v(s) is piecewise: accelerate with A toward the cruise
// speed (V for long vectors, min(V, B) for short ones), cruise, then brake with A to the exit
// speed. The exit speed is B when another C waits in the queue at the moment braking must begin,
// else 0 (a C that then stops and is followed by another C counts as a starvation stop). A vector
// too short to brake from its entry speed to its exit speed arrives faster: a brake violation.
//
// Nothing is integrated in small steps: the engine knows the current segment (constant
// acceleration +A, 0 or -A) and where it ends, and `step()` moves to any time up to that end in
// closed form. Axis counters are integers derived from the path position with one rule
// (steps done = floor(|d| * s / L)), and a completed vector adds exactly its steps.

#include <array>
#include <cstdint>
#include <deque>
#include <functional>
#include <limits>
#include <vector>

namespace frezka::emulator {

inline constexpr int kMaxAxes = 4;
inline constexpr double kNever = std::numeric_limits<double>::infinity();

// A vector as captured when it was accepted.
struct MotionVector
{
    std::array<std::int64_t, kMaxAxes> steps{}; // relative steps per axis
    bool isLine = false;                        // L: stand-alone, ends at zero speed
    bool isHoming = false;                      // W travel: constant speed, no statistics
    bool isShort = false;                       // major-axis steps < $ at acceptance
    bool velocityCorrection = false;            // VK (path = Euclidean) instead of VN
    double speedPulsesPerS = 0;                 // V captured (path speed)
    double brakePulsesPerS = 0;                 // B captured (exit speed when a C follows)
    double accelPulsesPerS2 = 0;                // A captured
    std::uint64_t serial = 0;                   // acceptance order, for traces

    double lengthSteps() const;
    bool operator==(const MotionVector &) const = default;
};

struct TracePoint
{
    double timeS = 0;
    std::array<std::int64_t, kMaxAxes> position{};
    double pathSpeedPulsesPerS = 0;
    bool operator==(const TracePoint &) const = default;
};

struct MotionStats
{
    static constexpr std::size_t kStarvationTimes = 256;
    std::int64_t vectorsExecuted = 0;      // L and C vectors completed (homing travel not counted)
    std::int64_t brakeViolations = 0;      // vectors that arrived faster than their exit speed
    double worstBrakeExcessPulsesPerS = 0; // largest arrival speed above the allowed exit speed
    std::vector<double> brakeViolationAtS; // when the first kStarvationTimes of them happened
    std::int64_t starvationStops = 0;      // C stopped because the queue ran dry, then a C followed
    std::vector<double> starvationAtS;     // when the first kStarvationTimes of them restarted
    std::array<double, kMaxAxes> peakAxisSpeedPulsesPerS{};
    double movingTimeS = 0;       // time with a vector executing (dwell excluded)
    std::int64_t axisOverMax = 0; // vectors in which an axis ran above its maximum (setAxisMax)
    bool operator==(const MotionStats &) const = default;
};

// Global speed modifiers that act at execution time (XM, VL, the unit's pulse rate).
struct SpeedLimits
{
    int xmPercent = 100;
    std::array<double, kMaxAxes> velocityLimitPulsesPerS{};
    double maxPulseRate = 50000;
};

class MotionEngine
{
public:
    MotionEngine() = default;
    // Back to the power-on state (J): empty queue, counters zero, at rest. Keeps the clock,
    // statistics, trace, watches and callbacks (they belong to the emulator, not the unit).
    void reset();

    // Time of the engine clock, seconds since construction.
    double now() const { return m_now; }
    // Seconds until the next discrete change (segment or vector end, dwell end, watched
    // threshold); kNever when nothing moves or waits.
    double nextEventIn() const;
    // Moves the clock by dt (0 <= dt <= nextEventIn()) and handles whatever ends exactly there.
    void step(double dt);

    // Queue access. enqueue() never refuses; capacity is the caller's rule.
    void enqueue(const MotionVector &v);
    std::size_t queueLength() const { return m_queue.size(); }
    std::deque<MotionVector> &queue() { return m_queue; }
    bool isIdle() const { return m_queue.empty(); }
    // True while a vector executes or waits only for the T pause (not when held).
    bool isRunning() const { return !m_queue.empty() && !m_held; }
    bool isMoving() const { return isRunning() && m_v > 0; }
    bool isStopping() const { return m_stopping; }
    bool isHeld() const { return m_held; }
    double pathSpeed() const { return m_v; }

    // Brake along the ramp to zero (H, interrupts). When zero is reached the engine is held
    // and `onStopped` runs. Immediate when nothing moves.
    void requestStop();
    // Leave the held state and continue the queue (G).
    void release();
    // Drop everything queued, including a partially run head (D). Counters keep their value.
    void clear();
    // End the head vector where it is now, at zero speed (homing switch found).
    void abortHead();
    // Take the queue out (K) / put it back (R); counters stay exact across the two.
    struct Saved
    {
        std::deque<MotionVector> queue;
        double headProgress = 0;
    };
    Saved takeQueue();
    void restoreQueue(Saved saved);

    std::array<std::int64_t, kMaxAxes> position() const;
    void setPosition(int axis, std::int64_t value);

    void setPauseS(double pause) { m_pauseS = pause; }
    void setLimits(const SpeedLimits &limits) { m_limits = limits; }
    // The machine's axis maxima, pulses/s (0 = none), for MotionStats::axisOverMax only.
    void setAxisMax(const std::array<double, kMaxAxes> &max) { m_axisMax = max; }
    // Counters where the head vector ends (the position when nothing is queued).
    std::array<std::int64_t, kMaxAxes> headEnd() const;
    const SpeedLimits &limits() const { return m_limits; }

    // Axis thresholds to stop at: an event happens when the counter of `axis` moves from below
    // `threshold` to at or above it, or back.
    struct Watch
    {
        int axis = 0;
        std::int64_t threshold = 0;
    };
    void setWatches(std::vector<Watch> watches) { m_watches = std::move(watches); }

    void setTraceEnabled(bool on) { m_traceEnabled = on; }
    const std::vector<TracePoint> &trace() const { return m_trace; }
    void clearTrace() { m_trace.clear(); }
    const MotionStats &stats() const { return m_stats; }

    // Called when a stop requested by requestStop() has completed.
    std::function<void()> onStopped;
    // Called when a vector completes (after its steps were added).
    std::function<void(const MotionVector &)> onVectorDone;
    // Called when the head vector starts to move: from rest, out of a chain, or again after a
    // stop (G). For the emulator's safety counters; changes nothing of the motion.
    std::function<void(const MotionVector &)> onVectorStart;

private:
    struct Segment
    {
        double accel = 0; // +A, 0 or -A (pulses/s^2)
        double sEnd = 0;  // path position where it ends
        double vEnd = 0;
        bool finalBrake = false; // braking to the exit speed
    };
    Segment currentSegment() const;
    double exitTarget() const;
    double cruiseFor(const MotionVector &v) const;
    double timeTo(double sTarget, const Segment &seg) const;
    double nextWatchProgress() const;
    double dwellRemaining() const;
    std::int64_t partial(const MotionVector &v, double s, int axis) const;
    void completeHead();
    void finishStop();
    void notePeak();
    void record();

    std::deque<MotionVector> m_queue;
    std::array<std::int64_t, kMaxAxes> m_base{}; // counters at the start of the head vector
    double m_now = 0;
    double m_s = 0; // progress along the head vector, steps of path
    double m_v = 0; // path speed, pulses/s
    bool m_committedToZero = false;
    bool m_stopping = false;
    bool m_held = false;
    bool m_prevEndedDry = false;
    bool m_started = false;    // head vector has started (dwell done)
    double m_restSince = -1e9; // time the machine last came to rest
    double m_pauseS = 0;
    SpeedLimits m_limits;
    std::array<double, kMaxAxes> m_axisMax{};
    std::uint64_t m_overMaxSerial = 0; // the last vector counted in axisOverMax
    std::vector<Watch> m_watches;
    bool m_traceEnabled = false;
    std::vector<TracePoint> m_trace;
    MotionStats m_stats;
};

} // namespace frezka::emulator
