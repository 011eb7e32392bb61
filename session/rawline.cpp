#include "rawline.h"

#include <QEventLoop>
#include <QTimer>

namespace frezka::session {

RawLine::RawLine(driver::Transport &transport)
    : m_transport(transport)
{
    m_received = QObject::connect(&m_transport, &driver::Transport::bytesReceived, &m_transport,
                                  [this](const QByteArray &bytes) { onBytes(bytes); });
    m_closedConnection = QObject::connect(&m_transport, &driver::Transport::closed, &m_transport,
                                          [this](const QString &) { m_closed = true; });
}

RawLine::~RawLine()
{
    QObject::disconnect(m_received);
    QObject::disconnect(m_closedConnection);
}

void RawLine::onBytes(const QByteArray &bytes)
{
    m_bytesIn += bytes.size();
    for (char c : bytes) {
        if (c == '\r') {
            m_lines.push_back(m_partial);
            m_partial.clear();
        } else if (c != '\n') {
            m_partial.push_back(c);
        }
    }
}

bool RawLine::open(double timeoutS, QString *why)
{
    QEventLoop loop;
    bool opened = false;
    QString reason;
    auto a = QObject::connect(&m_transport, &driver::Transport::opened, &loop, [&] {
        opened = true;
        loop.quit();
    });
    auto b =
        QObject::connect(&m_transport, &driver::Transport::closed, &loop, [&](const QString &w) {
            reason = w;
            loop.quit();
        });
    QTimer::singleShot(static_cast<int>(timeoutS * 1000), &loop, &QEventLoop::quit);
    m_closed = false;
    m_transport.open();
    if (!opened && !m_transport.isOpen())
        loop.exec();
    QObject::disconnect(a);
    QObject::disconnect(b);
    if (!opened && !m_transport.isOpen()) {
        *why = reason.isEmpty() ? QStringLiteral("timeout") : reason;
        return false;
    }
    return true;
}

void RawLine::close()
{
    if (m_transport.isOpen())
        m_transport.close();
}

RawLine::Answer RawLine::ask(const std::string &bytes, int replies, double timeoutS)
{
    m_stray += static_cast<int>(m_lines.size());
    m_lines.clear();
    m_partial.clear();
    Answer answer;
    QElapsedTimer clock;
    clock.start();
    m_transport.write(QByteArray(bytes.data(), static_cast<qsizetype>(bytes.size())));
    m_bytesOut += static_cast<long long>(bytes.size());
    QEventLoop loop;
    QTimer deadline;
    deadline.setSingleShot(true);
    QObject::connect(&deadline, &QTimer::timeout, &loop, &QEventLoop::quit);
    auto check = QObject::connect(&m_transport, &driver::Transport::bytesReceived, &loop, [&] {
        if (static_cast<int>(m_lines.size()) >= replies)
            loop.quit();
    });
    deadline.start(static_cast<int>(timeoutS * 1000));
    if (static_cast<int>(m_lines.size()) < replies && !m_closed)
        loop.exec();
    QObject::disconnect(check);
    answer.roundTripS = static_cast<double>(clock.nsecsElapsed()) * 1e-9;
    answer.timedOut = static_cast<int>(m_lines.size()) < replies;
    answer.lines = std::move(m_lines);
    m_lines.clear();
    return answer;
}

std::vector<std::string> RawLine::listen(double seconds)
{
    QEventLoop loop;
    QTimer::singleShot(static_cast<int>(seconds * 1000), &loop, &QEventLoop::quit);
    loop.exec();
    std::vector<std::string> lines = std::move(m_lines);
    m_lines.clear();
    return lines;
}

} // namespace frezka::session
