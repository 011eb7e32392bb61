// ProgressCheck: a job's progress re-established from the unit's counters. See progresscheck.h.

#include "progresscheck.h"

#include "driver/link/corehost.h"
#include "driver/link/job.h"
#include "driver/link/machinecore_internal.h"

#include <algorithm>
#include <array>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::isModal;
using machine::UnitOp;

void ProgressCheck::verify(const std::string &why)
{
    m_host.log("re-establishing job progress from the unit's counters: " + why);
    ++m_job.report().verified;
    m_needVerify = true;
    m_job.setStreamBlocked(true);
    m_job.releaseLeadIn(); // a unit held at a chain's start would never run dry
    readStillPosition();
}

// Waits for RUN = 0, then reads the counters twice: the machine stands only when both reads
// agree (a late reply on a noisy line must not pass for the final position).
void ProgressCheck::readStillPosition()
{
    m_host.afterIdle([this] {
        const Command pos = m_host.positionCommand();
        m_host.send(pos, [this, pos](const Outcome &first) {
            if (m_host.unitError(first, "reading the position", MachineMode::LinkLost))
                return;
            m_host.send(pos, [this, a = first.reply.values](const Outcome &second) {
                if (m_host.unitError(second, "reading the position", MachineMode::LinkLost))
                    return;
                if (second.reply.values != a) {
                    readStillPosition(); // still moving: wait again
                    return;
                }
                m_host.applyPosition(second.reply);
                matchProgress();
            });
        });
    });
}

// The unit ran everything it accepted; it accepted a prefix of the program. Finds the prefix
// lengths j from the cursor to the end of what was in flight whose end position equals the
// counters. Long for the several outcomes it tells apart.
void ProgressCheck::matchProgress()
{
    const auto &program = m_job.program();
    const auto &cmds = program.commands;
    const int axes = program.axisCount;
    const auto &at = m_host.liveState().positionSteps;
    JobCursor &cursor = m_job.cursor();
    const std::size_t hi = std::min(std::max(cursor.inflightEnd, cursor.next), cmds.size());
    std::size_t lo = cursor.next;
    auto endOf = [&](std::size_t j) -> machine::Steps4 {
        return j == 0 ? program.startSteps : cmds.endSteps(j - 1);
    };
    std::vector<std::size_t> matches;
    for (std::size_t j = lo; j <= hi; ++j) {
        bool same = true;
        for (int a = 0; a < axes; ++a)
            same = same && endOf(j)[a] == at[a];
        if (same)
            matches.push_back(j);
    }
    // Several j with the same end position differ only by modal commands (B) or zero moves:
    // taking the first is exact as long as they are contiguous (modal commands are re-sent).
    const JobPace &pace = m_job.pace();
    bool contiguous = !matches.empty();
    for (std::size_t k = 1; k < matches.size(); ++k)
        contiguous =
            contiguous && (matches[k] == matches[k - 1] + 1 ||
                           pace.vectorsBefore(matches[k]) == pace.vectorsBefore(matches[0]));
    const std::string counters =
        std::to_string(at[0]) + ", " + std::to_string(at[1]) + ", " + std::to_string(at[2]);
    if (matches.empty() && !m_linkWasLost) {
        // The link stayed up, so the unit's counters were not reset: the unit ran something
        // other than what was sent.
        m_job.guard().fault("after an unsettled reply the counters read " + counters +
                            " steps, which no point of the job sent so far has");
        return;
    }
    if (!contiguous) {
        m_host.log("counters " + counters + "; searched commands " + std::to_string(lo) + ".." +
                   std::to_string(hi) + " ending " + std::to_string(endOf(lo)[0]) + ".." +
                   std::to_string(endOf(hi)[0]) + " on X");
        m_host.fail(
            {matches.empty() ? DriverCode::CountersMatchNothing : DriverCode::CountersMatchSeveral},
            nullptr, MachineMode::Alarm);
        return;
    }
    const std::size_t j = matches.front();
    m_linkWasLost = false;
    m_host.log("progress re-established at command " + std::to_string(j) + " of " +
               std::to_string(cmds.size()));
    m_job.acceptUpTo(j);
    cursor.inflightEnd = j;
    cursor.exec = std::min(cursor.exec, j);
    resendModals([this] {
        m_needVerify = false;
        m_job.setStreamBlocked(false);
        m_job.setQueueFullSeen(false);
    });
}

void ProgressCheck::resendModals(std::function<void()> then)
{
    const auto &cmds = m_job.program().commands;
    std::vector<std::size_t> last;
    std::array<bool, 16> seen{};
    for (std::size_t i = m_job.cursor().next; i-- > 0;) {
        const UnitOp op = cmds[i].op;
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
        m_host.send(m_job.toCommand(cmds[i]), [this](const Outcome &o) {
            m_host.unitError(o, "re-sending the job's speed settings", MachineMode::Alarm);
        });
    }
    m_host.send(cmd::flag(), [this, then = std::move(then)](const Outcome &o) {
        if (m_host.unitError(o, "status", MachineMode::Alarm))
            return;
        m_host.applyFlags(*o.reply.hexValue());
        then();
    });
}

} // namespace frezka::driver
