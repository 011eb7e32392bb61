// The default transport factory.

#include "driver/link/linkworker.h"
#include "driver/link/serialtransport.h"

#include <QCoreApplication>

namespace frezka::driver {

Transport *createTransport(const ConnectionSettings &settings, QObject *parent, QString *error)
{
    switch (settings.kind) {
    case ConnectionSettings::Kind::SerialPort:
        if (settings.portName.isEmpty()) {
            *error = QCoreApplication::translate("LinkWorker", "no serial port given");
            return nullptr;
        }
        return new SerialTransport(settings.portName, settings.baud, parent);
    case ConnectionSettings::Kind::Emulator:
        break;
    }
    *error =
        QCoreApplication::translate("LinkWorker", "the built-in emulator is not available yet");
    return nullptr;
}

} // namespace frezka::driver
