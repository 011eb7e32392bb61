// PathGuard: the job's position checked against the planned path. See pathguard.h.

#include "pathguard.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/machinecore_internal.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::isMotion;
using detail::stepsText;
using machine::UnitOp;

PathGuard::PathGuard(CoreHost &host, Job &job)
    : m_host(host)
    , m_job(job)
    , m_return(host, job, *this)
{}

void PathGuard::reset()
{
    m_verified = 0;
    m_pathFault = m_off = false;
}

const machine::Steps4 &PathGuard::plannedBefore(std::size_t index) const
{
    const machine::UnitProgram &program = m_job.program();
    return index == 0 ? program.startSteps
                      : program.commands[std::min(index, program.commands.size()) - 1].endSteps;
}

bool PathGuard::onPlannedPath()
{
    const auto &cmds = m_job.program().commands;
    const int axes = m_job.program().axisCount;
    const auto &p = m_host.liveState().positionSteps;
    const JobCursor &cursor = m_job.cursor();
    // A probe move runs before it counts as accepted (the job waits at it): include it.
    const bool probing = cursor.next < cmds.size() && cmds[cursor.next].op == UnitOp::Probe;
    const std::size_t hi =
        std::min(std::max(cursor.next + (probing ? 1 : 0), cursor.inflightEnd), cmds.size());
    const std::size_t lo = std::min(m_verified, hi);
    bool atStart = true;
    for (int a = 0; a < axes; ++a)
        atStart = atStart && p[a] == plannedBefore(lo)[a];
    if (atStart)
        return true;
    constexpr double kTolerance = 1.0 + 1e-9; // steps, per axis
    for (std::size_t i = lo; i < hi; ++i) {
        const machine::UnitCommand &c = cmds[i];
        if (!isMotion(c.op) && c.op != UnitOp::Probe)
            continue;
        // The part t of the segment (0..1) where every axis is within a step of the line.
        double t0 = 0, t1 = 1;
        for (int a = 0; a < axes && t0 <= t1; ++a) {
            const double d = c.d[a];
            const double off = static_cast<double>(p[a] - (c.endSteps[a] - c.d[a]));
            if (d == 0) {
                if (std::abs(off) > kTolerance)
                    t0 = 2;
                continue;
            }
            double u0 = (off - kTolerance) / d, u1 = (off + kTolerance) / d;
            if (u0 > u1)
                std::swap(u0, u1);
            t0 = std::max(t0, u0);
            t1 = std::min(t1, u1);
        }
        if (t0 <= t1) {
            m_verified = std::max(m_verified, i);
            return true;
        }
    }
    return false;
}

void PathGuard::checkAtRest(std::size_t index, std::function<void()> then)
{
    if (m_off) {
        then();
        return;
    }
    m_host.send(m_host.positionCommand(), [this, index, then = std::move(then)](const Outcome &o) {
        if (m_host.unitError(o, "reading the position", MachineMode::LinkLost))
            return;
        m_host.applyPosition(o.reply);
        const int axes = m_job.program().axisCount;
        const auto &at = m_host.liveState().positionSteps;
        const machine::Steps4 &want = plannedBefore(index);
        bool same = true;
        for (int a = 0; a < axes; ++a)
            same = same && at[a] == want[a];
        if (same) {
            m_verified = std::max(m_verified, index);
            then();
            return;
        }
        fault("the machine stands at " + stepsText(at, axes) +
              " steps where the program has it at " + stepsText(want, axes));
    });
}

void PathGuard::fault(const std::string &why)
{
    if (m_pathFault || !m_job.active())
        return;
    m_pathFault = true;
    ++m_job.report().pathFaults;
    m_faultText = why;
    m_host.log("path guard: " + why + "; stopping");
    m_job.setStreamBlocked(true);
    m_job.progress().cancel(); // the job runs on from the last verified command, whatever ran
    m_job.setWaitUntil(-1);
    m_host.clearJobIdleWaiters();
    m_host.setMode(MachineMode::Stopping);
    m_host.sendFront(cmd::halt(), [this](const Outcome &o) {
        m_host.unitError(o, "stopping (H) off the planned path", MachineMode::Alarm);
    });
    m_host.send(cmd::deleteQueue(), [this](const Outcome &o) {
        if (m_host.unitError(o, "dropping the queue (D) off the planned path", MachineMode::Alarm))
            return;
        m_host.setHoldNeedsGo(false);
        m_host.liveState().inta = false;
        m_host.whenStill([this] { holdOrReturn(); });
    });
}

void PathGuard::holdOrReturn()
{
    const auto &cmds = m_job.program().commands;
    const std::size_t g = std::min(m_verified, cmds.size());
    const machine::UnitCommand *at = cmds.empty() ? nullptr : &cmds[std::min(g, cmds.size() - 1)];
    const DriverMessage text{DriverCode::OffPath,
                             {m_faultText, at ? detail::lineArg(*at) : std::string("setup")}};
    if (m_host.options().returnToPathAutomatically) {
        m_host.log(englishText(text, true));
        m_return.start(1);
        return;
    }
    MachineState &state = m_host.liveState();
    detail::setHold(state, HoldReason::PathFault, text, at ? at->sourceLine : 0);
    m_host.fail(text, nullptr, MachineMode::Paused);
}

} // namespace frezka::driver
