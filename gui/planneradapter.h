#pragma once
// The planning step of ProgramSession: machine::plan() against the active profile. It turns
// plan errors (soft limits, absent axes, ...) into program errors with their line, keeps the
// unit program for the run, and derives the planned speed along the path for the plot and the
// duration for the ETA.

#include "programsession.h"

#include "machine/machineconfig.h"
#include "machine/planner.h"
#include "session/planerrortext.h"
#include "session/programplanner.h"

namespace frezka::gui {

AnalyseFn plannerAnalyser(const machine::MachineConfig &config, double feedOverride = 1.0);

// Planned speed samples (mm/min over path mm) from a unit program: the cruise speed of each
// vector at its middle and the brake speed at its end.
std::vector<SpeedSample> plannedSpeed(const machine::UnitProgram &program,
                                      const machine::MachineConfig &config, bool speedModeVk);

// Planned seconds to the end of each source line (index = line), from the vectors' lengths and
// speeds, scaled so that the last equals totalS (the planner's estimate with its waits).
std::vector<float> plannedLineTimes(const machine::UnitProgram &program,
                                    const machine::MachineConfig &config, bool speedModeVk,
                                    double totalS);

// Translated one-line text of a plan error (the session layer's).
using session::planErrorText;

} // namespace frezka::gui
