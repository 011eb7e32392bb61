#include "linkworker.h"

#include "driver/link/emulatortransport.h"
#include "driver/link/tracingtransport.h"
#include "driver/link/transport.h"

#include <QCoreApplication>
#include <QTimer>

#include <cmath>

namespace frezka::driver {

LinkWorker::LinkWorker(QObject *parent)
    : QObject(parent)
    , m_config(machine::defaultMachineConfig(protocol::Variant::Gve64))
    , m_factory(&createTransport)
{
    m_clock.start();
}

LinkWorker::~LinkWorker() = default;

double LinkWorker::now() const
{
    return static_cast<double>(m_clock.nsecsElapsed()) * 1e-9;
}

MachineCore &LinkWorker::core()
{
    if (!m_core) {
        m_core = std::make_unique<MachineCore>(m_config, m_options);
        m_core->onStateChanged = [this](const MachineState &s) { emit stateChanged(s); };
        m_core->onLog = [this](const std::string &line) {
            emit logLine(QString::fromStdString(line));
        };
        m_core->onError = [this](const MachineError &e) { emit errorOccurred(e); };
        m_core->onJobFinished = [this](bool ok) { emit jobFinished(ok); };
    }
    if (!m_timer) {
        m_timer = new QTimer(this);
        m_timer->setSingleShot(true);
        m_timer->setTimerType(Qt::PreciseTimer);
        connect(m_timer, &QTimer::timeout, this, [this] {
            m_core->onTime(now());
            service();
        });
    }
    return *m_core;
}

void LinkWorker::service()
{
    if (!m_core)
        return;
    const std::string out = m_core->takeOutput();
    if (!out.empty() && m_transport && m_transport->isOpen())
        m_transport->write(QByteArray(out.data(), static_cast<qsizetype>(out.size())));
    const double d = m_core->deadline();
    if (std::isinf(d)) {
        m_timer->stop();
        return;
    }
    const double ms = std::max(0.0, (d - now()) * 1000.0);
    m_timer->start(static_cast<int>(std::ceil(ms)));
}

void LinkWorker::apply(const MachineCore::Result &result)
{
    if (result)
        emit errorOccurred(*result);
    service();
}

void LinkWorker::setMachineConfig(const machine::MachineConfig &config)
{
    m_config = config;
    if (m_core)
        m_core->setConfig(config);
}

void LinkWorker::connectTo(const ConnectionSettings &settings)
{
    core();
    if (m_transport) {
        m_transport->disconnect(this);
        m_transport->close();
        m_transport->deleteLater();
        m_transport = nullptr;
    }
    QString error;
    m_transport = m_factory(settings, m_config, this, &error);
    if (!m_transport) {
        MachineError e;
        e.reason = {DriverCode::CannotConnect, {error.toStdString()}};
        e.message = englishText(e.reason, true);
        emit errorOccurred(e);
        return;
    }
    connect(m_transport, &Transport::opened, this, [this] {
        emit logLine(QCoreApplication::translate("LinkWorker", "connected: %1")
                         .arg(m_transport->description()));
        m_core->linkOpened(now());
        service();
    });
    connect(m_transport, &Transport::bytesReceived, this, &LinkWorker::onBytes);
    connect(m_transport, &Transport::closed, this, &LinkWorker::onClosed);
    connect(m_transport, &Transport::logLine, this, &LinkWorker::logLine);
    m_transport->open();
}

void LinkWorker::disconnectFromUnit()
{
    if (m_transport)
        m_transport->close();
}

void LinkWorker::onBytes(const QByteArray &bytes)
{
    m_core->receive(std::string_view(bytes.constData(), static_cast<std::size_t>(bytes.size())),
                    now());
    service();
}

void LinkWorker::onClosed(const QString &why)
{
    if (!m_core)
        return;
    m_core->linkClosed(why.toStdString(), now());
    service();
}

void LinkWorker::execute(const MachineCommand &command)
{
    apply(core().execute(command, now()));
}

void LinkWorker::turnEmulatedWheel(int axis, int multiplier, int detents)
{
    Transport *t = m_transport;
    if (auto *tracing = qobject_cast<TracingTransport *>(t))
        t = tracing->inner();
    auto *emulated = qobject_cast<EmulatorTransport *>(t);
    if (!emulated || !emulated->isOpen()) {
        emit logLine(QCoreApplication::translate(
            "LinkWorker", "simulated handwheel: not connected to the built-in emulator; "
                          "turn the unit's own MPG wheel"));
        return;
    }
    emulator::Unit &unit = emulated->unit();
    unit.setWheelAxis(axis);
    unit.setWheelMultiplier(multiplier);
    if (!unit.turnWheel(detents))
        emit logLine(QCoreApplication::translate(
            "LinkWorker", "simulated handwheel: the unit ignored the turn; switch Handwheel (MPG) "
                          "on, and enable the MPG in the profile's EEPROM settings"));
}

} // namespace frezka::driver
