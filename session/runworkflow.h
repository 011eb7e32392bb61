#pragma once
// RunWorkflow: the operator's run workflow, one class for both front ends. Over a MachineLink
// it connects (and reconnects after a lost link when asked), homes, runs the planned program
// (planning it again first when the machine is not where the plan starts), checks it, holds,
// resumes, aborts, lifts the tool and lowers it again ("lower and continue" resumes once the
// tool is down). The GUI drives it from its buttons and renders its signals; frezka-cli run
// drives the headless sequence start(): connect, home if asked, run, and one runEnded(ok). The
// program itself is loaded and planned by the front end (the GUI in a worker thread, the CLI
// in place): it hands the plan over with setProgram() and, when a replanner is set, plans again
// from the start position the workflow asks for. Texts are in the user's language.
//
// The operator's stops: stop() is the controlled stop (H along the ramp: the job is held, its
// position known, resume() continues it; homing ends and its axes stay not homed), abort()
// drops the job (H, D). A run before homing asks for homing first (homingNeeded(), then
// homeThenRun()) unless the profile allows it (motion.runBeforeHoming: it runs with a warning).
// The machine's START button (unit.startInput, read by the driver's input polls) runs the
// loaded, checked program as Run does, or resumes a held job; it acts on the press (the edge
// to its active level), never on a button held while connecting.
//
// The program's own stops (M0, M1, M6) in the headless sequence: setProgramStops() says whether
// they end the run (End: nobody at the machine), continue at once (Continue: frezka-cli run
// --continue-at-stops; the driver switches a spindle the stop switched off on again and waits its
// spin-up first, as the GUI's Continue does), or are put to the front end (Ask:
// programStopped(), then resume() or abort()). Other holds (an input, a failed probe, the path
// guard) end a headless run whenever setEndOnHold() is on.
//
// Programs that probe for themselves (setProbeFollow(), session/probefollow.h): Run plans the
// program from the machine's position up to its first probe (the ProbeFollow's, not the plan
// setProgram() gave); when that job has ended with the probe, the rest of the program is
// interpreted again with the probe's result and planned from where the machine stands up to the
// next probe, and runs at once as the same run (no jobFinished in between; probeFollowed() tells
// the front end, which shows the program as re-interpreted). A probe that fails (a G38.2 that
// never touched) holds or ends the job as before.

#include "session/machinelink.h"
#include "session/probefollow.h"

#include <QElapsedTimer>

#include <QObject>
#include <QTimer>
#include <optional>

#include <array>
#include <functional>
#include <memory>

namespace frezka::session {

class RunWorkflow : public QObject
{
    Q_OBJECT

public:
    using Position = std::array<double, 4>;
    using Replanner = std::function<void(const Position &startMm)>;

    explicit RunWorkflow(MachineLink &link, QObject *parent = nullptr);

    MachineLink &link() const { return m_link; }
    const driver::MachineState &state() const { return m_link.state(); }
    // The state of the machine in the user's words ("Ready", "Tool lifted").
    static QString modeText(driver::MachineMode mode);
    // How a profile reaches its unit: "emulator" (or no port) is the built-in emulator, with the
    // simulated work top of the environment's FREZKA_EMULATOR_SURFACE (a --surface spec), if any.
    static driver::ConnectionSettings connectionFor(const machine::MachineConfig &config);

    void setProfile(const machine::MachineConfig &config);
    // The connection asked for last (the built-in emulator or which port).
    const driver::ConnectionSettings &connection() const { return m_settings; }
    // Whether a connection has been asked for since the start (a front end's first connect may
    // choose the port used before a restart; a new port applied later reconnects).
    bool connectionAsked() const { return m_connectionAsked; }
    const machine::MachineConfig &profile() const { return m_profile; }

    // ---- connection
    void connectToUnit(const driver::ConnectionSettings &settings);
    void disconnectFromUnit(); // the operator's: no reconnecting after it
    void setAutoReconnect(bool on, int delayMs = 2000);

