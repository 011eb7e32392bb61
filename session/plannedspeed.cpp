// The planned speed and line times of a unit program. See plannedspeed.h.

#include "plannedspeed.h"

#include <algorithm>
#include <cmath>

namespace frezka::session {

std::vector<SpeedSample> decimateSpeed(const std::vector<SpeedSample> &in, std::size_t maxPoints)
{
    if (in.size() <= maxPoints || maxPoints < 4)
        return in;
    std::vector<SpeedSample> out;
    out.reserve(maxPoints);
    const std::size_t buckets = maxPoints / 2;
    const double per = double(in.size()) / double(buckets);
    for (std::size_t b = 0; b < buckets; ++b) {
        const auto from = std::size_t(double(b) * per);
        const auto to = std::min(in.size(), std::size_t(double(b + 1) * per));
        if (from >= to)
            continue;
        auto [lo, hi] = std::minmax_element(in.begin() + long(from), in.begin() + long(to),
                                            [](const SpeedSample &a, const SpeedSample &c) {
                                                return a.speedMmPerMin < c.speedMmPerMin;
                                            });
        if (lo->distanceMm <= hi->distanceMm) {
            out.push_back(*lo);
            if (hi != lo)
                out.push_back(*hi);
        } else {
            out.push_back(*hi);
            out.push_back(*lo);
        }
    }
    return out;
}

std::vector<SpeedSample> plannedSpeed(const machine::UnitProgram &program,
                                      const machine::MachineConfig &config, bool speedModeVk)
{
    std::vector<SpeedSample> out;
    double distance = 0;
    double v = 0, b = 0; // pulses/s
    for (const auto &c : program.commands) {
        using Op = machine::UnitOp;
        if (c.op == Op::Speed) {
            v = double(c.value);
        } else if (c.op == Op::Brake) {
            b = double(c.value);
        } else if (c.op == Op::Vector || c.op == Op::Line) {
            double mm2 = 0, steps2 = 0, major = 0;
            for (int i = 0; i < 4; ++i) {
                const double d = c.d[std::size_t(i)];
                const double mm = d / config.axes[std::size_t(i)].stepsPerMm;
                mm2 += i < 3 ? mm * mm : 0;
                steps2 += i < 3 ? d * d : 0;
                major = std::max(major, std::abs(d));
            }
            const double lengthMm = std::sqrt(mm2);
            const double stepLength = speedModeVk ? std::sqrt(steps2) : major;
            if (stepLength <= 0 || lengthMm <= 0)
                continue;
            const double toMmPerMin = lengthMm / stepLength * 60.0;
            const bool continuous = c.op == Op::Vector;
            out.push_back({distance, out.empty() ? 0.0 : out.back().speedMmPerMin, c.sourceLine});
            out.push_back({distance + lengthMm / 2, v * toMmPerMin, c.sourceLine});
            distance += lengthMm;
            out.push_back({distance, continuous ? std::min(v, b) * toMmPerMin : 0.0, c.sourceLine});
        }
    }
    return out;
}

std::vector<float> plannedLineTimes(const machine::UnitProgram &program, bool speedModeVk,
                                    double totalS)
{
    std::uint32_t maxLine = 0;
    for (const auto &c : program.commands)
        maxLine = std::max(maxLine, c.sourceLine);
    std::vector<double> atLine(std::size_t(maxLine) + 1, -1.0);
    double t = 0, v = 0;
    for (const auto &c : program.commands) {
        using Op = machine::UnitOp;
        if (c.op == Op::Speed) {
            v = double(c.value);
        } else if (c.op == Op::Dwell) {
            t += double(c.value) / 1000.0;
        } else if ((c.op == Op::Vector || c.op == Op::Line) && v > 0) {
            double steps2 = 0, major = 0;
            for (int i = 0; i < 3; ++i) {
                const double d = c.d[std::size_t(i)];
                steps2 += d * d;
                major = std::max(major, std::abs(d));
            }
            t += (speedModeVk ? std::sqrt(steps2) : major) / v;
        }
        atLine[c.sourceLine] = t;
    }
    std::vector<float> out(atLine.size(), 0.f);
    const double scale = t > 0 ? totalS / t : 0.0;
    double last = 0;
    for (std::size_t i = 0; i < atLine.size(); ++i) {
        if (atLine[i] >= 0)
            last = atLine[i] * scale;
        out[i] = float(last);
    }
    return out;
}

} // namespace frezka::session
