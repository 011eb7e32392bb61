// MachineCore: the path guard. The protocol's checksum is a sum of the bytes mod 256, so two
// faults in one line can cancel out: a dropped '0' and a doubled '0' turn `C60,20,2` into
// `C6,200,2` with the same checksum, and the unit runs a vector nobody planned. Nothing in the
// protocol can catch that before the unit runs it, so the driver checks what the unit does:
//
// - every position poll of a running job must lie on the planned path, within one step of a
//   segment between the last verified command and the last one sent (the unit's counters step
//   along the straight line of each vector, each axis within one step of it);
// - where the machine stands (before I/O, dwells, operator stops, probes and at the end), its
//   counters must equal the planned position exactly.
//
// A position off the path stops the unit (H), drops its queue (D) and holds the job with the
// reason (HoldReason::PathFault). Resuming (or CoreOptions::returnToPathAutomatically) lifts
// the tool as far as Z's soft limit allows, moves to the start of the last verified command,
// lowers it, sends the modal settings in force there again, and streams on from that command,
// so the job ends at exactly the planned counters.

#include "machinecore.h"

#include "driver/link/machinecore_internal.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::isMotion;
using detail::lineText;
using machine::UnitOp;

namespace {

std::string stepsText(const machine::Steps4 &s, int axes)
{
    std::string t;
    for (int a = 0; a < axes; ++a)
        t += (a ? ", " : "") + std::to_string(s[static_cast<std::size_t>(a)]);
    return t;
}

} // namespace

// The planned position before program command `index` (after the motion before it).
const machine::Steps4 &MachineCore::plannedBefore(std::size_t index) const
{
    return index == 0 ? m_program.startSteps
                      : m_program.commands[std::min(index, m_program.commands.size()) - 1].endSteps;
}

