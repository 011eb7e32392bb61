#include "driver/grinder/grinderfile.h"

#include <charconv>

namespace frezka::grinder {

namespace {

constexpr std::string_view kMagic = "FREZKA-GRINDER 1\n";

// "key: value" lines up to the blank line; returns the offset after it, or npos.
std::size_t readLine(const Bytes &bytes, std::size_t at, std::string &line)
{
    line.clear();
    for (std::size_t i = at; i < bytes.size() && i < at + 200; ++i) {
        if (bytes[i] == '\n')
            return i + 1;
        line.push_back(char(bytes[i]));
    }
    return std::string::npos;
}

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

bool parseHeader(const std::string &hex, Header &header)
{
    if (hex.size() != 2 * kHeaderSize)
        return false;
    for (std::size_t i = 0; i < kHeaderSize; ++i) {
        const int hi = hexDigit(hex[2 * i]), lo = hexDigit(hex[2 * i + 1]);
        if (hi < 0 || lo < 0)
            return false;
        header[i] = std::uint8_t(hi * 16 + lo);
    }
    return true;
}

} // namespace

Bytes encodeGrinderFile(const GrinderFile &file)
{
    static const char digits[] = "0123456789ABCDEF";
    std::string text(kMagic);
    text += "system: " + std::string(familyInfo(file.family).id) + "\n";
    text += "header: ";
    for (std::uint8_t byte : file.header) {
        text.push_back(digits[byte >> 4]);
        text.push_back(digits[byte & 15]);
    }
    text += "\nlength: " + std::to_string(file.data.size()) + "\n\n";
    Bytes bytes(text.begin(), text.end());
    bytes.insert(bytes.end(), file.data.begin(), file.data.end());
    return bytes;
}

std::optional<GrinderFile> decodeGrinderFile(const Bytes &bytes, std::string &error)
{
    GrinderFile file;
    if (bytes.size() < kMagic.size() ||
        std::string_view(reinterpret_cast<const char *>(bytes.data()), kMagic.size()) != kMagic) {
        file.data = bytes;
        return file;
    }
    file.container = true;
    bool hasSystem = false, hasHeader = false, hasLength = false;
    std::size_t length = 0;
    std::size_t at = kMagic.size();
    std::string line;
    while (true) {
        at = readLine(bytes, at, line);
        if (at == std::string::npos) {
            error = "the file's description ends before its data";
            return std::nullopt;
        }
        if (line.empty())
            break;
        const std::size_t colon = line.find(": ");
        const std::string key = line.substr(0, colon);
        const std::string value = colon == std::string::npos ? "" : line.substr(colon + 2);
        if (key == "system") {
            const auto family = familyFromId(value);
            hasSystem = family.has_value();
            file.family = family.value_or(Family::K51);
        } else if (key == "header") {
            hasHeader = parseHeader(value, file.header);
        } else if (key == "length") {
            auto [ptr, ec] = std::from_chars(value.data(), value.data() + value.size(), length);
            hasLength = ec == std::errc() && ptr == value.data() + value.size();
        }
    }
    if (!hasSystem || !hasHeader || !hasLength) {
        error = std::string("the file's description lacks a valid ") + (!hasSystem   ? "system"
                                                                        : !hasHeader ? "header"
                                                                                     : "length");
        return std::nullopt;
    }
    if (bytes.size() - at != length) {
        error = "the file says " + std::to_string(length) + " data bytes but holds " +
                std::to_string(bytes.size() - at);
        return std::nullopt;
    }
    file.data.assign(bytes.begin() + std::ptrdiff_t(at), bytes.end());
    return file;
}

} // namespace frezka::grinder
