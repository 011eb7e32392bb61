// The default transport factory.

#include "driver/link/emulatortransport.h"
#include "driver/link/linkworker.h"
#include "driver/link/serialtransport.h"

#include <QCoreApplication>

namespace frezka::driver {

Transport *createTransport(const ConnectionSettings &settings, const machine::MachineConfig &config,
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
        return new EmulatorTransport(unitOptionsFor(config), wire, parent);
    }
    }
    *error = QCoreApplication::translate("LinkWorker", "unknown connection kind");
    return nullptr;
}

} // namespace frezka::driver
