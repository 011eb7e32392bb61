#include "stockzero.h"

namespace frezka::session {

Axes4 stockZeroOffset(const TravelFit &fit, const OffsetState &offsets, const Axes4 &machineMm,
                      StockAnchor anchor)
{
    const Axes4 total = offsets.total();
    Axes4 offset = offsets.systems[std::size_t(offsets.active)];
    // The program's own coordinates of its extent: machine minus the offsets it was read with.
    const double xMin = fit.minMm[0] - total[0], xMax = fit.maxMm[0] - total[0];
    const double yMin = fit.minMm[1] - total[1], yMax = fit.maxMm[1] - total[1];
    double x = 0, y = 0;
    switch (anchor) {
    case StockAnchor::ProgramZero:
        break;
    case StockAnchor::FrontLeft:
        x = xMin, y = yMin;
        break;
    case StockAnchor::FrontRight:
        x = xMax, y = yMin;
        break;
    case StockAnchor::BackLeft:
        x = xMin, y = yMax;
        break;
    case StockAnchor::BackRight:
        x = xMax, y = yMax;
        break;
    case StockAnchor::Centre:
        x = (xMin + xMax) / 2, y = (yMin + yMax) / 2;
        break;
    }
    if (!fit.moves)
        x = y = 0;
    // machine = program + system + G92, so system = machine - program - G92.
    offset[0] = machineMm[0] - x - offsets.g92[0];
    offset[1] = machineMm[1] - y - offsets.g92[1];
    offset[2] = machineMm[2] - offsets.g92[2];
    return offset;
}

Placement placeProgram(const TravelFit &fit, const OffsetState &offsets, const Axes4 &newOffsetMm,
                       const machine::MachineConfig &config)
{
    Placement placed;
    const Axes4 &old = offsets.systems[std::size_t(offsets.active)];
    for (std::size_t a = 0; a < 4; ++a) {
        const double shift = newOffsetMm[a] - old[a];
        placed.minMm[a] = fit.minMm[a] + shift;
        placed.maxMm[a] = fit.maxMm[a] + shift;
        const machine::AxisConfig &axis = config.axes[a];
        if (fit.moves && axis.present &&
            (placed.minMm[a] < axis.softMinMm - 1e-9 || placed.maxMm[a] > axis.softMaxMm + 1e-9))
            placed.inside = false;
    }
    return placed;
}

} // namespace frezka::session