// Whether the polled position lies on the planned path between the last verified command and
// the last one sent; moves m_verified to the first segment that holds it.
bool MachineCore::onPlannedPath()
{
    const auto &cmds = m_program.commands;
    const int axes = m_program.axisCount;
    const auto &p = m_state.positionSteps;
    // A probe move runs before it counts as accepted (the job waits at it): include it.
    const bool probing = m_next < cmds.size() && cmds[m_next].op == UnitOp::Probe;
    const std::size_t hi =
        std::min(std::max(m_next + (probing ? 1 : 0), m_inflightEnd), cmds.size());
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

// The machine stands before program command `index` (a wait for idle is done): its counters
// must be exactly where the plan has it. Then `then`; otherwise the path fault.
void MachineCore::checkAtRest(std::size_t index, std::function<void()> then)
{
    if (m_pathGuardOff) {
        then();
        return;
    }
    const Command pos = m_state.axisCount == 4 ? cmd::positionXYZA() : cmd::positionXYZ();
    send(pos, [this, index, then = std::move(then)](const Outcome &o) {
        if (unitError(o, "reading the position", MachineMode::LinkLost))
            return;
        applyPosition(o.reply);
        const machine::Steps4 &want = plannedBefore(index);
        bool same = true;
        for (int a = 0; a < m_program.axisCount; ++a)
            same = same && m_state.positionSteps[a] == want[a];
        if (same) {
            m_verified = std::max(m_verified, index);
            then();
            return;
        }
        pathFault("the machine stands at " + stepsText(m_state.positionSteps, m_program.axisCount) +
                  " steps where the program has it at " + stepsText(want, m_program.axisCount));
    });
}

void MachineCore::pathFault(const std::string &why)
{
    if (m_pathFault || !m_job)
        return;
    m_pathFault = true;
    ++m_report.pathFaults;
    m_pathFaultText = why;
    log("path guard: " + why + "; stopping");
    m_streamBlocked = true;
    m_needVerify = false; // the job runs on from the last verified command, whatever else ran
    m_waitUntil = -1;
    m_jobIdleWaiters.clear();
    setMode(MachineMode::Stopping);
    sendFront(cmd::halt(), [this](const Outcome &o) {
        unitError(o, "stopping (H) off the planned path", MachineMode::Alarm);
    });
    send(cmd::deleteQueue(), [this](const Outcome &o) {
        if (unitError(o, "dropping the queue (D) off the planned path", MachineMode::Alarm))
            return;
        m_holdNeedsGo = false;
        m_state.inta = false;
        whenStill([this] { holdOrReturn(); });
    });
}

void MachineCore::holdOrReturn()
{
    const auto &cmds = m_program.commands;
    const std::size_t g = std::min(m_verified, cmds.size());
    const std::string where = cmds.empty() ? "setup" : lineText(cmds[std::min(g, cmds.size() - 1)]);
    const std::string text = "the machine left the planned path: " + m_pathFaultText +
                             ". A command was damaged on the serial line in a way its checksum "
                             "cannot show. Resuming lifts the tool, returns to " +
                             where + " and runs the job on from there";
    if (m_options.returnToPathAutomatically) {
        log(text);
        returnToPath(1);
        return;
    }
    m_state.hold = HoldReason::PathFault;
    m_state.holdText = text;
    fail(text, nullptr, MachineMode::Paused);
}

void MachineCore::returnToPath(int attempt)
{
    constexpr int kAttempts = 3;
    if (attempt > kAttempts) {
        fail("the machine did not arrive back on the planned path after " +
                 std::to_string(kAttempts) + " attempts; abort the job and check the machine",
             nullptr, MachineMode::Alarm);
        return;
    }
    m_state.hold = HoldReason::None;
    m_state.holdText = "returning to the planned path";
    m_state.lastError.reset();
    setMode(MachineMode::Running); // m_pathFault keeps the stream and the guard off meanwhile
    const int axes = m_program.axisCount;
    const std::size_t g = std::min(m_verified, m_program.commands.size());
    const machine::Steps4 target = plannedBefore(g);
    const machine::Steps4 from = m_state.positionSteps;

    // Z travels above both ends by the tool-lift height, never beyond its upper soft limit.
    const std::int64_t top = stepsFromMm(2, m_config.axes[2].softMaxMm);
    const std::int64_t high = std::max(from[2], target[2]);
    const std::int64_t travelZ = std::max(
        high, std::min(top, high + stepsFromMm(2, std::max(0.0, m_config.motion.toolLiftMm))));
    std::vector<machine::Steps4> moves;
    auto add = [&](machine::Steps4 d) {
        if (std::any_of(d.begin(), d.end(), [](std::int64_t v) { return v != 0; }))
            moves.push_back(d);
    };
    add({0, 0, travelZ - from[2], 0});
    add({target[0] - from[0], target[1] - from[1], 0, axes == 4 ? target[3] - from[3] : 0});
    add({0, 0, target[2] - travelZ, 0});

    // At the slowest axis's maximum feed, so that no axis exceeds its own in either speed mode.
    double rate = m_config.unit.maxPulseRate;
    for (int a = 0; a < axes; ++a) {
        const machine::AxisConfig &ax = m_config.axes[static_cast<std::size_t>(a)];
        rate = std::min(rate, ax.maxSpeedMmPerMin / 60.0 * ax.stepsPerMm);
    }
    const auto pulses =
        std::clamp<std::int64_t>(std::llround(rate), 10, m_config.unit.maxPulseRate);
    log("returning to the planned path at command " + std::to_string(g) + ": " +
        stepsText(from, axes) + " -> " + stepsText(target, axes));
    send(cmd::speed(pulses), [this](const Outcome &o) {
        unitError(o, "setting the speed to return to the path", MachineMode::Alarm);
    });
    m_returnMoves = std::move(moves);
    m_returnAttempt = attempt;
    afterIdle([this] { returnStep(0); });
}

// Each L from rest to rest: the next one only when the machine stands (L needs an empty queue).
void MachineCore::returnStep(std::size_t k)
{
    if (k < m_returnMoves.size()) {
        const machine::Steps4 &d = m_returnMoves[k];
        const Command l = m_program.axisCount == 4 ? cmd::line(d[0], d[1], d[2], d[3])
                                                   : cmd::line(d[0], d[1], d[2]);
        send(l, [this, k](const Outcome &o) {
            if (o.status == OutcomeStatus::Ok && o.reply.code == ReplyCode::QueueFull) {
                afterIdle([this, k] { returnStep(k); }); // the unit was not done yet: again
                return;
            }
            if (unitError(o, "returning to the planned path", MachineMode::Alarm))
                return;
            ++m_report.returnMoves;
            afterIdle([this, k] { returnStep(k + 1); });
        });
        return;
    }
    whenStill([this] {
        const std::size_t g = std::min(m_verified, m_program.commands.size());
        const machine::Steps4 &target = plannedBefore(g);
        for (int a = 0; a < m_program.axisCount; ++a) {
            if (m_state.positionSteps[a] != target[a]) {
                log("not back on the planned path: trying again");
                returnToPath(m_returnAttempt + 1);
                return;
            }
        }
        // Everything sent from g on goes again (accepted, or in flight when the job stopped);
        // g may also lie beyond the accepted commands (the unit was seen running one in flight).
        const std::size_t sent =
            std::min(std::max({m_next, m_inflightEnd, g}), m_vectorPrefix.size() - 1);
        m_report.rerun += m_vectorPrefix[sent] - m_vectorPrefix[g];
        m_report.vectors += m_vectorPrefix[g] - m_vectorPrefix[m_next];
        m_report.commands += static_cast<std::int64_t>(g) - static_cast<std::int64_t>(m_next);
        m_vectorsAcked = m_vectorPrefix[g];
        m_next = m_exec = m_inflightEnd = g;
        m_execAt = m_now;
        m_packetLimit = maxPacket();
        m_state.commandsAcked = static_cast<std::int64_t>(g);
        m_state.vectorsAcked = m_vectorsAcked;
        resendModals([this, g] {
            log("back on the planned path: the job runs on from command " + std::to_string(g));
            m_pathFault = false;
            m_streamBlocked = false;
            m_queueFullSeen = false;
            m_state.holdText.clear();
            m_dirty = true;
        });
    });
}

} // namespace frezka::driver
