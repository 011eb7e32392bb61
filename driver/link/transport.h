#pragma once
// Transport: the byte pipe under the link worker. Implementations: SerialTransport (QSerialPort:
// a real port or a pty path from gve-emu) and EmulatorTransport (the in-process emulator in real
// time), wrapped by TracingTransport (the session's serial trace, docs/serial-trace.md); and
// ReplayTransport (a recorded unit). Created and used in the link worker's thread only.

#include <QByteArray>
#include <QObject>
#include <QString>

namespace frezka::driver {

class Transport : public QObject
{
    Q_OBJECT

public:
    using QObject::QObject;
    // Starts opening; emits opened() or closed(why) later (never from inside open()).
    virtual void open() = 0;
    // Closes; emits closed("") unless already closed.
    virtual void close() = 0;
    // Queues bytes for sending; a short or failed write ends in closed(why).
    virtual void write(const QByteArray &bytes) = 0;
    virtual bool isOpen() const = 0;
    // For logs: "/dev/ttyUSB0 at 115200 Bd", "built-in GVE64 emulator".
    virtual QString description() const = 0;
    // Emits bytesReceived now (from inside the call) for bytes that have already arrived but
    // whose notification the event loop has not delivered yet. The link worker calls it before
    // it judges a reply's deadline: a busy event loop must not make a reply that came in time
    // look lost (the allowance after the round trip is 50 ms, linkengine.h).
    virtual void deliverPending() {}

signals:
    void opened();
    void bytesReceived(const QByteArray &bytes);
    // The transport closed: by request (why empty) or by an error (why says what happened).
    void closed(const QString &why);
    void logLine(const QString &line);
};

} // namespace frezka::driver
