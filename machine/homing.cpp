#include "machine/homing.h"

#include "machine/steps.h"

#include <algorithm>
#include <cmath>

namespace frezka::machine {

namespace {

std::int64_t pulses(double mmPerS, double stepsPerMm, int maxRate)
{
    return speedPulses(mmPerS * stepsPerMm, maxRate);
}

} // namespace

std::vector<HomingMove> homingSequence(const MachineConfig &config)
{
    std::vector<HomingMove> moves;
    for (int i = 0; i < kAxisCount; ++i) {
        const AxisConfig &a = config.axes[static_cast<std::size_t>(i)];
        if (!a.present || a.homing.order <= 0)
            continue;
        const HomingConfig &h = a.homing;
        HomingMove m;
        m.axis = static_cast<Axis>(i);
        m.order = h.order;
        m.travelSteps = stepsOf(h.travelMm, a.stepsPerMm) * (h.direction < 0 ? -1 : 1);
        m.towardPulsesPerS = pulses(h.towardMmPerS, a.stepsPerMm, config.unit.maxPulseRate);
        m.backOffSteps = stepsOf(h.backOffMm, a.stepsPerMm);
        m.offPulsesPerS = pulses(h.offMmPerS, a.stepsPerMm, config.unit.maxPulseRate);
        m.homeSteps = stepsOf(h.homePositionMm, a.stepsPerMm);
        moves.push_back(m);
    }
    std::stable_sort(moves.begin(), moves.end(),
                     [](const HomingMove &x, const HomingMove &y) { return x.order < y.order; });
    return moves;
}

} // namespace frezka::machine
