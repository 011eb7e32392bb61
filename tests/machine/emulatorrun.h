#pragma once
// Runs a UnitProgram on the in-process emulator core (driver/emulator), fed as fast as its
// queue accepts with no link delay, and measures what the plan promised: job time, brake
// violations, starvation stops, final counters and the real speed step at every vertex.
// Shared by the planner tests and the planner benchmark.

#include "driver/emulator/motion.h"
#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <cstdint>
#include <string>
#include <vector>

namespace frezka::machine::test {

struct EmulatorRun
{
    double jobS = 0;          // virtual time from the first command to the end
    std::int64_t vectors = 0; // vectors the unit executed
    std::int64_t brakeViolations = 0;
    double worstBrakeExcess = 0;      // pulses/s
    std::int64_t starvationStops = 0; // as the emulator counts them
    std::int64_t plannedStops = 0;    // machine::plannedRestarts of the program
    bool countersMatch = false;       // final counters == the plan's last endSteps
    std::size_t vertices = 0;         // vertices passed at speed
    std::size_t jumpOverLimit = 0;    // ... whose per-axis speed step exceeds the axis limit
    double maxJumpMmPerS = 0;
    double maxJumpRatio = 0; // largest speed step / axis limit
    std::string error;       // an unexpected reply; empty when all went well
};

EmulatorRun runOnEmulator(const UnitProgram &program, const MachineConfig &config);

// The per-axis speed step at every vertex the unit passed at speed, from its trace (a Unit
// with UnitOptions::trace), against the axes' jump limits.
struct JumpFigures
{
    std::size_t vertices = 0;  // vertices passed at speed
    std::size_t overLimit = 0; // ... whose speed step exceeds an axis's limit
    double maxJumpMmPerS = 0;
    double maxRatio = 0; // largest speed step / axis limit
};
JumpFigures measureJumps(const std::vector<emulator::TracePoint> &trace, const UnitProgram &program,
                         const MachineConfig &config);

} // namespace frezka::machine::test
