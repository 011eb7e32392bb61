#pragma once
// Cutter radius compensation (G40, G41, G42, G41.1, G42.1) as LinuxCNC's rs274ngc does it: the
// state the interpreter keeps (gcode/interp_comp.cpp does the moves) and the geometry that needs
// no interpreter.
//
// The compensated path needs one move of lookahead: where a move ends depends on the next one
// (an inside corner moves the end back to where the two offset paths meet). As in rs274ngc the
// last move is "queued": it is already in the toolpath, and the queue remembers which entries
// may still have their end moved (the move, and the Z-only moves and events after it). The next
// move in the plane fixes the end and "flushes" the queue; G40, M0, M1, M2 and M30 flush it at
// the current point. All coordinates here are the plane's (u, v) as in gcode/toolpath.h (XY:
// x, y; XZ: z, x) in program coordinates, mm.

#include "gcode/toolpath.h"

#include <cstddef>
#include <vector>

namespace frezka::gcode {

enum class CompSide : std::uint8_t { Off, Left, Right };

// Angles (radians) and lengths of rs274ngc's compensation (interp_internal.hh).
inline constexpr double kCompConcaveTolerance = 0.05; // TOLERANCE_CONCAVE_CORNER
inline constexpr double kCompEqualTolerance = 0.0001; // TOLERANCE_EQUAL

struct CompQueued
{
    std::size_t entry = 0;    // toolpath index of a queued motion
    double du = 0, dv = 0;    // straight: the programmed direction (a move must not reverse)
    double originalTurns = 0; // arc: its sweep when queued (0: an inserted corner arc)
};

struct CutterComp
{
    CompSide side = CompSide::Off;
    double radius = 0;          // mm, > 0 when compensating
    bool firstMove = true;      // the next move in the plane is the entry move
    bool arcNotAllowed = false; // the move after G40 must be straight
    std::uint32_t onLine = 0;   // the line of G41/G42 (run from a line refuses lines after it)
    std::vector<CompQueued> queue;
    double endU = 0, endV = 0; // where the queued moves start (rs274ngc's endpoint)
    bool endValid = false;

    bool on() const { return side != CompSide::Off; }
    bool active() const { return side != CompSide::Off && radius > 0; }
    void setEndpoint(double u, double v)
    {
        endU = u;
        endV = v;
        endValid = true;
    }
    // rs274ngc's dequeue_canons: the queued moves keep their ends.
    void dequeue()
    {
        queue.clear();
        endValid = false;
    }
};

// The tool is inside the arc it follows (left of a counter-clockwise arc, right of a clockwise).
inline bool toolInsideArc(CompSide side, int turn)
{
    return (side == CompSide::Left && turn > 0) || (side == CompSide::Right && turn < 0);
}

// The signed sweep (radians, + counter-clockwise) of an arc from (u1, v1) to (u2, v2) around
// (cu, cv) making `turn` turns (rs274ngc's find_turn); 0 when turn is 0.
double findTurn(double u1, double v1, double cu, double cv, int turn, double u2, double v2);

// Why a queued end could not be moved (rs274ngc's move_endpoint_and_flush errors).
enum class CompFault : std::uint8_t { None, StraightReversed, ArcTooLong, ArcRadiiDiffer };

// Moves the plane end of every queued motion of `path` to (u, v) (program coordinates; offsetU/V
// turn them into machine coordinates), then puts every event after the first queued entry at the
// end of the motion before it. radiusTolerance: the largest change of an arc's radius, arcSlack:
// how much longer an arc may get. Nothing is changed when a fault is returned.
CompFault moveQueuedEnds(Toolpath &path, const CutterComp &comp, Plane plane, double offsetU,
                         double offsetV, double u, double v, double radiusTolerance,
                         double arcSlack);

} // namespace frezka::gcode
