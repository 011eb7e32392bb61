#pragma once
// Where a program written relative to its stock would sit, and the work zero that puts it there
// (issue 16 item 7). Nearly every CAM program has X/Y around 0 and its safe heights at Z+; on a
// machine whose travel starts at 0 it leaves the travel until the work zero is set. The operator
// brings the tool to a point of the stock — its corner, its centre, or where the program's own
// X0 Y0 is — with the tool tip on the stock's top (the program's Z0), and this gives the active
// system's offset that puts that point of the program's extent there. Pure.

#include "session/travelcheck.h"
#include "session/workoffsets.h"

#include "machine/machineconfig.h"

namespace frezka::session {

// The point of the program's X/Y extent the operator's position stands for.
enum class StockAnchor {
    ProgramZero, // the program's own X0 Y0
    FrontLeft,   // X min, Y min of the extent
    FrontRight,  // X max, Y min
    BackLeft,    // X min, Y max
    BackRight,   // X max, Y max
    Centre,      // the middle of the extent
};

// The active system's new offset (mm) that puts the anchor of the program's extent (fit: at
// the offsets `offsets`) at machineMm on X and Y, and the program's Z0 at machineMm's Z; A is
// kept. G92 stays as it is.
Axes4 stockZeroOffset(const TravelFit &fit, const OffsetState &offsets, const Axes4 &machineMm,
                      StockAnchor anchor);

// The extent the program would have (machine mm) with the active system at newOffsetMm.
struct Placement
{
    Axes4 minMm{}, maxMm{};
    bool inside = true; // within the soft limits on every present axis
};
Placement placeProgram(const TravelFit &fit, const OffsetState &offsets, const Axes4 &newOffsetMm,
                       const machine::MachineConfig &config);

} // namespace frezka::session
