#pragma once
// The interpreter's state where a chosen line of the program begins, for running a program from
// that line (session/runfromline.h). The interpreter runs the whole program as usual and, when
// Options::startLine is set, records its modal state at the moment the first line at or after
// it is about to run at the program's top level (not inside a subroutine call), with the index
// of the toolpath entry that line starts at: everything the program does before that index is
// what a run from the line skips, everything from it on is what it runs, in the same machine
// coordinates (LinuxCNC's run from line runs the lines before with their motion discarded, which
// leaves the same state).
//
// A line the program runs more than once (inside an O-word loop), only when called (inside a
// subroutine), or never (a branch not taken, after the program's end) has no single state to
// start from: the mark says why and names the line to choose instead.

#include "gcode/toolpath.h"

#include <array>
#include <cstdint>
#include <string>

namespace frezka::gcode {

struct LineState
{
    Point4 machineMm;         // where the machine is when the line begins (mm, A degrees)
    Point4 programMm;         // the same point in the program's coordinates (mm)
    bool metric = true;       // G21 (false: G20)
    int plane = 170;          // 10 x G code: 170 G17, 180 G18, 190 G19
    bool absolute = true;     // G90 (false: G91)
    bool arcAbsolute = false; // G90.1 (false: G91.1)
    bool inverseTime = false; // G93 (false: G94)
    int coordinateSystem = 0; // 0 = G54 .. 8 = G59.3
    std::array<double, 4> workOffsetMm{}; // of the active system, machine mm
    std::array<double, 4> g92Mm{};        // the G92 offset in force
    int tool = 0;                         // in the spindle (M6 loaded it)
    int selectedTool = 0;                 // T
    double toolLengthMm = 0;              // G43's offset in force (0: G49)
    double speedRpm = 0;                  // S
    int spindle = 0;                      // 1 M3, -1 M4, 0 M5
    bool mist = false;                    // M7
    bool flood = false;                   // M8
    double feedMmPerMin = 0;              // the modal feed (G94), mm/min
    int motion = 800;                     // 10 x G code of the motion mode (800: G80)
    int pathMode = 2;                     // 0 G61, 1 G61.1, 2 G64
    double pathToleranceMm = 0;           // G64 P
    double pathQMm = 0;                   // G64 Q
    friend bool operator==(const LineState &, const LineState &) = default;
};

enum class LineMarkRefusal : std::uint8_t {
    None,
    NotReached,   // after the program's end or past its last line (refLine: the last line run)
    InSubroutine, // in a subroutine's body (refLine: its sub line)
    InCall,       // run only by a call (refLine: the call's line at the top level)
    InLoop,       // inside a loop (refLine: the loop's opening line)
    NotTaken,     // in a branch or loop body the program skips (refLine: the O line skipping it)
    InCutterComp, // cutter radius compensation is on there (refLine: its G41/G42 line)
};

struct LineMark
{
    std::uint32_t askedLine = 0; // Options::startLine
    std::uint32_t line = 0;      // the line the run starts at (the first run at or after it)
    std::size_t entry = 0;       // toolpath entries before it
    LineState state;
    LineMarkRefusal refusal = LineMarkRefusal::None;
    std::uint32_t refLine = 0;
    std::string label; // the O word's label ("100", "<name>")
    bool ok() const { return refusal == LineMarkRefusal::None; }
};

} // namespace frezka::gcode
