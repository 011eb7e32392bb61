#pragma once
// PC side of the Z-position link (zposition.h). FORM=1: query() and go() send one ASCII
// message and wait for the position answer; E0/E1 and unreadable replies are reported.
// FORM=2: nothing is sent; every binary frame received reports a position.

#include "driver/grinder/clock.h"
#include "driver/grinder/transport.h"
#include "driver/grinder/zposition.h"

#include <QObject>
#include <QString>

namespace frezka::grinder {

class ZLinkSession : public QObject
{
    Q_OBJECT
public:
    ZLinkSession(Transport &transport, Clock &clock, int form, QObject *parent = nullptr);
    ~ZLinkSession() override;

    int form() const { return m_form; }
    void setForm(int form);
    void setReplyTimeoutMs(int ms) { m_replyTimeoutMs = ms; }
    void setGoTimeoutMs(int ms) { m_goTimeoutMs = ms; }
    bool isWaiting() const { return m_waiting; }

    // FORM=1 only; false (and nothing sent) when waiting for an answer or in FORM=2.
    bool query();
    bool go(std::int64_t targetUm);

signals:
    void positionReceived(qint64 positionUm);
    void replyFailed(const QString &message); // E0/E1, unreadable reply, timeout
    void bytesSkipped(int count);             // FORM=2 resynchronisation
    void traced(const QString &line);

private:
    bool send(const std::string &text, int timeoutMs);
    void onReceived(const QByteArray &bytes);
    void done();

    Transport &m_transport;
    Clock &m_clock;
    int m_form;
    ZAsciiReader m_ascii;
    ZBinaryDecoder m_binary;
    bool m_waiting = false;
    QString m_pending; // message waited for, for reports
    int m_replyTimeoutMs = 3000;
    int m_goTimeoutMs = 300000; // the table may travel far at a slow feed
    Clock::TimerId m_timer = 0;
};

} // namespace frezka::grinder
