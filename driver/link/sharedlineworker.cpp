#include "sharedlineworker.h"

#include "driver/link/transport.h"

#include <QTimer>

#include <cmath>

namespace frezka::driver {

SharedLineWorker::SharedLineWorker(SharedLine &line, Transport *transport, QObject *parent)
    : QObject(parent)
    , m_line(line)
    , m_transport(transport)
    , m_timer(new QTimer(this))
{
    m_clock.start();
    m_transport->setParent(this);
    m_timer->setSingleShot(true);
    m_timer->setTimerType(Qt::PreciseTimer);
    connect(m_timer, &QTimer::timeout, this, [this] {
        m_line.onTime(now());
        service();
    });
    connect(m_transport, &Transport::opened, this, [this] {
        m_line.linkOpened(now());
        service();
    });
    connect(m_transport, &Transport::bytesReceived, this, [this](const QByteArray &bytes) {
        m_line.receive(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())),
                       now());
        service();
    });
    connect(m_transport, &Transport::closed, this, [this](const QString &why) {
        m_timer->stop();
        m_line.linkClosed(why.toStdString(), now());
        emit closed(why);
    });
}

SharedLineWorker::~SharedLineWorker() = default;

double SharedLineWorker::now() const
{
    return static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
}

void SharedLineWorker::open()
{
    m_transport->open();
}

void SharedLineWorker::close()
{
    m_transport->close();
}

void SharedLineWorker::service()
{
    const std::string out = m_line.takeOutput();
    if (!out.empty() && m_transport->isOpen())
        m_transport->write(QByteArray(out.data(), static_cast<qsizetype>(out.size())));
    const double d = m_line.deadline();
    if (std::isinf(d)) {
        m_timer->stop();
        return;
    }
    const double ms = std::max(0.0, (d - now()) * 1000.0);
    m_timer->start(static_cast<int>(std::ceil(ms)));
}

} // namespace frezka::driver
