#pragma once
// MachineCore: the machine operations state machine and the job streamer, on top of LinkEngine.
//
// Pure C++ and clock-free like LinkEngine: the owner (LinkWorker on a real port, SimRunner on the
// emulator's virtual clock) passes bytes and time in and writes out what takeOutput() returns.
// Everything the driver does to the machine is decided here, in one thread, in this order each
// time the link is free:
//
//   1. the next step of an operation (connect sequence, pause, tool lift, homing, jog, ...)
//   2. a status poll when one is due (position PF/P4 + F at pollIntervalS; inputs less often).
//      While a job streams, every poll is a round trip the stream cannot use. Where the motion
//      ahead is slower than the wire and the unit holds plenty of it, polls are free and run at
//      the full rate. Where the wire is the bottleneck (the motion ahead runs faster than it can
//      be sent) or the unit holds little, polls read the position only and take at most
//      wireBoundPollShare of the link's time, yet come at least every maxPollGapS
//   3. the job: the next packet of C/B commands (sized to the estimated free queue space),
//      or the next single command; L waits for an empty queue, WaitIdle/Dwell/M0/M1/M6/ProgramEnd
//      wait for the machine to stop (F: RUN = 0).
//
// The core itself is only that scheduler, the published MachineState, the waits on the unit's
// status (CoreWaits) and the error reporting (CoreHost, what its parts may use). What to do next is
// decided by its parts, each in its own file pair with its own fields and a contract at its top:
//
//   ConnectSequence (+ EepromSync)  connecting          MachineActivity::Connecting
//   HomingCycle                     homing in legs of W  Homing
//   Jog                             jogging             Jogging
//   Job (+ JobPace, JobOverride,    streaming a job     Job
//        JobTracker, JobFigures)
//     ProgressCheck                 progress from the counters after an unknown outcome
//                                                       CheckingProgress
//     ProbeMove                     a G38 move          Probing
//     PathGuard, ReturnToPath       off the planned path, and back  PathFault, ReturnToPath
//   ToolLift                        K, lift, lower, R in a held job  ToolLift
//   Hold                            pause, resume, abort, input interrupts
//   SpindleHold                     spindle and coolant off for a hold, on again (spin-up) before
//                                   the work
//   UnitControls                    MPG, spindle, outputs, override, raw commands
//   InputHoming                     Y& while idle, Y- before motion (homing from an input)
//   Poller                          step 2 above
//   LiveModel                       the position shown between polls (MachineState::live)
//
// MachineState::activity names the one in charge (currentActivity()), so that every transition
// is observable. Operations arrive as one MachineCommand (execute()); each is accepted (its
// steps queued, the core pumped) or refused with a MachineError and nothing changed.

#include "driver/link/connectsequence.h"
#include "driver/link/corehost.h"
#include "driver/link/coretypes.h"
#include "driver/link/corewaits.h"
#include "driver/link/eepromsync.h"
#include "driver/link/hold.h"
#include "driver/link/homingcycle.h"
#include "driver/link/inputhoming.h"
#include "driver/link/job.h"
#include "driver/link/jog.h"
#include "driver/link/linkengine.h"
#include "driver/link/livemodel.h"
#include "driver/link/machinecommand.h"
#include "driver/link/machinestate.h"
#include "driver/link/poller.h"
#include "driver/link/spindlehold.h"
#include "driver/link/toollift.h"
#include "driver/link/unitcontrols.h"
#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <deque>
#include <functional>
#include <optional>
#include <string>

namespace frezka::driver {

class MachineCore : private CoreHost
{
public:
    MachineCore(machine::MachineConfig config, CoreOptions options = {});

    // ---- transport events
    void linkOpened(double now); // starts the connect sequence
    void linkClosed(const std::string &why, double now);
    void receive(std::string_view bytes, double now);
    void onTime(double now);
    double deadline() const;
    std::string takeOutput() { return m_engine.takeOutput(); }
    // ---- a line shared with other units (LinkOptions::sharedLine; SharedLine grants it)
    bool wantsLine() const { return m_engine.wantsLine(); }
    bool holdsLine() const { return !m_engine.idle() && !m_engine.wantsLine(); }
    void grantLine(double now)
    {
        m_now = now;
        m_engine.grantLine(now);
    }

