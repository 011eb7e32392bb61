#pragma once
// The spiral of bench_gui_load (tests/bench/gui/bench_gui_load.cpp), `lines` long: one long
// chain of short G1 moves, the shape of the 5 M-line load. For the planner's tests that need
// that shape small (plan_golden_test, pace_replan_test); the GUI's tests and benches write the
// same lines to a file (tests/gui/spiralprogram.h).

#include <cmath>
#include <cstdio>
#include <string>

namespace frezka::machine::test {

inline constexpr const char *kSpiralHead = "G21 G90 G94\nG0 X0 Y0 Z0\nG1 Z-1 F1500\n";
inline constexpr const char *kSpiralTail = "M30\n";
inline constexpr long kSpiralFirst = 3; // the spiral's lines are [kSpiralFirst, lines - 1)

// Line i of a spiral `lines` long, with its newline; its length.
inline int spiralLine(long i, long lines, char (&buf)[64])
{
    const double t = double(i) * 0.002;
    const double r = 10 + double(i) * 120.0 / double(lines);
    return std::snprintf(buf, sizeof buf, "G1 X%.3f Y%.3f\n", 200 + r * std::cos(t),
                         150 + r * std::sin(t));
}

inline std::string spiral(long lines)
{
    std::string s = kSpiralHead;
    char buf[64];
    for (long i = kSpiralFirst; i < lines - 1; ++i)
        s.append(buf, static_cast<std::size_t>(spiralLine(i, lines, buf)));
    return s + kSpiralTail;
}

} // namespace frezka::machine::test
