#include "serialtransport.h"

#include <QCoreApplication>
#include <QFileInfo>
#include <QTimer>

#include <sys/ioctl.h>

namespace frezka::driver {

QString serialOpenFailure(const QString &portName, QSerialPort::SerialPortError error,
                          const QString &errorString)
{
    if (error != QSerialPort::PermissionError)
        return QCoreApplication::translate("SerialTransport", "cannot open %1: %2")
            .arg(portName, errorString);
    const QString path =
        portName.startsWith(QLatin1Char('/')) ? portName : QStringLiteral("/dev/") + portName;
    QString group = QFileInfo(path).group();
    if (group.isEmpty() || group == QLatin1String("root"))
        group = QStringLiteral("dialout");
    return QCoreApplication::translate(
               "SerialTransport",
               "cannot open %1: permission denied. The port belongs to the group %2: join it "
               "with \"sudo usermod -aG %2 $USER\", then log out and in again.")
        .arg(portName, group);
}

SerialTransport::SerialTransport(QString portName, int baud, QObject *parent)
    : Transport(parent)
    , m_portName(std::move(portName))
    , m_baud(baud)
{}

SerialTransport::~SerialTransport()
{
    if (m_port)
        m_port->close();
}

QString SerialTransport::description() const
{
    return QCoreApplication::translate("SerialTransport", "%1 at %2 Bd")
        .arg(m_portName)
        .arg(m_baud);
}

bool SerialTransport::isOpen() const
{
    return m_port && m_port->isOpen();
}

void SerialTransport::open()
{
    if (!m_port) {
        m_port = new QSerialPort(this);
        connect(m_port, &QSerialPort::readyRead, this,
                [this] { emit bytesReceived(m_port->readAll()); });
        connect(m_port, &QSerialPort::errorOccurred, this, &SerialTransport::onError);
    }
    m_port->setPortName(m_portName);
    // Deferred so that the caller sees opened()/closed() after open() returned.
    QTimer::singleShot(0, this, [this] {
        if (!m_port->open(QIODevice::ReadWrite)) {
            fail(serialOpenFailure(m_portName, m_port->error(), m_port->errorString()));
            return;
        }
        const bool ok = m_port->setBaudRate(m_baud) && m_port->setDataBits(QSerialPort::Data8) &&
                        m_port->setParity(QSerialPort::NoParity) &&
                        m_port->setStopBits(QSerialPort::OneStop) &&
                        m_port->setFlowControl(QSerialPort::NoFlowControl);
        if (!ok) {
            fail(QCoreApplication::translate("SerialTransport", "cannot configure %1: %2")
                     .arg(m_portName, m_port->errorString()));
            return;
        }
        m_port->clear();
        emit opened();
    });
}

void SerialTransport::close()
{
    if (!isOpen())
        return;
    m_port->close();
    emit closed(QString());
}

void SerialTransport::deliverPending()
{
    if (!m_port || !m_port->isOpen())
        return;
    // Bytes in the driver's buffer whose notifier the event loop has not served yet: read
    // them now (QSerialPort emits readyRead from inside waitForReadyRead). Asked first, so
    // that an empty port costs no wait and no timeout error.
    int waiting = 0;
    if (::ioctl(static_cast<int>(m_port->handle()), FIONREAD, &waiting) == 0 && waiting > 0)
        m_port->waitForReadyRead(0);
}

void SerialTransport::write(const QByteArray &bytes)
{
    if (!isOpen()) {
        fail(QCoreApplication::translate("SerialTransport", "write to %1: port not open")
                 .arg(m_portName));
        return;
    }
    const qint64 n = m_port->write(bytes);
    if (n != bytes.size())
        fail(
            QCoreApplication::translate("SerialTransport", "short write to %1: %2 of %3 bytes (%4)")
                .arg(m_portName)
                .arg(n)
                .arg(bytes.size())
                .arg(m_port->errorString()));
}

void SerialTransport::onError(QSerialPort::SerialPortError error)
{
    switch (error) {
    case QSerialPort::NoError:
        return;
    case QSerialPort::UnsupportedOperationError: // DTR/RTS on a pty: harmless
        emit logLine(QCoreApplication::translate("SerialTransport", "%1: %2 (ignored)")
                         .arg(m_portName, m_port->errorString()));
        m_port->clearError();
        return;
    case QSerialPort::TimeoutError:
        m_port->clearError();
        return;
    default:
        if (isOpen()) // failures while opening are reported by open()
            fail(QCoreApplication::translate("SerialTransport", "%1: %2")
                     .arg(m_portName, m_port->errorString()));
        return;
    }
}

void SerialTransport::fail(const QString &why)
{
    const bool wasOpen = isOpen();
    if (m_port && m_port->isOpen())
        m_port->close();
    if (wasOpen || !why.isEmpty())
        emit closed(why);
}

} // namespace frezka::driver
