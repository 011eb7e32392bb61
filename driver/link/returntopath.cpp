// ReturnToPath: back to the last verified point of the job's path. See returntopath.h.

#include "returntopath.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/machinecore_internal.h"
#include "driver/link/pathguard.h"
#include "machine/manualmoves.h"
#include "machine/pathcheck.h"
#include "machine/steps.h"

#include <algorithm>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::stepsText;

void ReturnToPath::start(int attempt)
{
    constexpr int kAttempts = 3;
    if (attempt > kAttempts) {
        m_host.fail({DriverCode::ReturnFailed, {std::to_string(kAttempts)}}, nullptr,
                    MachineMode::Alarm);
        return;
    }
    MachineState &state = m_host.liveState();
    detail::setHold(state, HoldReason::None, {DriverCode::HoldReturning}, state.holdLine);
    state.lastError.reset();
    m_host.setMode(MachineMode::Running); // the path fault keeps the stream and the guard off
    const machine::MachineConfig &config = m_host.config();
    const int axes = m_job.program().axisCount;
    const std::size_t g = std::min(m_guard.verified(), m_job.program().commands.size());
    // At the slowest axis's maximum feed, so that no axis exceeds its own in either speed mode.
    const std::int64_t pulses =
        machine::speedPulses(machine::slowestAxisPulseRate(config, axes), config.unit.maxPulseRate);
    m_host.log("returning to the planned path at command " + std::to_string(g) + ": " +
               stepsText(state.positionSteps, axes) + " -> " +
               stepsText(m_guard.plannedBefore(g), axes));
    m_host.send(cmd::speed(pulses), [this](const Outcome &o) {
        m_host.unitError(o, "setting the speed to return to the path", MachineMode::Alarm);
    });
    m_moves = planMoves();
    m_attempt = attempt;
    m_host.afterIdle([this] { step(0); });
}

// Z travels above both ends by the tool-lift height, never beyond its upper soft limit.
std::vector<machine::Steps4> ReturnToPath::planMoves() const
{
    const std::size_t g = std::min(m_guard.verified(), m_job.program().commands.size());
    return machine::returnToPathMoves(m_host.config(), m_host.liveState().positionSteps,
                                      m_guard.plannedBefore(g), m_job.program().axisCount);
}

// Each L from rest to rest: the next one only when the machine stands (L needs an empty queue).
void ReturnToPath::step(std::size_t k)
{
    if (k >= m_moves.size()) {
        m_host.whenStill([this] { arrived(); });
        return;
    }
    const machine::Steps4 &d = m_moves[k];
    const Command l = m_job.program().axisCount == 4 ? cmd::line(d[0], d[1], d[2], d[3])
                                                     : cmd::line(d[0], d[1], d[2]);
    m_host.send(l, [this, k](const Outcome &o) {
        if (o.status == OutcomeStatus::Ok && o.reply.code == ReplyCode::QueueFull) {
            m_host.afterIdle([this, k] { step(k); }); // the unit was not done yet: again
            return;
        }
        if (m_host.unitError(o, "returning to the planned path", MachineMode::Alarm))
            return;
        ++m_job.report().returnMoves;
        m_host.afterIdle([this, k] { step(k + 1); });
    });
}

// The machine stands: on the path, the job runs on from the last verified command; else again.
void ReturnToPath::arrived()
{
    const auto &program = m_job.program();
    const std::size_t g = std::min(m_guard.verified(), program.commands.size());
    const machine::Steps4 &target = m_guard.plannedBefore(g);
    MachineState &state = m_host.liveState();
    if (!machine::sameSteps(state.positionSteps, target, program.axisCount)) {
        m_host.log("not back on the planned path: trying again");
        start(m_attempt + 1);
        return;
    }
    // Everything sent from g on goes again (accepted, or in flight when the job stopped); g may
    // also lie beyond the accepted commands (the unit was seen running one in flight).
    JobCursor &cursor = m_job.cursor();
    JobReport &report = m_job.report();
    const JobPace &pace = m_job.pace();
    const std::size_t sent =
        std::min(std::max({cursor.next, cursor.inflightEnd, g}), pace.size() - 1);
    report.rerun += pace.vectorsBefore(sent) - pace.vectorsBefore(g);
    report.vectors += pace.vectorsBefore(g) - pace.vectorsBefore(cursor.next);
    report.commands += static_cast<std::int64_t>(g) - static_cast<std::int64_t>(cursor.next);
    cursor.vectorsAcked = pace.vectorsBefore(g);
    cursor.next = cursor.exec = cursor.inflightEnd = g;
    cursor.execAt = m_host.now();
    m_job.resetPacketLimit();
    state.commandsAcked = static_cast<std::int64_t>(g);
    state.vectorsAcked = cursor.vectorsAcked;
    m_job.progress().resendModals([this, g] {
        m_host.log("back on the planned path: the job runs on from command " + std::to_string(g));
        m_guard.clearFault();
        m_job.setStreamBlocked(false);
        m_job.setQueueFullSeen(false);
        detail::setHold(m_host.liveState(), HoldReason::None, {}, 0);
        m_host.markDirty();
    });
}

} // namespace frezka::driver
