#pragma once
// TracingTransport: a Transport that records both ways of another into a TraceRecorder (the
// session's serial trace, docs/serial-trace.md) and passes everything through unchanged. The
// link worker's snapshots and errors are noted as event entries (observe()), and an alarm
// saves the record into the recorder's alarm folder by itself (when the front end set one).

#include "driver/link/tracerecorder.h"
#include "driver/link/transport.h"

#include <QElapsedTimer>

namespace frezka::driver {

class LinkWorker;

class TracingTransport : public Transport
{
    Q_OBJECT

public:
    // Takes `inner` over (re-parented to this). `header`: the record's header (variant, baud ...).
    TracingTransport(Transport *inner, TraceRecorder &recorder,
                     std::vector<std::pair<std::string, std::string>> header,
                     QObject *parent = nullptr);

    void open() override { m_inner->open(); }
    void close() override { m_inner->close(); }
    void write(const QByteArray &bytes) override;
    bool isOpen() const override { return m_inner->isOpen(); }
    QString description() const override { return m_inner->description(); }
    void deliverPending() override { m_inner->deliverPending(); }

    // Notes the worker's mode changes, errors and job ends in the record; saves it on an alarm.
    void observe(LinkWorker *worker);
    void noteState(const MachineState &state);
    void noteError(const MachineError &error);
    Transport *inner() const { return m_inner; }

private:
    double now() const { return static_cast<double>(m_clock.nsecsElapsed()) * 1e-9; }
    void saveAlarm(const std::string &why);

    Transport *m_inner;
    TraceRecorder &m_recorder;
    std::vector<std::pair<std::string, std::string>> m_header;
    QElapsedTimer m_clock;
    MachineMode m_lastMode = MachineMode::Disconnected;
    bool m_alarmSaved = false;
    bool m_wasOpened = false;
};

} // namespace frezka::driver
