#include "machinecontroller.h"

#include "driver/link/linkworker.h"

#include <QThread>

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
void MachineController::run(const machine::UnitProgram &program)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, program] { w->run(program); });
}
void MachineController::pause()
{
    QMetaObject::invokeMethod(m_worker, &LinkWorker::pause);
}
void MachineController::resume()
{
    QMetaObject::invokeMethod(m_worker, &LinkWorker::resume);
}
void MachineController::abort()
{
    QMetaObject::invokeMethod(m_worker, &LinkWorker::abort);
}
void MachineController::toolLift(bool stopSpindle)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, stopSpindle] { w->toolLift(stopSpindle); });
}
void MachineController::toolLower(int speedPulsesPerS)
{
    QMetaObject::invokeMethod(m_worker,
                              [w = m_worker, speedPulsesPerS] { w->toolLower(speedPulsesPerS); });
}
void MachineController::home(unsigned axisMask)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, axisMask] { w->home(axisMask); });
}
void MachineController::jogStep(int axis, double distanceMm, double speedMmPerMin)
{
    QMetaObject::invokeMethod(m_worker,
                              [=, w = m_worker] { w->jogStep(axis, distanceMm, speedMmPerMin); });
}
void MachineController::jogContinuous(int axis, int direction, double speedMmPerMin)
{
    QMetaObject::invokeMethod(
        m_worker, [=, w = m_worker] { w->jogContinuous(axis, direction, speedMmPerMin); });
}
void MachineController::jogStop()
{
    QMetaObject::invokeMethod(m_worker, &LinkWorker::jogStop);
}
void MachineController::setMpg(bool on)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, on] { w->setMpg(on); });
}
void MachineController::setSpindleRpm(double rpm)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, rpm] { w->setSpindleRpm(rpm); });
}
void MachineController::setOutputs(quint8 mask, quint8 activeHigh)
{
    QMetaObject::invokeMethod(
        m_worker, [w = m_worker, mask, activeHigh] { w->setOutputs(mask, activeHigh); });
}
void MachineController::setOverride(int percent)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, percent] { w->setOverride(percent); });
}
void MachineController::overrideUp()
{
    QMetaObject::invokeMethod(m_worker, &LinkWorker::overrideUp);
}
void MachineController::overrideDown()
{
    QMetaObject::invokeMethod(m_worker, &LinkWorker::overrideDown);
}
void MachineController::writeEeprom()
{
    QMetaObject::invokeMethod(m_worker, &LinkWorker::writeEeprom);
}
void MachineController::sendRaw(const QString &text)
{
    QMetaObject::invokeMethod(m_worker, [w = m_worker, text] { w->sendRaw(text); });
}

} // namespace frezka::driver
