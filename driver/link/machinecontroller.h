#pragma once
// MachineController: the GUI-thread facade of the driver.
//
// Lives in the GUI thread and owns a QThread running the link worker (which owns the port or
// the in-process emulator and all machine state). Every slot is a queued call into that thread
// and returns at once; results come back as signals carrying values (MachineState snapshots,
// log lines, errors). Nothing here blocks and nothing here holds machine state besides the
// last snapshot for convenience.
//
// Status of the operations (what the link thread does with each, tests in tests/driver/link):
//   implemented and tested on the emulator: connectTo (serial port / pty path, built-in
//     emulator), disconnectFromUnit, run, pause, resume, abort, toolLift / toolLower (KEEP /
//     RESTORE, optional spindle stop, optional new speed V + XA), home, jogStep, jogContinuous /
//     jogStop (clipped to the soft limits), setSpindleRpm, setOutput, setOverride; the STOP
//     input and other enabled interrupts hold the job (state.hold == Interrupt); link loss keeps
//     the job and re-establishes its progress from the counters after reconnecting.
//   implemented, no dedicated test yet: setMpg, overrideUp / overrideDown, sendRaw.
//   G38.2-.5 probe moves in a job (IN15 armed as an interrupt; trip point in state.probeSteps;
//     when the probe stops short and motion follows, the job ends: the planner planned the rest
//     from the probe's end point).
//   writeEeprom: writes the profile's EEPROM settings when asked (connect only compares them).
//   turnEmulatedWheel: the built-in emulator's MPG wheel, not a unit operation (tested in
//     tests/gui/workflow_wheel_test.cpp).

#include "driver/link/machinecommand.h"
#include "driver/link/machinestate.h"
#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <QMetaType>
#include <QObject>
#include <QString>

#include <memory>
#include <optional>
#include <vector>

class QThread;

namespace frezka::emulator {
struct Stats;
}

namespace frezka::driver {

class LinkWorker;

// Where to connect.
struct ConnectionSettings
{
    enum class Kind : std::uint8_t {
        SerialPort, // a real port or a pty path ("/dev/ttyUSB0", "/dev/pts/5")
        Emulator,   // the built-in in-process emulator, real time (variant from the profile)
    };
    Kind kind = Kind::Emulator;
    QString portName;     // SerialPort
    int baud = 115200;    // both (the emulator paces its wire at this rate)
    double latencyMs = 0; // Emulator: USB-serial latency per direction
    double faultRate = 0; // Emulator: byte errors per byte (1e-3 = one per 1000 bytes)
    quint32 seed = 1;     // Emulator: fault injector seed
    // Emulator: the simulated work top for probing (driver/emulator/surface.h, such as
    // plane:-20,0.001,0); empty or malformed: none.
    QString surface;
    friend bool operator==(const ConnectionSettings &, const ConnectionSettings &) = default;
};

class MachineController : public QObject
{
    Q_OBJECT

public:
    explicit MachineController(QObject *parent = nullptr);
    ~MachineController() override;

    // The last snapshot received from the link thread.
    const MachineState &state() const { return m_state; }
    // The last snapshot of every unit on the line (setLineUnits' order; a unit alone: one),
    // empty before the first.
    const std::vector<MachineState> &unitStates() const { return m_unitStates; }

public slots:
    // The machine profile (axes, limits, steps/mm, outputs, homing). Applies from the next
    // connect / operation; a running job keeps the profile it started with.
    void setMachineConfig(const frezka::machine::MachineConfig &config);

    // Several units on one line (LinkWorker::setLineUnits): their profiles in the order of the
    // machine profile's line.units and which one is the machine (setMachineConfig's, which the
    // slots below operate). Applies from the next connect.
    void setLineUnits(const std::vector<frezka::machine::MachineConfig> &configs, int machineIndex);
    // Makes another unit of the line the machine while every unit is idle
    // (LinkWorker::chooseMachineUnit); then setMachineConfig with that unit's profile.
    void chooseMachineUnit(int unit);
    void connectTo(const frezka::driver::ConnectionSettings &settings);
    void disconnectFromUnit();

