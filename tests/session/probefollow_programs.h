#pragma once
// The programs that probe for themselves of the probe-following tests (issue 19 item 4: session
// ProbeFollow, the GUI's Run): a touch-off then a cut, and a pcb2gcode-style autolevel grid on a
// tilted work top.

#include <algorithm>
#include <cstdio>
#include <string>

namespace frezka::test {

// (a) G38.2 down to the work at Z -3.2, that point made Z0 of G54, a cut 0.1 below it.
inline constexpr const char *kTouchOff = "G21 G90 G54\n"
                                         "G0 X10 Y10\n"
                                         "G38.2 Z-10 F50\n" // 3
                                         "G10 L20 P1 Z0\n"
                                         "G0 Z1\n"
                                         "M3 S10000\n"
                                         "G1 Z-0.1 F100\n" // 7
                                         "G1 X20\n"
                                         "M5\n"
                                         "M2\n";

// (b) pcb2gcode's autolevel, in its shape: the first probe (line 4) makes the work's top Z0, a
// 3x3 grid of probes keeps each trip Z in #500..#508, and each cut point's Z is the bilinear
// interpolation of its cell's four corners (arithmetic on the parameters) minus the depth.
// probeFeed and cutFeed in mm/min.
inline std::string autolevelProgram(int probeFeed = 60, int cutFeed = 120)
{
    const std::string probeF = " F" + std::to_string(probeFeed) + "\n";
    std::string t =
        "G21 G90 G94 G54\nG0 Z0\nG0 X0 Y0\nG38.2 Z-6" + probeF + "G10 L20 P1 Z0\nG0 Z1\n";
    for (int j = 0; j < 3; ++j) {
        for (int i = 0; i < 3; ++i) {
            t += "G0 X" + std::to_string(10 * i) + " Y" + std::to_string(10 * j) + "\n";
            t += "G38.2 Z-3" + probeF + "#" + std::to_string(500 + 3 * j + i) + "=#5063\nG0 Z1\n";
        }
    }
    t += "M3 S12000\n";
    // The cut: a square through four cells, each corner's Z interpolated in its cell.
    const double pts[][2] = {{4, 3}, {16, 3}, {16, 17}, {4, 17}, {4, 3}};
    bool first = true;
    for (const auto &p : pts) {
        const int ci = std::min(1, int(p[0] / 10)), cj = std::min(1, int(p[1] / 10));
        const double fx = (p[0] - 10 * ci) / 10, fy = (p[1] - 10 * cj) / 10;
        const int z00 = 500 + 3 * cj + ci, z10 = z00 + 1, z01 = z00 + 3, z11 = z00 + 4;
        char z[256];
        std::snprintf(z, sizeof z,
                      "#1=[[1-%.3f]*[[1-%.3f]*#%d+%.3f*#%d]+%.3f*[[1-%.3f]*#%d+%.3f*#%d]-0.1]\n",
                      fy, fx, z00, fx, z10, fy, fx, z01, fx, z11);
        t += z;
        char move[96];
        std::snprintf(move, sizeof move, "G1 X%.3f Y%.3f Z#1 F%d\n", p[0], p[1], cutFeed);
        if (first)
            t += "G0 X4 Y3\n";
        t += move;
        first = false;
    }
    t += "G0 Z1\nM5\nM2\n";
    return t;
}

// The work top autolevelProgram's tests probe (machine mm): plane:-2,0.02,-0.015.
inline double tilted(double x, double y)
{
    return -2 + 0.02 * x - 0.015 * y;
}

} // namespace frezka::test
