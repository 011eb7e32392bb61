#pragma once
// One transfer with an ANC / K51 controller: link check, controller -> PC (save) or
// PC -> controller (load). A non-blocking state machine on a Transport and a Clock; it runs the
// same against a serial port in real time and against the in-process emulator in virtual time.
//
// Sequences (k51-protocol.md §3, adopted readings):
//   ping : ENQ -> ACK
//   save : ENQ -> ACK, request (DEJ / DEJ2 / empty ANC SAV) -> data message, ACK (NAK to repeat)
//   load : ENQ -> ACK, data message (LOA / LOA2 / ANC LOA) -> ACK (NAK: send it again)
// A pause precedes every message the PC sends (K51SAVE 2.21). Timeouts measure silence, not
// whole transfers, so a slow line or a slow controller does not trip them (K51SAVE 2.10's bug):
// the reply timeout after a control message, the first-byte timeout after a request, the gap
// timeout between bytes of a message, the store timeout after the last byte of a data message.
// Every timeout, NAK and bad checksum is retried at most maxRetries times, then reported.
//
// Waits start on the wire, not in the port: a port reports bytes as written when its driver
// takes them, which for a USB adapter can be the whole 21 KB message at once, 22.7 s before
// the last byte has left at 9600 Bd. The session therefore counts bytes x 10 / baud from when
// the port took them (WireModel) plus the adapter's latency before any reply timeout starts,
// and its progress follows that estimate of the wire, not the port's buffer. While the port
// has not taken everything, the timer guards the port instead (a stalled port is reported).

#include "driver/grinder/clock.h"
#include "driver/grinder/family.h"
#include "driver/grinder/framedecoder.h"
#include "driver/grinder/imagecheck.h"
#include "driver/grinder/transport.h"
#include "driver/grinder/wiremodel.h"

#include <QByteArray>
#include <QObject>
#include <QString>

#include <set>

namespace frezka::grinder {

struct SessionTiming
{
    int replyTimeoutMs = 3000;      // ACK to ENQ
    int firstByteTimeoutMs = 10000; // data message after a request or a NAK
    int gapTimeoutMs = 3000;        // silence inside a message
    int storeTimeoutMs = 20000;     // ACK after the last byte of a data message
    int pauseMs = 50;               // before each message the PC sends
    int maxRetries = 3;             // repeats after a timeout, NAK or bad checksum
    int adapterLatencyMs = 20;      // added to the wire time before a reply can be due
    bool operator==(const SessionTiming &) const = default;
};

enum class Operation { Ping, Save, Load };

enum class TransferError {
    None,
    NotOpen,         // the transport is closed
    Busy,            // another operation is running
    InvalidInput,    // the data cannot be sent (empty, too long, wrong size for the family)
    Timeout,         // no (complete) answer in time, after the retries
    Rejected,        // the controller kept answering NAK
    ChecksumFailed,  // the controller's data kept failing the checksum
    UnexpectedReply, // a message that does not belong in the sequence
    Transport,       // the port failed
    Cancelled,
};
// Stable identifier for logs and the CLI ("timeout", "checksum", ...).
const char *transferErrorId(TransferError error);

struct TransferResult
{
    Operation operation = Operation::Ping;
    TransferError error = TransferError::None;
    QString message;   // translated; names the message sent and the reply seen
    Header header{};   // save: as received; load: as sent
    QByteArray data;   // save: the data as received, byte for byte; load: as sent
    ImageReport image; // inner block check of `data` (reported, never changes a byte)
    int retries = 0;   // repeats of any kind
    int naks = 0;      // NAKs received
    int checksumFailures = 0;
    qint64 noiseBytes = 0;
    qint64 elapsedUs = 0;
    qint64 controllerBusyUs = 0; // cancelled: how long the controller goes on sending
    bool ok() const { return error == TransferError::None; }
    bool operator==(const TransferResult &) const = default;
};

// "K51", "ANC", "HEDIT": the system as the operator knows it.
QString familyName(Family family);
// Seconds left from the rate so far, or from the baud rate (8N1) before there is one.
double estimateSecondsLeft(qint64 doneBytes, qint64 totalBytes, qint64 elapsedUs, int baud);

class TransferSession : public QObject
{
    Q_OBJECT
public:
    TransferSession(Transport &transport, Clock &clock, Family family, QObject *parent = nullptr);
    ~TransferSession() override;

