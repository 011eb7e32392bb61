#pragma once
// LinkWorker: runs MachineCore on a transport in the link thread.
//
// A QObject moved to a QThread by MachineController; it creates its transport in that thread
// (connectTo), never blocks, and drives the core from three sources: bytes received, a single
// QTimer armed at the core's next deadline, and the execute slot (MachineCommand values queued
// from the GUI thread). Time is a QElapsedTimer in seconds. Results leave as queued signals
// carrying values.

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
    // An operation for the core (MachineController builds them); a refusal comes back as
    // errorOccurred.
    void execute(const frezka::driver::MachineCommand &command);
    // The built-in emulator's MPG handwheel (no hardware needed): sets its axis switch (0..3 =
    // X, Y, Z, 4th) and step switch (1, 10, 100), then turns it by detents (signed). The unit
    // moves only while its MPG is on and enabled in its EEPROM; a turn it ignores, or any turn
    // on another port, changes nothing and says why in a logLine.
    void turnEmulatedWheel(int axis, int multiplier, int detents);
    // The same operations by name, as MachineController has them, for the direct users of a
    // worker without a controller (frezka-cli run, session::QtMachineLink<LinkWorker>).
    void run(const frezka::machine::UnitProgram &program) { execute(op::Run{program}); }
    void pause() { execute(op::Pause{}); }
    void resume() { execute(op::Resume{}); }
    void abort() { execute(op::Abort{}); }
    void toolLift(bool stopSpindle) { execute(op::ToolLift{stopSpindle}); }
    void toolLower(int speedPulsesPerS) { execute(op::ToolLower{speedPulsesPerS}); }
    void home(unsigned axisMask = 0xF) { execute(op::Home{axisMask}); }
    void jogStep(int axis, double distanceMm, double speedMmPerMin)
    {
        execute(op::JogStep{axis, distanceMm, speedMmPerMin});
    }
    void jogContinuous(int axis, int direction, double speedMmPerMin)
    {
        execute(op::JogContinuous{axis, direction, speedMmPerMin});
    }
    void jogStop() { execute(op::JogStop{}); }
    void setMpg(bool on) { execute(op::SetMpg{on}); }
    void setSpindleRpm(double rpm) { execute(op::SetSpindleRpm{rpm}); }
    void setOutput(int output, bool on) { execute(op::SetOutput{output, on}); }
    void setOverride(int percent) { execute(op::SetOverride{percent}); }
    void overrideUp() { execute(op::OverrideStep{true}); }
    void overrideDown() { execute(op::OverrideStep{false}); }
    void sendRaw(const QString &text) { execute(op::SendRaw{text.toStdString()}); }
    void writeEeprom() { execute(op::WriteEeprom{}); }

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
