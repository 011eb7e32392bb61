#pragma once
// QtMachineLink<T>: a MachineLink over a driver object with MachineController's slots and
// signals: MachineController itself (the GUI, link thread of its own) or LinkWorker (frezka-cli
// run on a serial port / pty or the real-time emulator, on the caller's thread). It forwards
// each operation and re-emits the driver's signals; it keeps the last state for state(). The
// driver object is not owned.

#include "session/machinelink.h"

namespace frezka::session {

template<class Driver>
class QtMachineLink final : public MachineLink
{
public:
    explicit QtMachineLink(Driver &driver, QObject *parent = nullptr)
        : MachineLink(parent)
        , m_driver(driver)
    {
        QObject::connect(&driver, &Driver::stateChanged, this,
                         [this](const driver::MachineState &s) {
                             m_state = s;
                             emit stateChanged(s);
                         });
        QObject::connect(&driver, &Driver::errorOccurred, this,
                         [this](const driver::MachineError &e) { emit errorOccurred(e); });
        QObject::connect(&driver, &Driver::jobFinished, this,
                         [this](bool ok) { emit jobFinished(ok); });
    }

    const driver::MachineState &state() const override { return m_state; }
    void setMachineConfig(const machine::MachineConfig &c) override
    {
        m_driver.setMachineConfig(c);
    }
    void connectTo(const driver::ConnectionSettings &s) override { m_driver.connectTo(s); }
    void disconnectFromUnit() override { m_driver.disconnectFromUnit(); }
    void run(const machine::UnitProgram &program) override { m_driver.run(program); }
    void pause() override { m_driver.pause(); }
    void resume() override { m_driver.resume(); }
    void abort() override { m_driver.abort(); }
    void toolLift(bool stopSpindle) override { m_driver.toolLift(stopSpindle); }
    void toolLower(int speedPulsesPerS) override { m_driver.toolLower(speedPulsesPerS); }
    void home(unsigned axisMask) override { m_driver.home(axisMask); }
    void setSpindleRpm(double rpm) override { m_driver.setSpindleRpm(rpm); }
    void sendRaw(const QString &text) override { m_driver.sendRaw(text); }
    void execute(const driver::MachineCommand &command) override { m_driver.execute(command); }

private:
    Driver &m_driver;
    driver::MachineState m_state;
};

} // namespace frezka::session
