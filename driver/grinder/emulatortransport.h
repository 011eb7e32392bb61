#pragma once
// The controller emulator behind the Transport interface, paced on a Clock: every byte takes
// 10 bits / baud on the wire in each direction (8N1), so a K51 image (0x5507 bytes + frame) at
// 9600 Bd takes about 22.7 s — of virtual time under a VirtualClock.
//
// Like a serial port, write() hands bytes to an "OS buffer" of osBufferBytes: written() reports
// them when that buffer takes them, not when they have left the wire; the buffer drains at the
// baud rate into the controller. A large buffer takes a whole message at once (as a USB adapter
// does), so the session must time its waits from the wire, not from written().

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
    void discardOutput() override;
    qint64 pendingOutput() const override { return qint64(m_appQueue.size()); }
    int baud() const override { return m_baud; }
    QString name() const override { return tr("emulator"); }

    ControllerEmulator &emulator() { return m_emulator; }
    // Microseconds one byte takes on the wire.
    std::int64_t byteUs() const { return m_byteUs; }
    // Size of the port driver's buffer (default 4096 bytes, a tty's).
    void setOsBufferBytes(qint64 bytes) { m_osBufferBytes = std::max<qint64>(1, bytes); }
    // The controller's own line speed (0: the same as the PC's). When it differs, every byte
    // arrives garbled both ways, as on a real line with a baud rate mismatch (resampleUart).
    void setControllerBaud(int baud) { m_controllerBaud = baud; }
    // Fault for tests: the wire stops both ways (an adapter unplugged); the port keeps its bytes.
    void setWireStopped(bool stopped) { m_wireStopped = stopped; }
    // Bytes that have reached the controller over the wire since open().
    qint64 deliveredToController() const { return m_delivered; }

signals:
    void emulatorLogged(const QString &line);

private:
    void schedulePump();
    void pump();
    // Moves what fits from the application's queue into the OS buffer; returns the bytes moved.
    qint64 takeIntoOsBuffer();

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
    qint64 m_osBufferBytes = 4096;
    qint64 m_delivered = 0;
    bool m_wireStopped = false;
    int m_controllerBaud = 0;
    Clock::TimerId m_acceptTimer = 0;
    std::deque<std::uint8_t> m_appQueue;     // written, not yet taken by the OS buffer
    std::deque<std::uint8_t> m_toController; // the OS buffer: taken, not yet on the wire
    std::deque<std::uint8_t> m_toPc;
};

} // namespace frezka::grinder
