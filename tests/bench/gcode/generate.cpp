#include "generate.h"

#include <cmath>
#include <cstdio>

namespace frezka::gcode::bench {

namespace {

void line(std::string &out, const char *fmt, double a, double b, double c)
{
    char buf[96];
    const int n = std::snprintf(buf, sizeof buf, fmt, a, b, c);
    out.append(buf, static_cast<std::size_t>(n));
}

} // namespace

std::string denseFinishing(std::size_t lines)
{
    std::string out;
    out.reserve(lines * 30);
    out += "(dense 3D finishing raster)\nG21 G90 G17 G94\nG0 Z5\nG0 X0 Y0\nG1 Z0 F1200\n";
    const std::size_t perRow = 1000;
    const std::size_t moves = lines - 7;
    for (std::size_t i = 0; i < moves; ++i) {
        const std::size_t row = i / perRow, k = i % perRow;
        const double x = (row % 2 == 0 ? k : perRow - 1 - k) * 0.1;
        const double y = row * 0.1;
        const double z = -2.0 + std::sin(x * 0.05) * std::cos(y * 0.07) * 1.5;
        line(out, "G1 X%.3f Y%.3f Z%.3f\n", x, y, z);
    }
    out += "G0 Z5\nM2\n";
    return out;
}

std::string arcHeavy(std::size_t lines)
{
    std::string out;
    out.reserve(lines * 32);
    out += "(arc-heavy 2.5D pockets)\nG21 G90 G17 G94\nG0 Z5\nF800\n";
    std::size_t written = 4;
    int pocket = 0;
    while (written + 12 < lines) {
        const double cx = (pocket % 20) * 30.0, cy = (pocket / 20 % 20) * 30.0;
        const double depth = -0.5 * (1 + pocket % 6);
        line(out, "G0 X%.3f Y%.3f Z%.3f\n", cx + 10, cy, 1.0);
        line(out, "G1 Z%.3f F%.1f\n", depth, 300.0, 0.0);
        // Ring of arcs with a straight step outwards between rings.
        for (int ring = 0; ring < 2 && written + 10 < lines; ++ring) {
            const double r = 10 + ring * 1.5;
            line(out, "G3 X%.3f Y%.3f I%.3f J0\n", cx, cy + r, -r);
            line(out, "G3 X%.3f Y%.3f I0 J%.3f\n", cx - r, cy, -r);
            line(out, "G3 X%.3f Y%.3f I%.3f J0\n", cx, cy - r, r);
            line(out, "G2 X%.3f Y%.3f R%.3f\n", cx + r, cy, -r);
            line(out, "G1 X%.3f Y%.3f F%.1f\n", cx + r + 1.5, cy, 800.0);
            written += 5;
        }
        out += "G0 Z1\n";
        written += 3;
        ++pocket;
    }
    out += "G0 Z5\nM2\n";
    return out;
}

} // namespace frezka::gcode::bench
