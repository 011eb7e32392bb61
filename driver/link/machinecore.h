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
// Progress is kept as the index of the next program command to send (everything before it was
// accepted by the unit). When a packet's fate is unknown (its reply and the recovery queries did
// not settle it) or the link was lost and came back, the streamer lets the unit run dry, reads
// the position counters and finds the program command whose end position they equal: that is
// exactly how far the unit got, and the job continues from the next command after the modal
// settings (V, A, B, T, $, VK/VN) in force there have been sent again.

#include "driver/link/linkengine.h"
#include "driver/link/machinecommand.h"
#include "driver/link/machinestate.h"
#include "machine/machineconfig.h"
#include "machine/unitprogram.h"

#include <deque>
#include <functional>
#include <optional>
#include <string>

namespace frezka::driver {

struct CoreOptions
{
    LinkOptions link;
    bool checksums = true;             // switch checksums on when connecting
    bool packets = true;               // send runs of C/B as packets
    int maxPacketCommands = 0;         // 0 = up to the variant's queue capacity
    double pollIntervalS = 0.05;       // 20 Hz position + status while connected
    double inputsPollIntervalS = 0.25; // I1/I2
    double maxPollGapS = 4.0;          // while streaming wire-bound, poll at least this often
    double wireBoundPollShare = 0.005; // ... and otherwise spend at most this share on polls
    double slowPacketWireS = 0.1;      // where the motion is slow, packets at most this long
    bool compareEeprom = true;         // read the unit's EEPROM on connect and report differences
    bool optionalStops = true;         // M1 pauses
    // When the position leaves the planned path (see machinecore_pathguard.cpp): false = stop
    // and hold the job for the operator (resume returns to the path); true = return to the
    // path and run on without asking (headless runs, soak tests).
    bool returnToPathAutomatically = false;
    friend bool operator==(const CoreOptions &, const CoreOptions &) = default;
};

// Figures of a job for the CLI and the benchmarks.
struct JobReport
{
    std::int64_t vectors = 0;  // C and L commands accepted
    std::int64_t commands = 0; // program commands accepted
    double startS = 0;
    double endS = 0;
    std::int64_t linkBytes = 0; // both directions during the job
    std::int64_t resent = 0;
    std::int64_t recovered = 0;
    std::int64_t verified = 0;    // times progress was re-established from the counters
    std::int64_t packets = 0;     // packets sent (first attempts and resends)
    std::int64_t polls = 0;       // position polls during the job
    std::int64_t streamPolls = 0; // ... of them while vectors were still to send
    double maxStreamPollGapS = 0; // the longest time without one then (from the start)
    double firstStreamPollS = -1; // when the first and last of them started
    double lastStreamPollS = -1;
    std::int64_t pathFaults = 0;  // times the position left the planned path (path guard)
    std::int64_t rerun = 0;       // vectors sent again after returning (queued ones too)
    std::int64_t returnMoves = 0; // L moves that took the machine back to the path
    double firstVectorAckS = -1;  // when the unit accepted the first / last motion command
    double lastVectorAckS = -1;
    bool finished = false; // reached ProgramEnd / the end of the program
    friend bool operator==(const JobReport &, const JobReport &) = default;
};

class MachineCore
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

    // ---- operations. Each returns nullopt when accepted, else why not (state unchanged).
    using Result = std::optional<MachineError>;
    // The one entry of the front ends (see machinecommand.h); the named operations below are
    // the same, spelled out for code that drives the core directly (SimRunner users, tests).
    Result execute(const MachineCommand &command, double now);
    Result run(machine::UnitProgram program, double now);
    Result pause(double now);
    Result resume(double now);
    Result abort(double now);
    Result toolLift(bool stopSpindle, double now);
    Result toolLower(int speedPulsesPerS, double now);
    // Homes the axes in axisMask (bit a = axis a; default all) that the profile homes, in the
    // profile's order: W per axis, then the counter set to the home position.
    Result home(double now, unsigned axisMask = 0xF);
    Result jogStep(int axis, double distanceMm, double speedMmPerMin, double now);
    Result jogContinuous(int axis, int direction, double speedMmPerMin, double now);
    Result jogStop(double now);
    Result setMpg(bool on, double now);
    Result setSpindleRpm(double rpm, double now);
    Result setOutputs(std::uint8_t mask, std::uint8_t activeHigh, double now);
    Result setOverride(int percent, double now);
    Result overrideStep(bool up, double now);
    Result sendRaw(const std::string &text, double now);
    // Writes the profile's EEPROM settings (§12) to the unit, then compares again.
    Result writeEeprom(double now);
    void setConfig(machine::MachineConfig config)
    {
        m_config = std::move(config);
        if (!m_job)
            m_state.axisCount = machine::wireAxisCount(m_config);
    }

