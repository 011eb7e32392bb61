#pragma once
// Runs LinuxCNC's standalone interpreter `rs274` (Debian package linuxcnc-uspace) on a file and
// reads its canonical output back as motions in machine coordinates (mm), for the differential
// tests. rs274 prints program coordinates; the SET_G5X_OFFSET, SET_G92_OFFSET,
// USE_TOOL_LENGTH_OFFSET and USE_LENGTH_UNITS lines it prints are applied to get machine mm.

#include "gcode/toolpath.h"

#include <gtest/gtest.h>

#include <string>
#include <vector>

namespace frezka::gcode::test {

struct CanonMove
{
    MotionKind kind = MotionKind::Rapid; // Rapid, Feed, Arc, Probe or Dwell
    Point4 end;                          // machine mm (A degrees)
    Point4 centre;                       // arcs: in-plane coordinates of the centre
    Plane plane = Plane::XY;
    int turns = 0;
    double unitMm = 1; // 25.4 when the program was in G20 at this move
    std::string call;  // the canonical line, for messages
};

struct Rs274Run
{
    bool available = false; // rs274 found on PATH
    std::vector<CanonMove> moves;
    std::string error;     // rs274's error message, empty when none
    std::string errorLine; // the program line rs274 quoted with the error
};

std::string rs274Path(); // empty when not installed
Rs274Run runRs274(const std::string &file);

// Runs the file through both interpreters: same motion and dwell sequence, kinds, end points and
// arc centres within 1e-4 program units (rs274 prints 4 decimals), same arc planes and turns.
testing::AssertionResult matchesRs274(const std::string &file);

} // namespace frezka::gcode::test
