#include "driver/emulator/commandargs.h"

#include <cctype>
#include <charconv>

namespace frezka::emulator::args {

Parsed parseDec(std::string_view s)
{
    if (!s.empty() && s.front() == '+')
        s.remove_prefix(1);
    if (s.empty())
        return {};
    bool neg = false;
    std::string_view digits = s;
    if (digits.front() == '-') {
        neg = true;
        digits.remove_prefix(1);
    }
    if (digits.empty())
        return {};
    for (char c : digits) {
        if (c < '0' || c > '9')
            return {};
    }
    std::int64_t v = 0;
    const auto res = std::from_chars(digits.data(), digits.data() + digits.size(), v);
    if (res.ec == std::errc::result_out_of_range)
        return {Num::Range, 0};
    return {Num::Ok, neg ? -v : v};
}

Parsed parseHex(std::string_view s)
{
    if (s.empty() || s.size() > 8)
        return {s.empty() ? Num::Syntax : Num::Range, 0};
    std::uint64_t v = 0;
    const auto res = std::from_chars(s.data(), s.data() + s.size(), v, 16);
    if (res.ec != std::errc() || res.ptr != s.data() + s.size())
        return {};
    return {Num::Ok, static_cast<std::int64_t>(v)};
}

std::vector<std::string_view> split(std::string_view s)
{
    std::vector<std::string_view> parts;
    std::size_t start = 0;
    for (;;) {
        const auto comma = s.find(',', start);
        parts.push_back(s.substr(start, comma - start));
        if (comma == std::string_view::npos)
            return parts;
        start = comma + 1;
    }
}

int parseAll(const std::vector<std::string_view> &parts, std::int64_t lo, std::int64_t hi,
             std::vector<std::int64_t> &out, bool hex)
{
    int code = 0;
    out.clear();
    for (auto p : parts) {
        const Parsed v = hex ? parseHex(p) : parseDec(p);
        if (v.status == Num::Syntax)
            return 4;
        if (v.status == Num::Range || v.value < lo || v.value > hi)
            code = 5;
        out.push_back(v.value);
    }
    return code;
}

std::string hex2(int v)
{
    static constexpr char kHex[] = "0123456789ABCDEF";
    return {kHex[(v >> 4) & 0xF], kHex[v & 0xF]};
}

int axisIndex(char c, int axisCount)
{
    static constexpr std::string_view kAxes = "XYZA";
    const auto i = kAxes.find(static_cast<char>(std::toupper(static_cast<unsigned char>(c))));
    if (i == std::string_view::npos || static_cast<int>(i) >= axisCount)
        return -1;
    return static_cast<int>(i);
}

} // namespace frezka::emulator::args