    const MachineState &state() const { return m_state; }
    const JobReport &jobReport() const { return m_report; }
    const LinkEngine &engine() const { return m_engine; }
    const machine::MachineConfig &config() const { return m_config; }

    std::function<void(const MachineState &)> onStateChanged;
    std::function<void(const std::string &)> onLog;
    std::function<void(const MachineError &)> onError;
    std::function<void(bool ok)> onJobFinished;

private:
    using Then = std::function<void(const Outcome &)>;
    struct Step
    {
        protocol::Command command;
        Then then;
    };

    // scheduling (machinecore.cpp)
    void pump(double now);
    void send(const protocol::Command &c, Then then);
    void sendFront(const protocol::Command &c, Then then);
    void onOutcome(const Outcome &o);
    bool pollDue(double now) const;
    double nextPollTime() const;
    void startPoll(double now);
    void applyPosition(const protocol::Reply &r);
    void applyFlags(std::uint8_t flags, double now);
    void setMode(MachineMode mode);
    void publish();
    MachineActivity currentActivity() const;
    void fail(const std::string &message, const Outcome *o, MachineMode mode);
    bool unitError(const Outcome &o, const std::string &what, MachineMode mode);
    void log(const std::string &text);
    void afterIdle(std::function<void()> then);
    void afterJobIdle(std::function<void()> then);
    // Runs `then` when F shows RUN = 0 or INTA = 1 (an interrupt braking a move).
    void afterStopOrInterrupt(std::function<void()> then);
    void whenStill(std::function<void()> then);
    void checkIdleWaiters();

    // connect sequence (machinecore_connect.cpp)
    void connectSequence();
    void switchChecksums(int attempt);
    void setupUnit();
    void setupAfterIdentify();
    void compareEeprom();
    void probeDoublePacketStart();
    void packetStartTest(int attempt);
    void connected();

    // job streaming (machinecore_job.cpp)
    void streamStep(double now);
    void estimateDurations();
    void sendPacket(double now);
    void onPacketOutcome(const Outcome &o, std::size_t first, std::size_t n, double now);
    void acceptUpTo(std::size_t end);
    void matchProgress();
    void readStillPosition();
    void onJobCommandOutcome(const Outcome &o, std::size_t index, double now);
    void handlePcOp(const machine::UnitCommand &c, double now);
    void finishJob(bool ok);
    void finishWithPosition();
    void atRest(std::size_t index, std::function<void()> then);
    void startProbe(std::size_t index);
    void endProbe(std::size_t index, bool mustTrip);
    void verifyProgress(const std::string &why);
    void resendModals(std::function<void()> then);
    void locateExecuting();
    int freeQueueEstimate() const;
    int maxPacket() const;
    double bufferedS() const;
    void calibrateFull();
    std::int64_t queuedAfter(double aheadS) const; // estimated motion time queued in the unit
    std::size_t execEstimate() const; // estimated executing command, from time since the poll
    bool streaming() const;
    bool wireBoundAhead() const; // the motion ahead runs faster than the wire can carry it
    std::size_t slowMotionPacketEnd() const; // where a packet ends to keep polls at their rate
    protocol::Command toCommand(const machine::UnitCommand &c) const;

