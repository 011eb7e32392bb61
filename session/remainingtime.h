#pragma once
// RemainingTime: the job's remaining time from the planner's model, for the front ends' ETA.
//
// The planned seconds to the end of each source line (plannedLineTimes) give what is left after
// the line being cut; the line itself adds its planned duration less the time it has shown so
// far. So the figure counts down through a long move and through a dwell (G4: the driver shows
// the dwell's line while it waits), where the driver's own estimate (elapsed time scaled by the
// commands run) counts up. The line's duration is its planned end less the planned end of the
// line before it in the file (exact for programs without loops and subroutines; inside them a
// line's time is that of one pass). A value: fed with the line shown and the job's clock.

#include <cstdint>
#include <vector>

namespace frezka::session {

class RemainingTime
{
public:
    RemainingTime() = default;
    // lineEndS: planned seconds from the start to the end of each line (index = line);
    // totalS: the planner's estimate of the whole job.
    RemainingTime(std::vector<float> lineEndS, double totalS);

    // Seconds left when the job shows `line` (0 = none yet) at nowS on the job's clock (s, any
    // origin, not decreasing); -1 when nothing was planned. While the job is held (running
    // false: paused, tool lifted, an operator stop) the time on the line does not count.
    double at(std::uint32_t line, double nowS, bool running = true);

private:
    double endOf(std::uint32_t line) const;

    std::vector<float> m_lineEndS;
    double m_totalS = -1;
    std::uint32_t m_line = 0;
    double m_onLineS = 0; // running time since m_line was first shown
    double m_lastS = 0;   // the clock at the last call
};

} // namespace frezka::session
