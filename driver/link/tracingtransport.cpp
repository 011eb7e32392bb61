#include "tracingtransport.h"

#include "driver/link/linkworker.h"

#include <QCoreApplication>

namespace frezka::driver {

TracingTransport::TracingTransport(Transport *inner, TraceRecorder &recorder,
                                   std::vector<std::pair<std::string, std::string>> header,
                                   QObject *parent)
    : Transport(parent)
    , m_inner(inner)
    , m_recorder(recorder)
    , m_header(std::move(header))
{
    m_clock.start();
    m_inner->setParent(this);
    connect(m_inner, &Transport::opened, this, [this] {
        m_header.emplace_back("port", m_inner->description().toStdString());
        m_header.emplace_back("clock", "real");
        m_recorder.begin(m_header, now());
        m_wasOpened = true;
        emit opened();
    });
    connect(m_inner, &Transport::bytesReceived, this, [this](const QByteArray &bytes) {
        m_recorder.record(
            emulator::TraceDirection::ToPc,
            std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())), now());
        emit bytesReceived(bytes);
    });
    connect(m_inner, &Transport::closed, this, [this](const QString &why) {
        if (!why.isEmpty() && m_wasOpened) { // a port that never opened has no record
            m_recorder.note("link closed: " + why.toStdString(), now());
            saveAlarm(why.toStdString());
        }
        emit closed(why);
    });
    connect(m_inner, &Transport::logLine, this, &Transport::logLine);
}

void TracingTransport::write(const QByteArray &bytes)
{
    m_recorder.record(emulator::TraceDirection::ToUnit,
                      std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())),
                      now());
    m_inner->write(bytes);
}

void TracingTransport::observe(LinkWorker *worker)
{
    connect(worker, &LinkWorker::stateChanged, this, &TracingTransport::noteState);
    connect(worker, &LinkWorker::errorOccurred, this, &TracingTransport::noteError);
    connect(worker, &LinkWorker::jobFinished, this,
            [this](bool ok) { m_recorder.note(traceJobEvent(ok), now()); });
}

void TracingTransport::noteState(const MachineState &state)
{
    if (state.mode == m_lastMode)
        return;
    m_lastMode = state.mode;
    if (state.mode != MachineMode::Alarm && state.mode != MachineMode::LinkLost &&
        state.mode != MachineMode::Stopping)
        m_alarmSaved = false; // the next alarm is a new one: save again
    m_recorder.note(traceModeEvent(state.mode), now());
    // An alarm: the machine needs the operator, or an input (the STOP button, a limit) or the
    // path guard stopped the job.
    const bool stopped =
        state.mode == MachineMode::Paused &&
        (state.hold == HoldReason::Interrupt || state.hold == HoldReason::PathFault);
    if (state.mode == MachineMode::Alarm || stopped)
        saveAlarm(traceModeEvent(state.mode) + (stopped ? ": " + state.holdText : std::string()));
}

void TracingTransport::noteError(const MachineError &error)
{
    m_recorder.note(traceErrorEvent(error), now());
    if (isTraceAlarm(error))
        saveAlarm(error.message);
}

void TracingTransport::saveAlarm(const std::string &why)
{
    if (m_alarmSaved)
        return; // one file per alarm: its error, mode change and closed link come together
    m_alarmSaved = true;
    QString error;
    const QString path = m_recorder.saveAlarm(&error);
    if (!path.isEmpty())
        emit logLine(
            QCoreApplication::translate("TracingTransport", "serial trace saved to %1 (%2)")
                .arg(path, QString::fromStdString(why)));
    else if (!error.isEmpty())
        emit logLine(error);
}

} // namespace frezka::driver