    // ---- the program. plan == nullptr: nothing can run (notRunnable says why, "" = none).
    void setProgram(std::shared_ptr<const machine::UnitProgram> plan, const Position &startMm,
                    const QString &name, const QString &notRunnable = {});
    void setReplanner(Replanner replan) { m_replan = std::move(replan); }
    // The program probes for itself: Run plans it with `follow`, one job up to each probe, the
    // rest again after every probe move it runs (nullptr: not; the plan runs as given). Not
    // owned; it must outlive the runs.
    void setProbeFollow(ProbeFollow *follow) { m_follow = follow; }
    // Probe moves after which the run went on with the re-interpreted rest, in this run.
    int probesFollowed() const { return m_probesFollowed; }
    // The restarts from rest that the jobs of this run plan (machine::plannedRestarts of each
    // job's program, a followed probe's rest included): the emulator counts them as starvation
    // stops, a report subtracts them.
    std::int64_t plannedRestarts() const { return m_plannedRestarts; }
    // Runs the program when the machine is ready; re-plans first from the machine's position.
    void runProgram();
    // Re-plans from the machine's position; checked(ok) follows.
    void checkProgram();
    // Headless: connect, home when asked, run; runEnded(ok) once, error() says why not.
    void start(const driver::ConnectionSettings &settings, bool homeFirst);
    void setEndOnHold(bool on) { m_endOnHold = on; } // nobody at the machine to answer a hold
    enum class ProgramStops : std::uint8_t { End, Continue, Ask };
    void setProgramStops(ProgramStops stops) { m_programStops = stops; }
    // Operator stops answered by continuing or asked (ProgramStops::Continue, Ask) in this run.
    int programStopsSeen() const { return m_programStopsSeen; }
    bool hasEnded() const { return m_step == Step::Ended; }
    QString error() const { return m_error; }

    // ---- during a job
    // Seconds of the job running now, or of the last one when none runs: on the link's own
    // clock when it has one (a virtual clock: MachineLink::clockS), else the wall clock.
    double jobElapsedS() const;
    void pause() { m_link.pause(); }
    void resume() { m_link.resume(); }
    // The controlled stop (Stop, Esc): a job is held (H), homing ends; nothing when idle.
    void stop();
    void abort() { m_link.abort(); }
    // Home every axis the profile homes, then run the program (the answer to homingNeeded()).
    void homeThenRun();
    void toolLift(bool stopSpindle);
    // Spindle back on when the lift stopped it, tool down (new speed when > 0), then resume
    // once the machine holds with the tool down when thenContinue.
    void lowerTool(double newFeedMmPerMin, bool thenContinue);

signals:
    void message(const QString &text); // for the console
    void failed(const QString &why);   // an error for the operator
    void jobStarted();
    void jobFinished(bool ok);
    void checked(bool ok);
    void connected(); // connecting -> ready
    void linkLost();  // before reconnecting is decided: a handler may still setAutoReconnect()
    void runEnded(bool ok); // the headless sequence of start()
    // The job holds at its line's M0 / M1 / M6 (ProgramStops::Ask): text says which stop, in the
    // user's words; resume() continues, abort() ends the job.
    void programStopped(std::uint32_t line, const QString &text);
    // Run (or START) was asked before the machine was homed: home first (homeThenRun()).
    void homingNeeded();
    // The probe move on `line` has run and the rest of the program, interpreted again with its
    // result, runs on (ProbeFollow::Next: the re-interpreted program and where it is still
    // provisional).
    void probeFollowed(std::uint32_t line, const frezka::session::ProbeFollow::Next &next);

private:
    enum class Step : std::uint8_t { None, Connecting, Homing, Running, Ended };
    enum class Pending : std::uint8_t { None, Run, Check };

    void onState(const driver::MachineState &state);
    void startJobClock();
    void onError(const driver::MachineError &error);
    void onJobFinished(bool ok);
    void advance(const driver::MachineState &state, driver::MachineMode last);
    void startJob();
    void watchStartInput(const driver::MachineState &state);
    void startPressed();
    void end(bool ok, const QString &why);
    bool planStartsHere() const;
    bool answerProgramStop(const driver::MachineState &state);
    bool followProbe();

    MachineLink &m_link;
    machine::MachineConfig m_profile;
    driver::ConnectionSettings m_settings;
    std::shared_ptr<const machine::UnitProgram> m_plan;
    Position m_planStart{};
    QString m_name, m_notRunnable;
    Replanner m_replan;
    ProbeFollow *m_follow = nullptr;
    int m_probesFollowed = 0;
    std::int64_t m_plannedRestarts = 0;
    bool m_planEndsAtProbe = false; // the job's last move is a probe to follow (m_follow)
    Pending m_pending = Pending::None;
    Step m_step = Step::None;
    bool m_homeFirst = false;
    bool m_endOnHold = false;
    ProgramStops m_programStops = ProgramStops::End;
    bool m_atProgramStop = false;        // the state shows an operator stop already answered
    std::uint32_t m_programStopLine = 0; // ... at this line
    int m_programStopsSeen = 0;
    bool m_autoReconnect = false;
    bool m_connectionAsked = false;
    bool m_userDisconnected = false;
    bool m_continueAfterLower = false;
    bool m_runAfterHoming = false; // homeThenRun(): run once homed
    int m_startActive = -1;        // START input's last state: -1 unknown, 0 / 1
    driver::MachineMode m_lastMode = driver::MachineMode::Disconnected;
    QString m_error;
    QTimer m_reconnect;
    QElapsedTimer m_jobClock;          // from the job's start (or the first state that shows one)
    std::optional<double> m_jobStartS; // the link's clock at the job's start, when it has one
    double m_lastJobS = 0;
};

} // namespace frezka::session
