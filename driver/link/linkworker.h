#pragma once
// LinkWorker: runs MachineCore on a transport in the link thread.
//
// A QObject moved to a QThread by MachineController; it creates its transport in that thread
// (connectTo), never blocks, and drives the core from three sources: bytes received, a single
// QTimer armed at the core's next deadline, and the execute slot (MachineCommand values queued
// from the GUI thread). Time is a QElapsedTimer in seconds. Results leave as queued signals
// carrying values.
//
// Several units on one line (setLineUnits, docs/architecture.md "Several units on one line"):
// the worker then owns one MachineCore per unit under a SharedLine arbiter, all on the one
// transport; the machine's core (the list's machine entry) is the one every operation above and
// the signals stateChanged / errorOccurred / jobFinished concern, as with a unit alone; every
// core's snapshot also leaves as unitStateChanged, and executeOn() operates any unit.

#include "driver/link/machinecontroller.h"
#include "driver/link/machinecore.h"
#include "driver/link/sharedline.h"

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
    // The profiles of the units on the line, in the profile's line.units order, and which of
    // them is the machine (setMachineConfig's). One config or none: a unit alone on its line.
    // Applies from the next connectTo.
    void setLineUnits(const std::vector<frezka::machine::MachineConfig> &configs, int machineIndex);
    void connectTo(const frezka::driver::ConnectionSettings &settings);
    void disconnectFromUnit();
    // Makes unit `unit` of the line the machine (the one execute() and the signals concern),
    // while every unit is idle; otherwise a logLine says why nothing changed. The connection
    // stays; the units keep their state. Call setMachineConfig with its profile after it.
    void chooseMachineUnit(int unit);
    // An operation for the core (MachineController builds them); a refusal comes back as
    // errorOccurred.
    void execute(const frezka::driver::MachineCommand &command);
    // An operation for unit `unit` of the line (an index of setLineUnits' list; the machine's
    // index is execute()). A refusal comes back as unitErrorOccurred.
    void executeOn(int unit, const frezka::driver::MachineCommand &command);
    // The built-in emulator's MPG handwheel (no hardware needed): sets its axis switch (0..3 =
    // X, Y, Z, 4th) and step switch (1, 10, 100), then turns it by detents (signed). The unit
    // moves only while its MPG is on and enabled in its EEPROM; a turn it ignores, or any turn
    // on another port, changes nothing and says why in a logLine.
    void turnEmulatedWheel(int axis, int multiplier, int detents);
    // What the built-in emulator's machine unit has counted (vectors, brake violations,
    // starvation stops, cuts without the spindle...): for tests that drive the window and judge
    // what the unit did. Empty on another port or while not connected.
    std::optional<emulator::Stats> builtInEmulatorStats() const;
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
    // Every unit of a line (index of setLineUnits' list), the machine's too; a unit alone: 0.
    void unitStateChanged(int unit, const frezka::driver::MachineState &state);
    void unitErrorOccurred(int unit, const frezka::driver::MachineError &error);
    // chooseMachineUnit made `unit` the machine (the same as before: it refused).
    void machineUnitChanged(int unit);

private:
    MachineCore &core();
    double now() const;
    void apply(const MachineCore::Result &result);
    void service(); // write pending output, re-arm the timer
    void onBytes(const QByteArray &bytes);
    void onClosed(const QString &why);
    bool lineMode() const { return m_lineConfigs.size() > 1; }
    // The cores of a line for this connection (fresh ones for the other units).
    void buildLine(const ConnectionSettings &settings);
    void watchOtherCore(MachineCore &core, int unit);
    void watchMachineCore(MachineCore &core);

    machine::MachineConfig m_config;
    std::vector<machine::MachineConfig> m_lineConfigs;
    int m_machineIndex = 0;
    bool m_coreShared = false; // m_core was made for a shared line
    int m_coreAddress = 0;     // ... and this address
    std::vector<std::unique_ptr<MachineCore>> m_otherCores;
    std::vector<MachineCore *> m_unitCores; // the line's cores in its order (m_core among them)
    std::unique_ptr<SharedLine> m_line;
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
// The transport of a shared line: the port, or the built-in emulator with every unit of
// `configs` on its wire (each with its profile's EEPROM; the machine's has the spindle).
Transport *createLineTransport(const ConnectionSettings &settings,
                               const std::vector<machine::MachineConfig> &configs, int machineIndex,
                               QObject *parent, QString *error);

} // namespace frezka::driver
