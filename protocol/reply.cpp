#include "reply.h"

#include "checksum.h"

#include <charconv>

namespace frezka::protocol {
namespace {

int hexDigit(char c)
{
    if (c >= '0' && c <= '9')
        return c - '0';
    if (c >= 'A' && c <= 'F')
        return c - 'A' + 10;
    if (c >= 'a' && c <= 'f')
        return c - 'a' + 10;
    return -1;
}

std::optional<std::int64_t> parseDecimal(std::string_view s)
{
    if (s.empty())
        return std::nullopt;
    std::string_view digits = s;
    if (digits.front() == '+')
        digits.remove_prefix(1);
    std::int64_t v = 0;
    auto [ptr, ec] = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (ec != std::errc() || ptr != digits.data() + digits.size())
        return std::nullopt;
    return v;
}

DecodeError error(DecodeErrorKind kind, std::string_view raw, std::string message)
{
    return {kind, std::string(raw), std::move(message)};
}

// Strips ",HH" when it is a valid checksum of what precedes it (including the comma).
bool stripChecksum(std::string_view &body)
{
    const auto comma = body.rfind(',');
    if (comma == std::string_view::npos || body.size() - comma != 3)
        return false;
    const auto sum = parseHexByte(body.substr(comma + 1));
    if (!sum || *sum != checksum(body.substr(0, comma + 1)))
        return false;
    body = body.substr(0, comma);
    return true;
}

enum class Shape { None, Text, Id, Decimals, HexByte, Real, Unsigned, Index, Count, Echo, Any };

struct ShapeSpec
{
    Shape shape;
    int count;
};

ShapeSpec shapeOf(Op op)
{
    switch (op) {
    case Op::Version:
        return {Shape::Text, 1};
    case Op::Identify:
        return {Shape::Id, 1};
    case Op::PositionXY:
        return {Shape::Decimals, 2};
    case Op::PositionXYZ:
        return {Shape::Decimals, 3};
    case Op::PositionXYZA:
        return {Shape::Decimals, 4};
    case Op::EepromReadByte:
    case Op::Input1:
    case Op::Input2:
    case Op::StatusRead:
    case Op::Flag:
        return {Shape::HexByte, 1};
    case Op::EepromReadFloat:
        return {Shape::Real, 1};
    case Op::EepromReadUint:
        return {Shape::Unsigned, 1};
    case Op::Index:
        return {Shape::Index, 1};
    case Op::PacketEnd:
        return {Shape::Count, 1};
    case Op::MpgReporting:
    case Op::MpgSilent:
    case Op::MpgOff:
        return {Shape::Echo, 1}; // "the reply echoes the command": 0 or 1 value accepted
    case Op::Repeat:
        return {Shape::Any, 0}; // the reply to whatever came before
    default:
        return {Shape::None, 0};
    }
}

bool fits(Shape shape, const Reply &r, std::size_t i)
{
    const std::string &v = r.values[i];
    switch (shape) {
    case Shape::Text:
        return !v.empty();
    case Shape::Id:
        return v.size() == 8 && v.find_first_not_of("0123456789") == std::string::npos;
    case Shape::Decimals:
        return r.decimal(i).has_value();
    case Shape::HexByte:
        return r.hexValue(i).has_value();
    case Shape::Real:
        return r.real(i).has_value();
    case Shape::Unsigned: {
        auto d = r.decimal(i);
        return d && *d >= 0 && *d <= 4294967295LL;
    }
    case Shape::Index: {
        auto d = r.decimal(i);
        return d && *d >= 0 && *d <= 255;
    }
    case Shape::Count: {
        auto d = r.decimal(i);
        return d && *d >= 0;
    }
    default:
        return true;
    }
}

} // namespace

std::string_view replyCodeText(ReplyCode code)
{
    switch (code) {
    case ReplyCode::Ok:
        return "OK";
    case ReplyCode::QueueFull:
        return "queue full";
    case ReplyCode::Watchdog:
        return "command not received completely in time";
    case ReplyCode::UnknownCommand:
        return "unknown command";
    case ReplyCode::Syntax:
        return "syntax error";
    case ReplyCode::OutOfRange:
        return "parameter out of range";
    case ReplyCode::NothingToContinue:
        return "nothing to continue";
    case ReplyCode::NotWhileRunning:
        return "not allowed while a vector runs";
    }
    return "?";
}

std::optional<std::vector<std::int64_t>> Reply::decimals() const
{
    std::vector<std::int64_t> out;
    out.reserve(values.size());
    for (const std::string &v : values) {
        auto d = parseDecimal(v);
        if (!d)
            return std::nullopt;
        out.push_back(*d);
    }
    return out;
}

std::optional<std::int64_t> Reply::decimal(std::size_t i) const
{
    if (i >= values.size())
        return std::nullopt;
    return parseDecimal(values[i]);
}

std::optional<std::uint8_t> Reply::hexValue(std::size_t i) const
{
    if (i >= values.size())
        return std::nullopt;
    return parseHexByte(values[i]);
}

std::optional<double> Reply::real(std::size_t i) const
{
    if (i >= values.size() || values[i].empty())
        return std::nullopt;
    std::string_view s = values[i];
    if (s.front() == '+')
        s.remove_prefix(1);
    double v = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v);
    if (ec != std::errc() || ptr != s.data() + s.size())
        return std::nullopt;
    return v;
}

