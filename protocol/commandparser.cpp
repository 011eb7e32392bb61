#include "commandparser.h"

#include "checksum.h"

#include <array>
#include <charconv>
#include <vector>

namespace frezka::protocol {
namespace {

struct Mnemonic
{
    std::string_view text;
    Op op;
};

// Longest first, so that "VL" wins over "V" and "EFR" over "E..".
constexpr std::array<Mnemonic, 48> kMnemonics{{
    {"EFR", Op::EepromReadFloat},
    {"EUR", Op::EepromReadUint},
    {"EFW", Op::EepromWriteFloat},
    {"EUW", Op::EepromWriteUint},
    {"VL", Op::VelocityLimit},
    {"VK", Op::SpeedModeVk},
    {"VN", Op::SpeedModeVn},
    {"XA", Op::ExchangeAll},
    {"XU", Op::ExchangeUp},
    {"XD", Op::ExchangeDown},
    {"XM", Op::Multiplier},
    {"PF", Op::PositionXYZ},
    {"P4", Op::PositionXYZA},
    {"ER", Op::EepromReadByte},
    {"EW", Op::EepromWriteByte},
    {"SR", Op::StatusRead},
    {"SW", Op::StatusWrite},
    {"I1", Op::Input1},
    {"I2", Op::Input2},
    {"O0", Op::Output},
    {"Y+", Op::MpgReporting},
    {"Y&", Op::MpgSilent},
    {"Y-", Op::MpgOff},
    {"%+", Op::ChecksumOn},
    {"%-", Op::ChecksumOff},
    {"*S", Op::PacketStart},
    {"*E", Op::PacketEnd},
    {"?", Op::Version},
    {"Q", Op::Identify},
    {"L", Op::Line},
    {"C", Op::Vector},
    {"T", Op::Pause},
    {"$", Op::ShortThreshold},
    {"A", Op::Accel},
    {"V", Op::Speed},
    {"B", Op::Brake},
    {"P", Op::PositionXY},
    {"N", Op::ZeroAll},
    {"W", Op::Home},
    {"K", Op::Keep},
    {"R", Op::Restore},
    {"H", Op::Halt},
    {"D", Op::Delete},
    {"G", Op::Go},
    {"F", Op::Flag},
    {"@", Op::Index},
    {">", Op::Repeat},
    {"J", Op::Jump},
}};

struct ArgError
{
    ReplyCode code;
    ParseProblem problem;
    std::string field; // the parameter it names, if any
};

class Args
{
public:
    explicit Args(std::string_view text)
        : m_text(text)
    {}

