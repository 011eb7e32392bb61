// JobTracker: where the unit is in the job's program, from its counters. See jobtracker.h.

#include "jobtracker.h"

#include "driver/link/corehost.h"
#include "driver/link/jobpace.h"
#include "driver/link/machinecore_internal.h"

#include <algorithm>
#include <cstdlib>

namespace frezka::driver {

using detail::isMotion;

// Whether the polled position lies inside vector i's box (from its start to its end position)
// and not at its end; `done` is then the share of its longest axis already run.
bool JobTracker::inBox(std::size_t i, bool &atEnd, double &done) const
{
    const machine::UnitCommand &c = m_program.commands[i];
    const auto &pos = m_host.liveState().positionSteps;
    const int axes = m_program.axisCount;
    bool inside = true;
    atEnd = true;
    for (int a = 0; a < axes; ++a) {
        const std::int64_t start = c.endSteps[a] - c.d[a];
        atEnd = atEnd && pos[a] == c.endSteps[a];
        inside = inside && pos[a] >= std::min(start, c.endSteps[a]) &&
                 pos[a] <= std::max(start, c.endSteps[a]);
    }
    if (!inside || atEnd)
        return false;
    int longest = 0;
    for (int a = 1; a < axes; ++a)
        longest = std::abs(c.d[a]) > std::abs(c.d[longest]) ? a : longest;
    const std::int64_t left = std::abs(c.endSteps[longest] - pos[longest]);
    const std::int64_t length = std::abs(c.d[longest]);
    done = length > 0 ? 1.0 - static_cast<double>(left) / static_cast<double>(length) : 0;
    return true;
}

// The executing command from the polled position: the first motion command from the last one
// seen executing on whose box holds the position and which has not ended. A position on none of
// them (the tool lifted, the machine off the path) says nothing about progress: the line,
// progress and ETA stay where they were.
//
// Where the path comes back over itself (a zig-zag along one axis, a raster's return) several
// boxes hold it. The first is what the screen shows (a later pass would put the listing ahead
// of the cut where the model runs ahead of the unit), but the unit may be on a later one: the
// pace takes the pass nearest to where its model puts the unit (JobCursor::paceExec). The first
// alone made the job take the unit for holding 0.8 s of motion where it held 0.1 s on a Z
// zig-zag (property seed 128), and 0.25 s where it held 0.11 s on an X raster (seed 344): the
// unit ran dry at speed.
bool JobTracker::positionRead(double startS)
{
    const auto &cmds = m_program.commands;
    MachineState &state = m_host.liveState();
    const std::size_t guess = m_pace.execEstimate(); // before the cursor moves
    std::size_t i = m_cursor.exec;
    const std::size_t limit = std::min(m_cursor.next, cmds.size());
    bool onPath = false; // inside a box, or at the end of the last motion sent
    double done = 0;     // the share of vector i's longest axis already run
    for (int guard = 0; i < limit && guard < 100000; ++i, ++guard) {
        if (!isMotion(cmds[i].op))
            continue;
        bool atEnd = false;
        const bool inside = inBox(i, atEnd, done);
        onPath = atEnd || inside;
        if (inside)
            break;
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
    placeForPace(i, done, guess);
    return true;
}

// The pace's reading (see positionRead): of the boxes from `first` on that hold the position,
// the one nearest to the model's guess.
void JobTracker::placeForPace(std::size_t first, double done, std::size_t guess)
{
    const std::size_t limit = std::min(m_cursor.next, m_program.commands.size());
    const auto distance = [guess](std::size_t j) { return j > guess ? j - guess : guess - j; };
    std::size_t best = first;
    double bestDone = done;
    if (first < limit) {
        for (std::size_t j = first + 1; j < limit && j < first + 100000; ++j) {
            if (j > guess && distance(j) >= distance(best))
                break; // the boxes further on lie further from the model
            bool atEnd = false;
            double share = 0;
            if (isMotion(m_program.commands[j].op) && inBox(j, atEnd, share) &&
                distance(j) < distance(best)) {
                best = j;
                bestDone = share;
            }
        }
    }
    m_cursor.paceExec = best;
    m_cursor.paceExecAt =
        m_host.now() - (best < limit ? bestDone * m_pace.runS(best, best + 1) : 0.0);
    m_cursor.paceKey = m_cursor.exec;
    m_cursor.paceKeyAt = m_cursor.execAt;
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
