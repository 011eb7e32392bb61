#pragma once
// Z-position link of K51-1 (KONFIG6 = 1) and ANC 3.67 (k51-protocol.md §5). Pure C++, no Qt.
//
// FORM=1, two-way ASCII; every message ends with a space, numbers are decimal millimetres with
// optional leading zeros:
//   PC -> controller  "Z? "            controller -> PC  "Z=-0001.234 "
//   PC -> controller  "GO 0012.123 "   controller -> PC  "Z=0012.123 " once reached
//   first bad character -> "E0 ", each further one -> "E1 "
// The manual shows both "," and "." as the decimal mark; both are accepted, "." is sent.
// FORM=2, one-way binary, periodic: position low, middle, high byte + a checksum byte making
// the 8-bit sum zero. Adopted reading: the 24 bits are a two's-complement count of micrometres
// (FORM=1 shows three decimals of a millimetre).
// Positions are integer micrometres throughout (no rounding drift).

#include "driver/grinder/frame.h"

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <vector>

namespace frezka::grinder {

// "-0001.234" from -1234 um (sign only when negative, 4 integer digits, 3 decimals).
std::string formatMillimetres(std::int64_t positionUm);
// Micrometres from "[+|-]digits[(.|,)digits]" with at most 3 decimals; nullopt otherwise.
std::optional<std::int64_t> parseMillimetres(std::string_view text);
// The largest |position| a FORM=1 GO can name: four digits before the decimal mark
// ("GO 9999.999 "), the same limit in the window and the CLI.
constexpr std::int64_t kMaxGoUm = 9'999'999;

std::string zQueryMessage();                          // "Z? "
std::string goMessage(std::int64_t targetUm);         // "GO 0012.123 "
std::string positionMessage(std::int64_t positionUm); // "Z=-0001.234 "

struct ZReply
{
    enum class Kind {
        Position, // Z=... (answer to Z? or GO reached)
        BadFirst, // E0: the controller rejected the first bad character
        BadMore,  // E1: a further bad character
        Unknown,  // anything else: reported with its text
    };
    Kind kind = Kind::Unknown;
    std::int64_t positionUm = 0;
    std::string text; // the message without its terminating space
    bool operator==(const ZReply &) const = default;
};

// PC side of FORM=1: splits the controller's stream at spaces and parses each message.
class ZAsciiReader
{
public:
    void feed(const std::uint8_t *bytes, std::size_t size, std::vector<ZReply> &replies);
    void reset() { m_text.clear(); }
    const std::string &pending() const { return m_text; }

private:
    std::string m_text;
};

constexpr std::size_t kZBinaryFrameSize = 4;
// FORM=2 frame of a position (micrometres, 24-bit two's complement; clamped to its range).
Bytes encodeZBinary(std::int64_t positionUm);

struct ZBinaryEvent
{
    bool position = true; // false: a byte was skipped to regain frame alignment
    std::int64_t positionUm = 0;
    std::uint8_t skipped = 0;
    bool operator==(const ZBinaryEvent &) const = default;
};

// PC side of FORM=2. The frames have no start marker: a 4-byte window whose sum is zero is a
// frame; otherwise its first byte is skipped (and reported) until one is.
class ZBinaryDecoder
{
public:
    void feed(const std::uint8_t *bytes, std::size_t size, std::vector<ZBinaryEvent> &events);
    void reset() { m_window.clear(); }

private:
    Bytes m_window;
};

} // namespace frezka::grinder
