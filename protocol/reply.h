#pragma once
// Unit replies (docs/gve-protocol.md §2): one hex digit (bit 3 INTA, bits 0-2 code), optional
// ','-separated values, optional ",HH" checksum, CR.
//
// decodeReply() turns one complete line into a Reply or a DecodeError that keeps the raw text;
// checkReplyShape() checks that the values fit the command the reply answers; typed accessors
// read them. The incremental part (bytes in any split -> lines) is LineAssembler in lines.h;
// ReplyDecoder joins the two.

#include "protocol/command.h"
#include "protocol/lines.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frezka::protocol {

enum class ReplyCode : std::uint8_t {
    Ok = 0,
    QueueFull = 1, // or, for L, queue not yet empty: wait and send again
    Watchdog = 2,  // command not received completely in time
    UnknownCommand = 3,
    Syntax = 4, // also: bad checksum (adopted reading §2.1)
    OutOfRange = 5,
    NothingToContinue = 6, // G without INTA
    NotWhileRunning = 7,
};

// English meaning of a code ("queue full").
std::string_view replyCodeText(ReplyCode code);

struct Reply
{
    ReplyCode code = ReplyCode::Ok;
    bool inta = false;               // bit 3: an interrupt/stop has been accepted
    std::vector<std::string> values; // the fields after the status digit, checksum removed
    friend bool operator==(const Reply &, const Reply &) = default;

    bool ok() const { return code == ReplyCode::Ok; }
    // All values as signed decimal integers; nullopt when one is not.
    std::optional<std::vector<std::int64_t>> decimals() const;
    // Value i as a signed decimal integer / two-digit hex byte / decimal float.
    std::optional<std::int64_t> decimal(std::size_t i = 0) const;
    std::optional<std::uint8_t> hexValue(std::size_t i = 0) const;
    std::optional<double> real(std::size_t i = 0) const;
};

enum class DecodeErrorKind : std::uint8_t {
    Empty,           // a bare CR
    BadStatus,       // first character not a hex digit, or not followed by ',' / end
    BadChecksum,     // checksum present but wrong
    MissingChecksum, // checksums on but the line has none
    BadValues,       // values do not fit the command (count or format)
    Overlong,        // no CR within kMaxLineLength bytes
    BadCharacter,    // a byte outside printable ASCII
};

struct DecodeError
{
    DecodeErrorKind kind = DecodeErrorKind::Empty;
    std::string raw;     // the line as received (without CR), for the user
    std::string message; // English description
    friend bool operator==(const DecodeError &, const DecodeError &) = default;
};

enum class ChecksumMode : std::uint8_t {
    Off,  // no checksum expected; a trailing ",HH" is a value
    On,   // the line must end with a valid ",HH"
    Auto, // strip a trailing ",HH" only when it is a valid checksum (used while the unit's
          // checksum state is unknown, e.g. around %+ and %- when connecting)
};

struct ReplyResult
{
    std::optional<Reply> reply; // set on success
    std::optional<DecodeError> error;
    bool checksummed = false; // the line carried a valid checksum
    friend bool operator==(const ReplyResult &, const ReplyResult &) = default;
};

// Decodes one line (without its CR).
ReplyResult decodeReply(std::string_view line, ChecksumMode mode);
// The error a LineAssembler event stands for as a DecodeError (Overlong / BadCharacter).
DecodeError lineError(const Line &line);

// Checks the values of a reply against the command it answers (a PF reply has 3 decimals, an
// SR reply one hex byte, ...). Error replies (code != 0) carry no values, except *E which
// carries the number of accepted commands. Returns the problem, or nullopt when it fits.
std::optional<DecodeError> checkReplyShape(const Command &c, const Reply &r, std::string_view raw);

// Unit side: the bytes of a reply line, CR-terminated, with ",HH" when checksums are on.
std::string encodeReply(const Reply &r, bool checksums);

// Incremental reply decoding: feed bytes as they come (one at a time, split anyhow), take
// decoded lines in order. Unsolicited or garbled lines come out as errors with their raw text;
// nothing is dropped silently.
class ReplyDecoder
{
public:
    void feed(std::string_view bytes) { m_lines.feed(bytes); }
    // The next complete line decoded with the given checksum mode, or nullopt if none yet.
    std::optional<ReplyResult> next(ChecksumMode mode);
    // The next complete raw line (for callers that decode themselves).
    std::optional<Line> nextLine()
    {
        if (!m_lines.hasLine())
            return std::nullopt;
        return m_lines.next();
    }
    bool hasLine() const { return m_lines.hasLine(); }
    // Bytes of an unfinished line (for a "partial reply" diagnosis on timeout).
    const std::string &pending() const { return m_lines.pending(); }
    void clear() { m_lines.clear(); }

private:
    LineAssembler m_lines;
};

} // namespace frezka::protocol
