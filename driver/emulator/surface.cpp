// ProbeSurface: the emulated work's top, tripping the tool probe (surface.h).
#include "driver/emulator/surface.h"

#include <cmath>
#include <numbers>
#include <sstream>

namespace frezka::emulator {

double ProbeSurface::heightMm(double x, double y) const
{
    switch (kind) {
    case Kind::None:
        return 0;
    case Kind::Plane:
        return p[0] + p[1] * x + p[2] * y;
    case Kind::Sine: {
        const double w = 2 * std::numbers::pi / p[1];
        return p[2] + p[0] * std::sin(w * x) * std::sin(w * y);
    }
    case Kind::Warp: {
        const double w = 2 * std::numbers::pi / p[4];
        return p[0] + p[1] * x + p[2] * y + p[3] * std::sin(w * x) * std::sin(w * y);
    }
    case Kind::Block: {
        const auto t = sideThresholds(); // the same sides as the unit's watches
        const std::int64_t sx = std::llround(x * stepsPerMm[0]);
        const std::int64_t sy = std::llround(y * stepsPerMm[1]);
        const bool over = sx >= t[0] && sx < t[1] && sy >= t[2] && sy < t[3];
        return over ? p[4] : -1e9; // beside the block: nothing to touch
    }
    }
    return 0;
}

std::array<std::int64_t, 4> ProbeSurface::sideThresholds() const
{
    auto up = [](double mm, double spm) {
        return static_cast<std::int64_t>(std::ceil(mm * spm - 1e-9));
    };
    auto down = [](double mm, double spm) {
        return static_cast<std::int64_t>(std::floor(mm * spm + 1e-9));
    };
    return {up(p[0], stepsPerMm[0]), down(p[2], stepsPerMm[0]) + 1, up(p[1], stepsPerMm[1]),
            down(p[3], stepsPerMm[1]) + 1};
}

std::int64_t ProbeSurface::touchZSteps(std::int64_t x, std::int64_t y) const
{
    const double z = heightMm(double(x) / stepsPerMm[0], double(y) / stepsPerMm[1]);
    return static_cast<std::int64_t>(std::floor(z * stepsPerMm[2] + 1e-9));
}

bool parseProbeSurface(const std::string &spec, ProbeSurface *out)
{
    const auto colon = spec.find(':');
    if (colon == std::string::npos)
        return false;
    const std::string name = spec.substr(0, colon);
    std::istringstream in(spec.substr(colon + 1));
    std::array<double, 5> v{};
    int n = 0;
    for (std::string cell; n < 5 && std::getline(in, cell, ',');) {
        std::size_t used = 0;
        try {
            v[std::size_t(n)] = std::stod(cell, &used);
        } catch (...) {
            return false;
        }
        if (used != cell.size() || !std::isfinite(v[std::size_t(n)]))
            return false;
        ++n;
    }
    if (in.rdbuf()->in_avail() > 0)
        return false; // more than five numbers
    ProbeSurface s = *out;
    if (name == "plane" && n == 3) {
        s.kind = ProbeSurface::Kind::Plane;
    } else if (name == "sine" && (n == 2 || n == 3) && v[1] > 0) {
        s.kind = ProbeSurface::Kind::Sine;
    } else if (name == "warp" && n == 5 && v[4] > 0) {
        s.kind = ProbeSurface::Kind::Warp;
    } else if (name == "block" && n == 5 && v[2] > v[0] && v[3] > v[1]) {
        s.kind = ProbeSurface::Kind::Block;
    } else {
        return false;
    }
    s.p = v;
    *out = s;
    return true;
}

} // namespace frezka::emulator
