#pragma once
// Byte pipe between a grinder session and a controller: a serial port (SerialTransport) or the
// in-process emulator (EmulatorTransport). Non-blocking; everything arrives by signal.

#include <QByteArray>
#include <QObject>
#include <QString>

class QSerialPort;

namespace frezka::grinder {

// Line settings, as in KCOMMcfg.txt ("9600,n,8,1").
struct SerialSettings
{
    QString portName; // "/dev/ttyUSB0", "/dev/pts/5", "COM1"
    int baud = 9600;
    int dataBits = 8;
    char parity = 'n'; // 'n', 'e', 'o'
    int stopBits = 1;
    bool operator==(const SerialSettings &) const = default;
};

class Transport : public QObject
{
    Q_OBJECT
public:
    using QObject::QObject;
    // Opens the pipe; false with a translated reason in `error`.
    virtual bool open(QString *error) = 0;
    virtual void close() = 0;
    virtual bool isOpen() const = 0;
    // Queues bytes for sending; a failure is reported by failed().
    virtual void write(const QByteArray &bytes) = 0;
    // Drops what was written but has not yet left for the line (a cancelled message).
    virtual void discardOutput() = 0;
    // Bytes written that the port's driver has not taken yet (QSerialPort::bytesToWrite: it
    // reports bytesWritten only when the device is writable again, which lags the take).
    virtual qint64 pendingOutput() const = 0;
    // Line speed, for progress estimates.
    virtual int baud() const = 0;
    // Human name for messages ("/dev/ttyUSB0", "emulator").
    virtual QString name() const = 0;

signals:
    void received(const QByteArray &bytes);
    void written(qint64 bytes); // bytes that left for the line
    void failed(const QString &error);
};

class SerialTransport : public Transport
{
    Q_OBJECT
public:
    explicit SerialTransport(SerialSettings settings, QObject *parent = nullptr);
    ~SerialTransport() override;
    bool open(QString *error) override;
    void close() override;
    bool isOpen() const override;
    void write(const QByteArray &bytes) override;
    void discardOutput() override;
    qint64 pendingOutput() const override;
    int baud() const override { return m_settings.baud; }
    QString name() const override { return m_settings.portName; }

private:
    void onError();

    SerialSettings m_settings;
    QSerialPort *m_port;
};

// Why opening portName failed, in words the operator can act on: when permission was denied,
// the group that owns the device (dialout on Debian) and the command that joins it (as
// driver/link's serialOpenFailure; the two modules share no code).
QString serialOpenFailure(const QString &portName, bool permissionDenied,
                          const QString &errorString);

} // namespace frezka::grinder
