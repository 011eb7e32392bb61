#include "tracedrive.h"

#include "driver/link/emulatorport.h"
#include "driver/link/machinecore.h"
#include "driver/link/replayport.h"
#include "driver/link/tracerecorder.h"
#include "driver/link/tracingport.h"
#include "gcode/interpreter.h"
#include "machine/planner.h"

#include <functional>
#include <sstream>

namespace frezka::driver::tracetest {
namespace {

using emulator::SerialTrace;
using emulator::TraceDirection;
using emulator::TraceEntry;

constexpr double kWaitLimitS = 300; // virtual seconds: a wait longer than this is a hang

struct Drive
{
    const SerialTrace &recipe;
    std::string dir;
    MachineCore &core;
    SimRunner &runner;
    std::function<bool()> abandon; // the far end gave up (a replay's divergence)
    bool jobDone = false;
    std::string error;

    bool wait(const std::function<bool()> &done, const std::string &what)
    {
        runner.runUntil([&] { return done() || abandon(); }, kWaitLimitS);
        if (abandon())
            return false;
        if (!done()) {
            error = "the driver did not " + what + " within " + std::to_string(int(kWaitLimitS)) +
                    " s (mode " + machineModeName(core.state().mode) + ")";
            return false;
        }
        return true;
    }
    bool accepted(const MachineCore::Result &r, const std::string &what)
    {
        if (r)
            error = "the driver refused to " + what + ": " + r->message;
        return !r;
    }
    bool modeIs(MachineMode m) const { return core.state().mode == m; }

