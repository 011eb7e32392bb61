#pragma once
// Unit side of the codec: one received command line -> Command, or the reply code a unit gives
// for it (docs/gve-protocol.md §2). Used by the emulator and by round-trip tests.
//
// parseCommand() checks the framing, the checksum and the syntax; unitCheck() then applies the
// variant table (validate() in command.h) and maps its verdict to the unit's reply code.

#include "protocol/command.h"
#include "protocol/reply.h"

#include <string>
#include <string_view>

namespace frezka::protocol {

enum class ParseStatus : std::uint8_t {
    Ok,          // command parsed
    NotACommand, // no '!' + address digit at the start: a unit ignores the line
    Error,       // addressed, but malformed: reply with code
};

// Why a line is not a command a unit accepts, with ParsedCommand::field where it names one.
enum class ParseProblem : std::uint8_t {
    None,
    NoAddress,            // not '!' and an address digit at the start (status NotACommand)
    BadChecksum,          // missing or wrong checksum
    UnknownCommand,       // no command of the protocol
    MissingNumber,        // an empty parameter
    NumberTooLarge,       // `field` does not fit 64 bits
    NotDecimal,           // `field` is not a decimal number
    NotHexByte,           // `field` is not a hex byte
    NotANumber,           // `field` is not a number
    ParameterCount,       // wrong number of parameters
    HomeNeedsAxis,        // W without X, Y, Z or A
    OutputNeedsByte,      // O0 without ',hh'
    UnexpectedParameters, // parameters after a command that takes none
};

struct ParsedCommand
{
    ParseStatus status = ParseStatus::NotACommand;
    std::uint8_t address = 0;
    Command command;                // valid when status == Ok
    ReplyCode code = ReplyCode::Ok; // when status == Error: UnknownCommand / Syntax / OutOfRange
    bool checksumFailed = false;    // Error because the checksum was missing or wrong
    std::string message;            // English, for logs (parseProblemText)
    ParseProblem problem = ParseProblem::NoAddress; // when status != Ok
    std::string line;                               // the line parsed
    std::string field;                              // the parameter the problem names
    friend bool operator==(const ParsedCommand &, const ParsedCommand &) = default;
};

// The English text of a parse problem ("'!0V1x': not a decimal number: 1x").
std::string parseProblemText(const ParsedCommand &p);

// Parses a line (without CR). checksums: whether the unit currently expects ",HH".
ParsedCommand parseCommand(std::string_view line, bool checksums);

// The reply code a unit of the given variant gives a parsed command that fails validate():
// Ok when it passes; UnknownCommand for a command the variant lacks; Syntax for a wrong
// component count (adopted reading §4); OutOfRange for a value outside its range.
ReplyCode unitCheck(const Command &c, Variant variant, int maxPulseRate = 0);

} // namespace frezka::protocol
