// The default transport factory: the serial port or the built-in emulator, recorded into the
// session's serial trace (TraceRecorder::session(), docs/serial-trace.md) unless that is off.

#include "driver/link/emulatortransport.h"
#include "driver/link/linkworker.h"
#include "driver/link/serialtransport.h"
#include "driver/link/tracingtransport.h"

#include <QCoreApplication>

namespace frezka::driver {

namespace {

Transport *createInner(const ConnectionSettings &settings, const machine::MachineConfig &config,
                       QObject *parent, QString *error)
{
    switch (settings.kind) {
    case ConnectionSettings::Kind::SerialPort:
        if (settings.portName.isEmpty()) {
            *error = QCoreApplication::translate("LinkWorker", "no serial port given");
            return nullptr;
        }
        return new SerialTransport(settings.portName, settings.baud, parent);
    case ConnectionSettings::Kind::Emulator: {
        WireOptions wire;
        wire.baud = settings.baud;
        wire.latencyS = settings.latencyMs / 1000.0;
        wire.byteErrorRate = settings.faultRate;
        wire.replyLossRate = settings.faultRate;
        wire.seed = settings.seed;
        emulator::UnitOptions unit = unitOptionsFor(config);
        if (!settings.surface.isEmpty())
            setProbeSurface(unit, settings.surface.toStdString(), config);
        return new EmulatorTransport(unit, wire, parent);
    }
    }
    *error = QCoreApplication::translate("LinkWorker", "unknown connection kind");
    return nullptr;
}

} // namespace

Transport *createTransport(const ConnectionSettings &settings, const machine::MachineConfig &config,
                           QObject *parent, QString *error)
{
    Transport *inner = createInner(settings, config, parent, error);
    TraceRecorder &recorder = TraceRecorder::session();
    if (!inner || !recorder.enabled())
        return inner;
    const auto &info = protocol::variantInfo(config.unit.variant);
    auto *tracing = new TracingTransport(
        inner, recorder,
        {{"variant", std::string(info.id)},
         {"firmware", "v" + std::to_string(config.unit.firmwareVersion) + " (the profile's)"},
         {"baud", std::to_string(settings.baud)},
         {"profile", config.name}},
        parent);
    if (auto *worker = qobject_cast<LinkWorker *>(parent))
        tracing->observe(worker);
    return tracing;
}

} // namespace frezka::driver
