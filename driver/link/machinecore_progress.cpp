// MachineCore: progress from the polled position, its re-establishment from the unit's
// counters after an unknown outcome or a link loss, and G38 probe moves.

#include "machinecore.h"

#include "driver/link/machinecore_internal.h"
#include "gcode/toolpath.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::isModal;
using detail::isMotion;
using detail::lineText;
using machine::UnitOp;

// The executing command from the polled position: the first motion command from m_exec on
// whose box (from its start to its end position) holds the position and which has not ended.
void MachineCore::locateExecuting()
{
    const auto &cmds = m_program.commands;
    const int axes = m_program.axisCount;
    const auto &pos = m_state.positionSteps;
    std::size_t i = m_exec;
    const std::size_t limit = std::min(m_next, cmds.size());
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
        if (inside && !atEnd)
            break;
    }
    m_exec = i;
    const std::size_t shown = std::min(i, cmds.empty() ? 0 : cmds.size() - 1);
    m_state.sourceLine = cmds.empty() ? 0 : cmds[shown].sourceLine;
    m_state.progress = cmds.empty() ? 0 : static_cast<double>(i) / static_cast<double>(cmds.size());
    const double elapsed = m_now - m_report.startS;
    m_state.etaS =
        i > 0 ? elapsed * static_cast<double>(cmds.size() - i) / static_cast<double>(i) : -1;
}

void MachineCore::verifyProgress(const std::string &why)
{
    log("re-establishing job progress from the unit's counters: " + why);
    ++m_report.verified;
    m_needVerify = true;
    m_streamBlocked = true;
    readStillPosition();
}

// Waits for RUN = 0, then reads the counters twice: the machine stands only when both reads
// agree (a late reply on a noisy line must not pass for the final position).
void MachineCore::readStillPosition()
{
    afterIdle([this] {
        const Command pos = m_state.axisCount == 4 ? cmd::positionXYZA() : cmd::positionXYZ();
        send(pos, [this, pos](const Outcome &first) {
            if (unitError(first, "reading the position", MachineMode::LinkLost))
                return;
            send(pos, [this, a = first.reply.values](const Outcome &second) {
                if (unitError(second, "reading the position", MachineMode::LinkLost))
                    return;
                if (second.reply.values != a) {
                    readStillPosition(); // still moving: wait again
                    return;
                }
                applyPosition(second.reply);
                matchProgress();
            });
        });
    });
}

void MachineCore::matchProgress()
{
    // The unit ran everything it accepted; it accepted a prefix of the program. Find the
    // prefix lengths j in [m_next, m_inflightEnd] whose end position equals the counters.
    const auto &cmds = m_program.commands;
    const int axes = m_program.axisCount;
    const std::size_t hi = std::min(std::max(m_inflightEnd, m_next), cmds.size());
    std::size_t lo = m_next;
    auto endOf = [&](std::size_t j) -> const machine::Steps4 & {
        return j == 0 ? m_program.startSteps : cmds[j - 1].endSteps;
    };
    std::vector<std::size_t> matches;
    for (std::size_t j = lo; j <= hi; ++j) {
        bool same = true;
        for (int a = 0; a < axes; ++a)
            same = same && endOf(j)[a] == m_state.positionSteps[a];
        if (same)
            matches.push_back(j);
    }
    // Several j with the same end position differ only by modal commands (B) or zero moves:
    // taking the first is exact as long as they are contiguous (modal commands are re-sent).
    bool contiguous = !matches.empty();
    for (std::size_t k = 1; k < matches.size(); ++k)
        contiguous = contiguous && (matches[k] == matches[k - 1] + 1 ||
                                    m_vectorPrefix[matches[k]] == m_vectorPrefix[matches[0]]);
    if (matches.empty() && !m_linkWasLost) {
        // The link stayed up, so the unit's counters were not reset: the unit ran something
        // other than what was sent.
        pathFault("after an unsettled reply the counters read " +
                  std::to_string(m_state.positionSteps[0]) + ", " +
                  std::to_string(m_state.positionSteps[1]) + ", " +
                  std::to_string(m_state.positionSteps[2]) +
                  " steps, which no point of the job sent so far has");
        return;
    }
    if (!contiguous) {
        log("counters " + std::to_string(m_state.positionSteps[0]) + ", " +
            std::to_string(m_state.positionSteps[1]) + ", " +
            std::to_string(m_state.positionSteps[2]) + "; searched commands " + std::to_string(lo) +
            ".." + std::to_string(hi) + " ending " + std::to_string(endOf(lo)[0]) + ".." +
            std::to_string(endOf(hi)[0]) + " on X");
        fail(matches.empty()
                 ? "the unit's counters match no point the job has reached; the job cannot "
                   "resume exactly (re-home and start it again)"
                 : "the unit's counters match several points of the job; cannot tell how far "
                   "it got (abort the job)",
             nullptr, MachineMode::Alarm);
        return;
    }
    const std::size_t j = matches.front();
    m_linkWasLost = false;
    log("progress re-established at command " + std::to_string(j) + " of " +
        std::to_string(cmds.size()));
    acceptUpTo(j);
    m_inflightEnd = j;
    m_exec = std::min(m_exec, j);
    resendModals([this] {
        m_needVerify = false;
        m_streamBlocked = false;
        m_queueFullSeen = false;
    });
}

