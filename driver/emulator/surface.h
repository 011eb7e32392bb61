#pragma once
// ProbeSurface: the top of the work under the emulated machine, for probing (issue 19).
//
// A height function of the machine's X and Y (mm) that trips the tool probe input (IN15 at
// contactHigh's level) while the Z counter is at or below the surface there.
// The unit re-aims a Z watch at the surface under the current X/Y at every motion event, so a
// vertical probe move (G38.2 Z at fixed X/Y, as the probing of a grid makes) stops exactly at
// the surface's step; a move that also travels in X/Y trips at the latest event's aim or at
// the next event, whichever comes first (good to the next vector, not to the step).
//
// Specs (gve-emu --surface, frezka-cli --surface):
//   plane:Z0,DZDX,DZDY       z = Z0 + DZDX * x + DZDY * y
//   sine:AMP,PERIOD[,Z0]     z = Z0 + AMP * sin(2 pi x / PERIOD) * sin(2 pi y / PERIOD)
//   warp:Z0,DZDX,DZDY,AMP,PERIOD   the plane plus the sine (a tilted, warped board)
//   block:X0,Y0,X1,Y1,TOP    a work block: z = TOP over X0..X1, Y0..Y1, nothing beside it
//                            (its sides trip a probe moving in X or Y below TOP: edges and
//                            corners; the unit watches the sides, so the trip is exact)
// with x, y, z in machine millimetres. The probe is the tool's centre: a block meant for a
// tool of radius r is given r larger on each side.

#include <array>
#include <cstdint>
#include <string>

namespace frezka::emulator {

struct ProbeSurface
{
    enum class Kind { None, Plane, Sine, Warp, Block };
    Kind kind = Kind::None;
    // plane: Z0, DZDX, DZDY; sine: AMP, PERIOD, Z0; warp: Z0, DZDX, DZDY, AMP, PERIOD;
    // block: X0, Y0, X1, Y1, TOP
    std::array<double, 5> p{};
    std::array<double, 3> stepsPerMm{200, 200, 200}; // X, Y, Z of the machine
    int input = 15;
    // The input's level at contact: 1 for a normally closed probe (the unit's own reading of
    // IN15 pressed), 0 when the profile's EEPROM polarity (ST3 bit 7 clear) says contact reads
    // 0; away from the surface the input reads the other level.
    bool contactHigh = true;

    bool active() const { return kind != Kind::None; }
    double heightMm(double xMm, double yMm) const;
    // The highest Z counter at which the probe touches, under the counters x, y.
    std::int64_t touchZSteps(std::int64_t x, std::int64_t y) const;
    // A block's sides as counter thresholds (MotionEngine::Watch: crossing them changes whether
    // the tool is over the block): X0, X1 + 1 step, Y0, Y1 + 1 step; empty for the others.
    std::array<std::int64_t, 4> sideThresholds() const;
    bool operator==(const ProbeSurface &) const = default;
};

// Reads a spec (above) into *out (its steps/mm kept); false when it is malformed.
bool parseProbeSurface(const std::string &spec, ProbeSurface *out);

} // namespace frezka::emulator
