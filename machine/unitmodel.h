#pragma once
// The unit's motion model (docs/gve-protocol.md §4.2) applied to a UnitProgram: job time,
// brake violations and the speed at every vertex, without an emulator.
//
// Each C vector runs a trapezoid with its captured acceleration A: entry speed = exit speed of
// the vector before; cruise target V (long vector, >= $ in its speed units) or its B (short);
// exit speed B when another C follows in the chain, else 0. Distances are in the speed units
// of the mode: VN the major axis's steps, VK sqrt(dx²+dy²+dz²) steps. A chain ends at any
// PC-side wait (WaitIdle, Dwell, OperatorStop, Probe, ProgramEnd), where the queue drains.

#include "machine/unitprogram.h"

#include <cstddef>
#include <vector>

namespace frezka::machine {

// One vector's trapezoid: entry speed e, cruise target c, exit target x, acceleration a (all in
// the same units), distance n > 0. The vector arrives at exit (<= x unless it could not brake).
struct VectorRun
{
    double timeS = 0;
    double exit = 0;
    double peak = 0;        // highest speed inside the vector (0: never above entry and exit)
    bool violation = false; // could not slow from e to x within n
};
VectorRun runVector(double e, double c, double x, double a, double n);

// T (pause between non-continuous vectors) the model assumes until the program sets one.
inline constexpr double kInitialPauseS = 0.010;

struct ModelResult
{
    double motionS = 0; // time with the axes moving
    double waitS = 0;   // Dwell ms (PC side) and T pauses after rests
    std::size_t vectors = 0;
    std::size_t chains = 0;
    std::size_t brakeViolations = 0;
    double peakSpeed = 0;             // highest speed reached, in the mode's units (pulses/s)
    std::vector<double> vertexSpeeds; // per C vector, the speed it ends at (its real exit)
    std::vector<double> vectorTimes;  // per C/L vector, the time it runs, s
    double totalS() const { return motionS + waitS; }
};

// Runs a program through the §4.2 model. speedModeVk: the mode at the program's start (the
// program's own VK/VN commands switch it).
ModelResult runUnitModel(const UnitProgram &program, bool speedModeVk = false);

// Distance of a vector in the speed units of the mode (VN: major axis steps, VK: the length of
// its X/Y/Z step vector).
double speedUnitsLength(const std::array<std::int32_t, 4> &d, bool vk);

} // namespace frezka::machine