    // path guard (machinecore_pathguard.cpp)
    bool onPlannedPath();
    void checkAtRest(std::size_t index, std::function<void()> then);
    void pathFault(const std::string &why);
    void holdOrReturn();
    void returnToPath(int attempt);
    void returnStep(std::size_t k);
    const machine::Steps4 &plannedBefore(std::size_t index) const;

    // operations helpers (machinecore_ops.cpp)
    void interrupted();
    std::int64_t stepsFromMm(int axis, double mm) const;
    double mmFromSteps(int axis, std::int64_t steps) const;
    Result jogTo(int axis, std::int64_t target, double speedMmPerMin, double now);

    machine::MachineConfig m_config;
    CoreOptions m_options;
    LinkEngine m_engine;
    MachineState m_state;
    bool m_dirty = false;
    double m_now = 0;
    std::deque<Step> m_steps;                         // operation steps, before polls and the job
    Then m_inFlight;                                  // continuation of the transaction in flight
    std::vector<std::function<void()>> m_idleWaiters; // run when F shows RUN = 0
    std::vector<std::function<void()>> m_jobIdleWaiters; // the same, only while the job runs
    std::vector<std::function<void()>> m_stopWaiters;    // RUN = 0 or INTA = 1
    double m_waitUntil = -1; // a dwell or back-off: nothing from the job before this time
    bool m_open = false;

    // polling
    double m_lastPoll = -1e9;
    double m_lastInputsPoll = -1e9;
    std::deque<double> m_pollTimes; // for pollHz
    bool m_haltPending = false;     // H / W in flight: the unit answers nothing else meanwhile

    // job
    machine::UnitProgram m_program;
    bool m_job = false;
    std::size_t m_next = 0;        // next program command to send
    std::size_t m_exec = 0;        // program command executing (from the polled position)
    std::size_t m_inflightEnd = 0; // end of the commands in flight
    std::int64_t m_vectorsAcked = 0;
    bool m_streamBlocked = false; // waiting for idle / operator / verification
    bool m_queueFullSeen = false; // last C/packet hit a full queue
    std::int64_t m_queuedAtFull = 0;
    JobReport m_report;
    std::int64_t m_bytesAtStart = 0;
    bool m_needVerify = false; // progress must be re-established from the counters
    bool m_jogContinuous = false;
    int m_packetLimit = 1;                  // adaptive packet size (commands)
    std::vector<double> m_timePrefix;       // estimated motion seconds before each program index
    std::vector<std::int64_t> m_bytePrefix; // wire bytes of the program commands before each
    double m_execAt = 0;                    // when m_exec was read from the unit
    double m_rttS = 0.01;                   // round trip of a poll, smoothed
    int m_lastPollTransactions = 1;         // transactions of the last poll (position, F, inputs)
    double m_pollSentAt = 0;
    std::int64_t m_pollCount = 0;
    std::vector<std::int64_t> m_vectorPrefix; // motion commands before each program index
    std::int64_t m_resentAtStart = 0;
    std::int64_t m_recoveredAtStart = 0;
    bool m_holdNeedsGo = false;
    bool m_haltExpected = false; // an interrupt is part of the operation (probe), not a hold // the
                                 // unit holds (INTA): resume with G
    // path guard: commands before m_verified ran as planned (the unit was seen on the path at
    // or after the start of command m_verified); m_pathFault while stopping and returning
    std::size_t m_verified = 0;
    bool m_pathFault = false;
    bool m_pathGuardOff = false; // a probe stopped short: the rest was planned from elsewhere
    std::string m_pathFaultText;
    std::vector<machine::Steps4> m_returnMoves; // L moves back to the path, in order
    int m_returnAttempt = 0;
    bool m_linkWasLost = false; // counters matching nothing then mean a reset unit, not a fault

    // tool lift
    std::int64_t m_liftSteps = 0;
    bool m_spindleStopped = false;
    int m_liftSpindle = 0;
    bool m_kept = false;
    bool m_toolLift = false; // from toolLift() until the tool is down again
};

} // namespace frezka::driver
