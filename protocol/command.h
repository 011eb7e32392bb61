#pragma once
// Typed GVE unit commands (docs/gve-protocol.md §2-§13) and their wire form.
//
// A Command is a plain value: which operation, which address (0 = interpolator, 7 = spindle
// unit of GVE64/GVE114), and its arguments. Build them with the factory functions in
// namespace cmd (cmd::vector(697, 30, 0)), turn them into bytes with encode(), and check them
// against a variant before sending with validate(). The reverse direction (bytes -> Command,
// what a unit does) is in commandparser.h.
//
// Wire form: '!' address op [args separated by ','] CR, or with checksums on
// '!' address op [args] ',' HH CR where HH = checksum of everything up to that last comma.

#include "protocol/variant.h"

#include <array>
#include <cstdint>
#include <optional>
#include <span>
#include <string>
#include <string_view>

namespace frezka::protocol {

enum class Op : std::uint8_t {
    Version,          // ?            -> 0,<firmware text>
    Identify,         // Q            -> 0,ddmmyypp
    Line,             // Lx,y,z[,a]   stand-alone move, relative steps
    Vector,           // Cx,y,z[,a]   continuous vector, relative steps
    Pause,            // Tn           ms between non-continuous moves, 1..24
    ShortThreshold,   // $n           steps
    Accel,            // An           thousands of pulses/s^2
    Speed,            // Vn           pulses/s (address 0)
    VelocityLimit,    // VLx,y,z[,a]  pulses/s per axis
    Brake,            // Bn           pulses/s
    SpeedModeVk,      // VK           path speeds
    SpeedModeVn,      // VN           major-axis speeds
    ExchangeAll,      // XA           queued speeds := last V
    ExchangeUp,       // XU           queued speeds + 1/16
    ExchangeDown,     // XD           queued speeds - 1/16
    Multiplier,       // XMn          percent of V
    PositionXY,       // P            -> 0,x,y
    PositionXYZ,      // PF           -> 0,x,y,z
    PositionXYZA,     // P4           -> 0,x,y,z,a
    ZeroAll,          // N
    SetCounter,       // N<axis>n     NX100
    Home,             // W<axis>,n2,n3,n4,n5
    MpgReporting,     // Y+
    MpgSilent,        // Y&
    MpgOff,           // Y-
    Keep,             // K
    Restore,          // R
    Halt,             // H            replies when stopped
    Delete,           // D
    Go,               // G
    EepromReadByte,   // ERaa         -> 0,hh
    EepromWriteByte,  // EWaa,hh
    EepromReadFloat,  // EFRaa        -> 0,<decimal>
    EepromReadUint,   // EURaa        -> 0,<decimal>
    EepromWriteFloat, // EFWaa,<decimal>
    EepromWriteUint,  // EUWaa,<decimal>
    Output,           // O0,hh        outputs active low
    Input1,           // I1           -> 0,hh (IN0..IN7)
    Input2,           // I2           -> 0,hh (bit6 IN14, bit7 IN15)
    StatusRead,       // SRn          -> 0,hh, n = 0..6
    StatusWrite,      // SWn,hh       n = 0..6
    Flag,             // F            -> 0,hh (ST6 + bit5 queue full)
    Index,            // @            -> 0,n (decimal, mod 256)
    Repeat,           // >            last reply again
    Jump,             // J            reset
    ChecksumOn,       // %+
    ChecksumOff,      // %-
    PacketStart,      // *S
    PacketEnd,        // *En          -> code,accepted
    SpindleSpeed,     // V n on address 7: per mille of 0-10 V / PWM duty, 0..1000
};

// Number of Op values (for tables and exhaustive tests).
inline constexpr int kOpCount = static_cast<int>(Op::SpindleSpeed) + 1;

enum class Axis : std::uint8_t { X, Y, Z, A };

struct Command
{
    Op op = Op::Version;
    std::uint8_t address = 0;           // 0..7; 7 = spindle unit (GVE64/GVE114)
    std::array<std::int64_t, 4> args{}; // numeric arguments, meaning per Op (see cmd::)
    std::uint8_t argCount = 0;          // components used for L/C/VL (3 or 4), else per Op
    Axis axis = Axis::X;                // SetCounter, Home
    double real = 0;                    // EepromWriteFloat value
    friend bool operator==(const Command &, const Command &) = default;
};

// Factory functions: one per operation, arguments in the units of the wire.
namespace cmd {
Command version(std::uint8_t address = 0);
Command identify(std::uint8_t address = 0);
Command line(std::int64_t x, std::int64_t y, std::int64_t z);
Command line(std::int64_t x, std::int64_t y, std::int64_t z, std::int64_t a);
Command vector(std::int64_t x, std::int64_t y, std::int64_t z);
Command vector(std::int64_t x, std::int64_t y, std::int64_t z, std::int64_t a);
Command pause(std::int64_t ms);
Command shortThreshold(std::int64_t steps);
Command accel(std::int64_t kiloPulsesPerS2);
Command speed(std::int64_t pulsesPerS);
Command velocityLimit(std::int64_t x, std::int64_t y, std::int64_t z);
Command velocityLimit(std::int64_t x, std::int64_t y, std::int64_t z, std::int64_t a);
Command brake(std::int64_t pulsesPerS);
Command speedModeVk();
Command speedModeVn();
Command exchangeAll();
Command exchangeUp();
Command exchangeDown();
Command multiplier(std::int64_t percent);
Command positionXY();
Command positionXYZ();
Command positionXYZA();
Command zeroAll();
Command setCounter(Axis axis, std::int64_t steps);
// W: toward the switch up to |travel| steps in its sign's direction at speedIn pulses/s, then
// off it up to backOff steps at speedOut pulses/s.
Command home(Axis axis, std::int64_t travel, std::int64_t speedIn, std::int64_t backOff,
             std::int64_t speedOut);
Command mpgReporting();
Command mpgSilent();
Command mpgOff();
Command keep();
Command restore();
Command halt();
Command deleteQueue();
Command go();
Command eepromReadByte(int addr, std::uint8_t address = 0);
Command eepromWriteByte(int addr, int value, std::uint8_t address = 0);
Command eepromReadFloat(int addr, std::uint8_t address = 0);
Command eepromReadUint(int addr, std::uint8_t address = 0);
Command eepromWriteFloat(int addr, double value, std::uint8_t address = 0);
Command eepromWriteUint(int addr, std::int64_t value, std::uint8_t address = 0);
Command output(int activeLowByte);
Command input1();
Command input2();
Command statusRead(int n);
Command statusWrite(int n, int value);
Command flag();
Command index(std::uint8_t address = 0);
Command repeat(std::uint8_t address = 0);
Command jump(std::uint8_t address = 0);
Command checksumOn(std::uint8_t address = 0);
Command checksumOff(std::uint8_t address = 0);
Command packetStart();
Command packetEnd(std::int64_t count);
Command spindle(std::int64_t perMille);
} // namespace cmd

// The message text without terminator or checksum: "!0C697,30,0".
std::string encodeBody(const Command &c);
// Bytes to send: body + CR, or body + ',' + HH + CR when checksums are on.
std::string encode(const Command &c, bool checksums);
// Appends ",HH" to a body (the checksum of body + ',').
std::string withChecksum(std::string_view body);

// Whether a command may go inside a *S .. *E packet (only C and B, §2.2).
bool allowedInPacket(Op op);
// The bytes of a whole packet: *S, the commands, *E n. Empty result when a command is not
// allowed in a packet or the span is empty (check with validatePacket first).
std::string encodePacket(std::span<const Command> commands, bool checksums);

// Why a command cannot be sent to a unit: the kind (CommandError, which reply code a unit gives)
// and exactly what is wrong (CommandProblem with its values), so that a Qt layer words it in the
// user's language (the driver's code table); `message` is the same in English, for logs.
enum class CommandError : std::uint8_t {
    None,
    BadAddress,   // address not 0..7, or the command does not exist on that address
    NotOnVariant, // the variant has no such command (e.g. Y on GVE84, P4 on 3 axes)
    AxisCount,    // wrong number of vector components for the variant
    OutOfRange,   // an argument outside the documented range
    NotInPacket,  // only C and B belong in a packet
    EmptyPacket,
};

// What CommandCheck's values mean for each problem (command = the body, "!0XM0").
enum class CommandProblem : std::uint8_t {
    None,
    AddressRange,      // the address is not 0..7
    NoSpindleAddress,  // unit has no address 7 (spindle)
    NotOnAddress7,     // the command is not one of address 7
    SpindleOnAddress7, // the spindle speed goes to address 7
    AddressZeroOnly,   // unit answers on address 0 only
    ComponentCount,    // value components; unit takes 3 (high: 3) or 3 or 4 (high: 4)
    ValueOutOfRange,   // argument `what` is `value`, outside low..high
    NotFinite,         // the value is not a finite number
    ZeroTravel,        // the travel toward the switch is 0
    NoSuchAxis,        // unit has no axis `what` (its letter)
    NoSuchCommand,     // unit has no command `what` (its mnemonic)
    NotInPacket,       // only C and B belong in a packet
    EmptyPacket,       // a packet needs at least one command
};

struct CommandCheck
{
    CommandError error = CommandError::None;
    std::string message; // English, names the command and the bad value (commandProblemText)
    CommandProblem problem = CommandProblem::None;
    std::string command; // the command's body ("!0XM0"); empty for an empty packet
    std::string unit;    // the variant's name, where the problem names it
    std::string what;    // the argument's English name ("speed"), an axis letter or a mnemonic
    std::int64_t value = 0, low = 0, high = 0;
    explicit operator bool() const { return error != CommandError::None; }
    friend bool operator==(const CommandCheck &, const CommandCheck &) = default;
};

// The English text of a check's problem, from its values ("'!0XM0': multiplier (%) 0 is
// outside 1..2147483647").
std::string commandProblemText(const CommandCheck &check);

// Checks a command against the variant table before it is sent. maxPulseRate: the unit's
// ordered maximum (pulses/s); 0 = the highest rate the variant can be ordered with.
CommandCheck validate(const Command &c, Variant variant, int maxPulseRate = 0);
// Checks every command of a packet (allowed op, validate()) and that it is not empty.
CommandCheck validatePacket(std::span<const Command> commands, Variant variant,
                            int maxPulseRate = 0);

// The wire mnemonic of an op ("C", "PF", "EFW", "*E"); "V" for SpindleSpeed.
std::string_view mnemonic(Op op);
// Axis letter 'X'..'A'.
char axisLetter(Axis axis);

} // namespace frezka::protocol
