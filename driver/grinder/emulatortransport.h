#pragma once
// The controller emulator behind the Transport interface, paced on a Clock: every byte takes
// 10 bits / baud on the wire in each direction (8N1), so a K51 image (0x5507 bytes + frame) at
// 9600 Bd takes about 22.7 s — of virtual time under a VirtualClock.

#include "driver/grinder/clock.h"
#include "driver/grinder/controlleremulator.h"
#include "driver/grinder/transport.h"

#include <deque>

namespace frezka::grinder {

class EmulatorTransport : public Transport
{
    Q_OBJECT
public:
    // `clock` must outlive the transport. `tickUs` is the pump period (0: one byte time).
    EmulatorTransport(Clock &clock, EmulatorConfig config, int baud, std::int64_t tickUs = 0,
                      QObject *parent = nullptr);
    ~EmulatorTransport() override;
    bool open(QString *error) override;
    void close() override;
    bool isOpen() const override { return m_open; }
    void write(const QByteArray &bytes) override;
    int baud() const override { return m_baud; }
    QString name() const override { return tr("emulator"); }

    ControllerEmulator &emulator() { return m_emulator; }
    // Microseconds one byte takes on the wire.
    std::int64_t byteUs() const { return m_byteUs; }

signals:
    void emulatorLogged(const QString &line);

private:
    void schedulePump();
    void pump();

    Clock &m_clock;
    ControllerEmulator m_emulator;
    int m_baud;
    std::int64_t m_byteUs;
    std::int64_t m_tickUs;
    bool m_open = false;
    Clock::TimerId m_timer = 0;
    std::int64_t m_lastUs = 0;
    std::int64_t m_txCreditUs = 0; // wire time available PC -> controller
    std::int64_t m_rxCreditUs = 0; // wire time available controller -> PC
    std::deque<std::uint8_t> m_toController;
    std::deque<std::uint8_t> m_toPc;
};

} // namespace frezka::grinder
