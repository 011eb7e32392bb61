#include "programplanner.h"

#include "planerrortext.h"

#include "gcode/interpreter.h"

#include <QCoreApplication>

#include <algorithm>

namespace frezka::session {

InterpretOutcome interpretProgram(const InterpretRequest &req)
{
    gcode::Options options;
    options.collectAllErrors = true;
    options.maxErrors = req.maxErrors;
    // The interpreter takes no G92 at its start: it is added to every system, which is what
    // G92 does to the program's coordinates.
    for (std::size_t s = 0; s < options.workOffsetsMm.size(); ++s)
        for (std::size_t i = 0; i < 4; ++i)
            options.workOffsetsMm[s][i] = req.offsets.systems[s][i] + req.offsets.g92[i];
    options.coordinateSystem = req.offsets.active;
    options.startMm = {req.startMm[0], req.startMm[1], req.startMm[2], req.startMm[3]};
    options.startLine = req.startLine;
    options.probeResults = req.probeResults;
    options.toolTable = req.toolTable;
    options.programDirectory = req.programDirectory;
    options.subroutinePath = req.subroutinePath;
    options.splineToleranceMm = req.splineToleranceMm;
    options.maxBlocks = std::uint64_t(std::max(1, req.limits.maxLinesExecuted));
    options.maxMoves = std::uint64_t(std::max(1, req.limits.maxMoves));
    options.cancel = req.cancel;
    if (req.progress) {
        options.progress = [&req](std::size_t done, std::size_t total) {
            req.progress(double(done) / double(std::max<std::size_t>(1, total)));
        };
    }
    gcode::Interpreter interpreter(options);
    gcode::Result result =
        interpreter.run(std::string_view(req.text.constData(), std::size_t(req.text.size())));
    InterpretOutcome out;
    if (!req.toolTableError.isEmpty())
        out.errors.push_back({0, 0, req.toolTableError});
    for (const auto &e : result.errors)
        out.errors.push_back({int(e.line), int(e.column), gcode::formatError(req.fileName, e)});
    if (result.errorsNotShown > 0) {
        out.errors.push_back(
            {0, 0,
             QCoreApplication::translate("frezka::gcode", "%1: %n more error(s) not shown", "",
                                         int(result.errorsNotShown))
                 .arg(req.fileName)});
    }
    for (const auto &w : result.warnings)
        out.warnings.push_back({int(w.line), int(w.column), gcode::formatError(req.fileName, w)});
    if (result.warningsNotShown > 0) {
        out.warnings.push_back(
            {0, 0,
             QCoreApplication::translate("frezka::gcode", "%1: %n more warning(s) not shown", "",
                                         int(result.warningsNotShown))
                 .arg(req.fileName)});
    }
    out.toolpath = std::make_shared<gcode::Toolpath>(std::move(result.toolpath));
    out.linesRead = result.linesRead;
    out.provisionalEntry = result.provisionalEntry;
    out.provisionalLine = result.provisionalLine;
    out.probes = result.probes;
    out.cancelled = result.cancelled;
    out.errorsNotShown = result.errorsNotShown;
    out.mark = std::move(result.mark);
    out.toolTable = std::move(result.toolTable);
    out.toolTableChanged = result.toolTableChanged;
    out.workOffsetsMm = result.workOffsetsMm;
    out.workOffsetsChanged = result.workOffsetsChanged;
    return out;
}

PlanOutcome planProgram(const gcode::Toolpath &toolpath, const machine::MachineConfig &config,
                        const QString &fileName, double feedOverride)
{
    machine::PlanOptions options;
    options.feedOverride = feedOverride;
    machine::PlanResult result = machine::plan(toolpath, config, options);
    PlanOutcome out;
    for (const auto &e : result.errors)
        out.errors.push_back({int(e.line), 0, planErrorText(fileName, e)});
    for (const auto &w : result.warnings)
        out.warnings.push_back({int(w.line), 0, planErrorText(fileName, w)});
    out.stats = result.stats;
    if (result.ok())
        out.program = std::make_shared<machine::UnitProgram>(std::move(result.program));
    return out;
}

} // namespace frezka::session