void MachineCore::resendModals(std::function<void()> then)
{
    // The last value of each modal command before m_next, sent again in program order.
    std::vector<std::size_t> last;
    std::array<bool, 16> seen{};
    for (std::size_t i = m_next; i-- > 0;) {
        const UnitOp op = m_program.commands[i].op;
        if (!isModal(op))
            continue;
        const auto slot =
            static_cast<std::size_t>(op == UnitOp::SpeedModeVn ? UnitOp::SpeedModeVk : op);
        if (seen[slot])
            continue;
        seen[slot] = true;
        last.push_back(i);
    }
    std::reverse(last.begin(), last.end());
    for (std::size_t i : last) {
        send(toCommand(m_program.commands[i]), [this](const Outcome &o) {
            unitError(o, "re-sending the job's speed settings", MachineMode::Alarm);
        });
    }
    send(cmd::flag(), [this, then = std::move(then)](const Outcome &o) {
        if (unitError(o, "status", MachineMode::Alarm))
            return;
        applyFlags(*o.reply.hexValue(), m_now);
        then();
    });
}

// Two position reads that agree: the machine stands (after RUN = 0 or an interrupt's brake).
void MachineCore::whenStill(std::function<void()> then)
{
    const Command pos = m_state.axisCount == 4 ? cmd::positionXYZA() : cmd::positionXYZ();
    send(pos, [this, pos, then](const Outcome &first) {
        if (unitError(first, "reading the position", MachineMode::Alarm))
            return;
        send(pos, [this, then, a = first.reply.values](const Outcome &second) {
            if (unitError(second, "reading the position", MachineMode::Alarm))
                return;
            applyPosition(second.reply);
            if (second.reply.values == a)
                then();
            else
                whenStill(then);
        });
    });
}

