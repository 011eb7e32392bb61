#pragma once
// SerialTransport: QSerialPort, asynchronous (readyRead / bytesWritten / errorOccurred), 8N1,
// no flow control. Any port name is accepted, including a pty path typed by the user
// (QSerialPortInfo does not list ptys). On a pty, DTR/RTS calls fail with
// UnsupportedOperationError: logged, not fatal (docs/platform-notes.md).

#include "driver/link/transport.h"

#include <QSerialPort>

namespace frezka::driver {

// Why opening portName failed, in words the operator can act on: for a permission error, which
// group owns the device (dialout on Debian) and the command that joins it
// (sudo usermod -aG dialout $USER, then log in again); otherwise Qt's errorString.
QString serialOpenFailure(const QString &portName, QSerialPort::SerialPortError error,
                          const QString &errorString);

class SerialTransport : public Transport
{
    Q_OBJECT

public:
    SerialTransport(QString portName, int baud, QObject *parent = nullptr);
    ~SerialTransport() override;

    void open() override;
    void close() override;
    void write(const QByteArray &bytes) override;
    bool isOpen() const override;
    QString description() const override;
    void deliverPending() override;

private:
    void onError(QSerialPort::SerialPortError error);
    void fail(const QString &why);

    QString m_portName;
    int m_baud;
    QSerialPort *m_port = nullptr;
};

} // namespace frezka::driver
