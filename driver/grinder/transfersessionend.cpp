// How a transfer ends: cancel (what the controller is still doing) and finish (the result).
#include "driver/grinder/transfersession.h"

namespace frezka::grinder {

void TransferSession::cancel(const QString &reason)
{
    if (!isBusy())
        return;
    QString message = reason.isEmpty() ? tr("Cancelled.") : reason;
    const std::int64_t now = m_clock.nowUs();
    if (m_state == State::Requesting || m_state == State::AckingSave) {
        // The controller's data message runs to its end whatever the PC does.
        const std::size_t total = m_decoder.pendingTotal() > 0
                                      ? m_decoder.pendingTotal()
                                      : familyInfo(m_family).defaultSize + 22;
        const std::size_t left = total - std::min(total, m_decoder.pendingBytes());
        if (m_state == State::Requesting && left > 0) {
            m_result.controllerBusyUs = qint64(left) * m_wire.byteUs();
            message += QLatin1Char(' ') +
                       tr("The controller may still be sending its data for about %1 s; the link "
                          "check waits until then.")
                           .arg(qRound(m_result.controllerBusyUs / 1e6));
        }
    } else if (m_state == State::Sending &&
               (m_inFlight > 0 || m_wire.sentBy(now) < m_wire.acceptedBytes())) {
        m_transport.discardOutput();
        // The controller drops an incomplete message after kControllerGapUs of silence.
        m_result.controllerBusyUs = kControllerGapUs + 500'000;
        message += QLatin1Char(' ') + tr("The controller received only part of the data and "
                                         "discards it; the programs it holds are unchanged.");
    } else if (m_state == State::Sending) {
        message += QLatin1Char(' ') + tr("All data had been sent: the controller may have "
                                         "stored them. Check its programs.");
    }
    finish(TransferError::Cancelled, message);
}

QString TransferSession::frameName(const Frame &frame) const
{
    QString name = QString::fromStdString(codeName(frame.framing, std::uint8_t(frame.code)));
    if (frame.payloadSize() > 0)
        name += QStringLiteral(" (%1 B)").arg(frame.payloadSize());
    return name;
}

void TransferSession::finish(TransferError error, const QString &message)
{
    m_clock.cancel(m_timer);
    m_clock.cancel(m_pauseTimer);
    m_clock.cancel(m_progressTimer);
    m_timer = m_pauseTimer = m_progressTimer = 0;
    if (error == TransferError::None && m_operation == Operation::Load)
        emit progressed(m_sentSize, m_sentSize);
    m_state = State::Idle;
    m_result.error = error;
    m_result.elapsedUs = m_clock.nowUs() - m_startUs;
    m_result.message = message;
    if (error == TransferError::None) {
        switch (m_operation) {
        case Operation::Ping:
            m_result.message = tr("Connected.");
            break;
        case Operation::Save:
            m_result.message = tr("Received %1 bytes, header \"%2\".")
                                   .arg(m_result.data.size())
                                   .arg(QString::fromLatin1(headerText(m_result.header)));
            break;
        case Operation::Load:
            m_result.message =
                tr("Sent %1 bytes; the controller stored them.").arg(m_result.data.size());
            break;
        }
    }
    emit traced(m_result.message);
    // A copy: a slot may start the next operation, which resets m_result under later slots
    // (the window's link check did, and the panel then saw a ping instead of the failure).
    const TransferResult result = m_result;
    emit finished(result);
}

} // namespace frezka::grinder
