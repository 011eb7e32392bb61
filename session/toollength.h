#pragma once
// Tool length from a fixed tool-length sensor (issue 19 item 1; docs/probing.md "Tool length"):
// the profile's tools.sensor (machine::ToolSensorConfig) gives where the sensor is and how to
// probe it; session::HeightProbe::startAt() runs the probe (up to the clearance, across, G38.2
// down fast, back off, G38.2 slow, back up to the clearance; the probe input read before each
// probe move, a probe that does not trip within the travel an error). The tool's length is the
// slow trip's machine Z minus the sensor's referenceZMm, and goes into the tool table's Z (the
// length G43 applies), as LinuxCNC keeps it.

#include "session/heightprobe.h"

#include "gcode/tooltable.h"
#include "machine/machineconfig.h"

#include <QString>

namespace frezka::session {

// Empty when the profile's sensor can be used; else why not and what to do (translated).
QString toolSensorProblem(const machine::MachineConfig &config);
// The probing of the sensor (clearance, bottom = clearance - travel, fast, slow, retract, ending
// at the clearance).
HeightProbeSettings toolSensorSettings(const machine::ToolSensorConfig &sensor);
// The tool's length from its slow trip at machine Z tripZMm.
double toolLengthFromTrip(const machine::ToolSensorConfig &sensor, double tripZMm);
// Sets tool's length (the Z word) in the table; a tool not in it is added (pocket = tool, no
// diameter, a comment saying it was measured). The other words of an entry stay.
void setToolLength(gcode::ToolTable *table, int tool, double lengthMm);

} // namespace frezka::session
