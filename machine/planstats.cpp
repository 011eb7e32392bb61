// The plan's figures: the estimate and the time-optimal bound with the link's part of each
// rest (docs/planner.md §7), and the one warning for capped feeds. Part of Planner
// (planner_internal.h).
#include "machine/planner_internal.h"

#include "machine/chainparts.h"
#include "machine/unitmodel.h"
#include "machine/unitwire.h"

#include <algorithm>
#include <cmath>
#include <string>

namespace frezka::machine::detail {

// One warning for the whole program: where the feed is first above what the axes allow, the
// feed asked for, the feed the machine will run there, and how many lines are capped.
void Planner::feedCapWarning()
{
    if (m_feedCapLines == 0)
        return;
    const detail::FeedCap &c = m_firstFeedCap;
    auto mmPerMin = [](double mmPerS) { return std::to_string(std::llround(mmPerS * 60)); };
    const std::string limit =
        c.limit == 'P' ? "the unit's " + std::to_string(m_config.unit.maxPulseRate) + " pulses/s"
                       : std::string(1, c.limit) + "'s maximum speed of " +
                             mmPerMin(c.limitMmPerS) + " mm/min";
    std::string what = "F" + mmPerMin(c.askedMmPerS) +
                       " mm/min is above what the axes allow along this move; the machine runs "
                       "it at " +
                       mmPerMin(c.runMmPerS) + " mm/min (" + limit + ")";
    if (m_feedCapLines == 2)
        what += "; 1 more line is capped the same way";
    else if (m_feedCapLines > 2)
        what += "; " + std::to_string(m_feedCapLines - 1) + " more lines are capped the same way";
    what += ". Lower the F word, or raise the axis maxima in the machine profile if the machine "
            "can go faster";
    m_result.warnings.push_back(
        {PlanErrorCode::FeedCapped, c.line, "line " + std::to_string(c.line) + ": " + what});
}

// The link's part of each rest (docs/planner.md §7): where the queue drains (the program's start,
// a wait for it to drain, a dwell, an operator stop, a probe) the driver learns that the unit
// stands from its next status poll (half the poll interval on average), reads the position
// (the path guard), sends the commands that cannot travel in a packet one round trip each, and
// the unit starts again when the first packet's first vector arrives.
Planner::RestCosts Planner::restCosts() const
{
    const LinkConfig &link = m_config.link;
    if (!m_options.wireLimited || link.baud <= 0)
        return {};
    const double exchangeS = detail::LinkTiming(m_config, m_options).nonPacketS(kExchangeBytes);
    RestCosts costs;
    bool atRest = true;
    bool moved = false;             // a chain ran before this rest: the unit pauses T after it
    double pauseS = kInitialPauseS; // T, as the unit model starts
    double dwellS = 0;              // PC-side dwell since the rest began
    int commands = 0;
    for (const UnitCommand &c : m_result.program.commands) {
        if (c.op == UnitOp::Vector || c.op == UnitOp::Line) {
            if (atRest) {
                // The unit's own T pause after the rest (what a dwell has not covered) runs
                // while the link does its part: the estimate counts the longer of the two.
                const double unitS = moved ? std::max(0.0, pauseS - dwellS) : 0.0;
                costs.linkS += std::max(0.0, kStatusPollS / 2 + (2 + commands) * exchangeS - unitS);
                costs.unitPauseS += unitS;
            }
            atRest = false;
            moved = true;
            commands = 0;
            dwellS = 0;
        } else if (c.op == UnitOp::Brake && link.packets) {
            // travels in the first packet
        } else if (wireCommand(c, m_result.program.axisCount)) {
            pauseS = c.op == UnitOp::Pause ? static_cast<double>(c.value) / 1000.0 : pauseS;
            commands += atRest ? 1 : 0;
        } else {
            atRest = true; // a PC-side wait: the queue drains
            dwellS += c.op == UnitOp::Dwell ? static_cast<double>(c.value) / 1000.0 : 0.0;
        }
    }
    return costs;
}

void Planner::finishStats()
{
    PlanStats &s = m_result.stats;
    const ModelResult model = runUnitModel(m_result.program, m_vk);
    s.vectors = model.vectors;
    s.brakeViolations = model.brakeViolations;
    // The unit's T pause after each PC-side rest is the program's (a wait, a dwell, a stop) or
    // the machine's (a reversal its jump limits cannot pass moving), not the plan's: the bound
    // pays it as the estimate does (seed 30: 181 such rests, the estimate 2.9 % above a bound
    // that left them out). Rests the plan chooses (exact stop's L moves) stay out of it.
    const RestCosts rests = restCosts();
    s.linkWaitS = rests.linkS;
    s.waitS = m_waitS;
    s.estimatedS = model.motionS + model.waitS + s.linkWaitS;
    s.boundS = m_bound + m_waitS + rests.unitPauseS + s.linkWaitS;
}

} // namespace frezka::machine::detail