    bool home()
    {
        if (!accepted(core.home(runner.now()), "home"))
            return false;
        return wait([this] { return !modeIs(MachineMode::Homing); }, "end homing");
    }
    bool jog()
    {
        std::istringstream in(recipe.value("jog", "X 1 600"));
        std::string axis;
        double mm = 0, speed = 0;
        in >> axis >> mm >> speed;
        const auto a = static_cast<int>(std::string("XYZA").find(axis));
        if (!accepted(core.jogStep(a, mm, speed, runner.now()), "jog"))
            return false;
        return wait([this] { return !modeIs(MachineMode::Jogging); }, "end the jog");
    }
    bool job();
    bool run();
};

bool Drive::job()
{
    const std::string program = recipe.value("program");
    const std::string file = program.rfind('/', 0) == 0 ? program : dir + "/" + program;
    const gcode::Result g = gcode::interpretFile(file);
    if (!g.ok()) {
        error = gcode::formatError(QString::fromStdString(file), g.errors.front()).toStdString();
        return false;
    }
    const machine::PlanResult plan = machine::plan(g.toolpath, core.config());
    if (!plan.ok()) {
        error = file + ": the plan failed";
        return false;
    }
    if (!accepted(core.run(plan.program, runner.now()), "run " + file))
        return false;
    const std::string pause = recipe.value("pause-after-ms");
    if (!pause.empty()) {
        runner.runUntil([this] { return jobDone || abandon(); }, std::stod(pause) / 1000.0);
        if (abandon())
            return false;
        if (!accepted(core.pause(runner.now()), "pause") ||
            !wait([this] { return modeIs(MachineMode::Paused); }, "hold the job"))
            return false;
        runner.runUntil([this] { return abandon(); },
                        std::stod(recipe.value("resume-after-ms", "500")) / 1000.0);
        if (abandon() || !accepted(core.resume(runner.now()), "resume"))
            return false;
    }
    return wait([this] { return jobDone && !modeIs(MachineMode::Running); }, "finish the job");
}

bool Drive::run()
{
    const std::string op = recipe.value("operation");
    runner.open();
    if (!wait([this] { return !modeIs(MachineMode::Connecting); }, "connect"))
        return false;
    if (op == "connect" || !modeIs(MachineMode::Idle))
        return true; // a failed connection ends the operation: its events say how
    if ((op == "home" || recipe.value("home") == "yes") && !home())
        return false;
    if (op == "home")
        return true;
    if (op == "jog")
        return jog();
    if (op == "job")
        return job();
    error = "the trace's header names no operation the helper knows: '" + op +
            "' (connect, home, jog, job)";
    return false;
}

// The core with its events going to `sink`; `far` is the unit's end of the line.
bool driveOperation(const SerialTrace &recipe, const std::string &dir, VirtualPort &far,
                    const std::function<void(const std::string &)> &sink,
                    const std::function<bool()> &abandon, const std::function<bool()> &played,
                    std::string &error)
{
    const auto variant = protocol::variantFromId(recipe.value("variant", "gve64"));
    if (!variant) {
        error = "unknown variant '" + recipe.value("variant") + "'";
        return false;
    }
    MachineCore core(machine::defaultMachineConfig(*variant));
    SimRunner runner(core, far);
    Drive d{recipe, dir, core, runner, abandon, false, {}};
    MachineMode last = core.state().mode;
    core.onStateChanged = [&](const MachineState &s) {
        if (s.mode != last)
            sink(traceModeEvent(s.mode));
        last = s.mode;
    };
    core.onError = [&](const MachineError &e) { sink(traceErrorEvent(e)); };
    core.onJobFinished = [&](bool ok) {
        d.jobDone = true;
        sink(traceJobEvent(ok));
    };
    const bool ok = d.run();
    error = d.error;
    // A record may go on after the operation (a front end saves it later): what the driver does
    // meanwhile (its polls) must match too.
    if (ok)
        runner.runUntil([&] { return played() || abandon(); }, kWaitLimitS);
    return ok;
}

// A record on the virtual clock: the driver shows exactly the recorded events, in order.
bool sameEvents(const SerialTrace &trace, const std::vector<std::string> &seen, std::string &error)
{
    std::size_t next = 0;
    for (const TraceEntry &e : trace.entries) {
        if (e.direction != TraceDirection::Event)
            continue;
        if (next >= seen.size() || seen[next] != e.bytes) {
            error = "trace line " + std::to_string(e.fileLine) + ": the trace shows '" + e.bytes +
                    "', the driver showed " +
                    (next < seen.size() ? "'" + seen[next] + "'" : std::string("nothing more"));
            return false;
        }
        ++next;
    }
    if (next < seen.size()) {
        error = "the driver showed '" + seen[next] + "' after the trace's last event";
        return false;
    }
    return true;
}

// A record on the wall clock was noted from the link worker's snapshots, which merge changes
// that come quickly one after the other (Idle between connecting and a job the front end started
// at once), and goes on after the operation (the front end disconnected): the events it has up
// to its last wire line must come in order among the driver's, and the errors must be the same.
bool recordedEventsShown(const SerialTrace &trace, const std::vector<std::string> &seen,
                         std::string &error)
{
    std::size_t lastWire = 0;
    for (std::size_t i = 0; i < trace.entries.size(); ++i) {
        if (trace.entries[i].direction != TraceDirection::Event)
            lastWire = i;
    }
    std::size_t next = 0;
    std::vector<std::string> recordedErrors, seenErrors;
    for (std::size_t i = 0; i < trace.entries.size(); ++i) {
        const TraceEntry &e = trace.entries[i];
        if (e.direction != TraceDirection::Event)
            continue;
        if (e.bytes.rfind("error ", 0) == 0)
            recordedErrors.push_back(e.bytes);
        if (i > lastWire)
            continue;
        while (next < seen.size() && seen[next] != e.bytes)
            ++next;
        if (next >= seen.size()) {
            error = "trace line " + std::to_string(e.fileLine) + ": the trace shows '" + e.bytes +
                    "', the driver did not show it";
            return false;
        }
        ++next;
    }
    for (const std::string &s : seen) {
        if (s.rfind("error ", 0) == 0)
            seenErrors.push_back(s);
    }
    if (seenErrors != recordedErrors) {
        error = "the driver showed " + std::to_string(seenErrors.size()) + " errors (" +
                (seenErrors.empty() ? std::string() : seenErrors.front()) + "), the trace " +
                std::to_string(recordedErrors.size()) + " (" +
                (recordedErrors.empty() ? std::string() : recordedErrors.front()) + ")";
        return false;
    }
    return true;
}

} // namespace

bool recordTrace(const SerialTrace &recipe, const std::string &dir, SerialTrace &out,
                 std::string &error)
{
    const auto variant = protocol::variantFromId(recipe.value("variant", "gve64"));
    if (!variant) {
        error = "unknown variant '" + recipe.value("variant") + "'";
        return false;
    }
    const machine::MachineConfig config = machine::defaultMachineConfig(*variant);
    WireOptions wire;
    wire.baud = config.link.baud;
    wire.byteErrorRate = std::stod(recipe.value("record-faults", "0"));
    wire.seed = static_cast<std::uint32_t>(std::stoul(recipe.value("record-seed", "1")));
    EmulatorPort emulator(unitOptionsFor(config), wire);
    TraceRecorder recorder;
    recorder.setLimitBytes(1LL << 40);
    recorder.setProgramVersion("Frezka (tests/driver/traces helper)");
    TracingPort port(emulator, recorder);
    recorder.begin({}, port.now());
    const bool ok = driveOperation(
        recipe, dir, port, [&](const std::string &e) { recorder.note(e, port.now()); },
        [] { return false; }, [] { return true; }, error);
    out = recorder.snapshot();
    for (const auto &[k, v] : recipe.header) {
        if (k != "frezka" && k != "started")
            out.set(k, v);
    }
    out.set("clock", "virtual");
    return ok;
}

bool replayTrace(const SerialTrace &trace, const std::string &dir, std::string &error)
{
    // A record made on the virtual clock replays instant for instant: every poll where it was.
    // One made on the wall clock has its polls where the wall clock put them: they are free.
    ReplayPort port(trace, trace.value("clock") != "virtual");
    std::vector<std::string> seen;
    const bool ok = driveOperation(
        trace, dir, port, [&](const std::string &e) { seen.push_back(e); },
        [&] { return bool(port.replay().divergence()); }, [&] { return port.replay().finished(); },
        error);
    const auto &replay = port.replay();
    if (replay.divergence()) {
        error = emulator::englishText(replay.divergence());
        return false;
    }
    const std::string after =
        " (the last unit line given was trace line " + std::to_string(replay.lastReplyLine()) + ")";
    if (!ok) {
        error += after;
        return false;
    }
    if (!(trace.value("clock") == "virtual" ? sameEvents(trace, seen, error)
                                            : recordedEventsShown(trace, seen, error))) {
        error += after;
        return false;
    }
    if (!replay.finished()) {
        error = "the operation ended before the trace did" + after;
        return false;
    }
    return true;
}

} // namespace frezka::driver::tracetest
