#include "emulatortransport.h"

#include <QCoreApplication>
#include <QTimer>

namespace frezka::driver {

EmulatorTransport::EmulatorTransport(emulator::UnitOptions unit, WireOptions wire, QObject *parent)
    : Transport(parent)
    , m_port(std::make_unique<EmulatorPort>(std::move(unit), wire))
{}

EmulatorTransport::EmulatorTransport(std::vector<emulator::UnitOptions> units, WireOptions wire,
                                     QObject *parent)
    : Transport(parent)
    , m_port(std::make_unique<EmulatorPort>(std::move(units), wire))
{}

EmulatorTransport::~EmulatorTransport() = default;

QString EmulatorTransport::description() const
{
    return QCoreApplication::translate("EmulatorTransport", "built-in %1 emulator")
        .arg(QString::fromUtf8(
            m_port->unit().variantInfo().displayName.data(),
            static_cast<qsizetype>(m_port->unit().variantInfo().displayName.size())));
}

void EmulatorTransport::open()
{
    if (!m_timer) {
        m_timer = new QTimer(this);
        m_timer->setTimerType(Qt::PreciseTimer);
        connect(m_timer, &QTimer::timeout, this, &EmulatorTransport::tick);
    }
    QTimer::singleShot(0, this, [this] {
        m_open = true;
        m_clock.start();
        m_started = m_port->now();
        m_timer->start(1);
        emit opened();
    });
}

void EmulatorTransport::close()
{
    if (!m_open)
        return;
    m_open = false;
    m_timer->stop();
    emit closed(QString());
}

void EmulatorTransport::deliverPending()
{
    if (m_open)
        tick(); // the emulator brought to now: what it has sent by now is read
}

void EmulatorTransport::write(const QByteArray &bytes)
{
    if (!m_open)
        return;
    tick(); // bring the emulator to now before the bytes go on its wire
    m_port->write(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
}

void EmulatorTransport::tick()
{
    const double target = m_started + static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
    if (target > m_port->now())
        m_port->advance(target - m_port->now());
    const std::string in = m_port->read();
    if (!in.empty())
        emit bytesReceived(QByteArray(in.data(), static_cast<qsizetype>(in.size())));
}

} // namespace frezka::driver