    // Job: stream a planned program (its first command runs from the current position).
    void run(const frezka::machine::UnitProgram &program);
    void pause();  // H: brake along the ramp, keep the queue
    void resume(); // G (after pause, interrupt, M0/M1/M6)
    void abort();  // H, D: stop and drop the rest of the job
    // Tool lift while paused: K, lift Z by the profile's toolLiftMm, optional spindle stop;
    // toolLower lowers back, R, optional new speed (V + XA) when speedPulsesPerS > 0.
    void toolLift(bool stopSpindle);
    void toolLower(int speedPulsesPerS);

    // W per axis in the configured order, then set the counters; axisMask: bit a = axis a.
    void home(unsigned axisMask = 0xF);
    // Incremental jog: distance in mm (A: degrees), clipped to the soft limits.
    void jogStep(int axis, double distanceMm, double speedMmPerMin);
    // Continuous jog toward the soft limit until jogStop().
    void jogContinuous(int axis, int direction, double speedMmPerMin);
    void jogStop();
    void setMpg(bool on);
    // Turns the built-in emulator's handwheel (LinkWorker::turnEmulatedWheel): axis 0..3,
    // multiplier 1/10/100, detents signed. Elsewhere a no-op with a logLine saying so.
    void turnEmulatedWheel(int axis, int multiplier, int detents);
    // What the built-in emulator's machine unit has counted (LinkWorker::builtInEmulatorStats),
    // read in the link thread while this one waits; empty on another port.
    std::optional<frezka::emulator::Stats> builtInEmulatorStats() const;

    void setSpindleRpm(double rpm);      // !7V, per mille from the profile's max rpm
    void setOutput(int output, bool on); // OUTn (0..3) on or off, others kept
    void setOverride(int percent);       // XM
    void overrideUp();                   // XU
    void overrideDown();                 // XD
    // A raw command for the console, e.g. "!0PF" or "PF" (address 0 assumed). Validated
    // against the variant; the reply comes as a logLine.
    void sendRaw(const QString &text);
    // Writes the profile's EEPROM settings to the unit (only when asked; on connect they are
    // only compared: state.eepromDifferences). Idle only.
    void writeEeprom();

signals:
    void stateChanged(const frezka::driver::MachineState &state);
    // One line for the communication console / log ("> !0PF", "< 0,1,2,3", "! recovery ...").
    void logLine(const QString &line);
    // A user-visible error: the message names the command and the reply.
    void errorOccurred(const frezka::driver::MachineError &error);
    // The job ended (ok = reached its end; otherwise aborted or failed with lastError).
    void jobFinished(bool ok);
    // Each unit of the line (an index of setLineUnits' list), the machine's included.
    void unitStateChanged(int unit, const frezka::driver::MachineState &state);
    void unitErrorOccurred(int unit, const frezka::driver::MachineError &error);
    // chooseMachineUnit made `unit` the machine (then the window takes its profile); the
    // machine it had when it refused.
    void machineUnitChanged(int unit);

public:
    // The one way into the link thread: every slot above that operates the machine builds one.
    void execute(frezka::driver::MachineCommand command);
    // The same for any unit of the line (the machine's index: as execute).
    void executeOn(int unit, frezka::driver::MachineCommand command);

private:
    void onState(const frezka::driver::MachineState &state);
    void onUnitState(int unit, const frezka::driver::MachineState &state);

    QThread *m_thread = nullptr;
    LinkWorker *m_worker = nullptr; // lives in m_thread
    MachineState m_state;
    std::vector<MachineState> m_unitStates;
};

} // namespace frezka::driver

Q_DECLARE_METATYPE(frezka::driver::MachineState)
Q_DECLARE_METATYPE(frezka::driver::MachineError)
Q_DECLARE_METATYPE(frezka::driver::ConnectionSettings)
Q_DECLARE_METATYPE(frezka::machine::UnitProgram)
Q_DECLARE_METATYPE(frezka::machine::MachineConfig)
