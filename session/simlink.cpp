#include "simlink.h"

namespace frezka::session {

SimLink::SimLink(const machine::MachineConfig &config, const emulator::UnitOptions &unit,
                 const driver::WireOptions &wire, const driver::CoreOptions &options,
                 QObject *parent, driver::TraceRecorder *recorder)
    : MachineLink(parent)
    , m_port(unit, wire)
    , m_tracing(recorder ? std::make_unique<driver::TracingPort>(m_port, *recorder) : nullptr)
    , m_core(config, options)
    , m_runner(m_core, m_tracing ? static_cast<driver::VirtualPort &>(*m_tracing) : m_port)
{
    auto note = [this, recorder](const std::string &event) {
        if (recorder)
            recorder->note(event, m_runner.now());
    };
    m_core.onStateChanged = [this, note, last = driver::MachineMode::Disconnected](
                                const driver::MachineState &s) mutable {
        if (s.mode != last)
            note(driver::traceModeEvent(s.mode));
        last = s.mode;
        m_pending.push_back([this, s] {
            m_state = s;
            emit stateChanged(s);
        });
    };
    m_core.onError = [this, note](const driver::MachineError &e) {
        note(driver::traceErrorEvent(e));
        m_pending.push_back([this, e] { emit errorOccurred(e); });
    };
    m_core.onJobFinished = [this, note](bool ok) {
        note(driver::traceJobEvent(ok));
        m_pending.push_back([this, ok] { emit jobFinished(ok); });
    };
}

SimLink::~SimLink() = default;

void SimLink::deliver()
{
    if (m_delivering)
        return;
    m_delivering = true;
    // Handlers may start operations that queue more events: deliver until none is left.
    while (!m_pending.empty()) {
        auto batch = std::move(m_pending);
        m_pending.clear();
        for (auto &event : batch)
            event();
    }
    m_delivering = false;
}

bool SimLink::runUntil(const std::function<bool()> &done, double limitS)
{
    deliver();
    if (done())
        return true;
    m_runner.runUntil(
        [&] {
            deliver();
            return done();
        },
        limitS);
    deliver();
    return done();
}

void SimLink::runFor(double seconds)
{
    const double end = now() + seconds;
    runUntil([&] { return now() >= end; }, seconds);
}

void SimLink::apply(const driver::MachineCore::Result &result)
{
    if (result)
        m_pending.push_back([this, e = *result] { emit errorOccurred(e); });
    deliver();
}

void SimLink::setMachineConfig(const machine::MachineConfig &config)
{
    m_core.setConfig(config);
}

void SimLink::connectTo(const driver::ConnectionSettings &)
{
    // The wire was chosen with the link; connecting opens it (again, after a disconnect).
    if (m_open)
        m_runner.unplug({}); // closed on purpose
    m_open = true;
    m_runner.open();
    deliver();
}

void SimLink::disconnectFromUnit()
{
    if (!m_open)
        return;
    m_open = false;
    m_runner.unplug({}); // closed on purpose: Disconnected, not LinkLost
    deliver();
}

void SimLink::unplug(const std::string &why)
{
    if (!m_open)
        return;
    m_open = false;
    m_runner.unplug(why);
    deliver();
}

void SimLink::run(const machine::UnitProgram &program)
{
    apply(m_core.run(program, now()));
}

void SimLink::pause()
{
    apply(m_core.pause(now()));
}

void SimLink::resume()
{
    apply(m_core.resume(now()));
}

void SimLink::abort()
{
    apply(m_core.abort(now()));
}

void SimLink::execute(const driver::MachineCommand &command)
{
    apply(m_core.execute(command, now()));
}

void SimLink::toolLift(bool stopSpindle)
{
    apply(m_core.toolLift(stopSpindle, now()));
}

void SimLink::toolLower(int speedPulsesPerS)
{
    apply(m_core.toolLower(speedPulsesPerS, now()));
}

void SimLink::home(unsigned axisMask)
{
    apply(m_core.home(now(), axisMask));
}

void SimLink::setSpindleRpm(double rpm)
{
    apply(m_core.setSpindleRpm(rpm, now()));
}

void SimLink::sendRaw(const QString &text)
{
    apply(m_core.sendRaw(text.toStdString(), now()));
}

} // namespace frezka::session
