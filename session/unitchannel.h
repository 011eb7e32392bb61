#pragma once
// UnitChannel: GVE commands as text over a RawLine, for the commissioning's checks: frames a
// command for an address with or without a checksum (docs/gve-protocol.md §2, §2.1), sends it
// and decodes the reply. Unlike the link engine it recovers nothing: a lost or garbled reply is
// what a check reports.

#include "protocol/reply.h"
#include "session/rawline.h"

#include <optional>
#include <string>

namespace frezka::session {

class UnitChannel
{
public:
    struct Exchange
    {
        std::string sent;                     // the bytes, CR included
        std::string raw;                      // the first reply line, "" when none
        std::optional<protocol::Reply> reply; // decoded (checksum stripped and checked)
        double roundTripMs = 0;
        bool timedOut = false;
        // "!0F -> 0,40,4E" for the report (CR left out).
        std::string text() const;
        // The reply's code, or -1 without a reply.
        int code() const { return reply ? static_cast<int>(reply->code) : -1; }
    };

    explicit UnitChannel(RawLine &line)
        : m_line(line)
    {}

    // The bytes of `body` ("F", "ER05") for `address`, CR-terminated, with ",HH" when
    // checksums are on.
    std::string frame(const std::string &body, int address = 0) const;
    // Frames, sends and decodes; timeoutS bounds the wait for the reply.
    Exchange send(const std::string &body, int address = 0, double timeoutS = 1.0);
    // Sends bytes as they are (a deliberately wrong checksum, a packet of several lines) and
    // decodes the first reply line.
    Exchange sendBytes(const std::string &bytes, double timeoutS = 1.0);

    bool checksums() const { return m_checksums; }
    void setChecksums(bool on) { m_checksums = on; }
    RawLine &line() { return m_line; }

private:
    RawLine &m_line;
    bool m_checksums = false;
};

} // namespace frezka::session
