// LiveModel: the unit's position between polls, from the driver's model. See livemodel.h.

#include "livemodel.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/machinecore_internal.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using detail::isMotion;

bool LiveModel::modelling() const
{
    return m_job.active() && m_host.liveState().mode == MachineMode::Running && !m_job.offPath() &&
           !m_job.verifying() && !m_job.probing();
}

double LiveModel::nextTime() const
{
    return modelling() ? m_next : kNoDeadline;
}

std::optional<LivePosition> LiveModel::at(double now) const
{
    const JobPace &pace = m_job.pace();
    const machine::UnitProgram &program = m_job.program();
    const auto &cmds = program.commands;
    if (!modelling() || cmds.empty() || pace.size() != cmds.size() + 1)
        return std::nullopt;
    const MachineState &state = m_host.liveState();
    const JobCursor &cursor = m_job.cursor();
    const std::size_t next = std::min(cursor.next, cmds.size());
    if (next == 0)
        return std::nullopt; // nothing accepted yet: the counters say all there is
    // The unit runs the override it was sent (XM scales the cruise: below 100 % the model lags,
    // never leads); the polled counters are half a round trip old when they arrive.
    const double rate = std::max(1, state.overrideSentPercent) / 100.0;
    double elapsed = std::max(0.0, now - cursor.execAt + m_host.rttS() / 2) * rate;
    std::size_t i = std::min(cursor.exec, next);
    double share = 0;
    for (; i < next; ++i) {
        const double t = pace.timeBefore(i + 1) - pace.timeBefore(i);
        if (elapsed < t) {
            share = elapsed / t;
            break;
        }
        elapsed -= t;
    }
    LivePosition live;
    live.modelled = true;
    live.atS = now;
    live.steps = state.positionSteps; // before the first motion the cursor has seen
    if (i < next && isMotion(cmds[i].op)) {
        for (int a = 0; a < program.axisCount && a < 4; ++a) {
            const auto d = static_cast<double>(cmds[i].d[std::size_t(a)]);
            live.steps[std::size_t(a)] =
                cmds[i].endSteps[std::size_t(a)] - std::llround(d * (1.0 - share));
        }
    } else {
        // A dwell or another stop, or the end of what the unit accepted: where the last motion
        // before it ended.
        for (std::size_t k = i; k > cursor.exec && k > 0; --k) {
            if (isMotion(cmds[k - 1].op)) {
                live.steps = cmds[k - 1].endSteps;
                break;
            }
        }
    }
    const std::size_t shown = i < next ? i : (next > 0 ? next - 1 : 0);
    live.command = static_cast<std::int64_t>(shown);
    live.sourceLine = cmds[shown].sourceLine;
    const auto &axes = m_host.config().axes;
    for (std::size_t a = 0; a < 4; ++a)
        live.mm[a] = static_cast<double>(live.steps[a]) / axes[a].stepsPerMm;
    return live;
}

void LiveModel::update(double now)
{
    m_next = now + kIntervalS;
    MachineState &state = m_host.liveState();
    if (const std::optional<LivePosition> live = at(now)) {
        // A machine that stands (a dwell, a spin-up) publishes nothing new.
        LivePosition same = *live;
        same.atS = state.live.atS;
        if (!(state.live == same)) {
            state.live = *live;
            m_host.markDirty();
        }
    } else if (state.live.modelled) {
        positionRead();
        m_host.markDirty();
    }
}

void LiveModel::settle()
{
    if (m_host.liveState().live.modelled && !modelling()) {
        positionRead();
        m_host.markDirty();
    }
}

void LiveModel::positionRead()
{
    MachineState &state = m_host.liveState();
    state.live.modelled = false;
    state.live.steps = state.positionSteps;
    state.live.mm = state.positionMm;
    state.live.sourceLine = state.sourceLine;
    state.live.command = -1;
    state.live.atS = m_host.now();
}

} // namespace frezka::driver
