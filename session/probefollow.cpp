#include "probefollow.h"

#include <optional>
#include <utility>

namespace frezka::session {

ProbeFollow::ProbeFollow(InterpretRequest request, machine::MachineConfig config,
                         double feedOverride)
    : m_request(std::move(request))
    , m_config(std::move(config))
    , m_feedOverride(feedOverride)
{}

ProbeFollow::Next ProbeFollow::start(const std::array<double, 4> &startMm)
{
    m_results.clear();
    m_request.startMm = startMm;
    std::size_t unused = 0;
    Next next = interpret(&unused);
    if (!next.whole)
        return next;
    const gcode::Toolpath &whole = *next.whole;
    auto job = std::make_shared<gcode::Toolpath>();
    job->setOrigin(whole.origin());
    const std::size_t end = next.endsAtProbe ? m_lastProvisional + 1 : whole.size();
    job->appendEntries(whole, 0, end);
    plan(&next, std::move(job));
    return next;
}

ProbeFollow::Next ProbeFollow::afterProbe(const gcode::Point4 &atMm, bool tripped)
{
    m_results.push_back({atMm, tripped});
    std::size_t probe = 0;
    Next next = interpret(&probe);
    if (!next.whole)
        return next;
    const gcode::Toolpath &whole = *next.whole;
    if (!(whole.end(probe) == atMm)) {
        next.whole.reset();
        next.error = tr("%1: the probe move that ran does not end where the machine stopped when "
                        "the program is interpreted again; it cannot go on from the probe's "
                        "result.")
                         .arg(m_request.fileName);
        return next;
    }
    const std::size_t end = next.endsAtProbe ? m_lastProvisional + 1 : whole.size();
    plan(&next, restAfterProbe(whole, probe, end));
    return next;
}

ProbeFollow::Next ProbeFollow::interpret(std::size_t *probeEntry)
{
    Next next;
    m_request.probeResults = m_results;
    const InterpretOutcome g = interpretProgram(m_request);
    if (!g.errors.empty() || !g.toolpath) {
        next.error = g.errors.empty() ? tr("the program could not be interpreted again")
                                      : g.errors.front().text;
        return next;
    }
    if (g.probes < m_results.size()) {
        next.error = tr("%1: the program runs %2 probe moves when interpreted with the results "
                        "of those run so far, fewer than the %3 the machine has run; it cannot "
                        "go on from the probe's result.")
                         .arg(m_request.fileName)
                         .arg(g.probes)
                         .arg(m_results.size());
        return next;
    }
    // The probe that has just run: the n-th in the order the program runs them.
    std::size_t seen = 0;
    for (std::size_t i = 0; i < g.toolpath->size() && !m_results.empty(); ++i) {
        if (g.toolpath->kind(i) == gcode::MotionKind::Probe && ++seen == m_results.size()) {
            *probeEntry = i;
            break;
        }
    }
    next.whole = g.toolpath;
    if (g.toolTableChanged)
        next.toolTable = g.toolTable;
    if (g.workOffsetsChanged)
        next.workOffsetsMm = g.workOffsetsMm;
    next.endsAtProbe = dependsOnProbe(*g.toolpath, g.provisionalEntry);
    next.provisionalLine = g.provisionalLine;
    if (next.endsAtProbe)
        next.provisionalEntry = g.provisionalEntry;
    m_lastProvisional = g.provisionalEntry;
    return next;
}

void ProbeFollow::plan(Next *next, std::shared_ptr<gcode::Toolpath> job)
{
    next->planned = planProgram(*job, m_config, m_request.fileName, m_feedOverride);
    next->job = std::move(job);
    if (!next->planned.ok()) {
        next->error = next->planned.errors.empty() ? tr("the program could not be planned")
                                                   : next->planned.errors.front().text;
        return;
    }
    next->plan = next->planned.program;
}

QString selfProbingRefusal(std::uint32_t probeLine, std::uint32_t startLine, bool heightMap)
{
    if (startLine != 0)
        return ProbeFollow::tr("Line %1: the program probes for itself: after line %2 its path "
                               "depends on that probe's result, and the probes before line %1 "
                               "would not run. Run the whole program.")
            .arg(startLine)
            .arg(probeLine);
    if (heightMap)
        return ProbeFollow::tr("Line %1: the program probes for itself (after this line its "
                               "path depends on the probe's result): a height map cannot be "
                               "applied to it. Remove the map to run the program.")
            .arg(probeLine);
    return {};
}

bool dependsOnProbe(const gcode::Toolpath &whole, std::size_t provisionalEntry)
{
    if (provisionalEntry >= whole.size())
        return false;
    for (std::size_t i = provisionalEntry + 1; i < whole.size(); ++i) {
        if (whole.isMotion(i))
            return true;
    }
    return false;
}

std::shared_ptr<gcode::Toolpath> restAfterProbe(const gcode::Toolpath &whole,
                                                std::size_t probeEntry, std::size_t end)
{
    using gcode::EventKind;
    std::optional<gcode::Event> pathMode, spindle;
    bool mist = false, flood = false;
    for (std::size_t i = 0; i < probeEntry; ++i) {
        if (whole.kind(i) != gcode::MotionKind::Event)
            continue;
        const gcode::Event &e = whole.event(i);
        switch (e.kind) {
        case EventKind::PathMode:
            pathMode = e;
            break;
        case EventKind::SpindleCw:
        case EventKind::SpindleCcw:
            spindle = e;
            break;
        case EventKind::SpindleSpeed:
            if (spindle)
                spindle->value = e.value;
            break;
        case EventKind::SpindleOff:
            spindle.reset();
            break;
        case EventKind::CoolantMist:
            mist = true;
            break;
        case EventKind::CoolantFlood:
            flood = true;
            break;
        case EventKind::CoolantOff:
            mist = flood = false;
            break;
        default:
            break;
        }
    }
    auto rest = std::make_shared<gcode::Toolpath>();
    rest->setOrigin(whole.end(probeEntry));
    const double feed = whole.feedMmPerMin(probeEntry);
    const std::uint32_t line = whole.line(probeEntry);
    if (pathMode)
        rest->appendEvent(*pathMode, feed, line);
    if (spindle)
        rest->appendEvent(*spindle, feed, line);
    if (mist)
        rest->appendEvent({EventKind::CoolantMist, 0, 0, 0}, feed, line);
    if (flood)
        rest->appendEvent({EventKind::CoolantFlood, 0, 0, 0}, feed, line);
    rest->appendEntries(whole, probeEntry + 1, end);
    return rest;
}

} // namespace frezka::session
