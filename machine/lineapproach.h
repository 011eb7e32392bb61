#pragma once
// The approach of a run from a line (session/runfromline.h): from where the machine stands to
// the point where the chosen line begins, without cutting on the way. Z rises to the safe
// height first, X, Y and A go to the line's start at that height (rapids), and Z comes down to
// the start at the line's feed (a cut may start in the material, so the last move is a feed).
// Pure functions of the profile and positions in machine mm.
//
// The safe height is the highest of: the program's own clearance (the highest Z any of its
// moves reaches, which its plan has already kept within the soft limits), the line's start
// lifted by motion.toolLiftMm, and where Z stands already; capped at the Z soft maximum, which
// only a Z already above it exceeds (the approach never lowers Z before moving sideways).

#include "machine/machineconfig.h"

#include "gcode/toolpath.h"

#include <vector>

namespace frezka::machine {

struct ApproachMove
{
    gcode::Point4 endMm;
    bool feed = false; // false: rapid
    friend bool operator==(const ApproachMove &, const ApproachMove &) = default;
};

// The safe height (machine mm) for an approach from `fromMm` to `toMm` of `program` (the whole
// program, in machine mm).
double approachSafeZ(const MachineConfig &config, const gcode::Toolpath &program,
                     const gcode::Point4 &fromMm, const gcode::Point4 &toMm);

// The moves from `fromMm` to `toMm` by way of `safeZMm`: up, across, down (a move that would
// not move is left out).
std::vector<ApproachMove> lineApproach(const gcode::Point4 &fromMm, const gcode::Point4 &toMm,
                                       double safeZMm);

} // namespace frezka::machine
