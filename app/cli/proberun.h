#pragma once
// Running a session::HeightProbe from frezka-cli (probe-grid, probe z-plate) on the unit: the
// in-process emulator on a virtual clock (--port sim, with --surface its simulated work top,
// recording the lowest Z counter it reached) or a serial port / pty through the link worker on
// this thread's event loop, as frezka-cli run does.

#include "machine/machineconfig.h"
#include "machine/steps.h"
#include "session/workoffsets.h"

#include <QJsonValue>

#include <QString>
#include <QStringList>

#include <cstdint>
#include <functional>
#include <optional>

namespace frezka::driver {
struct MachineState;
}
namespace frezka::session {
class HeightProbe;
}

namespace frezka::cli {

struct ProbeRunOutcome
{
    bool ok = false;
    QString error;                                // translated; empty when ok
    std::optional<machine::Steps4> unitSteps;     // the emulator's counters at the end
    std::optional<std::int64_t> unitLowestZSteps; // the lowest Z counter the emulator reached
};

// Connects, calls start(probe, the idle machine's state) once (false: it did not start, its
// error is probe.error()), runs until the probe's finished() and calls done(probe, ok) then;
// when done() starts the probe again (a corner's second edge), runs on until that finishes.
ProbeRunOutcome
runProbe(const QString &port, const QString &surface, const machine::MachineConfig &config,
         const std::function<bool(session::HeightProbe &, const driver::MachineState &)> &start,
         const std::function<void(session::HeightProbe &, bool)> &done);

// The active system's offset as a --offset argument ("G54:X,Y,Z,A", machine mm).
QString offsetArgument(const session::OffsetState &offsets);
// The emulator's counters as a JSON value: [x, y, z, a], or null when there are none (a real
// port).
QJsonValue stepsJson(const std::optional<machine::Steps4> &steps);

// frezka-cli probe edge / probe corner (cmd_probe_edge.cpp): args after the subcommand.
int runProbeEdge(const QStringList &args, bool corner);

} // namespace frezka::cli
