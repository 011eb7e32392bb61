#pragma once
// Parameter parsing of the emulated unit's command lines: decimal and hex numbers, comma lists,
// axis letters. Syntax errors give reply code 4, range errors 5 (docs/gve-protocol.md §2).

#include <cstdint>
#include <string>
#include <string_view>
#include <vector>

namespace frezka::emulator::args {

enum class Num { Ok, Syntax, Range };

struct Parsed
{
    Num status = Num::Syntax;
    std::int64_t value = 0;
};

// Decimal integer with optional sign; more digits than int64 holds is a range error.
Parsed parseDec(std::string_view s);
// Hex number of 1..8 digits (either case).
Parsed parseHex(std::string_view s);
// "a,b,,c" -> {"a", "b", "", "c"}; "" -> {""}.
std::vector<std::string_view> split(std::string_view s);
// Parses every value into `out`, then checks [lo, hi]: returns 0, 4 (a syntax error anywhere
// wins) or 5.
int parseAll(const std::vector<std::string_view> &parts, std::int64_t lo, std::int64_t hi,
             std::vector<std::int64_t> &out, bool hex = false);
// Two upper-case hex digits.
std::string hex2(int v);
// 'X'..'A' (either case) -> 0..3 when the unit has that axis, else -1.
int axisIndex(char c, int axisCount);

} // namespace frezka::emulator::args