ReplyResult decodeReply(std::string_view line, ChecksumMode mode)
{
    ReplyResult res;
    if (line.empty()) {
        res.error = error(DecodeErrorKind::Empty, line, "empty reply line");
        return res;
    }
    for (unsigned char c : line) {
        if (c < 0x20 || c > 0x7E) {
            res.error = error(DecodeErrorKind::BadCharacter, line,
                              "reply contains a non-printable byte 0x" + hexByte(c));
            return res;
        }
    }
    std::string_view body = line;
    if (mode != ChecksumMode::Off) {
        res.checksummed = stripChecksum(body);
        if (mode == ChecksumMode::On && !res.checksummed) {
            const auto comma = line.rfind(',');
            const bool hasField = comma != std::string_view::npos && line.size() - comma == 3 &&
                                  parseHexByte(line.substr(comma + 1));
            res.error = hasField ? error(DecodeErrorKind::BadChecksum, line, "reply checksum wrong")
                                 : error(DecodeErrorKind::MissingChecksum, line,
                                         "reply has no checksum although checksums are on");
            return res;
        }
    }
    const int status = hexDigit(body.front());
    if (status < 0 || (body.size() > 1 && body[1] != ',')) {
        res.error =
            error(DecodeErrorKind::BadStatus, line, "reply does not start with a status digit");
        return res;
    }
    Reply r;
    r.code = static_cast<ReplyCode>(status & 7);
    r.inta = (status & 8) != 0;
    if (body.size() > 1) {
        std::string_view rest = body.substr(2);
        while (true) {
            const auto comma = rest.find(',');
            std::string_view field = rest.substr(0, comma);
            if (field.empty()) {
                res.error = error(DecodeErrorKind::BadValues, line, "reply has an empty value");
                return res;
            }
            r.values.emplace_back(field);
            if (comma == std::string_view::npos)
                break;
            rest.remove_prefix(comma + 1);
        }
    }
    res.reply = std::move(r);
    return res;
}

DecodeError lineError(const Line &line)
{
    if (line.overlong)
        return error(DecodeErrorKind::Overlong, line.text,
                     "line longer than " + std::to_string(kMaxLineLength) + " bytes");
    return decodeReply(line.text, ChecksumMode::Off).error.value_or(DecodeError{});
}

std::optional<DecodeError> checkReplyShape(const Command &c, const Reply &r, std::string_view raw)
{
    const ShapeSpec spec = shapeOf(c.op);
    const std::string what = "reply to '" + encodeBody(c) + "'";
    if (spec.shape == Shape::Any)
        return std::nullopt;
    if (!r.ok() && c.op != Op::PacketEnd) {
        if (r.values.empty())
            return std::nullopt;
        return error(DecodeErrorKind::BadValues, raw, what + ": an error reply carries no values");
    }
    if (spec.shape == Shape::Echo && r.values.size() <= 1)
        return std::nullopt;
    if (c.op == Op::PacketEnd && !r.ok() && r.values.empty())
        return std::nullopt; // a unit may refuse *E without a count
    if (static_cast<int>(r.values.size()) != spec.count)
        return error(DecodeErrorKind::BadValues, raw,
                     what + ": expected " + std::to_string(spec.count) + " value(s), got " +
                         std::to_string(r.values.size()));
    for (std::size_t i = 0; i < r.values.size(); ++i) {
        if (!fits(spec.shape, r, i))
            return error(DecodeErrorKind::BadValues, raw,
                         what + ": value '" + r.values[i] + "' is malformed");
    }
    return std::nullopt;
}

std::string encodeReply(const Reply &r, bool checksums)
{
    std::string s(1, "0123456789ABCDEF"[(static_cast<int>(r.code) & 7) | (r.inta ? 8 : 0)]);
    for (const std::string &v : r.values) {
        s += ',';
        s += v;
    }
    if (checksums)
        s = withChecksum(s);
    s += '\r';
    return s;
}

std::optional<ReplyResult> ReplyDecoder::next(ChecksumMode mode)
{
    if (!m_lines.hasLine())
        return std::nullopt;
    Line l = m_lines.next();
    if (l.overlong) {
        ReplyResult r;
        r.error = lineError(l);
        return r;
    }
    return decodeReply(l.text, mode);
}

} // namespace frezka::protocol