// G38.x: the tool sensor probe (IN15) as an interrupt, armed for contact (G38.2/.3) or for its
// loss (G38.4/.5), then the probe move as an L. The unit brakes when the input fires; the
// counters give the trip point. The planner planned the rest of the program from the probe's
// end point, so when the probe stops short and motion follows, the job ends there (to be planned
// again from the trip point) rather than run displaced.
void MachineCore::startProbe(std::size_t index)
{
    const machine::UnitCommand c = m_program.commands[index];
    const auto kind = static_cast<gcode::ProbeKind>(c.aux);
    const bool toward =
        kind == gcode::ProbeKind::TowardErrorIfNoContact || kind == gcode::ProbeKind::Toward;
    const bool mustTrip = kind == gcode::ProbeKind::TowardErrorIfNoContact ||
                          kind == gcode::ProbeKind::AwayErrorIfNoLoss;
    const machine::EepromConfig &ee = m_config.eeprom;
    const std::uint8_t contactHigh = ee.polarityHigh & 0x80; // IN15 level that means contact
    const auto armPolarity = static_cast<std::uint8_t>(
        (ee.polarityHigh & 0x7F) | (toward ? contactHigh : (contactHigh ^ 0x80)));
    send(cmd::input2(), [this, index, armPolarity](const Outcome &o) {
        if (unitError(o, "reading the probe input", MachineMode::Alarm))
            return;
        if ((*o.reply.hexValue() & 0x80) == (armPolarity & 0x80)) {
            m_steps.clear();
            finishJob(false);
            fail(lineText(m_program.commands[index]) +
                     ": the probe input is already in the state the probe move waits for",
                 &o, MachineMode::Alarm);
        }
    });
    send(cmd::statusWrite(1, ee.interruptEnableHigh | 0x80),
         [this](const Outcome &o) { unitError(o, "arming the probe input", MachineMode::Alarm); });
    send(cmd::statusWrite(3, armPolarity),
         [this](const Outcome &o) { unitError(o, "arming the probe input", MachineMode::Alarm); });
    send(toCommand({machine::UnitOp::Line, c.d}), [this, index, mustTrip](const Outcome &o) {
        if (unitError(o, "probe move", MachineMode::Alarm))
            return;
        m_haltExpected = true;
        afterStopOrInterrupt([this, index, mustTrip] {
            // The unit brakes after the input fires; H answers only once it stands (two equal
            // position reads alone can come from the last, slow steps of the ramp).
            send(cmd::halt(), [this](const Outcome &h) {
                unitError(h, "stopping the probe move (H)", MachineMode::Alarm);
            });
            whenStill([this, index, mustTrip] { endProbe(index, mustTrip); });
        });
    });
}

void MachineCore::endProbe(std::size_t index, bool mustTrip)
{
    const Command pos = m_state.axisCount == 4 ? cmd::positionXYZA() : cmd::positionXYZ();
    send(cmd::statusRead(5), [this](const Outcome &o) {
        if (!unitError(o, "reading the probe result", MachineMode::Alarm))
            m_state.probeTripped = (*o.reply.hexValue() & 0x80) != 0;
    });
    send(pos, [this](const Outcome &o) {
        if (!unitError(o, "reading the probe position", MachineMode::Alarm)) {
            applyPosition(o.reply);
            m_state.probeSteps = m_state.positionSteps;
        }
    });
    // D drops what is left of the probe move and clears INTA and the cause bits.
    send(cmd::deleteQueue(), [this](const Outcome &o) { unitError(o, "D", MachineMode::Alarm); });
    const machine::EepromConfig &ee = m_config.eeprom;
    send(cmd::statusWrite(1, ee.interruptEnableHigh), [](const Outcome &) {});
    send(cmd::statusWrite(3, ee.polarityHigh), [this, index, mustTrip](const Outcome &o) {
        m_haltExpected = false;
        if (unitError(o, "disarming the probe input", MachineMode::Alarm))
            return;
        m_state.inta = false;
        const machine::UnitCommand &c = m_program.commands[index];
        bool atEnd = true;
        for (int a = 0; a < m_program.axisCount; ++a)
            atEnd = atEnd && m_state.positionSteps[a] == c.endSteps[a];
        if (!m_state.probeTripped && mustTrip) {
            m_state.hold = HoldReason::ProbeFailed;
            finishJob(false);
            fail(lineText(c) + ": the probe move ended without the probe tripping", nullptr,
                 MachineMode::Alarm);
            return;
        }
        const bool motionFollows = std::any_of(
            m_program.commands.begin() + static_cast<std::ptrdiff_t>(index) + 1,
            m_program.commands.end(), [](const machine::UnitCommand &u) {
                return u.op == UnitOp::Vector || u.op == UnitOp::Line || u.op == UnitOp::Probe;
            });
        if (!atEnd)
            m_pathGuardOff = true; // the rest was planned from the probe's programmed end
        if (!atEnd && motionFollows) {
            finishJob(false);
            fail(lineText(c) + ": the probe tripped at " + std::to_string(m_state.probeSteps[0]) +
                     ", " + std::to_string(m_state.probeSteps[1]) + ", " +
                     std::to_string(m_state.probeSteps[2]) +
                     " steps; the rest of the program was planned from the probe's end point: "
                     "plan it again from here",
                 nullptr, MachineMode::Alarm);
            return;
        }
        acceptUpTo(index + 1);
        m_streamBlocked = false;
    });
}

} // namespace frezka::driver
