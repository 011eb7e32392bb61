#pragma once
// VirtualClockLink: the window's built-in emulator on a virtual clock (frezka --clock virtual,
// docs/gui.md). A MachineLink over a SimLink made afresh at each connect (with the profile of
// that moment: variant, axes, baud, the emulated work top), whose clock is turned from the
// event loop in slices of at most sliceMs of wall time: as fast as the computer allows while
// the machine moves (a job, homing, a jog, the connect), at the pace of the wall clock while it
// waits (idle, held), so that an idle window does not spin. Between slices the loop handles
// input and paints: the window stays responsive. The run workflow hears every state (the link's
// stateChanged); the screen, which costs more (a frame of a big toolpath outlasts a slice), is
// given the state at the end of a slice at most 20 times a second while the machine moves, as
// the real-time link polls, and as soon as it comes to wait (sliceEnded). Only
// the built-in emulator runs on it: a port is refused (connectTo with a SerialPort errors).

#include "session/simlink.h"

#include <QElapsedTimer>

#include <memory>
#include <optional>

class QTimer;

namespace frezka::session {

class VirtualClockLink final : public MachineLink
{
    Q_OBJECT

public:
    explicit VirtualClockLink(QObject *parent = nullptr, int sliceMs = 15);
    ~VirtualClockLink() override;

    // The emulator and its clock of the current connection; null before the first connect.
    SimLink *sim() const { return m_sim.get(); }
    // The longest slice so far (ms of wall time): what the event loop waited for the clock.
    qint64 longestSliceMs() const { return m_longestSliceMs; }
    // Turns the clock once (what the timer does); public for tests.
    void slice();

    const driver::MachineState &state() const override;
    std::optional<double> clockS() const override;
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

signals:
    // A slice has ended, the state changed since the last of these, and it is time to show it.
    void sliceEnded(const frezka::driver::MachineState &state);

private:
    bool moving() const;
    void schedule();
    template<class Call>
    void forward(Call call);

    machine::MachineConfig m_config;
    std::unique_ptr<SimLink> m_sim;
    driver::MachineState m_none; // state() before the first connect
    QTimer *m_timer;
    QElapsedTimer m_wall;  // since the last slice, for the wall-clock pace while waiting
    QElapsedTimer m_shown; // since the screen was last given a state
    int m_sliceMs;
    qint64 m_longestSliceMs = 0;
    bool m_changed = false;
};

} // namespace frezka::session
