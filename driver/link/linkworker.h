#pragma once
// LinkWorker: runs MachineCore on a transport in the link thread.
//
// A QObject moved to a QThread by MachineController; it creates its transport in that thread
// (connectTo), never blocks, and drives the core from three sources: bytes received, a single
// QTimer armed at the core's next deadline, and the operation slots (queued calls from the GUI
// thread). Time is a QElapsedTimer in seconds. Results leave as queued signals carrying values.

#include "driver/link/machinecontroller.h"
#include "driver/link/machinecore.h"

#include <QElapsedTimer>
#include <QObject>

#include <functional>
#include <memory>

class QTimer;

namespace frezka::driver {

class Transport;

class LinkWorker : public QObject
{
    Q_OBJECT

public:
    explicit LinkWorker(QObject *parent = nullptr);
    ~LinkWorker() override;

    // Creates the transport for a connection (serial port or in-process emulator). Replaceable
    // for tests; the default knows both kinds.
    using TransportFactory =
        std::function<Transport *(const ConnectionSettings &, const machine::MachineConfig &,
                                  QObject *parent, QString *error)>;
    void setTransportFactory(TransportFactory factory) { m_factory = std::move(factory); }
    void setCoreOptions(const CoreOptions &options) { m_options = options; }
    // The figures of the last job. Call from the worker's thread (or when it has none).
    JobReport jobReport() const { return m_core ? m_core->jobReport() : JobReport{}; }

public slots:
    void setMachineConfig(const frezka::machine::MachineConfig &config);
    void connectTo(const frezka::driver::ConnectionSettings &settings);
    void disconnectFromUnit();
    void run(const frezka::machine::UnitProgram &program);
    void pause();
    void resume();
    void abort();
    void toolLift(bool stopSpindle);
    void toolLower(int speedPulsesPerS);
    void home(unsigned axisMask = 0xF);
    void jogStep(int axis, double distanceMm, double speedMmPerMin);
    void jogContinuous(int axis, int direction, double speedMmPerMin);
    void jogStop();
    void setMpg(bool on);
    void setSpindleRpm(double rpm);
    void setOutputs(quint8 mask, quint8 activeHigh);
    void setOverride(int percent);
    void overrideUp();
    void overrideDown();
    void sendRaw(const QString &text);
    void writeEeprom();

signals:
    void stateChanged(const frezka::driver::MachineState &state);
    void logLine(const QString &line);
    void errorOccurred(const frezka::driver::MachineError &error);
    void jobFinished(bool ok);

private:
    MachineCore &core();
    double now() const;
    void apply(const MachineCore::Result &result);
    void service(); // write pending output, re-arm the timer
    void onBytes(const QByteArray &bytes);
    void onClosed(const QString &why);

    machine::MachineConfig m_config;
    CoreOptions m_options;
    std::unique_ptr<MachineCore> m_core;
    Transport *m_transport = nullptr;
    QTimer *m_timer = nullptr;
    QElapsedTimer m_clock;
    TransportFactory m_factory;
};

// The default transport factory: SerialTransport, or EmulatorTransport (the variant and home
// switches from the profile). Returns nullptr and sets *error when it cannot.
Transport *createTransport(const ConnectionSettings &settings, const machine::MachineConfig &config,
                           QObject *parent, QString *error);

} // namespace frezka::driver
