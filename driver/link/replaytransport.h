#pragma once
// ReplayTransport: a recorded unit (emulator::TraceReplay) in real time, for the link worker:
// each recorded reply comes as long after the driver's matching command as it did in the
// record. Its polls are free (emulator::TraceReplay): on the wall clock they cannot come where
// the record has them. A divergence from the record closes the transport with the trace line,
// what it expected and what the driver sent.

#include "driver/emulator/tracereplay.h"
#include "driver/link/transport.h"

#include <QElapsedTimer>

class QTimer;

namespace frezka::driver {

class ReplayTransport : public Transport
{
    Q_OBJECT

public:
    ReplayTransport(emulator::SerialTrace trace, QString name, QObject *parent = nullptr);

    void open() override;
    void close() override;
    void write(const QByteArray &bytes) override;
    bool isOpen() const override { return m_open; }
    QString description() const override;

    const emulator::TraceReplay &replay() const { return m_replay; }

private:
    void tick();

    emulator::TraceReplay m_replay;
    QString m_name;
    QTimer *m_timer = nullptr;
    QElapsedTimer m_clock;
    bool m_open = false;
};

// The replay's divergence in the user's language.
QString translatedTraceMessage(const emulator::TraceMessage &message);

} // namespace frezka::driver
