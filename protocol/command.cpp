#include "command.h"

#include "checksum.h"

#include <charconv>
#include <cstdio>

namespace frezka::protocol {
namespace {

Command make(Op op, std::uint8_t address = 0)
{
    Command c;
    c.op = op;
    c.address = address;
    return c;
}

Command scalar(Op op, std::int64_t v, std::uint8_t address = 0)
{
    Command c = make(op, address);
    c.args[0] = v;
    c.argCount = 1;
    return c;
}

Command components(Op op, std::initializer_list<std::int64_t> v)
{
    Command c = make(op);
    std::size_t i = 0;
    for (std::int64_t x : v)
        c.args[i++] = x;
    c.argCount = static_cast<std::uint8_t>(v.size());
    return c;
}

Command pair(Op op, std::int64_t a, std::int64_t b, std::uint8_t address = 0)
{
    Command c = make(op, address);
    c.args[0] = a;
    c.args[1] = b;
    c.argCount = 2;
    return c;
}

void appendHex(std::string &out, std::int64_t v)
{
    out += hexByte(static_cast<std::uint8_t>(v & 0xFF));
}

// Decimal text of a float that always reads as a float: 400 -> "400.0", 0.25 -> "0.25".
std::string decimalReal(double v)
{
    char buf[64];
    auto res = std::to_chars(buf, buf + sizeof buf, v);
    std::string s(buf, res.ptr);
    if (s.find_first_of(".eEn") == std::string::npos)
        s += ".0";
    return s;
}

} // namespace

namespace cmd {
Command version(std::uint8_t address)
{
    return make(Op::Version, address);
}
Command identify(std::uint8_t address)
{
    return make(Op::Identify, address);
}
Command line(std::int64_t x, std::int64_t y, std::int64_t z)
{
    return components(Op::Line, {x, y, z});
}
Command line(std::int64_t x, std::int64_t y, std::int64_t z, std::int64_t a)
{
    return components(Op::Line, {x, y, z, a});
}
Command vector(std::int64_t x, std::int64_t y, std::int64_t z)
{
    return components(Op::Vector, {x, y, z});
}
Command vector(std::int64_t x, std::int64_t y, std::int64_t z, std::int64_t a)
{
    return components(Op::Vector, {x, y, z, a});
}
Command pause(std::int64_t ms)
{
    return scalar(Op::Pause, ms);
}
Command shortThreshold(std::int64_t steps)
{
    return scalar(Op::ShortThreshold, steps);
}
Command accel(std::int64_t kiloPulsesPerS2)
{
    return scalar(Op::Accel, kiloPulsesPerS2);
}
Command speed(std::int64_t pulsesPerS)
{
    return scalar(Op::Speed, pulsesPerS);
}
Command velocityLimit(std::int64_t x, std::int64_t y, std::int64_t z)
{
    return components(Op::VelocityLimit, {x, y, z});
}
Command velocityLimit(std::int64_t x, std::int64_t y, std::int64_t z, std::int64_t a)
{
    return components(Op::VelocityLimit, {x, y, z, a});
}
Command brake(std::int64_t pulsesPerS)
{
    return scalar(Op::Brake, pulsesPerS);
}
Command speedModeVk()
{
    return make(Op::SpeedModeVk);
}
Command speedModeVn()
{
    return make(Op::SpeedModeVn);
}
Command exchangeAll()
{
    return make(Op::ExchangeAll);
}
Command exchangeUp()
{
    return make(Op::ExchangeUp);
}
Command exchangeDown()
{
    return make(Op::ExchangeDown);
}
Command multiplier(std::int64_t percent)
{
    return scalar(Op::Multiplier, percent);
}
Command positionXY()
{
    return make(Op::PositionXY);
}
Command positionXYZ()
{
    return make(Op::PositionXYZ);
}
Command positionXYZA()
{
    return make(Op::PositionXYZA);
}
Command zeroAll()
{
    return make(Op::ZeroAll);
}
Command setCounter(Axis axis, std::int64_t steps)
{
    Command c = scalar(Op::SetCounter, steps);
    c.axis = axis;
    return c;
}
Command home(Axis axis, std::int64_t travel, std::int64_t speedIn, std::int64_t backOff,
             std::int64_t speedOut)
{
    Command c = components(Op::Home, {travel, speedIn, backOff, speedOut});
    c.axis = axis;
    return c;
}
Command mpgReporting()
{
    return make(Op::MpgReporting);
}
Command mpgSilent()
{
    return make(Op::MpgSilent);
}
Command mpgOff()
{
    return make(Op::MpgOff);
}
Command keep()
{
    return make(Op::Keep);
}
Command restore()
{
    return make(Op::Restore);
}
Command halt()
{
    return make(Op::Halt);
}
Command deleteQueue()
{
    return make(Op::Delete);
}
Command go()
{
    return make(Op::Go);
}
Command eepromReadByte(int addr, std::uint8_t address)
{
    return scalar(Op::EepromReadByte, addr, address);
}
Command eepromWriteByte(int addr, int value, std::uint8_t address)
{
    return pair(Op::EepromWriteByte, addr, value, address);
}
Command eepromReadFloat(int addr, std::uint8_t address)
{
    return scalar(Op::EepromReadFloat, addr, address);
}
Command eepromReadUint(int addr, std::uint8_t address)
{
    return scalar(Op::EepromReadUint, addr, address);
}
Command eepromWriteFloat(int addr, double value, std::uint8_t address)
{
    Command c = scalar(Op::EepromWriteFloat, addr, address);
    c.real = value;
    c.argCount = 2; // address and the float
    return c;
}
Command eepromWriteUint(int addr, std::int64_t value, std::uint8_t address)
{
    return pair(Op::EepromWriteUint, addr, value, address);
}
Command output(int activeLowByte)
{
    return scalar(Op::Output, activeLowByte);
}
Command input1()
{
    return make(Op::Input1);
}
Command input2()
{
    return make(Op::Input2);
}
Command statusRead(int n)
{
    return scalar(Op::StatusRead, n);
}
Command statusWrite(int n, int value)
{
    return pair(Op::StatusWrite, n, value);
}
Command flag()
{
    return make(Op::Flag);
}
Command index(std::uint8_t address)
{
    return make(Op::Index, address);
}
Command repeat(std::uint8_t address)
{
    return make(Op::Repeat, address);
}
Command jump(std::uint8_t address)
{
    return make(Op::Jump, address);
}
Command checksumOn(std::uint8_t address)
{
    return make(Op::ChecksumOn, address);
}
Command checksumOff(std::uint8_t address)
{
    return make(Op::ChecksumOff, address);
}
Command packetStart()
{
    return make(Op::PacketStart);
}
Command packetEnd(std::int64_t count)
{
    return scalar(Op::PacketEnd, count);
}
Command spindle(std::int64_t perMille)
{
    return scalar(Op::SpindleSpeed, perMille, 7);
}
} // namespace cmd

std::string_view mnemonic(Op op)
{
    static constexpr std::string_view kNames[kOpCount] = {
        "?",  "Q",  "L",  "C", "T",  "$",  "A",   "V",   "VL",  "B",   "VK", "VN", "XA",
        "XU", "XD", "XM", "P", "PF", "P4", "N",   "N",   "W",   "Y+",  "Y&", "Y-", "K",
        "R",  "H",  "D",  "G", "ER", "EW", "EFR", "EUR", "EFW", "EUW", "O0", "I1", "I2",
        "SR", "SW", "F",  "@", ">",  "J",  "%+",  "%-",  "*S",  "*E",  "V"};
    return kNames[static_cast<int>(op)];
}

char axisLetter(Axis axis)
{
    return "XYZA"[static_cast<int>(axis)];
}

// One case per command shape: a table, kept whole so that every wire form is read in one place.
std::string encodeBody(const Command &c)
{
    std::string s = "!";
    s += static_cast<char>('0' + (c.address & 7));
    s += mnemonic(c.op);
    auto dec = [&s](std::int64_t v) { s += std::to_string(v); };
    switch (c.op) {
    case Op::Line:
    case Op::Vector:
    case Op::VelocityLimit:
        for (int i = 0; i < c.argCount; ++i) {
            if (i)
                s += ',';
            dec(c.args[i]);
        }
        break;
    case Op::Pause:
    case Op::ShortThreshold:
    case Op::Accel:
    case Op::Speed:
    case Op::Brake:
    case Op::Multiplier:
    case Op::PacketEnd:
    case Op::SpindleSpeed:
        dec(c.args[0]);
        break;
    case Op::SetCounter:
        s += axisLetter(c.axis);
        dec(c.args[0]);
        break;
    case Op::Home:
        s += axisLetter(c.axis);
        for (int i = 0; i < 4; ++i) {
            s += ',';
            dec(c.args[i]);
        }
        break;
    case Op::EepromReadByte:
    case Op::EepromReadFloat:
    case Op::EepromReadUint:
        appendHex(s, c.args[0]);
        break;
    case Op::EepromWriteByte:
        appendHex(s, c.args[0]);
        s += ',';
        appendHex(s, c.args[1]);
        break;
    case Op::EepromWriteFloat:
        appendHex(s, c.args[0]);
        s += ',';
        s += decimalReal(c.real);
        break;
    case Op::EepromWriteUint:
        appendHex(s, c.args[0]);
        s += ',';
        dec(c.args[1]);
        break;
    case Op::Output:
        s += ',';
        appendHex(s, c.args[0]);
        break;
    case Op::StatusRead:
        dec(c.args[0]);
        break;
    case Op::StatusWrite:
        dec(c.args[0]);
        s += ',';
        appendHex(s, c.args[1]);
        break;
    default:
        break;
    }
    return s;
}

std::string withChecksum(std::string_view body)
{
    std::string s(body);
    s += ',';
    s += hexByte(checksum(s));
    return s;
}

std::string encode(const Command &c, bool checksums)
{
    std::string s = checksums ? withChecksum(encodeBody(c)) : encodeBody(c);
    s += '\r';
    return s;
}

bool allowedInPacket(Op op)
{
    return op == Op::Vector || op == Op::Brake;
}

std::string encodePacket(std::span<const Command> commands, bool checksums)
{
    if (commands.empty())
        return {};
    // *S and *E go to the packet's address (a unit other than 0 on a shared line).
    Command start = cmd::packetStart();
    Command end = cmd::packetEnd(static_cast<std::int64_t>(commands.size()));
    start.address = end.address = commands.front().address;
    std::string s = encode(start, checksums);
    for (const Command &c : commands) {
        if (!allowedInPacket(c.op))
            return {};
        s += encode(c, checksums);
    }
    s += encode(end, checksums);
    return s;
}

} // namespace frezka::protocol
