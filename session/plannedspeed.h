#pragma once
// The planned speed along a program and the planned time to each of its lines, derived from the
// unit program the planner made: the speed plot's curve and the run's ETA. Pure functions.

#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <cstdint>
#include <vector>

namespace frezka::session {

struct SpeedSample
{
    double distanceMm = 0;
    double speedMmPerMin = 0;
    std::uint32_t line = 0;
    friend bool operator==(const SpeedSample &, const SpeedSample &) = default;
};

// Keeps at most maxPoints samples, preserving the minimum and maximum of each bucket so dips
// stay visible.
std::vector<SpeedSample> decimateSpeed(const std::vector<SpeedSample> &in, std::size_t maxPoints);

// Planned speed samples (mm/min over path mm) from a unit program: the cruise speed of each
// vector at its middle and the brake speed at its end.
std::vector<SpeedSample> plannedSpeed(const machine::UnitProgram &program,
                                      const machine::MachineConfig &config, bool speedModeVk);

// decimateSpeed(plannedSpeed(...), maxPoints), the same samples, without the three samples a
// vector in between (72 bytes a vector, 1.2 GB at the peak for 5 million vectors: issue 17):
// it counts the samples first, then keeps each bucket's minimum and maximum as they come.
std::vector<SpeedSample> plannedSpeedDecimated(const machine::UnitProgram &program,
                                               const machine::MachineConfig &config,
                                               bool speedModeVk, std::size_t maxPoints);

// Planned seconds to the end of each source line (index = line), from the vectors' speeds and
// the dwells, scaled so that the last equals totalS (the planner's estimate with its waits).
std::vector<float> plannedLineTimes(const machine::UnitProgram &program, bool speedModeVk,
                                    double totalS);

} // namespace frezka::session
