#include "commissionmoves.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QTimer>

#include <cmath>
#include <functional>

namespace frezka::session {

namespace {

// lupdate files the tr() calls of this namespace under its name: the same context here.
QString tr(const char *text)
{
    return QCoreApplication::translate("frezka::session", text);
}

QChar letter(int axis)
{
    return QChar::fromLatin1(machine::kAxisLetters[static_cast<std::size_t>(axis)]);
}

// The driver in this thread, with the last state and error it reported.
struct Driver
{
    driver::LinkWorker worker;
    driver::MachineState state;
    std::optional<driver::MachineError> error;

    Driver()
    {
        QObject::connect(&worker, &driver::LinkWorker::stateChanged, &worker,
                         [this](const driver::MachineState &s) { state = s; });
        QObject::connect(&worker, &driver::LinkWorker::errorOccurred, &worker,
                         [this](const driver::MachineError &e) { error = e; });
    }
    // Runs the event loop until `done` holds (checked on each state) or timeoutS passed.
    bool waitFor(const std::function<bool()> &done, double timeoutS)
    {
        if (done())
            return true;
        QEventLoop loop;
        QTimer deadline;
        deadline.setSingleShot(true);
        QObject::connect(&deadline, &QTimer::timeout, &loop, &QEventLoop::quit);
        QObject::connect(&worker, &driver::LinkWorker::stateChanged, &loop, [&] {
            if (done())
                loop.quit();
        });
        deadline.start(static_cast<int>(timeoutS * 1000));
        loop.exec();
        return done();
    }
    bool idle() const { return state.mode == driver::MachineMode::Idle; }
    // Waits for an operation to start and end: Idle again after it left Idle (or at once
    // when it ended between two snapshots).
    bool waitDone(double timeoutS)
    {
        waitFor([this] { return !idle(); }, 1.0);
        const bool done =
            waitFor([this] { return idle() || state.mode == driver::MachineMode::Alarm; },
                    timeoutS) &&
            idle();
        settle();
        return done;
    }
    // Lets the idle polls bring the counters where the machine stopped.
    void settle()
    {
        waitFor([] { return false; }, 0.5);
    }
};

void moveAxis(Driver &d, int axis, CommissionResult &r, CommissionOperator &op, double moveMm)
{
    const auto &cfg = r.profileBefore.axes[static_cast<std::size_t>(axis)];
    AxisResult a;
    a.axis = axis;
    a.movedMm = moveMm;
    a.stepsPerMmBefore = cfg.stepsPerMm;
    const double speed = std::min(300.0, cfg.maxSpeedMmPerMin / 10.0);
    const auto before = d.state.positionSteps[static_cast<std::size_t>(axis)];
    d.worker.jogStep(axis, moveMm, speed);
    const bool plusDone = d.waitDone(60.0 + moveMm / speed * 60.0 * 2);
    const auto moved = d.state.positionSteps[static_cast<std::size_t>(axis)] - before;
    a.details = tr("+ move: %1 steps counted").arg(moved);
    if (!plusDone || moved == 0) {
        a.plus = StepResult::DidNotHold;
        a.details += QLatin1Char(' ') + tr("(the axis did not move: at its soft limit, or the "
                                           "driver refused it)");
    } else {
        a.plus = op.ask(tr("Did axis %1 move in + (by about %2 mm)?").arg(letter(axis)).arg(moveMm))
                     ? StepResult::Held
                     : StepResult::DidNotHold;
        a.measuredMm = op.askNumber(
            tr("How far did axis %1 move, measured in mm? (empty: as asked)").arg(letter(axis)));
        if (a.measuredMm && *a.measuredMm > 0) {
            a.stepsPerMmProposed = static_cast<double>(std::llabs(moved)) / *a.measuredMm;
            r.profileAfter.axes[static_cast<std::size_t>(axis)].stepsPerMm = *a.stepsPerMmProposed;
        }
    }
    const auto mid = d.state.positionSteps[static_cast<std::size_t>(axis)];
    d.worker.jogStep(axis, -moveMm, speed);
    const bool minusDone = d.waitDone(60.0 + moveMm / speed * 60.0 * 2);
    const auto back = d.state.positionSteps[static_cast<std::size_t>(axis)] - mid;
    a.details += QStringLiteral("; ") + tr("− move: %1 steps counted").arg(back);
    a.minus = minusDone && back != 0 && op.ask(tr("Did axis %1 move back in −?").arg(letter(axis)))
                  ? StepResult::Held
                  : StepResult::DidNotHold;
    CommissionStep &step = *r.step(
        "axis-" + std::string(1, static_cast<char>(std::tolower(
                                     machine::kAxisLetters[static_cast<std::size_t>(axis)]))));
    step.result = a.plus == StepResult::Held && a.minus == StepResult::Held
                      ? StepResult::Held
                      : StepResult::DidNotHold;
    step.details = a.details;
    if (a.stepsPerMmProposed)
        step.details += QStringLiteral("; ") + tr("steps per mm %1 -> %2")
                                                   .arg(cfg.stepsPerMm, 0, 'f', 4)
                                                   .arg(*a.stepsPerMmProposed, 0, 'f', 4);
    r.axes.push_back(std::move(a));
}

// Whether input `in` (0..7 on I1, 14/15 on I2) changes within timeoutS.
bool watchInput(Driver &d, int in, double timeoutS)
{
    auto level = [&d, in] {
        return in < 8 ? (d.state.inputs1 >> in) & 1 : (d.state.inputs2 >> (in - 8)) & 1;
    };
    const int start = level();
    return d.waitFor([&] { return level() != start || d.state.interruptInputs & (1u << in); },
                     timeoutS);
}

void testSwitches(Driver &d, CommissionResult &r, CommissionOperator &op, double watchS)
{
    CommissionStep &step = *r.step("switches");
    QStringList seen;
    bool all = true;
    for (int a = 0; a < machine::kAxisCount; ++a) {
        const auto &cfg = r.profileBefore.axes[static_cast<std::size_t>(a)];
        if (!cfg.present || cfg.homing.order == 0)
            continue;
        op.instruct(tr("Press the home switch of %1 (IN%2) now.").arg(letter(a)).arg(a));
        const bool ok = watchInput(d, a, watchS);
        all = all && ok;
        seen << tr("home %1 (IN%2): %3")
                    .arg(letter(a))
                    .arg(a)
                    .arg(stepResultText(ok ? StepResult::Held : StepResult::DidNotHold));
        d.waitFor([] { return false; }, 0.3); // let go of it before the next
    }
    step.result =
        seen.isEmpty() ? StepResult::NotChecked : (all ? StepResult::Held : StepResult::DidNotHold);
    step.details =
        seen.isEmpty() ? tr("the profile homes no axis") : seen.join(QStringLiteral("; "));
}

void testStop(Driver &d, CommissionResult &r, CommissionOperator &op, double watchS)
{
    CommissionStep &step = *r.step("stop");
    op.instruct(tr("Press the STOP button (IN7) now."));
    const bool ok = watchInput(d, 7, watchS);
    step.result = ok ? StepResult::Held : StepResult::DidNotHold;
    step.details = ok ? tr("IN7 changed when the button was pressed")
                      : tr("IN7 did not change within %1 s: check the button's wiring").arg(watchS);
}

void testSpindle(Driver &d, CommissionResult &r, CommissionOperator &op)
{
    CommissionStep &step = *r.step("spindle");
    const double maxRpm = r.profileBefore.spindle.maxRpm;
    const double spinUpS = r.profileBefore.spindle.spinUpMs / 1000.0;
    QStringList seen;
    bool all = true;
    for (double fraction : {0.25, 0.5}) {
        d.worker.setSpindleRpm(maxRpm * fraction);
        d.waitFor([&] { return d.state.spindleOn; }, 5.0);
        d.waitFor([] { return false; }, spinUpS);
        const bool on = d.state.spindleOn;
        const bool turned =
            on && op.ask(tr("Does the spindle turn at about %1 rpm?").arg(maxRpm * fraction));
        all = all && turned;
        seen << tr("%1 rpm (%2 ‰): %3")
                    .arg(maxRpm * fraction)
                    .arg(d.state.spindlePermille)
                    .arg(stepResultText(turned ? StepResult::Held : StepResult::DidNotHold));
    }
    d.worker.setSpindleRpm(0);
    d.waitFor([&] { return !d.state.spindleOn; }, 5.0);
    step.result = all ? StepResult::Held : StepResult::DidNotHold;
    step.details = seen.join(QStringLiteral("; "));
}

void testOutputs(Driver &d, CommissionResult &r, CommissionOperator &op)
{
    CommissionStep &step = *r.step("outputs");
    QStringList seen;
    bool all = true;
    using F = machine::OutputFunction;
    for (F f : {F::Coolant, F::AirBlow, F::Laser, F::CoverLock, F::ToolRelease, F::ToolCoverOpen}) {
        const int n = machine::outputNumber(r.profileBefore, f);
        if (n < 0)
            continue;
        const std::uint8_t bit = machine::outputPortBit(r.profileBefore.unit.variant, n);
        d.worker.setOutput(n, true);
        const bool on = d.waitFor([&] { return (d.state.outputs & bit) == 0; }, 5.0);
        const bool confirmed = on && op.ask(tr("Did OUT%1 switch on?").arg(n));
        d.worker.setOutput(n, false);
        d.waitFor([&] { return (d.state.outputs & bit) != 0; }, 5.0);
        all = all && confirmed;
        seen << tr("OUT%1: %2")
                    .arg(n)
                    .arg(stepResultText(confirmed ? StepResult::Held : StepResult::DidNotHold));
    }
    step.result =
        seen.isEmpty() ? StepResult::NotChecked : (all ? StepResult::Held : StepResult::DidNotHold);
    step.details =
        seen.isEmpty() ? tr("the profile uses no output") : seen.join(QStringLiteral("; "));
}

void home(Driver &d, CommissionResult &r, double timeoutS)
{
    CommissionStep &step = *r.step("homing");
    d.error.reset();
    d.worker.home(0xF);
    d.waitDone(timeoutS);
    step.result = d.state.homed ? StepResult::Held : StepResult::DidNotHold;
    step.details = d.state.homed ? tr("every axis the profile homes was homed")
                                 : tr("homing did not finish: %1")
                                       .arg(d.error ? QString::fromStdString(d.error->message)
                                                    : tr("no error reported"));
}

} // namespace

void runOperatorSteps(const QString &port, int baud, CommissionResult &result,
                      CommissionOperator &op, const MoveOptions &options)
{
    Driver d;
    if (options.factory)
        d.worker.setTransportFactory(options.factory);
    d.worker.setMachineConfig(result.profileBefore);
    driver::ConnectionSettings settings;
    settings.kind = driver::ConnectionSettings::Kind::SerialPort;
    settings.portName = port;
    settings.baud = baud;
    d.worker.connectTo(settings);
    if (!d.waitFor([&] { return d.idle(); }, 30.0)) {
        skipOperatorSteps(
            result, tr("the driver could not connect: %1")
                        .arg(d.error ? QString::fromStdString(d.error->message) : tr("no reply")));
        d.worker.disconnectFromUnit();
        return;
    }
    for (auto &step : result.steps) {
        if (!step.needsOperator || step.result != StepResult::NotChecked)
            continue;
        if (!op.confirm(step)) {
            step.result = StepResult::Skipped;
            step.details = tr("skipped by the operator");
            continue;
        }
        if (step.id.rfind("axis-", 0) == 0)
            moveAxis(d, static_cast<int>(std::string("xyza").find(step.id.back())), result, op,
                     options.axisMoveMm);
        else if (step.id == "switches")
            testSwitches(d, result, op, options.watchSwitchS);
        else if (step.id == "stop")
            testStop(d, result, op, options.watchSwitchS);
        else if (step.id == "spindle")
            testSpindle(d, result, op);
        else if (step.id == "outputs")
            testOutputs(d, result, op);
        else if (step.id == "homing")
            home(d, result, options.homingTimeoutS);
    }
    d.worker.disconnectFromUnit();
}

} // namespace frezka::session
