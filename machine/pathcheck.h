#pragma once
// The path guard's geometry (driver/link/pathguard.h): where the plan has the machine before a
// command, and whether a position read while a job runs lies on the planned path. Pure functions
// of the unit program and the counters; the guard decides what to do about it.
//
// The unit's counters step along the straight line of each vector, each axis within one step of
// it, so a position lies on a command's segment when some part t (0..1) of the segment has every
// axis within one step of the position.

#include "machine/unitprogram.h"

#include <cstddef>
#include <optional>

namespace frezka::machine {

// The planned position before program command `index` (after the motion before it; an index
// past the end: the program's end).
Steps4 plannedBefore(const UnitProgram &program, std::size_t index);

// Whether the first `axes` counters of a and b are equal.
bool sameSteps(const Steps4 &a, const Steps4 &b, int axes);

// The first command in [from, to) that moves (a vector, a line or a probe move) whose segment
// holds `position` within one step on each of the program's axes; nullopt when none does.
std::optional<std::size_t> segmentHolding(const UnitProgram &program, std::size_t from,
                                          std::size_t to, const Steps4 &position);

} // namespace frezka::machine
