#pragma once
// ActualSpeed: the machine's speed along its path from the polled positions, for the speed plot.
//
// Contract: add() takes each position with the time it was seen; speed() is the path length
// travelled over the last window (at least windowS, and at least two readings) divided by the
// time it took, so that uneven poll intervals (a snapshot late, the next early) do not show as
// spikes; a snapshot whose position did not change is no reading until a window has passed
// without motion (a status poll between position polls would stretch the window and read low;
// a machine that stands reads 0 within two windows); the result never exceeds the ceiling (what
// the machine can reach: its axes' maximum speeds combined, times the feed override). reset() at
// the start of a job. Pure: no Qt, no clock of its own.

#include <array>
#include <deque>

namespace frezka::gui {

class ActualSpeed
{
public:
    explicit ActualSpeed(double windowS = 0.5)
        : m_windowS(windowS)
    {}
    void reset();
    void setCeiling(double mmPerMin) { m_ceiling = mmPerMin; }
    double ceiling() const { return m_ceiling; }
    // A reading at timeS (seconds, any origin, increasing); returns true when the position moved.
    bool add(double timeS, const std::array<double, 4> &positionMm);
    // mm/min over the window; 0 before two readings.
    double speed() const;
    // Path length travelled since reset(), mm.
    double distanceMm() const { return m_distance; }

private:
    struct Reading
    {
        double t;
        double distance; // path length at t since reset()
    };
    double m_windowS;
    double m_ceiling = 0; // 0 = none
    std::deque<Reading> m_readings;
    std::array<double, 4> m_last{};
    bool m_haveLast = false;
    double m_distance = 0;
};

} // namespace frezka::gui