    // ---- operations. Each returns nullopt when accepted, else why not (state unchanged).
    using Result = std::optional<MachineError>;
    // The one entry of the front ends (see machinecommand.h); the named operations below are
    // shorthands for it, for code that drives the core directly (tests, frezka-cli run).
    Result execute(MachineCommand command, double now);
    Result run(machine::UnitProgram program, double now)
    {
        return execute(op::Run{std::move(program)}, now);
    }
    // A job with sync points (machine/rotarysplit.h): at each the unit waits until
    // releaseSync; onSyncReady says it is there (called from inside the core: the handler may
    // release at once, and may pump other cores, not this one).
    Result runSynced(machine::SyncedProgram program, double now)
    {
        m_job.sync().setPoints(std::move(program.syncs));
        return run(std::move(program.program), now);
    }
    void releaseSync(std::size_t index) { m_job.sync().release(index); }
    void setSyncReadyHandler(std::function<void(std::size_t index, double now)> handler)
    {
        m_job.sync().onReady = std::move(handler);
    }
    Result pause(double now, bool stopSpindle = false)
    {
        return execute(op::Pause{stopSpindle}, now);
    }
    Result holdSpindle(bool stop, double now) { return execute(op::HoldSpindle{stop}, now); }
    Result resume(double now) { return execute(op::Resume{}, now); }
    Result abort(double now) { return execute(op::Abort{}, now); }
    Result toolLift(bool stopSpindle, double now)
    {
        return execute(op::ToolLift{stopSpindle}, now);
    }
    Result toolLower(int speedPulsesPerS, double now)
    {
        return execute(op::ToolLower{speedPulsesPerS}, now);
    }
    Result home(double now, unsigned axisMask = 0xF) { return execute(op::Home{axisMask}, now); }
    Result jogStep(int axis, double distanceMm, double speedMmPerMin, double now)
    {
        return execute(op::JogStep{axis, distanceMm, speedMmPerMin}, now);
    }
    Result jogContinuous(int axis, int direction, double speedMmPerMin, double now)
    {
        return execute(op::JogContinuous{axis, direction, speedMmPerMin}, now);
    }
    Result jogStop(double now) { return execute(op::JogStop{}, now); }
    Result setMpg(bool on, double now) { return execute(op::SetMpg{on}, now); }
    Result setSpindleRpm(double rpm, double now) { return execute(op::SetSpindleRpm{rpm}, now); }
    Result setOutput(int output, bool on, double now)
    {
        return execute(op::SetOutput{output, on}, now);
    }
    Result setOverride(int percent, double now) { return execute(op::SetOverride{percent}, now); }
    Result overrideStep(bool up, double now) { return execute(op::OverrideStep{up}, now); }
    Result sendRaw(const std::string &text, double now) { return execute(op::SendRaw{text}, now); }
    Result writeEeprom(double now) { return execute(op::WriteEeprom{}, now); }
    void setConfig(machine::MachineConfig config)
    {
        m_config = std::move(config);
        if (m_options.link.baud <= 0)
            m_engine.setBaud(m_config.link.baud);
        if (!m_job.active())
            m_state.axisCount = machine::wireAxisCount(m_config);
    }

    const MachineState &state() const { return m_state; }
    const JobReport &jobReport() const { return m_job.report(); }
    const LinkEngine &engine() const { return m_engine; }
    const machine::MachineConfig &config() const override { return m_config; }

    std::function<void(const MachineState &)> onStateChanged;
    std::function<void(const std::string &)> onLog;
    std::function<void(const MachineError &)> onError;
    std::function<void(bool ok)> onJobFinished;

private:
    struct Step
    {
        protocol::Command command;
        Then then;
    };

