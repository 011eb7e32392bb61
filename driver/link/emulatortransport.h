#pragma once
// EmulatorTransport: the in-process emulator in real time (the application's built-in
// simulator). An EmulatorPort (unit + wire model) advanced by a 1 ms timer to the wall clock.

#include "driver/link/emulatorport.h"
#include "driver/link/transport.h"

#include <QElapsedTimer>

#include <memory>

class QTimer;

namespace frezka::driver {

class EmulatorTransport : public Transport
{
    Q_OBJECT

public:
    EmulatorTransport(emulator::UnitOptions unit, WireOptions wire, QObject *parent = nullptr);
    // Several units on the one wire (a shared line; the first one's variant names it).
    EmulatorTransport(std::vector<emulator::UnitOptions> units, WireOptions wire,
                      QObject *parent = nullptr);
    ~EmulatorTransport() override;

    void open() override;
    void close() override;
    void write(const QByteArray &bytes) override;
    bool isOpen() const override { return m_open; }
    QString description() const override;
    void deliverPending() override;

    // The emulated unit (tests drive its inputs: STOP button, probe).
    emulator::Unit &unit() { return m_port->unit(); }
    // Every unit on its wire (unitAt(address)).
    emulator::Simulation &simulation() { return m_port->simulation(); }

private:
    void tick();

    std::unique_ptr<EmulatorPort> m_port;
    QTimer *m_timer = nullptr;
    QElapsedTimer m_clock;
    double m_started = 0; // emulator time when the clock started
    bool m_open = false;
};

} // namespace frezka::driver
