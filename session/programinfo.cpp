#include "programinfo.h"

#include "session/travelcheck.h"

#include <QFileInfo>

#include <cmath>

namespace frezka::session {
namespace {

double distance(const gcode::Point4 &a, const gcode::Point4 &b)
{
    return std::hypot(b.x - a.x, b.y - a.y, b.z - a.z);
}

// Seconds from the start to the end of a source line (the planner's line times), or -1.
double secondsAt(const LoadedProgram &p, std::uint32_t line)
{
    if (p.estimatedS < 0 || p.lineEndS.empty())
        return -1;
    return double(p.lineEndS[std::min<std::size_t>(line, p.lineEndS.size() - 1)]);
}

// Splits the job at its M6s; each share's time is the planner's from its M6 to the next.
std::vector<ToolShare> toolShares(const LoadedProgram &p)
{
    std::vector<ToolShare> shares{ToolShare{-1, 1, 0, 0}};
    const gcode::Toolpath &path = *p.toolpath;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (path.kind(i) == gcode::MotionKind::Event &&
            path.event(i).kind == gcode::EventKind::ToolChange) {
            shares.push_back({int(std::lround(path.event(i).value)), path.line(i), 0, 0});
        } else if (path.kind(i) == gcode::MotionKind::Feed ||
                   path.kind(i) == gcode::MotionKind::Arc) {
            // An arc's chord: the length is what the window shows, not what the planner takes.
            shares.back().cutLengthMm += distance(path.start(i), path.end(i));
        }
    }
    for (std::size_t s = 0; s < shares.size(); ++s) {
        const double from = s == 0 ? 0.0 : secondsAt(p, shares[s].fromLine);
        const double to = s + 1 < shares.size() ? secondsAt(p, shares[s + 1].fromLine)
                                                : (p.estimatedS >= 0 ? p.estimatedS : -1);
        shares[s].seconds = from < 0 || to < 0 ? -1 : std::max(0.0, to - from);
    }
    if (shares.size() > 1 && shares.front().cutLengthMm == 0)
        shares.erase(shares.begin()); // nothing cut before the first M6
    return shares;
}

} // namespace

ProgramInfo programInfo(const LoadedProgram &p, const OffsetState &offsets,
                        const machine::MachineConfig &config)
{
    ProgramInfo info;
    info.lines = p.text ? p.text->lineCount() : 0;
    info.bytes = QFileInfo(p.path).size();
    info.lengthMm = p.lengthMm;
    info.estimatedS = p.estimatedS;
    if (!p.toolpath)
        return info;
    for (std::size_t i = 0; i < p.toolpath->size(); ++i)
        info.motions += p.toolpath->isMotion(i) ? 1 : 0;
    const TravelFit fit = checkTravel(*p.toolpath, config);
    info.moves = fit.moves;
    info.machineMinMm = fit.minMm;
    info.machineMaxMm = fit.maxMm;
    const Axes4 total = offsets.total();
    for (std::size_t a = 0; a < 4; ++a) {
        info.workMinMm[a] = fit.minMm[a] - total[a];
        info.workMaxMm[a] = fit.maxMm[a] - total[a];
    }
    info.tools = toolShares(p);
    return info;
}

} // namespace frezka::session
