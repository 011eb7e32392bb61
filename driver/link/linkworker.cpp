#include "linkworker.h"

#include "driver/link/emulatortransport.h"
#include "driver/link/tracingtransport.h"
#include "driver/link/transport.h"

#include <QCoreApplication>
#include <QTimer>

#include <algorithm>
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
        CoreOptions options = m_options;
        if (lineMode()) {
            options.link.sharedLine = true;
            options.link.unitAddress = m_config.unit.address;
        }
        m_coreShared = lineMode();
        m_coreAddress = m_config.unit.address;
        m_core = std::make_unique<MachineCore>(m_config, options);
        watchMachineCore(*m_core);
    }
    if (!m_timer) {
        m_timer = new QTimer(this);
        m_timer->setSingleShot(true);
        m_timer->setTimerType(Qt::PreciseTimer);
        connect(m_timer, &QTimer::timeout, this, [this] {
            // A reply already in the port's buffer is read before its deadline is judged.
            if (m_transport)
                m_transport->deliverPending();
            if (m_line)
                m_line->onTime(now());
            else
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
    const std::string out = m_line ? m_line->takeOutput() : m_core->takeOutput();
    if (!out.empty() && m_transport && m_transport->isOpen())
        m_transport->write(QByteArray(out.data(), static_cast<qsizetype>(out.size())));
    const double d = m_line ? m_line->deadline() : m_core->deadline();
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

void LinkWorker::setLineUnits(const std::vector<machine::MachineConfig> &configs, int machineIndex)
{
    m_lineConfigs = configs;
    m_machineIndex = std::clamp(machineIndex, 0, std::max(0, int(configs.size()) - 1));
}

// The machine's core: its signals are the worker's own (the window's machine).
void LinkWorker::watchMachineCore(MachineCore &core)
{
    core.onStateChanged = [this](const MachineState &s) {
        emit stateChanged(s);
        emit unitStateChanged(lineMode() ? m_machineIndex : 0, s);
    };
    core.onLog = [this](const std::string &line) { emit logLine(QString::fromStdString(line)); };
    core.onError = [this](const MachineError &e) { emit errorOccurred(e); };
    core.onJobFinished = [this](bool ok) { emit jobFinished(ok); };
}

void LinkWorker::chooseMachineUnit(int unit)
{
    if (!lineMode() || unit == m_machineIndex || unit < 0 || unit >= int(m_unitCores.size()))
        return;
    for (const MachineCore *core : m_unitCores) {
        if (core->state().mode != MachineMode::Idle) {
            emit logLine(QCoreApplication::translate(
                "LinkWorker", "another unit becomes the machine only while every unit on the "
                              "line is idle; wait, or stop the units, then choose again"));
            emit machineUnitChanged(m_machineIndex); // unchanged
            return;
        }
    }
    // The cores stay where they are under the arbiter; only which one is the machine changes.
    for (auto &other : m_otherCores) {
        if (other.get() != m_unitCores[std::size_t(unit)])
            continue;
        std::swap(m_core, other);
        watchOtherCore(*other, m_machineIndex);
        break;
    }
    m_machineIndex = unit;
    m_config = m_lineConfigs[std::size_t(unit)];
    m_coreAddress = m_config.unit.address;
    watchMachineCore(*m_core);
    emit machineUnitChanged(unit);
    emit stateChanged(m_core->state());
}

void LinkWorker::watchOtherCore(MachineCore &core, int unit)
{
    core.onStateChanged = [this, unit](const MachineState &s) { emit unitStateChanged(unit, s); };
    // The wire's lines as they are (each command names its unit's address), the rest named.
    const QString who = QStringLiteral("unit %1: ").arg(core.config().unit.address);
    core.onLog = [this, who](const std::string &line) {
        const QString text = QString::fromStdString(line);
        const bool wire =
            text.startsWith(QLatin1String("> ")) || text.startsWith(QLatin1String("< "));
        emit logLine(wire ? text : who + text);
    };
    core.onError = [this, unit](const MachineError &e) { emit unitErrorOccurred(unit, e); };
}

// One core per unit, the machine's own (m_core, kept across connections) among them, under one
// arbiter; the others start afresh with each connection, as a unit does after a link loss.
void LinkWorker::buildLine(const ConnectionSettings &settings)
{
    m_line.reset();
    m_otherCores.clear();
    m_unitCores.clear();
    if (!lineMode())
        return;
    for (int i = 0; i < int(m_lineConfigs.size()); ++i) {
        if (i == m_machineIndex) {
            m_unitCores.push_back(m_core.get());
            continue;
        }
        CoreOptions options = m_options;
        options.link.sharedLine = true;
        options.link.unitAddress = m_lineConfigs[std::size_t(i)].unit.address;
        m_otherCores.push_back(
            std::make_unique<MachineCore>(m_lineConfigs[std::size_t(i)], options));
        watchOtherCore(*m_otherCores.back(), i);
        m_unitCores.push_back(m_otherCores.back().get());
    }
    SharedLineOptions line;
    line.baud = settings.baud;
    // A reply must come within the quiet time of the line's last byte: on a real port above
    // the adapter's round trip (docs/architecture.md, "Several units on one line").
    if (settings.kind == ConnectionSettings::Kind::SerialPort)
        line.quietS += 2 * m_config.link.latencyMs / 1000.0;
    m_line = std::make_unique<SharedLine>(m_unitCores, line);
    m_line->onLog = [this](const std::string &text) {
        emit logLine(QStringLiteral("line: ") + QString::fromStdString(text));
    };
}

void LinkWorker::connectTo(const ConnectionSettings &settings)
{
    if (m_transport) {
        m_transport->disconnect(this);
        m_transport->close();
        m_transport->deleteLater();
        m_transport = nullptr;
    }
    if (m_core && (m_coreShared != lineMode() || m_coreAddress != m_config.unit.address)) {
        // Made for a line of another shape: the machine's core starts afresh.
        m_line.reset();
        m_unitCores.clear();
        m_core.reset();
    }
    core();
    buildLine(settings);
    QString error;
    m_transport = lineMode()
                      ? createLineTransport(settings, m_lineConfigs, m_machineIndex, this, &error)
                      : m_factory(settings, m_config, this, &error);
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
        if (m_line)
            m_line->linkOpened(now());
        else
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
    const std::string_view in(bytes.constData(), static_cast<std::size_t>(bytes.size()));
    if (m_line)
        m_line->receive(in, now());
    else
        m_core->receive(in, now());
    service();
}

void LinkWorker::onClosed(const QString &why)
{
    if (!m_core)
        return;
    if (m_line)
        m_line->linkClosed(why.toStdString(), now());
    else
        m_core->linkClosed(why.toStdString(), now());
    service();
}

void LinkWorker::execute(const MachineCommand &command)
{
    apply(core().execute(command, now()));
}

void LinkWorker::executeOn(int unit, const MachineCommand &command)
{
    if (!lineMode() || unit == m_machineIndex)
        return execute(command);
    if (unit < 0 || unit >= int(m_unitCores.size()))
        return; // no such unit on this connection (not connected yet)
    if (auto refused = m_unitCores[std::size_t(unit)]->execute(command, now()))
        emit unitErrorOccurred(unit, *refused);
    service();
}

namespace {

// The built-in emulator behind the transport (a serial trace's wrapper looked through), when
// it is that and open; null otherwise.
EmulatorTransport *openBuiltInEmulator(Transport *t)
{
    if (auto *tracing = qobject_cast<TracingTransport *>(t))
        t = tracing->inner();
    auto *emulated = qobject_cast<EmulatorTransport *>(t);
    return emulated && emulated->isOpen() ? emulated : nullptr;
}

} // namespace

void LinkWorker::turnEmulatedWheel(int axis, int multiplier, int detents)
{
    EmulatorTransport *emulated = openBuiltInEmulator(m_transport);
    if (!emulated) {
        emit logLine(QCoreApplication::translate(
            "LinkWorker", "simulated handwheel: not connected to the built-in emulator; "
                          "turn the unit's own MPG wheel"));
        return;
    }
    emulator::Unit *machineUnit = emulated->simulation().unitAt(m_config.unit.address);
    if (!machineUnit)
        return;
    emulator::Unit &unit = *machineUnit;
    unit.setWheelAxis(axis);
    unit.setWheelMultiplier(multiplier);
    if (!unit.turnWheel(detents))
        emit logLine(QCoreApplication::translate(
            "LinkWorker", "simulated handwheel: the unit ignored the turn; switch Handwheel (MPG) "
                          "on, and enable the MPG in the profile's EEPROM settings"));
}

std::optional<emulator::Stats> LinkWorker::builtInEmulatorStats() const
{
    EmulatorTransport *emulated = openBuiltInEmulator(m_transport);
    if (!emulated)
        return std::nullopt;
    const emulator::Unit *unit = emulated->simulation().unitAt(m_config.unit.address);
    if (!unit)
        return std::nullopt;
    return unit->stats();
}

} // namespace frezka::driver
