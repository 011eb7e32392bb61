#pragma once
// GVE message checksum (docs/gve-protocol.md §2.1): the sum of all bytes of the message up to
// and including its last comma, modulo 256, written as two upper-case hex digits.

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace frezka::protocol {

// Sum of the bytes modulo 256.
std::uint8_t checksum(std::string_view bytes);
// Two upper-case hex digits of a byte: 0x4F -> "4F".
std::string hexByte(std::uint8_t value);
// Parses exactly two hex digits (either case); nullopt otherwise.
std::optional<std::uint8_t> parseHexByte(std::string_view text);

} // namespace frezka::protocol
