// The program's loading thread and its stages. See programsession.h.

#include "programsession.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QThread>

#include <algorithm>
#include <cmath>

namespace frezka::session {
namespace {

QString stageName(int stage)
{
    switch (stage) {
    case 0:
        return ProgramSession::tr("Reading");
    case 1:
        return ProgramSession::tr("Indexing lines");
    case 2:
        return ProgramSession::tr("Interpreting");
    case 3:
        return ProgramSession::tr("Preparing the view");
    default:
        return ProgramSession::tr("Planning");
    }
}

double pathLength(const gcode::Toolpath &path)
{
    double total = 0;
    for (std::size_t i = 0; i < path.size(); ++i) {
        if (!path.isMotion(i))
            continue;
        const auto a = path.start(i), b = path.end(i);
        total += std::sqrt((b.x - a.x) * (b.x - a.x) + (b.y - a.y) * (b.y - a.y) +
                           (b.z - a.z) * (b.z - a.z));
    }
    return total;
}

// What one load works with, copied into its worker thread.
struct LoadJob
{
    QString path;
    std::shared_ptr<std::atomic_bool> cancel;
    std::shared_ptr<std::atomic_int> progress; // permille
    std::shared_ptr<std::atomic_int> stage;    // as ProgramSession::m_stage
    ViewBuilder buildView;
    std::optional<machine::MachineConfig> profile;
    double feedOverride = 1.0;
    OffsetState offsets;
    std::array<double, 4> startMm{};
    std::uint32_t startLine = 0;
    std::optional<gcode::ToolTable> toolTable;
    QString toolTableError;
    std::vector<std::string> subroutinePath;
    std::optional<gcode::HeightMap> heightMap;
    bool measurePeaks = false;
};

// The toolpath's length and the entry of each source line.
void indexToolpath(const gcode::Toolpath &tp, LoadedProgram &result)
{
    result.lengthMm = pathLength(tp);
    std::uint32_t maxLine = 0;
    for (std::size_t i = 0; i < tp.size(); ++i)
        maxLine = std::max(maxLine, tp.line(i));
    result.lineToEntry.assign(std::size_t(maxLine) + 1, gcode::Toolpath::kNone);
    for (std::size_t i = 0; i < tp.size(); ++i)
        result.lineToEntry[tp.line(i)] = std::uint32_t(i);
}

// The plan for the profile: its errors and warnings, the unit program, the planned speed
// (decimated here, off the front end's thread: min and max of each bucket survive) and the
// planned time to each line for the ETA.
void planLoaded(const LoadJob &job, LoadedProgram &result, StageClock &clock)
{
    // A program that probes for itself: the part up to and including its first probe (the
    // first job of its run), the rest planned once the probe has run.
    std::shared_ptr<const gcode::Toolpath> part = result.toolpath;
    if (result.provisional()) {
        auto first = std::make_shared<gcode::Toolpath>();
        first->setOrigin(result.toolpath->origin());
        first->appendEntries(*result.toolpath, 0, result.provisionalEntry + 1);
        part = std::move(first);
    }
    const PlanOutcome plan =
        planProgram(*part, *job.profile, QFileInfo(job.path).fileName(), job.feedOverride);
    clock.done("plan");
    result.errors.insert(result.errors.end(), plan.errors.begin(), plan.errors.end());
    result.warnings.insert(result.warnings.end(), plan.warnings.begin(), plan.warnings.end());
    if (!plan.ok())
        return;
    result.estimatedS = plan.stats.estimatedS;
    result.speed = plannedSpeedDecimated(*plan.program, *job.profile, plan.stats.speedModeVk, 4000);
    clock.done("planned speed (plot)");
    result.lineEndS =
        plannedLineTimes(*plan.program, plan.stats.speedModeVk, plan.stats.estimatedS);
    clock.done("line times (ETA)");
    result.unitProgram = plan.program;
    result.planStats = plan.stats;
}

// Run from a line: the job (the line's state, the approach from the start position, the rest)
// replaces the whole program's toolpath, or the refusal is the load's error at that line.
void startFromLine(const LoadJob &job, const QString &fileName, InterpretOutcome &outcome,
                   LoadedProgram &result)
{
    const gcode::Point4 from{job.startMm[0], job.startMm[1], job.startMm[2], job.startMm[3]};
    FromLineOutcome f = runFromLine(*outcome.toolpath, outcome.mark, *job.profile, from, fileName);
    if (!f.ok()) {
        result.errors.push_back({int(job.startLine), 0, f.refusal});
        return;
    }
    result.fromLine = f.from;
    outcome.toolpath = std::move(f.toolpath);
}

// A program whose path depends on a probe it runs (session/probefollow.h): followed from its
// first probe when it runs whole, else refused with the probe's line (never run provisional).
void probesForItself(const LoadJob &job, const InterpretRequest &req,
                     const InterpretOutcome &outcome, LoadedProgram &result)
{
    if (!dependsOnProbe(*outcome.toolpath, outcome.provisionalEntry) || !result.errors.empty())
        return;
    const std::uint32_t line = outcome.provisionalLine;
    const QString refusal = selfProbingRefusal(line, job.startLine, job.heightMap.has_value());
    if (!refusal.isEmpty()) {
        result.errors.push_back({int(job.startLine != 0 ? job.startLine : line), 0, refusal});
        return;
    }
    auto follow = std::make_shared<InterpretRequest>(req);
    follow->cancel = nullptr; // the load's own, gone with it
    follow->progress = nullptr;
    result.followRequest = std::move(follow);
    result.provisionalEntry = outcome.provisionalEntry;
    result.provisionalLine = line;
    result.warnings.push_back(
        {int(line), 0,
         ProgramSession::tr("Line %1: after this line the path depends on the probe's result; it "
                            "is shown as provisional, and each part is planned and run once the "
                            "probe before it has run.")
             .arg(line)});
}

// What the interpreter is asked for the job's text.
InterpretRequest interpretRequest(const LoadJob &job, const QByteArray &data,
                                  const std::function<void(double)> &fraction)
{
    InterpretRequest req;
    req.text = data;
    req.fileName = QFileInfo(job.path).fileName();
    req.offsets = job.offsets;
    req.startMm = job.startMm;
    req.cancel = job.cancel.get();
    req.progress = fraction;
    req.startLine = job.startLine;
    req.toolTable = job.toolTable;
    req.toolTableError = job.toolTableError;
    req.programDirectory = QFileInfo(job.path).absolutePath().toStdString();
    req.subroutinePath = job.subroutinePath;
    req.limits = job.profile ? job.profile->program : machine::ProgramConfig{};
    if (job.profile)
        req.splineToleranceMm = job.profile->motion.chordToleranceMm;
    return req;
}

// The worker thread's load, stage by stage: read, index the lines, interpret, view, plan (each
// timed into result.stages). False when cancelled (nothing to report); else `result` and
// `failure` are what the front end gets.
bool loadInThread(const LoadJob &job, LoadedProgram &result, QString &failure)
{
    const std::atomic_bool *cancelFlag = job.cancel.get();
    std::atomic_int *progress = job.progress.get();
    std::atomic_int *stage = job.stage.get();
    const auto fraction = [progress](double f) { progress->store(int(f * 1000)); };
    StageClock clock(job.measurePeaks);
    QFile file(job.path);
    if (!file.open(QIODevice::ReadOnly)) {
        failure = ProgramSession::tr("Cannot open %1: %2").arg(job.path, file.errorString());
        return true;
    }
    QByteArray data = file.readAll();
    clock.done("read");
    stage->store(1);
    result.text = std::make_shared<ProgramText>(
        data, [&](qint64 d, qint64 t) { progress->store(int(d * 1000 / std::max<qint64>(1, t))); },
        cancelFlag);
    clock.done("index lines (listing)");
    if (cancelFlag->load())
        return false;
    stage->store(2);
    progress->store(0);
    const InterpretRequest req = interpretRequest(job, data, fraction);
    InterpretOutcome outcome = interpretProgram(req);
    clock.done("interpret");
    result.errors = std::move(outcome.errors);
    if (outcome.toolTableChanged)
        result.changedToolTable = std::move(outcome.toolTable);
    if (outcome.workOffsetsChanged)
        result.changedWorkOffsets = outcome.workOffsetsMm;
    if (cancelFlag->load() || !outcome.toolpath)
        return !cancelFlag->load();
    probesForItself(job, req, outcome, result);
    if (job.startLine != 0 && result.errors.empty() && job.profile)
        startFromLine(job, req.fileName, outcome, result);
    if (job.heightMap && result.errors.empty()) { // bent after the run from a line's approach
        gcode::HeightMapApplied bent = gcode::applyHeightMap(*outcome.toolpath, *job.heightMap);
        if (bent.path)
            outcome.toolpath = std::make_shared<gcode::Toolpath>(std::move(*bent.path));
        else
            result.errors.push_back({int(bent.refusedLine), 0, bent.error});
        clock.done("height map");
    }
    indexToolpath(*outcome.toolpath, result);
    clock.done("index toolpath");
    if (job.buildView) {
        stage->store(3);
        progress->store(0);
        result.view = job.buildView(*outcome.toolpath, fraction, cancelFlag);
        clock.done("scene");
    }
    result.toolpath = std::move(outcome.toolpath);
    if (result.errors.empty() && job.profile && !cancelFlag->load()) {
        stage->store(4);
        progress->store(0);
        planLoaded(job, result, clock);
    }
    returnFreeMemory(); // the plan's transient arrays, freed in this thread's arena
    clock.done("return free memory");
    result.stages = clock.take();
    return !cancelFlag->load();
}

} // namespace

std::uint32_t LoadedProgram::entryOfLine(std::uint32_t line) const
{
    if (line >= lineToEntry.size())
        return gcode::Toolpath::kNone;
    return lineToEntry[line];
}

double LoadedProgram::remainingS(std::uint32_t line) const
{
    if (estimatedS < 0 || lineEndS.empty())
        return -1;
    const std::size_t i = std::min<std::size_t>(line, lineEndS.size() - 1);
    return std::max(0.0, estimatedS - double(lineEndS[i]));
}

ProgramSession::ProgramSession(QObject *parent)
    : QObject(parent)
{
    m_poll.setInterval(100);
    connect(&m_poll, &QTimer::timeout, this, [this] {
        if (m_progress && m_stage)
            emit loadProgress(double(m_progress->load()) / 1000.0, stageName(m_stage->load()));
    });
}

ProgramSession::~ProgramSession()
{
    stopLoad();
    for (const QPointer<QThread> &thread : m_ending) {
        if (thread) {
            thread->wait();
            delete thread.data();
        }
    }
}

bool ProgramSession::stopLoad()
{
    if (!m_thread)
        return false;
    m_cancel->store(true);
    // Deleted once it has ended (or at the latest by the destructor, which waits for it).
    connect(m_thread, &QThread::finished, m_thread, &QObject::deleteLater);
    std::erase_if(m_ending, [](const QPointer<QThread> &t) { return t.isNull(); });
    m_ending.emplace_back(m_thread);
    m_thread = nullptr;
    m_poll.stop();
    ++m_generation;
    return true;
}

void ProgramSession::cancel()
{
    if (stopLoad())
        emit loadCancelled(m_loadingPath);
}

void ProgramSession::setProfile(const machine::MachineConfig &config, double feedOverride)
{
    m_profile = config;
    m_feedOverride = feedOverride;
}

void ProgramSession::reload()
{
    if (!m_program.path.isEmpty())
        load(m_program.path);
}

void ProgramSession::load(const QString &path)
{
    stopLoad();
    m_loadingPath = path;
    const quint64 generation = ++m_generation;
    m_cancel = std::make_shared<std::atomic_bool>(false);
    m_progress = std::make_shared<std::atomic_int>(0);
    m_stage = std::make_shared<std::atomic_int>(0);
    const LoadJob job{.path = path,
                      .cancel = m_cancel,
                      .progress = m_progress,
                      .stage = m_stage,
                      .buildView = m_buildView,
                      .profile = m_profile,
                      .feedOverride = m_feedOverride,
                      .offsets = m_offsets,
                      .startMm = m_startMm,
                      .startLine = m_startLine,
                      .toolTable = m_toolTable,
                      .toolTableError = m_toolTableError,
                      .subroutinePath = m_subroutinePath,
                      .heightMap = m_heightMap,
                      .measurePeaks = m_measurePeaks};
    emit loadStarted(path);

    m_thread = QThread::create([=, this] {
        auto result = std::make_shared<LoadedProgram>();
        result->path = path;
        QString failure;
        if (!loadInThread(job, *result, failure))
            return; // cancelled
        QMetaObject::invokeMethod(
            this,
            [this, generation, result, failure] {
                if (generation == m_generation)
                    finish(result, failure);
            },
            Qt::QueuedConnection);
    });
    m_thread->start();
    m_poll.start();
}

void ProgramSession::finish(std::shared_ptr<LoadedProgram> result, QString failure)
{
    if (m_thread) {
        m_thread->wait();
        delete m_thread;
        m_thread = nullptr;
    }
    m_poll.stop();
    if (!failure.isEmpty()) {
        emit loadFailed(failure);
        return;
    }
    m_program = std::move(*result);
    m_asLoaded.reset();
    returnFreeMemory(); // what the program before held
    emit loadProgress(1.0, QString());
    emit loaded();
}

void ProgramSession::showFollowed(const ProbeFollow::Next &next)
{
    if (!next.whole || !next.plan)
        return;
    if (!m_asLoaded)
        m_asLoaded = m_program;
    LoadedProgram &p = m_program;
    p.toolpath = next.whole;
    indexToolpath(*next.whole, p);
    if (m_buildView)
        p.view = m_buildView(
            *next.whole, [](double) {}, nullptr);
    const machine::PlanStats &stats = next.planned.stats;
    p.unitProgram = next.plan;
    p.planStats = stats;
    p.estimatedS = stats.estimatedS;
    p.speed = m_profile ? plannedSpeedDecimated(*next.plan, *m_profile, stats.speedModeVk, 4000)
                        : std::vector<SpeedSample>{};
    p.lineEndS = plannedLineTimes(*next.plan, stats.speedModeVk, stats.estimatedS);
    p.provisionalEntry = next.endsAtProbe ? next.provisionalEntry : gcode::Result::kNoEntry;
    p.provisionalLine = next.endsAtProbe ? next.provisionalLine : 0;
    // What the program's G10 set, with the probes' results so far (kept once it has run).
    p.changedToolTable = next.toolTable;
    p.changedWorkOffsets = next.workOffsetsMm;
    ++p.probesFollowed;
    emit probeFollowShown();
}

bool ProgramSession::restoreAsLoaded()
{
    if (!m_asLoaded)
        return false;
    m_program = std::move(*m_asLoaded);
    m_asLoaded.reset();
    emit probeFollowShown();
    return true;
}

} // namespace frezka::session
