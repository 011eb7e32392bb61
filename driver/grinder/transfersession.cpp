#include "driver/grinder/transfersession.h"

#include "driver/grinder/loadcheck.h"

namespace frezka::grinder {

TransferSession::TransferSession(Transport &transport, Clock &clock, Family family, QObject *parent)
    : QObject(parent)
    , m_transport(transport)
    , m_clock(clock)
    , m_family(family)
    , m_decoder(familyInfo(family).framing)
{
    qRegisterMetaType<frezka::grinder::TransferResult>();
    connect(&m_transport, &Transport::received, this, &TransferSession::onReceived);
    connect(&m_transport, &Transport::written, this, &TransferSession::onWritten);
    connect(&m_transport, &Transport::failed, this, &TransferSession::onTransportFailed);
}

TransferSession::~TransferSession()
{
    m_clock.cancel(m_timer);
    m_clock.cancel(m_pauseTimer);
    m_clock.cancel(m_progressTimer);
}

void TransferSession::setFamily(Family family)
{
    if (isBusy())
        return;
    m_family = family;
    m_decoder = FrameDecoder(familyInfo(family).framing);
}

bool TransferSession::start(Operation operation)
{
    if (isBusy())
        return false;
    m_operation = operation;
    m_result = TransferResult();
    m_result.operation = operation;
    m_attempt = 0;
    m_inFlight = m_written = m_reported = 0;
    m_startUs = m_clock.nowUs();
    m_wire.setBaud(m_transport.baud());
    m_wire.reset(m_startUs);
    std::vector<DecodeEvent> stale;
    m_decoder.reset(stale); // bytes from before this operation are not part of it
    if (!m_transport.isOpen()) {
        m_state = State::Enquiring; // finish() reports from a busy state
        finish(TransferError::NotOpen, tr("The port %1 is not open.").arg(m_transport.name()));
        return false;
    }
    return true;
}

void TransferSession::ping()
{
    if (start(Operation::Ping))
        sendLater(Frame::control(familyInfo(m_family).framing, Code::Enq), State::Enquiring);
}

void TransferSession::save()
{
    if (!familyInfo(m_family).saves) {
        if (start(Operation::Save)) {
            m_state = State::Enquiring; // finish() reports from a busy state
            finish(TransferError::InvalidInput,
                   tr("A table goes only from the PC to the controller (as APROXTAB sent it); "
                      "there is nothing to receive. Choose K51 programs to receive programs."));
        }
        return;
    }
    if (start(Operation::Save))
        sendLater(Frame::control(familyInfo(m_family).framing, Code::Enq), State::Enquiring);
}

void TransferSession::load(const Header &header, const QByteArray &data, bool sendAnyway)
{
    if (!start(Operation::Load))
        return;
    const FamilyInfo &info = familyInfo(m_family);
    const Bytes bytes(data.begin(), data.end());
    m_dataFrame = Frame::withData(info.framing, info.loadCode, header, bytes);
    m_result.header = m_dataFrame.header;
    m_result.data = data;
    m_result.image = checkImage(bytes);
    LoadCheck check = LoadCheck::check(m_family, data, m_result.image, sendAnyway, m_reportedSizes);
    if (check.ok() && validateFrame(m_dataFrame) != FrameError::None)
        check.refusal = tr("The data are too long for one message: %1 bytes, at most %2.")
                            .arg(data.size())
                            .arg(kMaxPayload - m_dataFrame.payloadSize() + data.size());
    if (!check.ok()) {
        m_state = State::Enquiring; // finish() reports from a busy state
        finish(TransferError::InvalidInput, check.refusal);
        return;
    }
    if (!check.warning.isEmpty())
        emit traced(tr("Warning: %1").arg(check.warning));
    sendLater(Frame::control(info.framing, Code::Enq), State::Enquiring);
}

QString TransferSession::modeHint() const
{
    if (m_family == Family::K51)
        return QLatin1Char(' ') + tr("Is it set to program transfer (KONFIG6 = 2)? Set to table "
                                     "transfer (KONFIG6 = 3) it refuses programs.");
    if (m_family == Family::Table)
        return QLatin1Char(' ') + tr("Is it set to table transfer (KONFIG6 = 3)? Only then does "
                                     "it take a table.");
    return {};
}

QString TransferSession::sentName() const
{
    return QString::fromStdString(codeName(m_lastSent.framing, std::uint8_t(m_lastSent.code)));
}

void TransferSession::arm(int timeoutMs, std::int64_t extraUs)
{
    m_clock.cancel(m_timer);
    m_timeoutMs = timeoutMs;
    m_timer = m_clock.callAfter(extraUs + std::int64_t(timeoutMs) * 1000, [this] {
        m_timer = 0;
        onTimeout();
    });
}

void TransferSession::armReplyWait()
{
    const std::int64_t now = m_clock.nowUs();
    const std::int64_t wireLeftUs = std::max<std::int64_t>(0, m_wire.endUs() - now);
    if (m_inFlight > 0) {
        // The port still holds bytes: guard it for the wire time of all it holds plus a gap.
        const std::int64_t guardUs = wireLeftUs + m_inFlight * m_wire.byteUs();
        m_requestDeadlineUs = now + guardUs + std::int64_t(m_timing.gapTimeoutMs) * 1000;
        arm(m_timing.gapTimeoutMs, guardUs);
        return;
    }
    const std::int64_t startUs = wireLeftUs + std::int64_t(m_timing.adapterLatencyMs) * 1000;
    if (m_state == State::Requesting)
        m_requestDeadlineUs = now + startUs + std::int64_t(m_timing.firstByteTimeoutMs) * 1000;
    arm(m_waitMs, startUs);
}

void TransferSession::syncAccepted()
{
    const qint64 taken =
        std::max(m_reported, m_written - std::min(m_written, m_transport.pendingOutput()));
    m_wire.accepted(m_clock.nowUs(), taken - m_wire.acceptedBytes());
    m_inFlight = m_written - taken;
}

void TransferSession::tickProgress()
{
    m_progressTimer = 0;
    if (m_state != State::Sending)
        return;
    syncAccepted();
    const std::int64_t now = m_clock.nowUs();
    const qint64 notGone = m_inFlight + (m_wire.acceptedBytes() - m_wire.sentBy(now));
    emit progressed(std::clamp<qint64>(m_sentSize - notGone, 0, m_sentSize), m_sentSize);
    constexpr std::int64_t kProgressTickUs = 200'000;
    if (notGone > 0)
        m_progressTimer = m_clock.callAfter(kProgressTickUs, [this] { tickProgress(); });
}

void TransferSession::sendLater(const Frame &frame, State next, int pauseMs)
{
    if (pauseMs < 0)
        pauseMs = m_timing.pauseMs;
    m_clock.cancel(m_timer);
    m_timer = 0;
    m_state = State::Pausing;
    m_pauseTimer = m_clock.callAfter(std::int64_t(pauseMs) * 1000, [this, frame, next] {
        m_pauseTimer = 0;
        const Bytes wire = encodeFrame(frame);
        m_lastSent = frame;
        m_state = next;
        if (next == State::Sending) {
            m_sentSize = qint64(wire.size());
            emit progressed(0, m_sentSize);
        }
        m_waitMs = next == State::Requesting ? m_timing.firstByteTimeoutMs
                   : next == State::Sending  ? m_timing.storeTimeoutMs
                                             : m_timing.replyTimeoutMs;
        m_written += qint64(wire.size());
        m_inFlight = m_written - m_wire.acceptedBytes();
        armReplyWait();
        if (next == State::Sending)
            m_progressTimer = m_clock.callAfter(0, [this] { tickProgress(); });
        emit traced(QStringLiteral("-> %1").arg(frameName(frame)));
        m_transport.write(
            QByteArray(reinterpret_cast<const char *>(wire.data()), qsizetype(wire.size())));
    });
}

void TransferSession::onReceived(const QByteArray &bytes)
{
    if (isBusy())
        syncAccepted(); // what the port took before this reply (the ACK guard below)
    std::vector<DecodeEvent> events;
    m_decoder.feed(reinterpret_cast<const std::uint8_t *>(bytes.constData()),
                   std::size_t(bytes.size()), events);
    for (const DecodeEvent &event : events) {
        onEvent(event);
        if (!isBusy())
            return; // finished: later bytes belong to no operation
    }
    if (m_state == State::Requesting && m_decoder.pendingBytes() > 0) {
        arm(m_timing.gapTimeoutMs); // a message is coming: now silence inside it counts
        if (m_decoder.pendingTotal() > 0)
            emit progressed(qint64(m_decoder.pendingBytes()), qint64(m_decoder.pendingTotal()));
    } else if (m_state == State::Requesting) {
        // Noise or a stray message: the wait for the data keeps its original deadline.
        const std::int64_t leftUs = m_requestDeadlineUs - m_clock.nowUs();
        arm(int(std::max<std::int64_t>(0, leftUs) / 1000));
    }
}

void TransferSession::onEvent(const DecodeEvent &event)
{
    switch (event.kind) {
    case DecodeEvent::Kind::Noise:
        m_result.noiseBytes += qint64(event.noise.size());
        emit traced(
            tr("<- noise, %1 bytes skipped: %2")
                .arg(event.noise.size())
                .arg(QString::fromStdString(hexDump(
                    Bytes(event.noise.begin(),
                          event.noise.begin() + std::min<std::size_t>(16, event.noise.size()))))));
        break;
    case DecodeEvent::Kind::ChecksumError:
        onBadChecksum(event);
        break;
    case DecodeEvent::Kind::Frame:
        emit traced(QStringLiteral("<- %1").arg(frameName(event.frame)));
        onFrame(event.frame);
        break;
    }
}

void TransferSession::onFrame(const Frame &frame)
{
    const FamilyInfo &info = familyInfo(m_family);
    const QString unexpected = tr("Unexpected reply %1 to %2.").arg(frameName(frame), sentName());
    if (frame.code == Code::Nak)
        ++m_result.naks;
    switch (m_state) {
    case State::Enquiring:
        if (frame.code == Code::Ack)
            afterAck();
        else if (frame.code == Code::Nak)
            retryOrFail(TransferError::Rejected, tr("The controller answered NAK to ENQ."));
        else
            finish(TransferError::UnexpectedReply, unexpected);
        break;
    case State::Requesting:
        if (frame.code == info.saveCode && !frame.data.empty()) {
            m_result.header = frame.header;
            m_result.data = QByteArray(reinterpret_cast<const char *>(frame.data.data()),
                                       qsizetype(frame.data.size()));
            m_result.image = checkImage(frame.data);
            m_reportedSizes.insert(m_result.data.size());
            const auto wireSize = qint64(4 + frame.payloadSize() + checksumSize(info.framing));
            emit progressed(wireSize, wireSize);
            sendLater(Frame::control(info.framing, Code::Ack), State::AckingSave);
        } else if (frame.code == Code::Nak) {
            retryOrFail(TransferError::Rejected,
                        m_family == Family::Anc
                            ? tr("The controller answered NAK to %1: is the ANC set up for "
                                 "program transfer and not grinding?")
                                  .arg(sentName())
                            : tr("The controller answered NAK to %1: is it set to program "
                                 "transfer (KONFIG6) with the selector in PGN?")
                                  .arg(sentName()));
        } else if (frame.code == Code::Ack) {
            // A late answer to a repeated ENQ: never an answer to a request.
            emit traced(tr("<- ACK ignored: a late answer to an earlier message"));
        } else {
            finish(TransferError::UnexpectedReply, unexpected);
        }
        break;
    case State::Sending:
        if (frame.code == Code::Ack && m_inFlight > 0)
            // The data message is not out yet, so this cannot be its answer.
            emit traced(tr("<- ACK ignored: a late answer to an earlier message"));
        else if (frame.code == Code::Ack)
            finish(TransferError::None);
        else if (frame.code == Code::Nak)
            retryOrFail(TransferError::Rejected,
                        tr("The controller answered NAK to %1 (%2 times): it did not accept "
                           "the data.")
                                .arg(sentName())
                                .arg(m_result.naks) +
                            modeHint());
        else
            finish(TransferError::UnexpectedReply, unexpected);
        break;
    case State::Idle:
    case State::Pausing:
    case State::AckingSave:
        emit traced(tr("<- %1 ignored: no reply expected now").arg(frameName(frame)));
        break;
    }
}

void TransferSession::onBadChecksum(const DecodeEvent &event)
{
    ++m_result.checksumFailures;
    QString text = tr("Bad checksum in %1 from the controller: received %2, computed %3.")
                       .arg(frameName(event.frame))
                       .arg(QString::number(event.receivedSum, 16).toUpper())
                       .arg(QString::number(event.expectedSum, 16).toUpper());
    if (event.frame.payloadSize() == 0) // a short reply in the other family's framing
        text = tr("The controller's reply does not fit the %1 messages: is the wrong system "
                  "selected (ANC or K51)? Choose the system the control is, then try again. "
                  "(%2)")
                   .arg(familyName(m_family), text);
    emit traced(QStringLiteral("<- ") + text);
    if (m_state == State::Enquiring || m_state == State::Requesting || m_state == State::Sending)
        retryOrFail(TransferError::ChecksumFailed, text, m_state == State::Requesting);
}

void TransferSession::afterAck()
{
    const FamilyInfo &info = familyInfo(m_family);
    // After a repeated ENQ a second ACK may still be on its way: let it arrive (and be
    // ignored) before the next message, so it cannot be taken for that message's answer.
    const int pauseMs =
        m_attempt > 0 ? std::max(m_timing.pauseMs, m_timing.replyTimeoutMs) : m_timing.pauseMs;
    m_attempt = 0;
    switch (m_operation) {
    case Operation::Ping:
        finish(TransferError::None);
        break;
    case Operation::Save:
        sendLater(Frame::control(info.framing, info.requestCode), State::Requesting, pauseMs);
        break;
    case Operation::Load:
        sendLater(m_dataFrame, State::Sending, pauseMs);
        break;
    }
}

void TransferSession::retryOrFail(TransferError error, const QString &message, bool askRepeat)
{
    if (m_attempt >= m_timing.maxRetries) {
        finish(error, m_timing.maxRetries > 0
                          ? tr("%1 Given up after %2 repeats.").arg(message).arg(m_attempt)
                          : message);
        return;
    }
    ++m_attempt;
    ++m_result.retries;
    emit traced(tr("Repeat %1 of %2: %3").arg(m_attempt).arg(m_timing.maxRetries).arg(message));
    if (askRepeat) // the data message came (partly): ask for it again
        sendLater(Frame::control(familyInfo(m_family).framing, Code::Nak), State::Requesting);
    else
        sendLater(m_lastSent, m_state);
}

void TransferSession::onTimeout()
{
    const double seconds = m_timeoutMs / 1000.0;
    syncAccepted();
    if (m_inFlight > 0 && m_state != State::AckingSave) {
        finish(TransferError::Transport,
               tr("The port %1 stopped taking data: %2 bytes of %3 were not sent. Check that the "
                  "cable and the USB adapter are plugged in.")
                   .arg(m_transport.name())
                   .arg(m_inFlight)
                   .arg(sentName()));
        return;
    }
    switch (m_state) {
    case State::Enquiring:
        retryOrFail(TransferError::Timeout,
                    m_family == Family::Anc
                        ? tr("No answer to ENQ within %1 s. Check the cable, the line settings "
                             "(%2 Bd), the selected system (ANC) and that the ANC is not "
                             "grinding.")
                              .arg(seconds)
                              .arg(m_transport.baud())
                        : tr("No answer to ENQ within %1 s. Check the cable, the line settings "
                             "(%2 Bd), the selected system (%3) and that the controller is set "
                             "to transfer (KONFIG6).")
                              .arg(seconds)
                              .arg(m_transport.baud())
                              .arg(familyName(m_family)));
        break;
    case State::Requesting: {
        const std::size_t got = m_decoder.pendingBytes();
        const std::size_t total = m_decoder.pendingTotal();
        std::vector<DecodeEvent> events;
        m_decoder.reset(events);
        for (const DecodeEvent &event : events)
            m_result.noiseBytes += qint64(event.noise.size());
        if (got > 0)
            retryOrFail(TransferError::Timeout,
                        tr("The data message stopped after %1 of %2 bytes (no byte for %3 s).")
                            .arg(got)
                            .arg(total)
                            .arg(seconds),
                        true);
        else
            retryOrFail(TransferError::Timeout,
                        tr("No data from the controller within %1 s after %2.")
                            .arg(m_timing.firstByteTimeoutMs / 1000.0)
                            .arg(sentName()));
        break;
    }
    case State::Sending:
        retryOrFail(
            TransferError::Timeout,
            tr("No ACK to %1 within %2 s after its last byte.").arg(sentName()).arg(seconds));
        break;
    case State::AckingSave:
        if (m_inFlight > 0)
            finish(TransferError::Transport,
                   tr("The final ACK could not be sent within %1 s.").arg(seconds));
        else
            finish(TransferError::None);
        break;
    case State::Idle:
    case State::Pausing:
        break;
    }
}

void TransferSession::onWritten(qint64 bytes)
{
    m_reported += bytes;
    syncAccepted();
    if (m_state == State::Enquiring || m_state == State::Requesting || m_state == State::Sending) {
        // Only while nothing of the reply has come: a message under way keeps its gap timer.
        if (m_state != State::Requesting || m_decoder.pendingBytes() == 0)
            armReplyWait();
    } else if (m_state == State::AckingSave && m_inFlight == 0) {
        finish(TransferError::None);
    }
}

void TransferSession::onTransportFailed(const QString &error)
{
    if (isBusy())
        finish(TransferError::Transport, error);
}

} // namespace frezka::grinder
