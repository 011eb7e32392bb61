#pragma once
// Where a program sits against the machine's travel (the soft limits, axes.*.softMinMm ..
// softMaxMm), for a check before anything runs: which line first leaves the travel on each side
// of each axis and by how much, the farthest it goes, and whether the program would fit at some
// other work zero (its extent on every axis no larger than the travel) and the shift that puts
// it inside. The planner refuses such a program with the line; this says what to do about it
// (frezka-cli check). Arcs are followed along their chords (the planner's tolerance). Pure.

#include "session/workoffsets.h"

#include "gcode/toolpath.h"
#include "machine/machineconfig.h"

#include <array>
#include <cstdint>
#include <vector>

namespace frezka::session {

// One side of one axis the program leaves.
struct TravelExcursion
{
    int axis = 0;                // 0 X .. 3 A
    bool aboveMax = false;       // beyond softMaxMm (else below softMinMm)
    std::uint32_t firstLine = 0; // the first line that leaves the travel on this side
    double firstValueMm = 0;     // where that line goes (machine mm)
    double firstBeyondMm = 0;    // how far beyond the limit, > 0
    std::uint32_t farthestLine = 0;
    double farthestValueMm = 0;
    double farthestBeyondMm = 0;
    double limitMm = 0; // the limit it passes
    friend bool operator==(const TravelExcursion &, const TravelExcursion &) = default;
};

struct TravelFit
{
    std::vector<TravelExcursion> excursions; // in program order of their first lines
    bool fitsElsewhere = true; // the extent fits the travel on every axis: a work zero exists
    Axes4 shiftMm{};           // added to the work offset, puts the program inside (if it fits)
    // The program's own extent, machine mm at the offsets it was read with: per axis from the
    // first motion that moves that axis (the position it starts from is the machine's, not the
    // program's). moves = some motion moved some axis (else min/max mean nothing).
    bool moves = false;
    Axes4 minMm{}, maxMm{};
    bool inside() const { return excursions.empty(); }
};

TravelFit checkTravel(const gcode::Toolpath &toolpath, const machine::MachineConfig &config);

} // namespace frezka::session
