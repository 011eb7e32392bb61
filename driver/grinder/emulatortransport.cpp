#include "driver/grinder/emulatortransport.h"

#include "driver/grinder/wiremodel.h"

namespace frezka::grinder {

EmulatorTransport::EmulatorTransport(Clock &clock, EmulatorConfig config, int baud,
                                     std::int64_t tickUs, QObject *parent)
    : Transport(parent)
    , m_clock(clock)
    , m_emulator(std::move(config))
    , m_baud(baud > 0 ? baud : 9600)
    , m_byteUs(10'000'000 / m_baud)
    , m_tickUs(tickUs > 0 ? tickUs : m_byteUs)
{}

EmulatorTransport::~EmulatorTransport()
{
    close();
}

bool EmulatorTransport::open(QString *)
{
    m_open = true;
    m_lastUs = m_clock.nowUs();
    schedulePump();
    return true;
}

void EmulatorTransport::close()
{
    if (m_timer)
        m_clock.cancel(m_timer);
    if (m_acceptTimer)
        m_clock.cancel(m_acceptTimer);
    m_timer = m_acceptTimer = 0;
    m_open = false;
    m_appQueue.clear();
    m_toController.clear();
    m_toPc.clear();
}

void EmulatorTransport::write(const QByteArray &bytes)
{
    if (!m_open) {
        emit failed(tr("The emulator is not open"));
        return;
    }
    m_appQueue.insert(m_appQueue.end(), bytes.begin(), bytes.end());
    if (m_acceptTimer)
        return;
    // Reported from the event loop, as QSerialPort's bytesWritten is.
    m_acceptTimer = m_clock.callAfter(0, [this] {
        m_acceptTimer = 0;
        const qint64 taken = takeIntoOsBuffer();
        schedulePump();
        if (taken > 0)
            emit written(taken);
    });
}

void EmulatorTransport::discardOutput()
{
    m_appQueue.clear();
    m_toController.clear();
}

qint64 EmulatorTransport::takeIntoOsBuffer()
{
    const qint64 space = m_osBufferBytes - qint64(m_toController.size());
    const qint64 n = std::min<qint64>(std::max<qint64>(0, space), qint64(m_appQueue.size()));
    m_toController.insert(m_toController.end(), m_appQueue.begin(), m_appQueue.begin() + n);
    m_appQueue.erase(m_appQueue.begin(), m_appQueue.begin() + n);
    return n;
}

void EmulatorTransport::schedulePump()
{
    if (m_timer || !m_open)
        return;
    m_timer = m_clock.callAfter(m_tickUs, [this] {
        m_timer = 0;
        pump();
    });
}

// Moves as many bytes each way as the wire time since the last pump allows.
void EmulatorTransport::pump()
{
    const std::int64_t now = m_clock.nowUs();
    const std::int64_t dt = now - m_lastUs;
    m_lastUs = now;
    if (m_wireStopped) {
        m_txCreditUs = m_rxCreditUs = 0;
        m_emulator.advance(dt);
        schedulePump();
        return;
    }

    m_txCreditUs = m_toController.empty() ? 0 : m_txCreditUs + dt;
    QByteArray sent;
    while (!m_toController.empty() && m_txCreditUs >= m_byteUs) {
        m_txCreditUs -= m_byteUs;
        sent.append(static_cast<char>(m_toController.front()));
        m_toController.pop_front();
    }
    m_delivered += sent.size();
    const qint64 taken = takeIntoOsBuffer();
    m_emulator.advance(dt);
    // A mismatch garbles each chunk as sent back to back; chunks are one pump tick apart.
    const int controllerBaud = m_controllerBaud > 0 ? m_controllerBaud : m_baud;
    if (!sent.isEmpty())
        m_emulator.feed(resampleUart(Bytes(sent.begin(), sent.end()), m_baud, controllerBaud));
    const Bytes out = resampleUart(m_emulator.takeOutput(), controllerBaud, m_baud);
    m_toPc.insert(m_toPc.end(), out.begin(), out.end());
    for (const std::string &line : m_emulator.takeLog())
        emit emulatorLogged(QString::fromStdString(line));

    m_rxCreditUs = m_toPc.empty() ? 0 : m_rxCreditUs + dt;
    QByteArray arrived;
    while (!m_toPc.empty() && m_rxCreditUs >= m_byteUs) {
        m_rxCreditUs -= m_byteUs;
        arrived.append(static_cast<char>(m_toPc.front()));
        m_toPc.pop_front();
    }
    if (!m_toPc.empty() || !m_toController.empty() || m_emulator.hasPendingWork())
        schedulePump();
    if (taken > 0)
        emit written(taken);
    if (!arrived.isEmpty())
        emit received(arrived);
}

} // namespace frezka::grinder
