#pragma once
// SimLink: a MachineLink on the in-process emulator and a virtual clock (MachineCore,
// EmulatorPort and SimRunner of the driver), for frezka-cli run --clock virtual and the
// headless tests of the run workflow. Nothing runs until the owner turns the clock
// (runUntil / runFor); the core's events are queued and delivered between the runner's steps,
// never from inside the core, so a workflow may call the next operation from its handler as it
// does on a real link. state() is the last state delivered. With a recorder, the line both ways
// and the driver's modes and errors go into it (frezka-cli run --trace), on a clock of whole
// nanoseconds (driver::TracingPort).

#include "session/machinelink.h"

#include "driver/link/emulatorport.h"
#include "driver/link/machinecore.h"
#include "driver/link/simrunner.h"
#include "driver/link/tracingport.h"

#include <functional>
#include <memory>
#include <vector>

namespace frezka::session {

class SimLink final : public MachineLink
{
public:
    SimLink(const machine::MachineConfig &config, const emulator::UnitOptions &unit,
            const driver::WireOptions &wire, const driver::CoreOptions &options,
            QObject *parent = nullptr, driver::TraceRecorder *recorder = nullptr);
    ~SimLink() override;

    // Turns the virtual clock until done() holds (checked after every delivery) or limitS
    // seconds have passed; returns done().
    bool runUntil(const std::function<bool()> &done, double limitS);
    void runFor(double seconds);
    // The cable pulled (why non-empty: the machine sees a lost link, not a disconnect).
    void unplug(const std::string &why);
    double now() const { return m_runner.now(); }
    const driver::JobReport &jobReport() const { return m_core.jobReport(); }
    driver::EmulatorPort &port() { return m_port; }
    // The state the core holds now (state() lags it until the next delivery).
    const driver::MachineState &liveState() const { return m_core.state(); }

    const driver::MachineState &state() const override { return m_state; }
    std::optional<double> clockS() const override { return now(); }
    void setMachineConfig(const machine::MachineConfig &config) override;
    void connectTo(const driver::ConnectionSettings &settings) override;
    void disconnectFromUnit() override;
    void run(const machine::UnitProgram &program) override;
    void pause() override;
    void resume() override;
    void abort() override;
    void toolLift(bool stopSpindle) override;
    void toolLower(int speedPulsesPerS) override;
    void home(unsigned axisMask) override;
    void setSpindleRpm(double rpm) override;
    void sendRaw(const QString &text) override;
    void execute(const driver::MachineCommand &command) override;

private:
    void apply(const driver::MachineCore::Result &result);
    void deliver();

    driver::EmulatorPort m_port;
    std::unique_ptr<driver::TracingPort> m_tracing; // with a recorder: the port the runner uses
    driver::MachineCore m_core;
    driver::SimRunner m_runner;
    driver::MachineState m_state;
    std::vector<std::function<void()>> m_pending;
    bool m_delivering = false;
    bool m_open = false;
};

} // namespace frezka::session