    std::vector<std::string_view> fields() const
    {
        std::vector<std::string_view> out;
        std::string_view rest = m_text;
        while (true) {
            const auto comma = rest.find(',');
            out.push_back(rest.substr(0, comma));
            if (comma == std::string_view::npos)
                return out;
            rest.remove_prefix(comma + 1);
        }
    }

private:
    std::string_view m_text;
};

// Decimal integer; code 4 when malformed, 5 when it does not fit 64 bits.
std::optional<ArgError> decimal(std::string_view s, std::int64_t &out)
{
    if (s.empty())
        return ArgError{ReplyCode::Syntax, ParseProblem::MissingNumber, {}};
    std::string_view d = s.front() == '+' ? s.substr(1) : s;
    auto [ptr, ec] = std::from_chars(d.data(), d.data() + d.size(), out);
    if (ec == std::errc::result_out_of_range)
        return ArgError{ReplyCode::OutOfRange, ParseProblem::NumberTooLarge, std::string(s)};
    if (ec != std::errc() || ptr != d.data() + d.size() || d.empty())
        return ArgError{ReplyCode::Syntax, ParseProblem::NotDecimal, std::string(s)};
    return std::nullopt;
}

std::optional<ArgError> hex(std::string_view s, std::int64_t &out)
{
    if (s.empty() || s.size() > 2)
        return ArgError{ReplyCode::Syntax, ParseProblem::NotHexByte, std::string(s)};
    unsigned v = 0;
    auto [ptr, ec] = std::from_chars(s.data(), s.data() + s.size(), v, 16);
    if (ec != std::errc() || ptr != s.data() + s.size())
        return ArgError{ReplyCode::Syntax, ParseProblem::NotHexByte, std::string(s)};
    out = v;
    return std::nullopt;
}

std::optional<ArgError> real(std::string_view s, double &out)
{
    std::string_view d = !s.empty() && s.front() == '+' ? s.substr(1) : s;
    auto [ptr, ec] = std::from_chars(d.data(), d.data() + d.size(), out);
    if (d.empty() || ec != std::errc() || ptr != d.data() + d.size())
        return ArgError{ReplyCode::Syntax, ParseProblem::NotANumber, std::string(s)};
    return std::nullopt;
}

std::optional<ArgError> count(const std::vector<std::string_view> &f, std::size_t lo,
                              std::size_t hi)
{
    if (f.size() < lo || f.size() > hi)
        return ArgError{ReplyCode::Syntax, ParseProblem::ParameterCount, {}};
    return std::nullopt;
}

std::optional<Axis> axisFrom(char c)
{
    switch (c) {
    case 'X':
        return Axis::X;
    case 'Y':
        return Axis::Y;
    case 'Z':
        return Axis::Z;
    case 'A':
        return Axis::A;
    default:
        return std::nullopt;
    }
}

std::optional<ArgError> decimals(Command &c, std::string_view text, std::size_t lo, std::size_t hi)
{
    const auto f = Args(text).fields();
    if (auto e = count(f, lo, hi))
        return e;
    for (std::size_t i = 0; i < f.size(); ++i) {
        if (auto e = decimal(f[i], c.args[i]))
            return e;
    }
    c.argCount = static_cast<std::uint8_t>(f.size());
    return std::nullopt;
}

// "<hex>,<hex|decimal|real>" or "<hex>" for the EEPROM, output and status commands.
std::optional<ArgError> addressed(Command &c, std::string_view text, bool hasValue,
                                  bool decimalIndex)
{
    const auto f = Args(text).fields();
    if (auto e = count(f, hasValue ? 2 : 1, hasValue ? 2 : 1))
        return e;
    if (auto e = decimalIndex ? decimal(f[0], c.args[0]) : hex(f[0], c.args[0]))
        return e;
    c.argCount = static_cast<std::uint8_t>(f.size());
    if (!hasValue)
        return std::nullopt;
    switch (c.op) {
    case Op::EepromWriteFloat:
        return real(f[1], c.real);
    case Op::EepromWriteUint:
        return decimal(f[1], c.args[1]);
    default:
        return hex(f[1], c.args[1]);
    }
}

std::optional<ArgError> parseArgs(Command &c, std::string_view text)
{
    switch (c.op) {
    case Op::Line:
    case Op::Vector:
    case Op::VelocityLimit: // adopted reading §4: fewer than 3 components is code 4
        return decimals(c, text, 3, 4);
    case Op::Pause:
    case Op::ShortThreshold:
    case Op::Accel:
    case Op::Speed:
    case Op::Brake:
    case Op::Multiplier:
    case Op::PacketEnd:
    case Op::SpindleSpeed:
        return decimals(c, text, 1, 1);
    case Op::SetCounter: {
        c.axis = *axisFrom(text.front());
        return decimals(c, text.substr(1), 1, 1);
    }
    case Op::Home: {
        const auto axis = text.empty() ? std::nullopt : axisFrom(text.front());
        if (!axis)
            return ArgError{ReplyCode::Syntax, ParseProblem::HomeNeedsAxis, {}};
        c.axis = *axis;
        text.remove_prefix(1);
        if (!text.empty() && text.front() == ',') // GVE114 prints it without this comma
            text.remove_prefix(1);
        return decimals(c, text, 4, 4);
    }
    case Op::EepromReadByte:
    case Op::EepromReadFloat:
    case Op::EepromReadUint:
        return addressed(c, text, false, false);
    case Op::EepromWriteByte:
    case Op::EepromWriteFloat:
    case Op::EepromWriteUint:
        return addressed(c, text, true, false);
    case Op::Output:
        if (text.empty() || text.front() != ',')
            return ArgError{ReplyCode::Syntax, ParseProblem::OutputNeedsByte, {}};
        c.argCount = 1;
        return hex(text.substr(1), c.args[0]);
    case Op::StatusRead:
        return addressed(c, text, false, true);
    case Op::StatusWrite:
        return addressed(c, text, true, true);
    default:
        if (!text.empty())
            return ArgError{ReplyCode::Syntax, ParseProblem::UnexpectedParameters, {}};
        return std::nullopt;
    }
}

ParsedCommand failure(std::string_view line, std::uint8_t address, ReplyCode code,
                      ParseProblem problem, std::string field = {})
{
    ParsedCommand p;
    p.status = ParseStatus::Error;
    p.address = address;
    p.code = code;
    p.problem = problem;
    p.line = std::string(line);
    p.field = std::move(field);
    p.message = parseProblemText(p);
    return p;
}

} // namespace

ParsedCommand parseCommand(std::string_view line, bool checksums)
{
    if (line.size() < 2 || line[0] != '!' || line[1] < '0' || line[1] > '7') {
        ParsedCommand p;
        p.line = std::string(line);
        return p;
    }
    const auto address = static_cast<std::uint8_t>(line[1] - '0');
    std::string_view body = line;
    if (checksums) {
        const auto comma = body.rfind(',');
        const auto sum = comma == std::string_view::npos || body.size() - comma != 3
                             ? std::nullopt
                             : parseHexByte(body.substr(comma + 1));
        if (!sum || *sum != checksum(body.substr(0, comma + 1))) {
            ParsedCommand p = failure(line, address, ReplyCode::Syntax, ParseProblem::BadChecksum);
            p.checksumFailed = true;
            return p;
        }
        body = body.substr(0, comma);
    }
    std::string_view rest = body.substr(2);
    for (const Mnemonic &m : kMnemonics) {
        if (!rest.starts_with(m.text))
            continue;
        Command c;
        c.op = m.op;
        c.address = address;
        if (c.op == Op::Speed && address == 7)
            c.op = Op::SpindleSpeed;
        std::string_view args = rest.substr(m.text.size());
        if (c.op == Op::ZeroAll && !args.empty() && axisFrom(args.front()))
            c.op = Op::SetCounter;
        if (auto e = parseArgs(c, args))
            return failure(line, address, e->code, e->problem, e->field);
        ParsedCommand p;
        p.status = ParseStatus::Ok;
        p.address = address;
        p.command = c;
        p.problem = ParseProblem::None;
        p.line = std::string(line);
        return p;
    }
    return failure(line, address, ReplyCode::UnknownCommand, ParseProblem::UnknownCommand);
}

std::string parseProblemText(const ParsedCommand &p)
{
    const std::string at = "'" + p.line + "': ";
    switch (p.problem) {
    case ParseProblem::None:
    case ParseProblem::NoAddress:
        return {};
    case ParseProblem::BadChecksum:
        return at + "missing or wrong checksum";
    case ParseProblem::UnknownCommand:
        return "unknown command '" + p.line + "'";
    case ParseProblem::MissingNumber:
        return at + "missing number";
    case ParseProblem::NumberTooLarge:
        return at + "number out of range: " + p.field;
    case ParseProblem::NotDecimal:
        return at + "not a decimal number: " + p.field;
    case ParseProblem::NotHexByte:
        return at + "not a hex byte: " + p.field;
    case ParseProblem::NotANumber:
        return at + "not a number: " + p.field;
    case ParseProblem::ParameterCount:
        return at + "wrong number of parameters";
    case ParseProblem::HomeNeedsAxis:
        return at + "W needs an axis X, Y, Z or A";
    case ParseProblem::OutputNeedsByte:
        return at + "O0 needs ',hh'";
    case ParseProblem::UnexpectedParameters:
        return at + "unexpected parameters";
    }
    return {};
}

ReplyCode unitCheck(const Command &c, Variant variant, int maxPulseRate)
{
    switch (validate(c, variant, maxPulseRate).error) {
    case CommandError::None:
        return ReplyCode::Ok;
    case CommandError::AxisCount:
        return ReplyCode::Syntax;
    case CommandError::OutOfRange:
        return ReplyCode::OutOfRange;
    default:
        return ReplyCode::UnknownCommand;
    }
}

} // namespace frezka::protocol
