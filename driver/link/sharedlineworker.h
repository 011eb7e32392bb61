#pragma once
// SharedLineWorker: a SharedLine (several units, one line; sharedline.h) on a real port in real
// time, as LinkWorker is for one unit: the transport's bytes in, the arbiter's bytes out, one
// QTimer at the arbiter's next deadline. Lives in one thread; nothing blocks.

#include "driver/link/sharedline.h"

#include <QElapsedTimer>
#include <QObject>

class QTimer;

namespace frezka::driver {

class Transport;

class SharedLineWorker : public QObject
{
    Q_OBJECT

public:
    // Takes the transport (a SerialTransport on the line's port) as a child.
    SharedLineWorker(SharedLine &line, Transport *transport, QObject *parent = nullptr);
    ~SharedLineWorker() override;

    // Opens the port; the cores start connecting once it is open.
    void open();
    void close();
    double now() const;
    // Writes what the arbiter has for the line and arms the timer (after an operation was
    // given to a core from outside).
    void service();

signals:
    void closed(const QString &why);

private:
    SharedLine &m_line;
    Transport *m_transport;
    QTimer *m_timer;
    QElapsedTimer m_clock;
};

} // namespace frezka::driver
