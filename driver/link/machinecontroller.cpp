#include "machinecontroller.h"

#include "driver/emulator/unit.h"
#include "driver/link/linkworker.h"

#include <QThread>

#include <algorithm>

namespace frezka::driver {

MachineController::MachineController(QObject *parent)
    : QObject(parent)
{
    qRegisterMetaType<MachineState>();
    qRegisterMetaType<MachineError>();
    qRegisterMetaType<ConnectionSettings>();
    qRegisterMetaType<machine::UnitProgram>();
    qRegisterMetaType<machine::MachineConfig>();
    m_thread = new QThread(this);
    m_thread->setObjectName(QStringLiteral("frezka-link"));
    m_worker = new LinkWorker;
    m_worker->moveToThread(m_thread);
    connect(m_thread, &QThread::finished, m_worker, &QObject::deleteLater);
    connect(m_worker, &LinkWorker::stateChanged, this, &MachineController::onState);
    connect(m_worker, &LinkWorker::logLine, this, &MachineController::logLine);
    connect(m_worker, &LinkWorker::errorOccurred, this, &MachineController::errorOccurred);
    connect(m_worker, &LinkWorker::jobFinished, this, &MachineController::jobFinished);
    connect(m_worker, &LinkWorker::unitStateChanged, this, &MachineController::onUnitState);
    connect(m_worker, &LinkWorker::unitErrorOccurred, this, &MachineController::unitErrorOccurred);
    connect(m_worker, &LinkWorker::machineUnitChanged, this,
            &MachineController::machineUnitChanged);
    m_thread->start();
}

MachineController::~MachineController()
{
    QMetaObject::invokeMethod(m_worker, &LinkWorker::disconnectFromUnit,
                              Qt::BlockingQueuedConnection);
    m_thread->quit();
    m_thread->wait();
}

void MachineController::onState(const MachineState &state)
{
    m_state = state;
    emit stateChanged(state);
}

void MachineController::onUnitState(int unit, const MachineState &state)
{
    if (unit < 0)
        return;
    if (std::size_t(unit) >= m_unitStates.size())
        m_unitStates.resize(std::size_t(unit) + 1);
    m_unitStates[std::size_t(unit)] = state;
    emit unitStateChanged(unit, state);
}

void MachineController::setLineUnits(const std::vector<machine::MachineConfig> &configs,
                                     int machineIndex)
{
    m_unitStates.assign(std::max<std::size_t>(1, configs.size()), MachineState{});
    QMetaObject::invokeMethod(m_worker, [w = m_worker, configs, machineIndex] {
        w->setLineUnits(configs, machineIndex);
    });
}

void MachineController::chooseMachineUnit(int unit)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, unit] { w->chooseMachineUnit(unit); });
}

void MachineController::executeOn(int unit, MachineCommand command)
{
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, unit, c = std::move(command)] { w->executeOn(unit, c); });
}

void MachineController::setMachineConfig(const machine::MachineConfig &config)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, config] { w->setMachineConfig(config); });
}
void MachineController::connectTo(const ConnectionSettings &settings)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, settings] { w->connectTo(settings); });
}
void MachineController::disconnectFromUnit()
{
    QMetaObject::invokeMethod(m_worker, &LinkWorker::disconnectFromUnit);
}
void MachineController::execute(MachineCommand command)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, c = std::move(command)] { w->execute(c); });
}
void MachineController::run(const machine::UnitProgram &program)
{
    execute(op::Run{program});
}
void MachineController::pause()
{
    execute(op::Pause{});
}
void MachineController::resume()
{
    execute(op::Resume{});
}
void MachineController::abort()
{
    execute(op::Abort{});
}
void MachineController::toolLift(bool stopSpindle)
{
    execute(op::ToolLift{stopSpindle});
}
void MachineController::toolLower(int speedPulsesPerS)
{
    execute(op::ToolLower{speedPulsesPerS});
}
void MachineController::home(unsigned axisMask)
{
    execute(op::Home{axisMask});
}
void MachineController::jogStep(int axis, double distanceMm, double speedMmPerMin)
{
    execute(op::JogStep{axis, distanceMm, speedMmPerMin});
}
void MachineController::jogContinuous(int axis, int direction, double speedMmPerMin)
{
    execute(op::JogContinuous{axis, direction, speedMmPerMin});
}
void MachineController::jogStop()
{
    execute(op::JogStop{});
}
void MachineController::setMpg(bool on)
{
    execute(op::SetMpg{on});
}
void MachineController::turnEmulatedWheel(int axis, int multiplier, int detents)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, axis, multiplier, detents] {
        w->turnEmulatedWheel(axis, multiplier, detents);
    });
}
std::optional<emulator::Stats> MachineController::builtInEmulatorStats() const
{
    std::optional<emulator::Stats> stats;
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, &stats] { stats = w->builtInEmulatorStats(); },
        Qt::BlockingQueuedConnection);
    return stats;
}
void MachineController::setSpindleRpm(double rpm)
{
    execute(op::SetSpindleRpm{rpm});
}
void MachineController::setOutput(int output, bool on)
{
    execute(op::SetOutput{output, on});
}
void MachineController::setOverride(int percent)
{
    execute(op::SetOverride{percent});
}
void MachineController::overrideUp()
{
    execute(op::OverrideStep{true});
}
void MachineController::overrideDown()
{
    execute(op::OverrideStep{false});
}
void MachineController::writeEeprom()
{
    execute(op::WriteEeprom{});
}
void MachineController::sendRaw(const QString &text)
{
    execute(op::SendRaw{text.toStdString()});
}

} // namespace frezka::driver
