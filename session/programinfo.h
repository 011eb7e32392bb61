#pragma once
// What the Program info window says about a loaded program (issue 16 item 7): its size, its
// extent in the program's own coordinates and on the machine, the tools it uses in their order
// with the planner's time for each, and its length and time. Pure: read from the loaded program
// (its toolpath, its planned line times) and the offsets it was read with.

#include "session/programsession.h"
#include "session/workoffsets.h"

#include <cstdint>
#include <vector>

namespace frezka::session {

// One tool's share of the job: from its M6 (or the start, tool -1 = the one in the spindle) to
// the next M6 or the end.
struct ToolShare
{
    int tool = -1;              // T of the M6, -1 = the tool in the spindle at the start
    std::uint32_t fromLine = 0; // the M6's line (1 for the start)
    double seconds = -1;        // planned, < 0 = not planned
    double cutLengthMm = 0;     // feed moves and arcs with this tool
    friend bool operator==(const ToolShare &, const ToolShare &) = default;
};

struct ProgramInfo
{
    std::int64_t lines = 0;
    std::int64_t bytes = 0;
    std::size_t motions = 0;
    bool moves = false;             // min/max mean something
    Axes4 workMinMm{}, workMaxMm{}; // the program's own coordinates (machine minus the offsets)
    Axes4 machineMinMm{}, machineMaxMm{};
    std::vector<ToolShare> tools; // in program order; a first share only when it cuts
    double lengthMm = 0;
    double estimatedS = -1;
};

// machine: the profile the program was checked against (its travel decides nothing here).
ProgramInfo programInfo(const LoadedProgram &program, const OffsetState &offsets,
                        const machine::MachineConfig &config);

} // namespace frezka::session
