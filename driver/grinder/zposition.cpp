#include "driver/grinder/zposition.h"

#include <cstdio>
#include <cstdlib>

namespace frezka::grinder {

std::string formatMillimetres(std::int64_t positionUm)
{
    const std::int64_t magnitude = positionUm < 0 ? -positionUm : positionUm;
    char text[32];
    std::snprintf(text, sizeof text, "%s%04lld.%03lld", positionUm < 0 ? "-" : "",
                  static_cast<long long>(magnitude / 1000),
                  static_cast<long long>(magnitude % 1000));
    return text;
}

std::optional<std::int64_t> parseMillimetres(std::string_view text)
{
    std::size_t i = 0;
    bool negative = false;
    if (i < text.size() && (text[i] == '+' || text[i] == '-'))
        negative = text[i++] == '-';
    std::int64_t whole = 0;
    std::size_t digits = 0;
    for (; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i, ++digits) {
        whole = whole * 10 + (text[i] - '0');
        if (whole > 100000000)
            return std::nullopt;
    }
    std::int64_t fraction = 0;
    std::size_t decimals = 0;
    if (i < text.size() && (text[i] == '.' || text[i] == ',')) {
        for (++i; i < text.size() && text[i] >= '0' && text[i] <= '9'; ++i, ++decimals)
            fraction = fraction * 10 + (text[i] - '0');
    }
    if (i != text.size() || digits + decimals == 0 || decimals > 3)
        return std::nullopt;
    for (std::size_t d = decimals; d < 3; ++d)
        fraction *= 10;
    const std::int64_t um = whole * 1000 + fraction;
    return negative ? -um : um;
}

std::string zQueryMessage()
{
    return "Z? ";
}

std::string goMessage(std::int64_t targetUm)
{
    return "GO " + formatMillimetres(targetUm) + " ";
}

std::string positionMessage(std::int64_t positionUm)
{
    return "Z=" + formatMillimetres(positionUm) + " ";
}

void ZAsciiReader::feed(const std::uint8_t *bytes, std::size_t size, std::vector<ZReply> &replies)
{
    for (std::size_t i = 0; i < size; ++i) {
        const char c = static_cast<char>(bytes[i]);
        if (c != ' ') {
            m_text.push_back(c);
            continue;
        }
        if (m_text.empty())
            continue;
        ZReply reply;
        reply.text = m_text;
        m_text.clear();
        if (reply.text == "E0") {
            reply.kind = ZReply::Kind::BadFirst;
        } else if (reply.text == "E1") {
            reply.kind = ZReply::Kind::BadMore;
        } else if (reply.text.size() > 2 && reply.text.compare(0, 2, "Z=") == 0) {
            if (auto um = parseMillimetres(std::string_view(reply.text).substr(2))) {
                reply.kind = ZReply::Kind::Position;
                reply.positionUm = *um;
            }
        }
        replies.push_back(std::move(reply));
    }
}

Bytes encodeZBinary(std::int64_t positionUm)
{
    constexpr std::int64_t kMax = (1 << 23) - 1;
    if (positionUm > kMax)
        positionUm = kMax;
    if (positionUm < -kMax - 1)
        positionUm = -kMax - 1;
    const auto raw = static_cast<std::uint32_t>(positionUm) & 0xFFFFFFu;
    Bytes frame = {std::uint8_t(raw & 0xFF), std::uint8_t((raw >> 8) & 0xFF),
                   std::uint8_t((raw >> 16) & 0xFF)};
    frame.push_back(std::uint8_t(0x100 - ((frame[0] + frame[1] + frame[2]) & 0xFF)));
    return frame;
}

void ZBinaryDecoder::feed(const std::uint8_t *bytes, std::size_t size,
                          std::vector<ZBinaryEvent> &events)
{
    for (std::size_t i = 0; i < size; ++i) {
        m_window.push_back(bytes[i]);
        while (m_window.size() == kZBinaryFrameSize) {
            const std::uint8_t sum =
                std::uint8_t(m_window[0] + m_window[1] + m_window[2] + m_window[3]);
            ZBinaryEvent event;
            if (sum == 0) {
                std::uint32_t raw = m_window[0] | (m_window[1] << 8) | (m_window[2] << 16);
                if (raw & 0x800000u)
                    raw |= 0xFF000000u;
                event.positionUm = static_cast<std::int32_t>(raw);
                m_window.clear();
            } else {
                event.position = false;
                event.skipped = m_window.front();
                m_window.erase(m_window.begin());
            }
            events.push_back(event);
        }
    }
}

} // namespace frezka::grinder
