#pragma once
// Generators of the benchmark programs (deterministic, no randomness).
#include <string>

namespace frezka::gcode::bench {

// Dense 3D finishing: a raster over a smooth surface, one short G1 X Y Z move per line, the
// way CAM finishing passes look ("G1 X12.345 Y6.789 Z-1.234"). lines >= 10.
std::string denseFinishing(std::size_t lines);
// Arc-heavy 2.5D: pockets of G2/G3 (I J) arcs and G1 lines at stepped depths.
std::string arcHeavy(std::size_t lines);

} // namespace frezka::gcode::bench
