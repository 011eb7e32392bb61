#include "driver/grinder/zlinksession.h"

namespace frezka::grinder {

ZLinkSession::ZLinkSession(Transport &transport, Clock &clock, int form, QObject *parent)
    : QObject(parent)
    , m_transport(transport)
    , m_clock(clock)
    , m_form(form == 2 ? 2 : 1)
{
    connect(&m_transport, &Transport::received, this, &ZLinkSession::onReceived);
}

ZLinkSession::~ZLinkSession()
{
    m_clock.cancel(m_timer);
}

void ZLinkSession::setForm(int form)
{
    m_form = form == 2 ? 2 : 1;
    m_ascii.reset();
    m_binary.reset();
    done();
}

bool ZLinkSession::query()
{
    return send(zQueryMessage(), m_replyTimeoutMs);
}

bool ZLinkSession::go(std::int64_t targetUm)
{
    return send(goMessage(targetUm), m_goTimeoutMs);
}

bool ZLinkSession::send(const std::string &text, int timeoutMs)
{
    if (m_form != 1 || m_waiting || !m_transport.isOpen())
        return false;
    m_waiting = true;
    m_pending = QString::fromLatin1(text).trimmed();
    m_timer = m_clock.callAfter(std::int64_t(timeoutMs) * 1000, [this, timeoutMs] {
        m_timer = 0;
        const QString what = m_pending;
        done();
        emit replyFailed(tr("No answer to \"%1\" within %2 s. Is the controller set to "
                            "Z-position transfer (KONFIG6 = 1) with the selector in PGN?")
                             .arg(what)
                             .arg(timeoutMs / 1000.0));
    });
    emit traced(QStringLiteral("-> %1").arg(m_pending));
    m_transport.write(QByteArray::fromStdString(text));
    return true;
}

void ZLinkSession::done()
{
    m_clock.cancel(m_timer);
    m_timer = 0;
    m_waiting = false;
    m_pending.clear();
}

void ZLinkSession::onReceived(const QByteArray &bytes)
{
    const auto *data = reinterpret_cast<const std::uint8_t *>(bytes.constData());
    const auto size = std::size_t(bytes.size());
    if (m_form == 2) {
        std::vector<ZBinaryEvent> events;
        m_binary.feed(data, size, events);
        int skipped = 0;
        for (const ZBinaryEvent &event : events) {
            if (event.position)
                emit positionReceived(event.positionUm);
            else
                ++skipped;
        }
        if (skipped > 0)
            emit bytesSkipped(skipped);
        return;
    }
    std::vector<ZReply> replies;
    m_ascii.feed(data, size, replies);
    for (const ZReply &reply : replies) {
        emit traced(QStringLiteral("<- %1").arg(QString::fromLatin1(reply.text)));
        const QString sent = m_pending;
        switch (reply.kind) {
        case ZReply::Kind::Position:
            done();
            emit positionReceived(reply.positionUm);
            break;
        case ZReply::Kind::BadFirst:
        case ZReply::Kind::BadMore:
            done();
            emit replyFailed(tr("The controller rejected a character of \"%1\" (%2).")
                                 .arg(sent, QString::fromLatin1(reply.text)));
            break;
        case ZReply::Kind::Unknown:
            emit replyFailed(tr("Unreadable reply \"%1\".").arg(QString::fromLatin1(reply.text)));
            break;
        }
    }
}

} // namespace frezka::grinder
