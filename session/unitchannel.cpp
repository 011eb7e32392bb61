#include "unitchannel.h"

#include "protocol/checksum.h"

namespace frezka::session {

std::string UnitChannel::Exchange::text() const
{
    std::string s = sent;
    while (!s.empty() && (s.back() == '\r' || s.back() == '\n'))
        s.pop_back();
    for (char &c : s)
        if (c == '\r')
            c = ' ';
    return s + " -> " + (timedOut && raw.empty() ? std::string("(no reply)") : raw);
}

std::string UnitChannel::frame(const std::string &body, int address) const
{
    std::string message = "!" + std::to_string(address) + body;
    if (m_checksums) {
        message += ",";
        message += protocol::hexByte(protocol::checksum(message));
    }
    return message + "\r";
}

UnitChannel::Exchange UnitChannel::send(const std::string &body, int address, double timeoutS)
{
    return sendBytes(frame(body, address), timeoutS);
}

UnitChannel::Exchange UnitChannel::sendBytes(const std::string &bytes, double timeoutS)
{
    Exchange e;
    e.sent = bytes;
    const RawLine::Answer answer = m_line.ask(bytes, 1, timeoutS);
    e.roundTripMs = answer.roundTripS * 1000.0;
    e.timedOut = answer.timedOut;
    e.raw = answer.first();
    if (!e.raw.empty()) {
        const auto decoded = protocol::decodeReply(
            e.raw, m_checksums ? protocol::ChecksumMode::On : protocol::ChecksumMode::Auto);
        e.reply = decoded.reply;
    }
    return e;
}

} // namespace frezka::session
