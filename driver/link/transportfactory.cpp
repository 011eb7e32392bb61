// The default transport factory: the serial port or the built-in emulator, recorded into the
// session's serial trace (TraceRecorder::session(), docs/serial-trace.md) unless that is off.

#include "driver/link/emulatedunit.h"
#include "driver/link/emulatortransport.h"
#include "driver/link/linkworker.h"
#include "driver/link/serialtransport.h"
#include "driver/link/tracingtransport.h"

#include <QCoreApplication>

namespace frezka::driver {

WireOptions wireFor(const ConnectionSettings &settings)
{
    WireOptions wire;
    wire.baud = settings.baud;
    wire.latencyS = settings.latencyMs / 1000.0;
    wire.byteErrorRate = settings.faultRate;
    wire.replyLossRate = settings.faultRate;
    wire.seed = settings.seed;
    return wire;
}

emulator::UnitOptions emulatedUnitFor(const ConnectionSettings &settings,
                                      const machine::MachineConfig &config)
{
    emulator::UnitOptions unit = unitOptionsFor(config);
    if (!settings.surface.isEmpty())
        setProbeSurface(unit, settings.surface.toStdString(), config);
    return unit;
}

namespace {

// Recorded into the session's serial trace unless that is off.
Transport *traced(Transport *inner, const ConnectionSettings &settings,
                  const machine::MachineConfig &config, QObject *parent)
{
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
    case ConnectionSettings::Kind::Emulator:
        return new EmulatorTransport(emulatedUnitFor(settings, config), wireFor(settings), parent);
    }
    *error = QCoreApplication::translate("LinkWorker", "unknown connection kind");
    return nullptr;
}

} // namespace

Transport *createTransport(const ConnectionSettings &settings, const machine::MachineConfig &config,
                           QObject *parent, QString *error)
{
    return traced(createInner(settings, config, parent, error), settings, config, parent);
}

Transport *createLineTransport(const ConnectionSettings &settings,
                               const std::vector<machine::MachineConfig> &configs, int machineIndex,
                               QObject *parent, QString *error)
{
    const machine::MachineConfig &machine = configs.at(std::size_t(machineIndex));
    if (settings.kind != ConnectionSettings::Kind::Emulator)
        return createTransport(settings, machine, parent, error);
    std::vector<emulator::UnitOptions> units;
    for (std::size_t i = 0; i < configs.size(); ++i) {
        units.push_back(unitOptionsFor(configs[i]));
        // The spindle (address 7) is the machine's unit's.
        units.back().spindleAddress = int(i) == machineIndex;
        if (int(i) == machineIndex && !settings.surface.isEmpty())
            setProbeSurface(units.back(), settings.surface.toStdString(), configs[i]);
    }
    emulator::SimulationOptions check;
    check.unit = units.front();
    check.moreUnits.assign(units.begin() + 1, units.end());
    if (const std::string problem = emulator::sharedLineProblem(check); !problem.empty()) {
        *error = QCoreApplication::translate("LinkWorker",
                                             "the units cannot share the built-in emulator's "
                                             "line: %1; fix line.units in the machine profile")
                     .arg(QString::fromStdString(problem));
        return nullptr;
    }
    return traced(new EmulatorTransport(std::move(units), wireFor(settings), parent), settings,
                  machine, parent);
}

} // namespace frezka::driver
