#include "tracerecorder.h"

#include <QCoreApplication>
#include <QDateTime>
#include <QDir>
#include <QFileInfo>
#include <QSaveFile>
#include <QStandardPaths>

namespace frezka::driver {

using emulator::TraceDirection;
using emulator::TraceEntry;

namespace {

// What an entry costs in the ring: about its line in the file (time, ASCII, hex).
std::int64_t costOf(const TraceEntry &e)
{
    return 20 + static_cast<std::int64_t>(e.bytes.size()) * 4;
}

} // namespace

std::string traceModeEvent(MachineMode mode)
{
    return std::string("mode ") + machineModeName(mode);
}

std::string traceErrorEvent(const MachineError &error)
{
    return "error " + std::to_string(static_cast<int>(error.reason.code)) + ": " + error.message;
}

std::string traceJobEvent(bool ok)
{
    return ok ? "job finished ok" : "job finished failed";
}

bool isTraceAlarm(const MachineError &error)
{
    const int code = static_cast<int>(error.reason.code);
    return code >= 200 && code < 400;
}

TraceRecorder &TraceRecorder::session()
{
    static TraceRecorder recorder;
    return recorder;
}

void TraceRecorder::setLimitBytes(std::int64_t bytes)
{
    std::lock_guard lock(m_mutex);
    m_limit = std::max<std::int64_t>(0, bytes);
    dropOverLimit();
}

std::int64_t TraceRecorder::limitBytes() const
{
    std::lock_guard lock(m_mutex);
    return m_limit;
}

void TraceRecorder::setProgramVersion(const std::string &version)
{
    std::lock_guard lock(m_mutex);
    m_version = version;
}

void TraceRecorder::begin(std::vector<std::pair<std::string, std::string>> header, double nowS)
{
    std::lock_guard lock(m_mutex);
    m_trace = {};
    m_trace.set("frezka", m_version.empty() ? "Frezka" : m_version);
    m_trace.set("started",
                QDateTime::currentDateTimeUtc().toString(Qt::ISODateWithMs).toStdString());
    for (auto &[k, v] : header)
        m_trace.set(k, v);
    m_ring.clear();
    m_ringBytes = 0;
    m_dropped = 0;
    m_open[0] = m_open[1] = {};
    m_startS = nowS;
}

void TraceRecorder::setValue(const std::string &key, const std::string &value)
{
    std::lock_guard lock(m_mutex);
    m_trace.set(key, value);
}

void TraceRecorder::push(TraceEntry entry)
{
    m_ringBytes += costOf(entry);
    m_ring.push_back(std::move(entry));
    dropOverLimit();
}

void TraceRecorder::dropOverLimit()
{
    while (!m_ring.empty() && m_ringBytes > m_limit) {
        m_ringBytes -= costOf(m_ring.front());
        m_ring.pop_front();
        ++m_dropped;
    }
}

void TraceRecorder::record(TraceDirection direction, std::string_view bytes, double nowS)
{
    std::lock_guard lock(m_mutex);
    if (m_limit <= 0 || direction == TraceDirection::Event)
        return;
    Open &open = m_open[direction == TraceDirection::ToUnit ? 0 : 1];
    for (const char c : bytes) {
        open.bytes += c;
        // A line ends at its CR, and is timed there: when the other side could act on it.
        if (c == '\r') {
            push(TraceEntry{direction, msOf(nowS), std::move(open.bytes), 0});
            open.bytes.clear();
        }
    }
    open.timeMs = msOf(nowS);
}

void TraceRecorder::note(const std::string &event, double nowS)
{
    std::lock_guard lock(m_mutex);
    if (m_limit > 0)
        push(TraceEntry{TraceDirection::Event, msOf(nowS), event, 0});
}

emulator::SerialTrace TraceRecorder::snapshot() const
{
    std::lock_guard lock(m_mutex);
    emulator::SerialTrace t = m_trace;
    if (m_dropped > 0)
        t.set("dropped", std::to_string(m_dropped) + " older lines (over the ring's limit)");
    t.entries.assign(m_ring.begin(), m_ring.end());
    for (int d = 0; d < 2; ++d) {
        if (!m_open[d].bytes.empty())
            t.entries.push_back(TraceEntry{d == 0 ? TraceDirection::ToUnit : TraceDirection::ToPc,
                                           m_open[d].timeMs, m_open[d].bytes, 0});
    }
    return t;
}

bool TraceRecorder::save(const QString &path, QString *error) const
{
    const std::string text = emulator::formatTrace(snapshot());
    QDir().mkpath(QFileInfo(path).absolutePath());
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly) ||
        file.write(text.data(), static_cast<qint64>(text.size())) !=
            static_cast<qint64>(text.size()) ||
        !file.commit()) {
        if (error)
            *error = QCoreApplication::translate("TraceRecorder",
                                                 "cannot write the serial trace to %1: %2. "
                                                 "Choose a folder you may write to.")
                         .arg(path, file.errorString());
        return false;
    }
    return true;
}

void TraceRecorder::setAlarmFolder(const QString &folder)
{
    std::lock_guard lock(m_mutex);
    m_alarmFolder = folder;
}

QString TraceRecorder::alarmFolder() const
{
    std::lock_guard lock(m_mutex);
    return m_alarmFolder;
}

QString TraceRecorder::defaultAlarmFolder()
{
    QString state = qEnvironmentVariable("XDG_STATE_HOME");
    if (state.isEmpty())
        state = QDir::homePath() + QStringLiteral("/.local/state");
    return state + QStringLiteral("/frezka/traces");
}

QString TraceRecorder::saveAlarm(QString *error) const
{
    const QString folder = alarmFolder();
    if (!enabled() || folder.isEmpty())
        return {};
    const QString path =
        folder +
        QStringLiteral("/trace-%1.txt")
            .arg(QDateTime::currentDateTime().toString(QStringLiteral("yyyyMMdd-HHmmss-zzz")));
    return save(path, error) ? path : QString();
}

} // namespace frezka::driver
