#pragma once
// JobFigures: the figures of one job for the CLI and the benchmarks (JobReport), a part of the job.
//
// Contract: start() clears the report and notes the link's counters and the time; the job and its
// parts then count into it as things happen (accepted() for each command the unit took,
// pollStarted() for each position poll, report() for the rest: packets, resends, verifications,
// path faults, return moves), and finish() adds the link's traffic, resends and recoveries since
// start() and the end time. Counting only: nothing here decides what the job does.

#include "driver/link/coretypes.h"

#include <cstdint>

namespace frezka::driver {

class JobFigures
{
public:
    const JobReport &report() const { return m_report; }
    JobReport &report() { return m_report; }

    // A new job starts at `now` with the link's counters at `stats`.
    void start(double now, const LinkStats &stats);
    // The unit accepted a program command at `now` (`motion`: a C or L).
    void accepted(bool motion, double now);
    // A position poll starts at `now`; `vectorsLeft`: motion commands are still to send.
    void pollStarted(double now, bool vectorsLeft);
    // The job ends at `now` (`ok`: it ran to its end) with the link's counters at `stats`.
    void finish(bool ok, double now, const LinkStats &stats);

private:
    JobReport m_report;
    std::int64_t m_bytesAtStart = 0;
    std::int64_t m_resentAtStart = 0;
    std::int64_t m_recoveredAtStart = 0;
};

} // namespace frezka::driver
