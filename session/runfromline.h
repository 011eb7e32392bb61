#pragma once
// Run from a line, one implementation for both front ends (the GUI's "Run from this line…",
// frezka-cli run --from-line N). The program is interpreted whole with the start line marked
// (gcode/linestate.h: its modal state where the line begins, LinuxCNC's run from line), and the
// job becomes: the line's path mode, the spindle and coolant as they are at the line (the
// planner waits the spindle's spin-up as after any M3), the safe approach (machine/
// lineapproach.h: Z up to the safe height, X/Y/A across, Z down at the line's feed to where the
// line begins), then the program's own entries from the line on, in the same machine
// coordinates, so that the job ends exactly where the whole program ends. Every entry of the
// approach carries the start line, so the listing shows it while it runs.
//
// A line the program does not run exactly once from the top level (inside a loop or a
// subroutine, in a branch not taken, after the end) and a line with no feed in force (G93, no
// F yet) are refused with the reason and the line to choose instead. Pure functions; texts in
// the user's language.

#include "gcode/linestate.h"
#include "gcode/toolpath.h"
#include "machine/machineconfig.h"

#include <QCoreApplication>
#include <QString>

#include <cstdint>
#include <memory>

namespace frezka::session {

struct RunFromLine
{
    Q_DECLARE_TR_FUNCTIONS(RunFromLine)
};

struct FromLine
{
    std::uint32_t askedLine = 0;     // what the operator chose
    std::uint32_t line = 0;          // the line the program's rest starts at
    gcode::LineState state;          // the interpreter's modal state there
    double safeZMm = 0;              // machine mm the approach moves across at
    std::size_t approachEntries = 0; // entries before the program's rest (events and moves)
    friend bool operator==(const FromLine &, const FromLine &) = default;
};

struct FromLineOutcome
{
    std::shared_ptr<gcode::Toolpath> toolpath; // the job; null when refused
    FromLine from;
    QString refusal; // why not and what to choose instead (empty when the job is there)
    bool ok() const { return toolpath != nullptr; }
};

// The job for a run from mark.askedLine: `whole` is the program interpreted with
// gcode::Options::startLine = that line (its mark), `fromMm` where the machine stands (machine
// mm), fileName for the refusal's "FILE:LINE: ...".
FromLineOutcome runFromLine(const gcode::Toolpath &whole, const gcode::LineMark &mark,
                            const machine::MachineConfig &config, const gcode::Point4 &fromMm,
                            const QString &fileName);

// "Line 12: tool 2 (length 10.000 mm), S12000 M3, M8, F600, G54 G90 G21 G17; the approach
// crosses at Z -10.000 (machine)": what the machine is about to take as the state at the line.
QString fromLineSummary(const FromLine &from);

} // namespace frezka::session
