#pragma once
// Runs LinuxCNC's standalone interpreter `rs274` (Debian package linuxcnc-uspace) on a file and
// reads its canonical output back as motions in machine coordinates (mm), for the differential
// tests. rs274 prints program coordinates; the SET_G5X_OFFSET, SET_G92_OFFSET,
// USE_TOOL_LENGTH_OFFSET and USE_LENGTH_UNITS lines it prints are applied to get machine mm.

#include "gcode/toolpath.h"
#include "gcode/tooltable.h"

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
    // The feed in force (SET_FEED_RATE in the units of its call, in mm/min: LinuxCNC's canon
    // keeps the physical rate across a units change), the dwell time (s) and the spindle speed
    // in force (rpm; + M3, - M4, 0 when stopped).
    double feedMmPerMin = 0;
    double dwellSeconds = 0;
    double spindleRpm = 0;
    std::string call; // the canonical line, for messages
    // NURBS_FEED (G5, G5.1, G5.3): rs274 prints no coordinates (end is not set); it stands for
    // Frezka's chords of the curve, the feed moves of one source line.
    bool spline = false;
};

struct Rs274Run
{
    bool available = false; // rs274 found on PATH
    std::vector<CanonMove> moves;
    std::string error;     // rs274's error message, empty when none
    std::string errorLine; // the program line rs274 quoted with the error
    // rs274's error is only that the file ended without M2/M30/% (which Frezka accepts with a
    // warning): the motions before it are complete.
    bool endedWithoutEnd() const;
};

std::string rs274Path(); // empty when not installed
// tools: the tool table (mm) both see; none: every tool 1..99 of length 0 for rs274, no table
// for Frezka. rs274 reads the table in inches (its standalone machine units), so it gets a copy
// converted from mm. ini: a LinuxCNC INI file rs274 is given (-i; a copy with SUBROUTINE_PATH's
// folders made absolute from the INI's folder, as rs274 runs in a folder of its own). A run that
// ends with exit status 0 has no error (lines a PRINT comment printed are not errors).
Rs274Run runRs274(const std::string &file, const ToolTable *tools = nullptr,
                  const std::string &ini = {});

// Runs the file through both interpreters: same motion and dwell sequence, kinds, end points and
// arc centres within 1e-4 program units (rs274 prints 4 decimals), same arc planes and turns,
// the same feed (mm/min) on every feed, arc and probe move, the same dwell times and the same
// spindle speed in force at every motion and dwell. rs274 sees rs274File when given (a copy
// edited to LinuxCNC's dialect, e.g. without the K0 words Frezka accepts and rs274 refuses).
// ini: the LinuxCNC INI file both see (Frezka: readLinuxCncIniFile; rs274: -i).
testing::AssertionResult matchesRs274(const std::string &file, const std::string &rs274File = {},
                                      const ToolTable *tools = nullptr,
                                      const std::string &ini = {});

} // namespace frezka::gcode::test