    // ---- CoreHost: what the activities use (machinecore.cpp)
    void send(const protocol::Command &c, Then then) override;
    void sendFront(const protocol::Command &c, Then then) override;
    void clearSteps() override { m_steps.clear(); }
    void start(const protocol::Command &c, Then then) override;
    void startPacket(std::vector<protocol::Command> packet, Then then) override;
    void afterIdle(std::function<void()> then) override;
    void afterJobIdle(std::function<void()> then) override;
    void clearJobIdleWaiters() override { m_waits.clearJobIdle(); }
    bool waitingForJobStand() const override;
    void dropPending() override;
    // Runs `then` when F shows RUN = 0 or INTA = 1 (an interrupt braking a move).
    void afterStopOrInterrupt(std::function<void()> then) override;
    void whenStill(std::function<void()> then) override;
    void afterDelay(double seconds, std::function<void()> then) override;
    MachineState &liveState() override { return m_state; }
    void markDirty() override { m_dirty = true; }
    void setMode(MachineMode mode) override;
    void publish() override;
    void fail(const DriverMessage &message, const Outcome *o, MachineMode mode) override;
    bool unitError(const Outcome &o, const std::string &what, MachineMode mode) override;
    void log(const std::string &text) override;
    void jobFinished(bool ok) override;
    void applyPosition(const protocol::Reply &r) override;
    void applyFlags(std::uint8_t flags) override;
    protocol::Command positionCommand() const override;
    void setHoldNeedsGo(bool on) override { m_hold.setNeedsGo(on); }
    void setHaltExpected(bool on) override { m_haltExpected = on; }
    void heldAtOperatorStop(machine::StopReason reason) override;
    double now() const override { return m_now; }
    double rttS() const override { return m_poller.rttS(); }
    void restartPollCount() override { m_poller.restartCount(); }
    void restartPolls() override { m_poller.restartAt(m_now); }
    const CoreOptions &options() const override { return m_options; }
    LinkEngine &link() override { return m_engine; }

    // scheduling (machinecore.cpp)
    void pump(double now);
    void onOutcome(const Outcome &o);
    bool streaming() const { return m_job.streaming(m_now); }
    MachineActivity currentActivity() const;
    void checkIdleWaiters();

    void readPositionAndStatus(std::function<void()> then) override;

    // operations (machinecore.cpp)
    Result accepted(Result refused, double now); // pumps when nothing was refused
    Result moving(const std::function<Result()> &operation, double now); // Y- first (InputHoming)
    Result runJob(machine::UnitProgram program, double now);
    Result startHoming(unsigned axisMask, double now);
    double mmFromSteps(int axis, std::int64_t steps) const;

    machine::MachineConfig m_config;
    CoreOptions m_options;
    LinkEngine m_engine;
    MachineState m_state;
    bool m_dirty = false;
    double m_now = 0;
    std::deque<Step> m_steps; // operation steps, before polls and the job
    Then m_inFlight;          // continuation of the transaction in flight
    CoreWaits m_waits;        // afterIdle, afterJobIdle, afterStopOrInterrupt, afterDelay
    bool m_open = false;

    // polling
    bool m_haltPending = false; // H / W in flight: the unit answers nothing else meanwhile

    bool m_haltExpected = false; // an interrupt is part of the operation (probe), not a hold

    // the job (job.h) and its parts
    Job m_job{*this};

    SpindleHold m_spindle{*this};
    ToolLift m_toolLift{*this, m_job, m_spindle};
    HomingCycle m_homing{*this};
    EepromSync m_eeprom{*this};
    ConnectSequence m_connect{*this, m_job, m_eeprom};
    Hold m_hold{*this, m_job, m_spindle, m_toolLift};
    UnitControls m_controls{*this, m_job};
    Poller m_poller{*this, m_job, m_toolLift};
    Jog m_jog{*this};
    InputHoming m_inputHoming{*this}; // Y& while idle, Y- before motion (homing from an input)
    LiveModel m_live{*this, m_job};   // the position between polls, for showing only
};

} // namespace frezka::driver
