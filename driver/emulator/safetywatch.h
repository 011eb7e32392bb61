#pragma once
// SafetyWatch: what must never happen at the machine, counted by the emulator (issue 14).
//
// Contract: the unit tells it every change of the spindle (on = turning) and every vector that
// starts to move, and observes it at every event with whether the job is held (INTA or KEEP)
// while the machine stands. It counts a cut without the spindle (cutWithoutSpindle): a vector
// into the work — with a work surface, one with Z below it at either end; without one, any move
// of Z down — that starts while the spindle is off or not yet at speed (MachineModel::
// spindleSpinUpS after it was switched on), and the spindle switched off under such a vector;
// not a probe move (one that starts with the probe input armed to stop it: it goes toward the
// work with the spindle stopped, as probing must); and the spindle on while the job is held
// (spindleOnWhileHeld, once per held stand): longer than readings::kHeldSpindleGraceS after the
// stop, or than its spin-up plus that grace when it was switched on during the hold. Pure and
// clock-free: times are passed in.

#include <array>
#include <cstdint>

namespace frezka::emulator {

struct SafetyStats
{
    std::int64_t cutWithoutSpindle = 0;
    std::int64_t spindleOnWhileHeld = 0;
    bool operator==(const SafetyStats &) const = default;
};

// The machine behind the unit, as far as the safety counters need it.
struct MachineModel
{
    double spindleSpinUpS = 0;                 // from switching on to cutting speed
    std::array<double, 4> axisMaxPulsesPerS{}; // per axis, 0 = no limit (MotionStats::axisOverMax)
    bool hasWorkSurface = false;               // whether workSurfaceZSteps is known
    std::int64_t workSurfaceZSteps = 0;        // Z counter of the work's top (at it: a cut)
    bool operator==(const MachineModel &) const = default;
};

class SafetyWatch
{
public:
    using Steps = std::array<std::int64_t, 4>;

    void setModel(const MachineModel &model) { m_model = model; }
    // The spindle switched on or off at `now`; `cutting`: a vector into the work moves now.
    void spindle(bool on, double now, bool cutting);
    // A vector starts to move from `from` toward `to` at `now` (homing travel is not passed);
    // probing: the probe input is armed to stop it.
    void vectorStarts(const Steps &from, const Steps &to, double now, bool probing = false);
    // Whether a move from `from` to `to` goes into the work.
    bool intoWork(const Steps &from, const Steps &to) const;
    // Called at every event: the job held with the machine standing, now.
    void observe(bool heldStanding, double now);
    const SafetyStats &stats() const { return m_stats; }

private:
    bool atSpeed(double now) const;

    MachineModel m_model;
    SafetyStats m_stats;
    bool m_on = false;
    double m_onSince = 0;
    double m_heldSince = -1; // start of the current held stand with the spindle on, -1: none
    bool m_heldCounted = false;
};

} // namespace frezka::emulator
