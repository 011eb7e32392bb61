// Running a HeightProbe from frezka-cli on the emulator or the unit. See proberun.h.

#include "proberun.h"

#include "driver/link/emulatorport.h"
#include "driver/link/linkworker.h"
#include "session/heightprobe.h"
#include "session/qtmachinelink.h"
#include "session/runworkflow.h"
#include "session/simlink.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QJsonArray>
#include <QTimer>

#include <algorithm>
#include <limits>

namespace frezka::cli {

namespace {

struct ProbeRunCli
{
    Q_DECLARE_TR_FUNCTIONS(ProbeRunCli)
};

using StartFn = std::function<bool(session::HeightProbe &, const driver::MachineState &)>;
using DoneFn = std::function<void(session::HeightProbe &, bool)>;

ProbeRunOutcome runVirtual(const QString &surface, const machine::MachineConfig &config,
                           const StartFn &start, const DoneFn &done)
{
    ProbeRunOutcome out;
    emulator::UnitOptions unit = driver::unitOptionsFor(config);
    if (!surface.isEmpty()) // checked by the caller; the surface in machine mm
        driver::setProbeSurface(unit, surface.toStdString(), config);
    unit.trace = true; // the lowest Z reached, from every motion event
    driver::WireOptions wire;
    wire.baud = config.link.baud;
    driver::CoreOptions options;
    options.link.baud = wire.baud;
    session::SimLink link(config, unit, wire, options);
    std::int64_t lowest = std::numeric_limits<std::int64_t>::max();
    auto watch = [&] {
        emulator::Unit &u = link.port().unit();
        for (const emulator::TracePoint &p : u.trace())
            lowest = std::min(lowest, p.position[2]);
        lowest = std::min(lowest, u.position()[2]);
        u.clearTrace();
    };
    link.connectTo(session::RunWorkflow::connectionFor(config));
    if (!link.runUntil([&] { return link.state().mode == driver::MachineMode::Idle; }, 120)) {
        out.error = ProbeRunCli::tr("could not connect to the emulator");
        return out;
    }
    session::HeightProbe probe(link, config);
    bool ended = false;
    QObject::connect(&probe, &session::HeightProbe::finished, [&](bool ok) {
        out.ok = ok;
        out.error = probe.error();
        done(probe, ok);
        ended = !probe.running(); // done() may have started the next probe
    });
    if (!start(probe, link.state())) {
        out.error = probe.error();
        return out;
    }
    while (!ended && link.now() < 24 * 3600.0) {
        link.runFor(0.25);
        watch();
    }
    if (!ended)
        out.error = ProbeRunCli::tr("probing did not end within a day of the emulator's time");
    out.unitSteps = link.port().unit().position();
    out.unitLowestZSteps = lowest;
    return out;
}

ProbeRunOutcome runReal(const QString &port, const machine::MachineConfig &config,
                        const StartFn &start, const DoneFn &done)
{
    ProbeRunOutcome out;
    driver::LinkWorker worker;
    driver::CoreOptions options;
    options.link.baud = config.link.baud;
    worker.setCoreOptions(options);
    worker.setMachineConfig(config);
    session::QtMachineLink<driver::LinkWorker> link(worker);
    session::HeightProbe probe(link, config);
    QEventLoop loop;
    bool started = false;
    QObject::connect(&link, &session::MachineLink::stateChanged, &loop,
                     [&](const driver::MachineState &s) {
                         if (started || s.mode != driver::MachineMode::Idle)
                             return;
                         started = true;
                         if (!start(probe, s)) {
                             out.error = probe.error();
                             loop.quit();
                         }
                     });
    QObject::connect(&link, &session::MachineLink::errorOccurred, &loop,
                     [&](const driver::MachineError &e) {
                         if (!started) {
                             out.error = driver::translatedText(e.reason, true);
                             loop.quit();
                         }
                     });
    QObject::connect(&probe, &session::HeightProbe::finished, &loop, [&](bool ok) {
        out.ok = ok;
        out.error = probe.error();
        done(probe, ok);
        if (!probe.running()) // done() may have started the next probe
            loop.quit();
    });
    driver::ConnectionSettings connection;
    connection.kind = driver::ConnectionSettings::Kind::SerialPort;
    connection.portName = port;
    connection.baud = config.link.baud;
    QTimer::singleShot(0, &worker, [&] { worker.connectTo(connection); });
    loop.exec();
    worker.disconnectFromUnit();
    return out;
}

} // namespace

QString offsetArgument(const session::OffsetState &o)
{
    const session::Axes4 &v = o.systems[static_cast<std::size_t>(o.active)];
    return QStringLiteral("%1:%2,%3,%4,%5")
        .arg(session::workSystemName(o.active))
        .arg(v[0], 0, 'f', 4)
        .arg(v[1], 0, 'f', 4)
        .arg(v[2], 0, 'f', 4)
        .arg(v[3], 0, 'f', 4);
}

QJsonValue stepsJson(const std::optional<machine::Steps4> &s)
{
    if (!s)
        return QJsonValue();
    return QJsonArray{qint64((*s)[0]), qint64((*s)[1]), qint64((*s)[2]), qint64((*s)[3])};
}

ProbeRunOutcome runProbe(const QString &port, const QString &surface,
                         const machine::MachineConfig &config, const StartFn &start,
                         const DoneFn &done)
{
    return port == QLatin1String("sim") ? runVirtual(surface, config, start, done)
                                        : runReal(port, config, start, done);
}

} // namespace frezka::cli