    void setTiming(const SessionTiming &timing) { m_timing = timing; }
    const SessionTiming &timing() const { return m_timing; }
    Family family() const { return m_family; }
    void setFamily(Family family);
    bool isBusy() const { return m_state != State::Idle; }
    const TransferResult &lastResult() const { return m_result; }

    // Translated one-line summary of an inner-block check ("20 blocks, all valid", ...).
    static QString describeImage(const ImageReport &report);

    void ping();
    void save();
    // Sends `data` exactly as given; `header` is ignored by the ANC family (no header). The
    // data are checked first (LoadCheck) and refused with InvalidInput before any byte is
    // sent; `sendAnyway` lets through what LoadCheck allows it to.
    void load(const Header &header, const QByteArray &data, bool sendAnyway = false);
    // Stops the operation: what the port has not sent is dropped, and the result's message
    // (`reason`, else "Cancelled.") says what the controller is still doing.
    void cancel(const QString &reason = QString());

signals:
    void progressed(qint64 doneBytes, qint64 totalBytes);
    void finished(const frezka::grinder::TransferResult &result);
    void traced(const QString &line); // "-> ENQ", "<- ACK", "<- noise 6 bytes: 00 13 ..."

private:
    enum class State { Idle, Pausing, Enquiring, Requesting, Sending, AckingSave };

    bool start(Operation operation);
    void onReceived(const QByteArray &bytes);
    void onWritten(qint64 bytes);
    void onTransportFailed(const QString &error);
    void onEvent(const DecodeEvent &event);
    void onFrame(const Frame &frame);
    void onBadChecksum(const DecodeEvent &event);
    void onTimeout();
    void afterAck();
    // Sends `frame` after a pause (the timing's pauseMs unless given), then waits in `next`.
    void sendLater(const Frame &frame, State next, int pauseMs = -1);
    // Repeats the last message (or sends NAK when `askRepeat`), or fails after maxRetries.
    void retryOrFail(TransferError error, const QString &message, bool askRepeat = false);
    // Arms the timer `extraUs + timeoutMs` from now; messages name `timeoutMs`.
    void arm(int timeoutMs, std::int64_t extraUs = 0);
    // Arms the wait for the reply to the message being sent, from the end of the wire.
    void armReplyWait();
    // Emits the progress of the data message on the wire, while it is being sent.
    void tickProgress();
    // Counts what the port has taken (its report or, earlier, its queue) into the wire model.
    void syncAccepted();
    void finish(TransferError error, const QString &message = QString());
    QString frameName(const Frame &frame) const;
    QString sentName() const;
    // " Is it set to ... (KONFIG6 = n)?" for the K51 kinds; empty for the others.
    QString modeHint() const;

    Transport &m_transport;
    Clock &m_clock;
    Family m_family;
    FrameDecoder m_decoder;
    SessionTiming m_timing;
    State m_state = State::Idle;
    Operation m_operation = Operation::Ping;
    TransferResult m_result;
    Frame m_dataFrame;     // load: the message to (re)send
    Frame m_lastSent;      // for messages and retries
    qint64 m_sentSize = 0; // wire size of the data message being sent
    qint64 m_inFlight = 0; // bytes written that the port has not taken yet
    qint64 m_written = 0;  // bytes written since start()
    qint64 m_reported = 0; // bytes the port reported written since start()
    int m_attempt = 0;     // retries in the current step
    int m_timeoutMs = 0;
    int m_waitMs = 0; // the reply wait of the message being sent, from the end of the wire
    WireModel m_wire;
    std::set<qsizetype> m_reportedSizes; // lengths of data the controller sent (saves)
    std::int64_t m_startUs = 0;
    std::int64_t m_requestDeadlineUs = 0; // first-byte deadline of the data after a request
    Clock::TimerId m_timer = 0;
    Clock::TimerId m_pauseTimer = 0;
    Clock::TimerId m_progressTimer = 0;
};

} // namespace frezka::grinder

Q_DECLARE_METATYPE(frezka::grinder::TransferResult)
