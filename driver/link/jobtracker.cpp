// JobTracker: where the unit is in the job's program, from its counters. See jobtracker.h.

#include "jobtracker.h"

#include "driver/link/corehost.h"
#include "driver/link/jobpace.h"
#include "driver/link/machinecore_internal.h"

#include <algorithm>
#include <cstdlib>

namespace frezka::driver {

using detail::isMotion;

// The executing command from the polled position: the first motion command from the last one
// seen executing on whose box (from its start to its end position) holds the position and which
// has not ended. A position on none of them (the tool lifted, the machine off the path) says
// nothing about progress: the line, progress and ETA stay where they were.
bool JobTracker::positionRead(double startS)
{
    const auto &cmds = m_program.commands;
    const int axes = m_program.axisCount;
    MachineState &state = m_host.liveState();
    const auto &pos = state.positionSteps;
    std::size_t i = m_cursor.exec;
    const std::size_t limit = std::min(m_cursor.next, cmds.size());
    bool onPath = false; // inside a box, or at the end of the last motion sent
    double done = 0;     // the share of vector i's longest axis already run
    for (int guard = 0; i < limit && guard < 100000; ++i, ++guard) {
        if (!isMotion(cmds[i].op))
            continue;
        const machine::Steps4 &end = cmds[i].endSteps;
        bool atEnd = true;
        bool inside = true;
        for (int a = 0; a < axes; ++a) {
            const std::int64_t start = end[a] - cmds[i].d[a];
            atEnd = atEnd && pos[a] == end[a];
            inside =
                inside && pos[a] >= std::min(start, end[a]) && pos[a] <= std::max(start, end[a]);
        }
        onPath = atEnd;
        if (inside && !atEnd) {
            onPath = true;
            int longest = 0;
            for (int a = 1; a < axes; ++a)
                longest = std::abs(cmds[i].d[a]) > std::abs(cmds[i].d[longest]) ? a : longest;
            const std::int64_t left = std::abs(end[longest] - pos[longest]);
            const std::int64_t length = std::abs(cmds[i].d[longest]);
            done = length > 0 ? 1.0 - static_cast<double>(left) / static_cast<double>(length) : 0;
            break;
        }
    }
    if (!onPath && i > m_cursor.exec)
        return false;
    m_cursor.exec = i;
    // Standing at the end of everything sent while the driver runs a step of its own (a dwell,
    // a wait for the spindle): that step's line is the one being executed, not the next
    // command's, which has not been sent (issue 16: the time left counts down through a dwell).
    const bool ownStep = i == limit && i > 0 && i < cmds.size() && !isMotion(cmds[i - 1].op);
    const std::size_t shown = ownStep ? i - 1 : std::min(i, cmds.empty() ? 0 : cmds.size() - 1);
    state.sourceLine = cmds.empty() ? 0 : cmds[shown].sourceLine;
    state.progress = cmds.empty() ? 0 : static_cast<double>(i) / static_cast<double>(cmds.size());
    const double elapsed = m_host.now() - startS;
    state.etaS =
        i > 0 ? elapsed * static_cast<double>(cmds.size() - i) / static_cast<double>(i) : -1;
    // Vector i began that share of its time ago (a long plunge read half way holds half its
    // time, not all of it: the packet after it was sized to arrive when it had already ended).
    m_cursor.execAt = m_host.now() - (i < limit ? done * m_pace.runS(i, i + 1) : 0.0);
    return true;
}

// F answered RUN = 0: the unit's queue is empty, so every command accepted before F was sent
// (all of them: one transaction at a time) has run. The counters alone cannot always tell: where
// the path comes back over itself, a standing position may lie inside the box of an earlier,
// longer vector, and the executing command read from it would stay there for good; the job
// would then take the unit's queue for full for ever and never send again.
void JobTracker::unitStands()
{
    if (m_cursor.exec >= m_cursor.next)
        return;
    m_cursor.exec = m_cursor.next;
    m_cursor.execAt = m_host.now();
}

} // namespace frezka::driver
