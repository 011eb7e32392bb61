#include "replaytransport.h"

#include <QCoreApplication>
#include <QTimer>

#include <cmath>

namespace frezka::driver {

QString translatedTraceMessage(const emulator::TraceMessage &message)
{
    if (!message)
        return {};
    QString text = QCoreApplication::translate("SerialTrace", message.text);
    for (const std::string &arg : message.args)
        text = text.arg(QString::fromStdString(arg));
    return text;
}

ReplayTransport::ReplayTransport(emulator::SerialTrace trace, QString name, QObject *parent)
    : Transport(parent)
    , m_replay(std::move(trace), true)
    , m_name(std::move(name))
{}

QString ReplayTransport::description() const
{
    return QCoreApplication::translate("ReplayTransport", "replay of the serial trace %1")
        .arg(m_name);
}

void ReplayTransport::open()
{
    if (!m_timer) {
        m_timer = new QTimer(this);
        m_timer->setSingleShot(true);
        m_timer->setTimerType(Qt::PreciseTimer);
        connect(m_timer, &QTimer::timeout, this, &ReplayTransport::tick);
    }
    QTimer::singleShot(0, this, [this] {
        m_open = true;
        m_clock.start();
        emit opened();
        tick();
    });
}

void ReplayTransport::close()
{
    if (!m_open)
        return;
    m_open = false;
    m_timer->stop();
    emit closed(QString());
}

void ReplayTransport::write(const QByteArray &bytes)
{
    if (!m_open)
        return;
    tick();
    m_replay.pcWrite(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())));
    if (m_replay.divergence()) {
        m_open = false;
        m_timer->stop();
        emit closed(translatedTraceMessage(m_replay.divergence()));
        return;
    }
    m_timer->start(0); // the reply comes from the event loop, never inside the writer's call
}

// Brings the replay to the wall clock, hands over what is due and waits for the next line.
void ReplayTransport::tick()
{
    if (!m_open)
        return;
    const double wall = static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
    if (wall > m_replay.now())
        m_replay.advance(wall - m_replay.now());
    const std::string out = m_replay.pcRead();
    if (!out.empty())
        emit bytesReceived(QByteArray(out.data(), static_cast<qsizetype>(out.size())));
    const double next = m_replay.nextEventIn();
    if (std::isfinite(next))
        m_timer->start(static_cast<int>(std::ceil(next * 1000.0)));
}

} // namespace frezka::driver
