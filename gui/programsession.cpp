#include "programsession.h"

#include <QCoreApplication>
#include <QFile>
#include <QFileInfo>
#include <QThread>

namespace frezka::gui {
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
    InterpretFn interpret;
    AnalyseFn analyse;
    session::OffsetState offsets;
    std::array<double, 4> startMm{};
    std::size_t maxSegments = 0;
    bool glVertices = false;
};

// The view of an interpreted program: its scene, length and the entry of each source line.
void showToolpath(const LoadJob &job, const gcode::Toolpath &tp, LoadedProgram &result)
{
    std::atomic_int *progress = job.progress.get();
    SceneOptions options;
    options.maxSegments = job.maxSegments;
    options.glVertices = job.glVertices;
    auto scene = std::make_shared<ToolpathScene>(buildScene(
        tp, options,
        [&](std::size_t d, std::size_t t) {
            progress->store(int(d * 1000 / std::max<std::size_t>(1, t)));
        },
        job.cancel.get()));
    result.scene = scene;
    result.lengthMm = pathLength(tp);
    std::uint32_t maxLine = 0;
    for (std::size_t i = 0; i < tp.size(); ++i)
        maxLine = std::max(maxLine, tp.line(i));
    result.lineToEntry.assign(std::size_t(maxLine) + 1, gcode::Toolpath::kNone);
    for (std::size_t i = 0; i < tp.size(); ++i)
        result.lineToEntry[tp.line(i)] = std::uint32_t(i);
}

// The worker thread's load, stage by stage: read, index the lines, interpret, show, analyse.
// False when cancelled (nothing to report); else `result` and `failure` are what the window gets.
bool loadInThread(const LoadJob &job, LoadedProgram &result, QString &failure)
{
    const std::atomic_bool *cancelFlag = job.cancel.get();
    std::atomic_int *progress = job.progress.get();
    std::atomic_int *stage = job.stage.get();
    QFile file(job.path);
    if (!file.open(QIODevice::ReadOnly)) {
        failure = ProgramSession::tr("Cannot open %1: %2").arg(job.path, file.errorString());
        return true;
    }
    QByteArray data = file.readAll();
    stage->store(1);
    auto text = std::make_shared<ProgramText>(
        data, [&](qint64 d, qint64 t) { progress->store(int(d * 1000 / std::max<qint64>(1, t))); },
        job.cancel.get());
    result.text = text;
    if (cancelFlag->load())
        return false;
    stage->store(2);
    progress->store(0);
    if (!job.interpret) {
        result.errors.push_back(
            {0, 0,
             ProgramSession::tr(
                 "This build has no G-code interpreter; the program cannot be checked.")});
        return true;
    }
    InterpretRequest req;
    req.text = data;
    req.fileName = QFileInfo(job.path).fileName();
    req.offsets = job.offsets;
    req.startMm = job.startMm;
    req.cancel = job.cancel.get();
    req.progress = [&](double f) { progress->store(int(f * 1000)); };
    InterpretOutcome outcome = job.interpret(req);
    result.errors = std::move(outcome.errors);
    if (cancelFlag->load())
        return false;
    if (outcome.toolpath) {
        stage->store(3);
        progress->store(0);
        showToolpath(job, *outcome.toolpath, result);
        result.toolpath = std::move(outcome.toolpath);
        if (result.errors.empty() && job.analyse) {
            stage->store(4);
            progress->store(0);
            job.analyse(result, job.cancel.get());
        }
    }
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
    cancel();
}

void ProgramSession::cancel()
{
    if (!m_thread)
        return;
    m_cancel->store(true);
    m_thread->wait();
    delete m_thread;
    m_thread = nullptr;
    m_poll.stop();
    ++m_generation;
}

void ProgramSession::reload()
{
    if (!m_program.path.isEmpty())
        load(m_program.path);
}

void ProgramSession::load(const QString &path)
{
    cancel();
    const quint64 generation = ++m_generation;
    m_cancel = std::make_shared<std::atomic_bool>(false);
    m_progress = std::make_shared<std::atomic_int>(0);
    m_stage = std::make_shared<std::atomic_int>(0);
    const LoadJob job{.path = path,
                      .cancel = m_cancel,
                      .progress = m_progress,
                      .stage = m_stage,
                      .interpret = m_interpret,
                      .analyse = m_analyse,
                      .offsets = m_offsets,
                      .startMm = m_startMm,
                      .maxSegments = m_maxSegments,
                      .glVertices = m_glVertices};
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
    emit loadProgress(1.0, QString());
    emit loaded();
}

} // namespace frezka::gui
