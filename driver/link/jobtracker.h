#pragma once
// JobTracker: where the unit is in the job's program, read from its counters (a part of the job).
//
// Contract: at each polled position (MachineState::positionSteps) positionRead() finds the
// command the unit executes: the first motion command from the last one seen executing, up to
// the next to send, whose box (from its start to its end position) holds the position and which
// has not ended. It moves the job's cursor there (exec, and execAt back by the share of that
// command already run) and shows its source line, the progress and the ETA in the state. A
// position on none of them (the tool lifted, the machine off the path) says nothing about
// progress: nothing changes. unitStands() is the other source: F read RUN = 0, so everything
// accepted has run. Reads only; the path the unit follows is the plan's, and what is off it is
// PathGuard's to judge.

#include "machine/unitprogram.h"

namespace frezka::driver {

class CoreHost;
class JobPace;
struct JobCursor;

class JobTracker
{
public:
    JobTracker(CoreHost &host, const machine::UnitProgram &program, JobCursor &cursor,
               const JobPace &pace)
        : m_host(host)
        , m_program(program)
        , m_cursor(cursor)
        , m_pace(pace)
    {}

    // The executing command from the polled position; `startS` is when the job started (for the
    // ETA). False when the position is on no command from the executing one on (nothing changed).
    bool positionRead(double startS);
    // F answered RUN = 0: every command accepted so far has run.
    void unitStands();

private:
    bool inBox(std::size_t i, bool &atEnd, double &done) const;
    void placeForPace(std::size_t first, double done, std::size_t guess);
    CoreHost &m_host;
    const machine::UnitProgram &m_program;
    JobCursor &m_cursor;
    const JobPace &m_pace;
};

} // namespace frezka::driver
