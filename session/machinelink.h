#pragma once
// MachineLink: what the session layer asks of a machine, whatever drives it. The run workflow
// talks to this interface only; three links implement it: QtMachineLink over the driver's
// MachineController (the GUI: the link in its own thread) or over a LinkWorker on the caller's
// thread (frezka-cli run on a port or the real-time emulator), and SimLink (the in-process
// emulator on a virtual clock: frezka-cli run --clock virtual and the headless tests). The
// operations are those of MachineController and return at once; what happens comes back as
// the signals, with state() the last snapshot.

#include "driver/link/machinecontroller.h"
#include "driver/link/machinestate.h"
#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <QObject>

#include <optional>

namespace frezka::session {

class MachineLink : public QObject
{
    Q_OBJECT

public:
    using QObject::QObject;
    ~MachineLink() override;

    virtual const driver::MachineState &state() const = 0;
    // The link's own clock in seconds (a virtual one: SimLink, VirtualClockLink), or none when
    // the link runs in real time (the wall clock is the job's clock then).
    virtual std::optional<double> clockS() const { return std::nullopt; }
    virtual void setMachineConfig(const machine::MachineConfig &config) = 0;
    virtual void connectTo(const driver::ConnectionSettings &settings) = 0;
    virtual void disconnectFromUnit() = 0;
    virtual void run(const machine::UnitProgram &program) = 0;
    virtual void pause() = 0;
    virtual void resume() = 0;
    virtual void abort() = 0;
    virtual void toolLift(bool stopSpindle) = 0;
    virtual void toolLower(int speedPulsesPerS) = 0;
    virtual void home(unsigned axisMask) = 0;
    virtual void setSpindleRpm(double rpm) = 0;
    virtual void sendRaw(const QString &text) = 0;
    // Any other operation of the driver (driver/link/machinecommand.h), e.g. op::HoldSpindle.
    virtual void execute(const driver::MachineCommand &command) = 0;

signals:
    void stateChanged(const frezka::driver::MachineState &state);
    void errorOccurred(const frezka::driver::MachineError &error);
    void jobFinished(bool ok);
};

} // namespace frezka::session
