#pragma once
// Text forms of a Toolpath: JSON Lines (the `frezka-cli toolpath` format and the golden traces)
// and a summary (the `frezka-cli check` report). Numbers are written with 4 decimals by a
// fixed-point formatter (no printf), so a million moves are written in a fraction of a second.
//
// One object per entry:
//   {"line":N,"type":"rapid"|"feed"|"arc"|"probe"|"dwell","x":..,"y":..,"z":..,"a":..,"f":..}
// arcs add "cx","cy","cz" (centre, machine mm), "plane":"XY"|"XZ"|"YZ", "turns" (signed,
// + counter-clockwise); dwells add "seconds"; probes add "probe":"G38.2".."G38.5".
// With events, the other events are written as {"line":N,"type":"event","event":"m3",
// "value":..} (value: rpm, tool, seconds or path-mode as in toolpath.h).

#include "gcode/toolpath.h"

#include <cstdio>
#include <string>

namespace frezka::gcode {

// Appends "-12.3457" (4 decimals, half away from zero) to out.
void appendFixed4(std::string &out, double value);

// Appends the JSON object of entry i (no newline). False for an event when !withEvents.
bool appendJsonLine(std::string &out, const Toolpath &toolpath, std::size_t i, bool withEvents);

// Writes all entries as JSON Lines; false on a write error.
bool writeJsonLines(const Toolpath &toolpath, std::FILE *out, bool withEvents);

// The whole trace as one string (golden tests).
std::string jsonLines(const Toolpath &toolpath, bool withEvents);

struct Summary
{
    std::size_t rapids = 0, feeds = 0, arcs = 0, probes = 0, dwells = 0, events = 0;
    bool hasMotion = false;
    Point4 min, max; // bounds of all motions incl. arc bulges, machine mm
    double rapidLengthMm = 0;
    double feedLengthMm = 0; // feeds, arcs (helix length) and probes
    double timeSeconds = 0;  // naive: lengths / feed or rapid rate, plus dwells
    std::size_t moves() const { return rapids + feeds + arcs + probes; }
};

// rapidMmPerMin is the machine's rapid rate assumed for the naive time.
Summary summarize(const Toolpath &toolpath, double rapidMmPerMin);

} // namespace frezka::gcode
