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

namespace {

// Calls sample(s) for each planned speed sample in order: three a vector (its start at the
// speed before it, its middle at V, its end at the brake speed or 0).
template<typename Sample>
void forEachSpeedSample(const machine::UnitProgram &program, const machine::MachineConfig &config,
                        bool speedModeVk, Sample &&sample)
{
    double distance = 0, last = 0;
    double v = 0, b = 0; // pulses/s
    bool any = false;
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
            sample(SpeedSample{distance, any ? last : 0.0, c.sourceLine});
            sample(SpeedSample{distance + lengthMm / 2, v * toMmPerMin, c.sourceLine});
            distance += lengthMm;
            last = continuous ? std::min(v, b) * toMmPerMin : 0.0;
            sample(SpeedSample{distance, last, c.sourceLine});
            any = true;
        }
    }
}

} // namespace

std::vector<SpeedSample> plannedSpeed(const machine::UnitProgram &program,
                                      const machine::MachineConfig &config, bool speedModeVk)
{
    std::vector<SpeedSample> out;
    forEachSpeedSample(program, config, speedModeVk,
                       [&out](const SpeedSample &s) { out.push_back(s); });
    return out;
}

// The buckets and the choice in each are decimateSpeed's, sample for sample: bucket b holds the
// samples [b per, (b + 1) per), its minimum is the first smallest and its maximum the last
// largest (std::minmax_element), and the samples past the last bucket are left out.
std::vector<SpeedSample> plannedSpeedDecimated(const machine::UnitProgram &program,
                                               const machine::MachineConfig &config,
                                               bool speedModeVk, std::size_t maxPoints)
{
    std::size_t total = 0;
    forEachSpeedSample(program, config, speedModeVk, [&total](const SpeedSample &) { ++total; });
    if (total <= maxPoints || maxPoints < 4)
        return plannedSpeed(program, config, speedModeVk);
    std::vector<SpeedSample> out;
    out.reserve(maxPoints);
    const std::size_t buckets = maxPoints / 2;
    const double per = double(total) / double(buckets);
    const auto bucketEnd = [&](std::size_t b) {
        return std::min(total, std::size_t(double(b + 1) * per));
    };
    std::size_t bucket = 0, to = bucketEnd(0), index = 0, count = 0;
    SpeedSample lo, hi;
    std::size_t loAt = 0, hiAt = 0;
    const auto close = [&] {
        if (count == 0)
            return;
        const bool loFirst = lo.distanceMm <= hi.distanceMm;
        out.push_back(loFirst ? lo : hi);
        if (loAt != hiAt)
            out.push_back(loFirst ? hi : lo);
    };
    forEachSpeedSample(program, config, speedModeVk, [&](const SpeedSample &s) {
        const std::size_t i = index++;
        while (bucket < buckets && i >= to) {
            close();
            count = 0;
            to = ++bucket < buckets ? bucketEnd(bucket) : 0;
        }
        if (bucket >= buckets || i < std::size_t(double(bucket) * per))
            return;
        if (count == 0 || s.speedMmPerMin < lo.speedMmPerMin)
            lo = s, loAt = i;
        if (count == 0 || !(s.speedMmPerMin < hi.speedMmPerMin))
            hi = s, hiAt = i;
        ++count;
    });
    if (bucket < buckets)
        close();
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
