#include "driver/grinder/frame.h"

#include <cstdio>

namespace frezka::grinder {

bool isKnownCode(Framing framing, std::uint8_t code)
{
    switch (code) {
    case 0x05:
    case 0x06:
    case 0x07:
        return true;
    case 0x01:
    case 0x02:
        return framing == Framing::Anc;
    case 0x10:
    case 0x11:
    case 0x12:
    case 0x20:
    case 0x22:
    case 0x40:
    case 0x42:
        return framing == Framing::K51;
    default:
        return false;
    }
}

bool carriesHeader(Framing framing, Code code)
{
    if (framing != Framing::K51)
        return false;
    switch (code) {
    case Code::Load:
    case Code::LoadTable:
    case Code::LoadHardChrome:
    case Code::Save:
    case Code::SaveHardChrome:
        return true;
    default:
        return false;
    }
}

bool isControlCode(Framing framing, Code code)
{
    switch (code) {
    case Code::Enq:
    case Code::Ack:
    case Code::Nak:
        return true;
    case Code::Request:
    case Code::RequestHardChrome:
        return framing == Framing::K51;
    default:
        return false;
    }
}

std::string codeName(Framing framing, std::uint8_t code)
{
    if (isKnownCode(framing, code)) {
        switch (static_cast<Code>(code)) {
        case Code::AncLoad:
            return "LOA";
        case Code::AncSave:
            return "SAV";
        case Code::Enq:
            return "ENQ";
        case Code::Ack:
            return "ACK";
        case Code::Nak:
            return "NAK";
        case Code::Load:
            return "LOA";
        case Code::LoadTable:
            return "LOA1";
        case Code::LoadHardChrome:
            return "LOA2";
        case Code::Request:
            return "DEJ";
        case Code::RequestHardChrome:
            return "DEJ2";
        case Code::Save:
            return "SAV";
        case Code::SaveHardChrome:
            return "SAV2";
        }
    }
    char text[8];
    std::snprintf(text, sizeof text, "0x%02X", code);
    return text;
}

Frame Frame::control(Framing framing, Code code)
{
    Frame frame;
    frame.framing = framing;
    frame.code = code;
    return frame;
}

Frame Frame::withData(Framing framing, Code code, const Header &header, Bytes data)
{
    Frame frame;
    frame.framing = framing;
    frame.code = code;
    if (carriesHeader(framing, code))
        frame.header = header;
    frame.data = std::move(data);
    return frame;
}

std::size_t Frame::payloadSize() const
{
    return (carriesHeader(framing, code) ? kHeaderSize : 0) + data.size();
}

const char *frameErrorText(FrameError error)
{
    switch (error) {
    case FrameError::None:
        return "no error";
    case FrameError::UnknownCode:
        return "message code not used by this controller family";
    case FrameError::DataInControl:
        return "a control message carries no data";
    case FrameError::PayloadTooLarge:
        return "header and data exceed 65535 bytes";
    }
    return "unknown error";
}

FrameError validateFrame(const Frame &frame)
{
    if (!isKnownCode(frame.framing, static_cast<std::uint8_t>(frame.code)))
        return FrameError::UnknownCode;
    if (isControlCode(frame.framing, frame.code) && !frame.data.empty())
        return FrameError::DataInControl;
    if (frame.payloadSize() > kMaxPayload)
        return FrameError::PayloadTooLarge;
    return FrameError::None;
}

std::size_t checksumSize(Framing framing)
{
    return framing == Framing::Anc ? 1 : 2;
}

std::uint16_t frameChecksum(Framing framing, const std::uint8_t *bytes, std::size_t size)
{
    std::uint32_t sum = 0;
    for (std::size_t i = 0; i < size; ++i)
        sum += bytes[i];
    if (framing == Framing::Anc)
        return static_cast<std::uint8_t>(0x100u - (sum & 0xFFu));
    return static_cast<std::uint16_t>(0x10000u - (sum & 0xFFFFu));
}

Bytes encodeFrame(const Frame &frame)
{
    if (validateFrame(frame) != FrameError::None)
        return {};
    const std::size_t payload = frame.payloadSize();
    Bytes out;
    out.reserve(4 + payload + 2);
    out.push_back(kStartByte);
    out.push_back(static_cast<std::uint8_t>(frame.code));
    out.push_back(static_cast<std::uint8_t>(payload >> 8));
    out.push_back(static_cast<std::uint8_t>(payload & 0xFF));
    if (carriesHeader(frame.framing, frame.code))
        out.insert(out.end(), frame.header.begin(), frame.header.end());
    out.insert(out.end(), frame.data.begin(), frame.data.end());
    const std::uint16_t sum = frameChecksum(frame.framing, out.data(), out.size());
    if (frame.framing == Framing::K51)
        out.push_back(static_cast<std::uint8_t>(sum >> 8));
    out.push_back(static_cast<std::uint8_t>(sum & 0xFF));
    return out;
}

Header headerFromText(const std::string &text)
{
    Header header;
    // An empty header is the manual's zero header; text is padded with spaces.
    header.fill(text.empty() ? 0 : ' ');
    for (std::size_t i = 0; i < kHeaderSize && i < text.size(); ++i)
        header[i] = static_cast<std::uint8_t>(text[i]);
    return header;
}

std::string headerText(const Header &header)
{
    std::string text;
    for (std::uint8_t byte : header)
        text.push_back(byte == 0 ? ' ' : (byte < 0x20 || byte == 0x7F ? '.' : char(byte)));
    while (!text.empty() && text.back() == ' ')
        text.pop_back();
    return text;
}

std::string hexDump(const std::uint8_t *bytes, std::size_t size)
{
    static const char digits[] = "0123456789ABCDEF";
    std::string text;
    text.reserve(size * 3);
    for (std::size_t i = 0; i < size; ++i) {
        if (i)
            text.push_back(' ');
        text.push_back(digits[bytes[i] >> 4]);
        text.push_back(digits[bytes[i] & 0xF]);
    }
    return text;
}

} // namespace frezka::grinder
