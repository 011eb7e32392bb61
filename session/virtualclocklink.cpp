#include "virtualclocklink.h"

#include "driver/link/emulatedunit.h"

#include <QTimer>

#include <algorithm>

namespace frezka::session {
namespace {

using driver::MachineMode;

// The most virtual time one slice may cover while the machine moves: a bound only for a far
// end that would wait forever (nothing moves, no deadline), never reached by a job.
constexpr double kFastSliceLimitS = 60.0;
// While waiting, the clock follows the wall clock, a slice at most this far (a stalled loop,
// a debugger) so that a wait is not skipped over.
constexpr double kWaitSliceLimitS = 0.1;
constexpr int kWaitIntervalMs = 10;
// The screen's refresh while the machine moves: 20 Hz, as the real-time link polls.
constexpr int kShowIntervalMs = 50;

} // namespace

VirtualClockLink::VirtualClockLink(QObject *parent, int sliceMs)
    : MachineLink(parent)
    , m_timer(new QTimer(this))
    , m_sliceMs(sliceMs)
{
    connect(m_timer, &QTimer::timeout, this, &VirtualClockLink::slice);
}

VirtualClockLink::~VirtualClockLink() = default;

const driver::MachineState &VirtualClockLink::state() const
{
    return m_sim ? m_sim->state() : m_none;
}

std::optional<double> VirtualClockLink::clockS() const
{
    return m_sim ? std::optional<double>(m_sim->now()) : std::nullopt;
}

bool VirtualClockLink::moving() const
{
    const driver::MachineState &s = m_sim->liveState();
    switch (s.mode) {
    case MachineMode::Disconnected:
    case MachineMode::LinkLost:
    case MachineMode::Idle:
    case MachineMode::Paused:
    case MachineMode::ToolLifted:
        return false;
    default:
        return true;
    }
}

void VirtualClockLink::slice()
{
    if (!m_sim)
        return;
    QElapsedTimer wall;
    wall.start();
    if (moving()) {
        // As fast as the computer allows, until the slice's wall time is spent or the machine
        // comes to wait.
        m_sim->runUntil([&] { return wall.elapsed() >= m_sliceMs || !moving(); }, kFastSliceLimitS);
    } else {
        const double waitedS = std::min(double(m_wall.nsecsElapsed()) * 1e-9, kWaitSliceLimitS);
        m_sim->runUntil([&] { return moving(); }, waitedS);
    }
    m_wall.restart();
    m_longestSliceMs = std::max(m_longestSliceMs, wall.elapsed());
    // The screen at most at the real-time link's poll rate while the machine moves (a frame of
    // a big toolpath costs more than a slice), and at once when it comes to wait.
    if (m_changed && (!m_shown.isValid() || m_shown.elapsed() >= kShowIntervalMs || !moving())) {
        m_changed = false;
        m_shown.start();
        emit sliceEnded(m_sim->state());
    }
    schedule();
}

void VirtualClockLink::schedule()
{
    // Another slice at once while the machine moves; at the wait's pace otherwise.
    m_timer->start(m_sim && moving() ? 0 : kWaitIntervalMs);
}

void VirtualClockLink::setMachineConfig(const machine::MachineConfig &config)
{
    m_config = config;
    if (m_sim)
        m_sim->setMachineConfig(config);
}

void VirtualClockLink::connectTo(const driver::ConnectionSettings &settings)
{
    // Only the built-in emulator: this link has no port to open (the window refuses a port
    // with its own message before it gets here).
    if (settings.kind != driver::ConnectionSettings::Kind::Emulator)
        return;
    driver::WireOptions wire = driver::wireFor(settings);
    if (wire.baud <= 0)
        wire.baud = m_config.link.baud;
    driver::CoreOptions options;
    options.link.baud = wire.baud;
    const emulator::UnitOptions unit = driver::emulatedUnitFor(settings, m_config);
    // A fresh unit at each connect, as the real-time emulator's; the old one's pending events
    // go with it.
    m_sim = std::make_unique<SimLink>(m_config, unit, wire, options);
    connect(m_sim.get(), &MachineLink::stateChanged, this, [this](const driver::MachineState &s) {
        m_changed = true;
        emit stateChanged(s);
    });
    connect(m_sim.get(), &MachineLink::errorOccurred, this,
            [this](const driver::MachineError &e) { emit errorOccurred(e); });
    connect(m_sim.get(), &MachineLink::jobFinished, this,
            [this](bool ok) { emit jobFinished(ok); });
    m_wall.start();
    m_sim->connectTo(settings);
    schedule();
}

void VirtualClockLink::disconnectFromUnit()
{
    forward([](SimLink &s) { s.disconnectFromUnit(); });
}

// The operations go to the emulator's core at the virtual clock's now; the next slice turns the
// clock on from there (at once when the operation set the machine moving).
template<class Call>
void VirtualClockLink::forward(Call call)
{
    if (!m_sim)
        return;
    call(*m_sim);
    schedule();
}

void VirtualClockLink::run(const machine::UnitProgram &program)
{
    forward([&](SimLink &s) { s.run(program); });
}

void VirtualClockLink::pause()
{
    forward([](SimLink &s) { s.pause(); });
}

void VirtualClockLink::resume()
{
    forward([](SimLink &s) { s.resume(); });
}

void VirtualClockLink::abort()
{
    forward([](SimLink &s) { s.abort(); });
}

void VirtualClockLink::toolLift(bool stopSpindle)
{
    forward([&](SimLink &s) { s.toolLift(stopSpindle); });
}

void VirtualClockLink::toolLower(int speedPulsesPerS)
{
    forward([&](SimLink &s) { s.toolLower(speedPulsesPerS); });
}

void VirtualClockLink::home(unsigned axisMask)
{
    forward([&](SimLink &s) { s.home(axisMask); });
}

void VirtualClockLink::setSpindleRpm(double rpm)
{
    forward([&](SimLink &s) { s.setSpindleRpm(rpm); });
}

void VirtualClockLink::sendRaw(const QString &text)
{
    forward([&](SimLink &s) { s.sendRaw(text); });
}

void VirtualClockLink::execute(const driver::MachineCommand &command)
{
    forward([&](SimLink &s) { s.execute(command); });
}

} // namespace frezka::session
