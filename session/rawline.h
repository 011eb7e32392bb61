#pragma once
// RawLine: the commissioning assistant's own conversation with a unit, below the link engine.
//
// The checks of the adopted readings must send what the driver never sends (a wrong checksum,
// an unknown command, `@` and `>` on purpose), so they talk to the Transport directly: write
// bytes, then wait in a local event loop until the expected number of reply lines (CR) came or
// the timeout passed. Used only before the driver connects (the commissioning's steps that move
// nothing), never beside a running link worker on the same port.

#include "driver/link/transport.h"

#include <QElapsedTimer>
#include <QString>

#include <string>
#include <vector>

namespace frezka::session {

class RawLine
{
public:
    struct Answer
    {
        std::vector<std::string> lines; // without CR; fewer than asked when timedOut
        double roundTripS = 0;          // from the write to the last line (or the timeout)
        bool timedOut = false;
        // The first line, or "" when none came.
        std::string first() const { return lines.empty() ? std::string() : lines.front(); }
    };

    // Uses `transport` (not owned); it must not be open yet.
    explicit RawLine(driver::Transport &transport);
    // Lets go of the transport's signals (the transport may live on: the driver reuses it).
    ~RawLine();
    RawLine(const RawLine &) = delete;
    RawLine &operator=(const RawLine &) = delete;

    // Opens the transport and waits for it; false with the reason.
    bool open(double timeoutS, QString *why);
    void close();
    // Writes `bytes` and waits for `replies` lines or `timeoutS`. Lines that came before the
    // write (late replies of an earlier question) are counted in strayLines() and dropped.
    Answer ask(const std::string &bytes, int replies = 1, double timeoutS = 1.0);
    // Waits `seconds` and returns the lines that came meanwhile (nothing was asked).
    std::vector<std::string> listen(double seconds);
    int strayLines() const { return m_stray; }
    // Bytes written and received since open().
    long long bytesOut() const { return m_bytesOut; }
    long long bytesIn() const { return m_bytesIn; }

private:
    void onBytes(const QByteArray &bytes);

    driver::Transport &m_transport;
    QMetaObject::Connection m_received;
    QMetaObject::Connection m_closedConnection;
    std::string m_partial;
    std::vector<std::string> m_lines;
    bool m_closed = false;
    int m_stray = 0;
    long long m_bytesOut = 0;
    long long m_bytesIn = 0;
};

} // namespace frezka::session
