#pragma once
// The spiral of bench_gui_load (tests/bench/gui/bench_gui_load.cpp), `lines` long: one long
// chain of short G1 moves, the shape of the 5 M-line load. For the planner's tests that need
// that shape small (plan_golden_test, pace_replan_test).

#include <cmath>
#include <cstdio>
#include <string>

namespace frezka::machine::test {

inline std::string spiral(long lines)
{
    std::string s = "G21 G90 G94\nG0 X0 Y0 Z0\nG1 Z-1 F1500\n";
    char buf[64];
    for (long i = 3; i < lines - 1; ++i) {
        const double t = double(i) * 0.002;
        const double r = 10 + double(i) * 120.0 / double(lines);
        std::snprintf(buf, sizeof buf, "G1 X%.3f Y%.3f\n", 200 + r * std::cos(t),
                      150 + r * std::sin(t));
        s += buf;
    }
    return s + "M30\n";
}

} // namespace frezka::machine::test
