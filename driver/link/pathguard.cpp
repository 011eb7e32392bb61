// PathGuard: the job's position checked against the planned path. See pathguard.h.

#include "pathguard.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/machinecore_internal.h"
#include "machine/pathcheck.h"

#include <algorithm>

namespace frezka::driver {

using namespace frezka::protocol;
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

machine::Steps4 PathGuard::plannedBefore(std::size_t index) const
{
    return machine::plannedBefore(m_job.program(), index);
}

bool PathGuard::onPlannedPath()
{
    const machine::UnitProgram &program = m_job.program();
    const auto &cmds = program.commands;
    const auto &p = m_host.liveState().positionSteps;
    const JobCursor &cursor = m_job.cursor();
    // A probe move runs before it counts as accepted (the job waits at it): include it.
    const bool probing = cursor.next < cmds.size() && cmds[cursor.next].op == UnitOp::Probe;
    const std::size_t hi =
        std::min(std::max(cursor.next + (probing ? 1 : 0), cursor.inflightEnd), cmds.size());
    const std::size_t lo = std::min(m_verified, hi);
    if (machine::sameSteps(p, plannedBefore(lo), program.axisCount))
        return true;
    const std::optional<std::size_t> i = machine::segmentHolding(program, lo, hi, p);
    if (!i)
        return false;
    m_verified = std::max(m_verified, *i);
    return true;
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
        if (machine::sameSteps(at, want, axes)) {
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
    const bool any = !cmds.empty();
    const machine::UnitCommand at =
        any ? cmds[std::min(g, cmds.size() - 1)] : machine::UnitCommand{};
    const DriverMessage text{DriverCode::OffPath,
                             {m_faultText, any ? detail::lineArg(at) : std::string("setup")}};
    if (m_host.options().returnToPathAutomatically) {
        m_host.log(englishText(text, true));
        m_return.start(1);
        return;
    }
    MachineState &state = m_host.liveState();
    detail::setHold(state, HoldReason::PathFault, text, any ? at.sourceLine : 0);
    m_host.fail(text, nullptr, MachineMode::Paused);
}

} // namespace frezka::driver
