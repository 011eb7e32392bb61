#include "driver/grinder/transport.h"

#include <QFileInfo>
#include <QLockFile>
#include <QSerialPort>

#include <unistd.h>

namespace frezka::grinder {

SerialTransport::SerialTransport(SerialSettings settings, QObject *parent)
    : Transport(parent)
    , m_settings(std::move(settings))
    , m_port(new QSerialPort(this))
{
    connect(m_port, &QSerialPort::readyRead, this, [this] { emit received(m_port->readAll()); });
    connect(m_port, &QSerialPort::bytesWritten, this, &Transport::written);
    connect(m_port, &QSerialPort::errorOccurred, this, &SerialTransport::onError);
}

SerialTransport::~SerialTransport() = default;

bool SerialTransport::open(QString *error)
{
    m_port->setPortName(m_settings.portName);
    if (!m_port->open(QIODevice::ReadWrite)) {
        if (error)
            *error = serialOpenFailure(m_settings.portName,
                                       m_port->error() == QSerialPort::PermissionError,
                                       m_port->errorString());
        return false;
    }
    const auto parity = m_settings.parity == 'e'   ? QSerialPort::EvenParity
                        : m_settings.parity == 'o' ? QSerialPort::OddParity
                                                   : QSerialPort::NoParity;
    const bool ok = m_port->setBaudRate(m_settings.baud) &&
                    m_port->setDataBits(static_cast<QSerialPort::DataBits>(m_settings.dataBits)) &&
                    m_port->setParity(parity) &&
                    m_port->setStopBits(m_settings.stopBits == 2 ? QSerialPort::TwoStop
                                                                 : QSerialPort::OneStop) &&
                    m_port->setFlowControl(QSerialPort::NoFlowControl);
    if (!ok) {
        if (error)
            *error = tr("Cannot set %1 to %2 Bd: %3")
                         .arg(m_settings.portName)
                         .arg(m_settings.baud)
                         .arg(m_port->errorString());
        m_port->close();
        return false;
    }
    m_port->clear();
    return true;
}

namespace {

// Who holds QSerialPort's lock on `path` ("name (process N)"), or empty. QSerialPort locks a
// port with a QLockFile "LCK..<name, '/' as '_'>" in the first writable of these directories.
QString lockHolder(const QString &path)
{
    QString name = path.startsWith(QLatin1String("/dev/")) ? path.mid(5) : path;
    name.replace(QLatin1Char('/'), QLatin1Char('_'));
    for (const char *dir : {"/var/lock", "/etc/locks", "/var/spool/locks", "/var/spool/uucp",
                            "/tmp", "/var/tmp", "/run/lock"}) {
        const QString file = QLatin1String(dir) + QStringLiteral("/LCK..") + name;
        if (!QFileInfo::exists(file))
            continue;
        QLockFile lock(file);
        qint64 pid = 0;
        QString host, app;
        if (lock.getLockInfo(&pid, &host, &app))
            return SerialTransport::tr("%1 (process %2)")
                .arg(app.isEmpty() ? SerialTransport::tr("another program") : app)
                .arg(pid);
    }
    return {};
}

} // namespace

QString serialOpenFailure(const QString &portName, bool permissionDenied,
                          const QString &errorString)
{
    if (!permissionDenied)
        return SerialTransport::tr("Cannot open %1: %2").arg(portName, errorString);
    const QString path =
        portName.startsWith(QLatin1Char('/')) ? portName : QStringLiteral("/dev/") + portName;
    const QFileInfo device(path);
    // QSerialPort reports a port another program holds as a permission error with its own words;
    // a user who may read and write the device, yet is refused, meets the same (root may read
    // and write anything, so for root only the words tell).
    const bool locked =
        errorString == QSerialPort::tr("Permission error while locking the device") ||
        (::geteuid() != 0 && device.isReadable() && device.isWritable());
    if (locked) {
        // Allowed to open it, yet refused: another program holds the port.
        const QString holder = lockHolder(path);
        return holder.isEmpty()
                   ? SerialTransport::tr("Cannot open %1: the port is in use by another "
                                         "program. Close it (or disconnect it), then connect "
                                         "again.")
                         .arg(portName)
                   : SerialTransport::tr("Cannot open %1: the port is in use by %2. Close that "
                                         "program (or disconnect it there), then connect again.")
                         .arg(portName, holder);
    }
    QString group = QFileInfo(path).group();
    if (group.isEmpty() || group == QLatin1String("root"))
        group = QStringLiteral("dialout");
    return SerialTransport::tr(
               "Cannot open %1: permission denied. The port belongs to the group %2: join it "
               "with \"sudo usermod -aG %2 $USER\", then log out and in again.")
        .arg(portName, group);
}

void SerialTransport::close()
{
    if (m_port->isOpen())
        m_port->close();
}

bool SerialTransport::isOpen() const
{
    return m_port->isOpen();
}

void SerialTransport::write(const QByteArray &bytes)
{
    if (!m_port->isOpen()) {
        emit failed(tr("%1 is not open").arg(m_settings.portName));
        return;
    }
    const qint64 queued = m_port->write(bytes);
    if (queued != bytes.size())
        emit failed(tr("Short write on %1: %2 of %3 bytes queued (%4)")
                        .arg(m_settings.portName)
                        .arg(queued)
                        .arg(bytes.size())
                        .arg(m_port->errorString()));
}

qint64 SerialTransport::pendingOutput() const
{
    return m_port->bytesToWrite();
}

void SerialTransport::discardOutput()
{
    if (m_port->isOpen())
        m_port->clear(QSerialPort::Output);
}

void SerialTransport::onError()
{
    const QSerialPort::SerialPortError error = m_port->error();
    // A pty refuses DTR/RTS ioctls (platform notes): not a failure of the link.
    if (error == QSerialPort::NoError || error == QSerialPort::UnsupportedOperationError)
        return;
    if (error == QSerialPort::TimeoutError)
        return;
    const QString path = m_settings.portName.startsWith(QLatin1Char('/'))
                             ? m_settings.portName
                             : QStringLiteral("/dev/") + m_settings.portName;
    if (error == QSerialPort::ResourceError || error == QSerialPort::DeviceNotFoundError ||
        !QFileInfo::exists(path)) {
        // The device vanished (errno ENXIO/EIO, "Inappropriate ioctl" on a dead pty).
        emit failed(tr("The port %1 went away: is the cable or the USB adapter unplugged? Plug "
                       "it in, then connect again.")
                        .arg(m_settings.portName));
        return;
    }
    emit failed(tr("Serial port %1: %2").arg(m_settings.portName, m_port->errorString()));
}

} // namespace frezka::grinder
