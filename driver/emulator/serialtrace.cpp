#include "serialtrace.h"

#include "protocol/checksum.h"

#include <cctype>
#include <cstdio>
#include <cstdlib>

namespace frezka::emulator {
namespace {

TraceMessage message(const char *text, int line, std::vector<std::string> args = {})
{
    return TraceMessage{text, std::move(args), line};
}

char directionChar(TraceDirection d)
{
    switch (d) {
    case TraceDirection::ToUnit:
        return '>';
    case TraceDirection::ToPc:
        return '<';
    case TraceDirection::Event:
        return '=';
    }
    return '?';
}

// The ASCII column back to bytes; false on a bad escape.
bool unescape(std::string_view text, std::string &out)
{
    out.clear();
    for (std::size_t i = 0; i < text.size(); ++i) {
        const char c = text[i];
        if (c != '\\') {
            out += c;
            continue;
        }
        if (++i >= text.size())
            return false;
        switch (text[i]) {
        case 'r':
            out += '\r';
            break;
        case 'n':
            out += '\n';
            break;
        case '\\':
            out += '\\';
            break;
        case 'x': {
            const auto byte = protocol::parseHexByte(text.substr(i + 1, 2));
            if (!byte)
                return false;
            out += static_cast<char>(*byte);
            i += 2;
            break;
        }
        default:
            return false;
        }
    }
    return true;
}

bool unhex(std::string_view text, std::string &out)
{
    out.clear();
    std::size_t i = 0;
    while (i < text.size()) {
        if (text[i] == ' ') {
            ++i;
            continue;
        }
        if (i + 1 >= text.size())
            return false;
        const auto byte = protocol::parseHexByte(text.substr(i, 2));
        if (!byte || (i + 2 < text.size() && text[i + 2] != ' '))
            return false;
        out += static_cast<char>(*byte);
        i += 2;
    }
    return true;
}

std::string_view trimmed(std::string_view s)
{
    while (!s.empty() && (s.front() == ' ' || s.front() == '\t'))
        s.remove_prefix(1);
    while (!s.empty() && (s.back() == ' ' || s.back() == '\t' || s.back() == '\r'))
        s.remove_suffix(1);
    return s;
}

// "# key: value" -> key, value; false for a plain comment.
bool headerLine(std::string_view line, std::string &key, std::string &value)
{
    line.remove_prefix(1);
    line = trimmed(line);
    const auto colon = line.find(':');
    if (colon == std::string_view::npos || colon == 0)
        return false;
    for (char c : line.substr(0, colon)) {
        if (!(std::isalnum(static_cast<unsigned char>(c)) || c == '-' || c == '_' || c == '.'))
            return false;
    }
    key = std::string(line.substr(0, colon));
    value = std::string(trimmed(line.substr(colon + 1)));
    return true;
}

// One entry line ("  12.345 > !0?\r | 21 30 3F 0D"); `lineNo` names it in the error.
bool parseEntry(std::string_view line, int lineNo, TraceEntry &e, TraceMessage &error)
{
    std::string_view rest = line;
    while (!rest.empty() && rest.front() == ' ')
        rest.remove_prefix(1);
    const auto space = rest.find(' ');
    const std::string timeText(rest.substr(0, space));
    char *end = nullptr;
    const double t = std::strtod(timeText.c_str(), &end);
    if (timeText.empty() || *end != '\0' || !(t >= 0) || space == std::string_view::npos ||
        space + 2 > rest.size()) {
        error = message(QT_TRANSLATE_NOOP("SerialTrace",
                                          "line %1: not an entry (time in ms, then >, < or =, "
                                          "then the bytes): %2"),
                        lineNo, {std::to_string(lineNo), std::string(line)});
        return false;
    }
    e.timeMs = t;
    e.fileLine = lineNo;
    const char d = rest[space + 1];
    rest.remove_prefix(std::min(rest.size(), space + 3));
    if (d == '=') {
        e.direction = TraceDirection::Event;
        e.bytes = std::string(trimmed(rest));
        return true;
    }
    if (d != '>' && d != '<') {
        error = message(QT_TRANSLATE_NOOP("SerialTrace",
                                          "line %1: the direction must be > (to the unit), < "
                                          "(from the unit) or = (an event), not '%2'"),
                        lineNo, {std::to_string(lineNo), std::string(1, d)});
        return false;
    }
    e.direction = d == '>' ? TraceDirection::ToUnit : TraceDirection::ToPc;
    const auto bar = rest.find('|');
    std::string_view ascii = rest.substr(0, bar);
    if (bar != std::string_view::npos && !ascii.empty() && ascii.back() == ' ')
        ascii.remove_suffix(1);
    if (!unescape(ascii, e.bytes)) {
        error = message(QT_TRANSLATE_NOOP("SerialTrace",
                                          "line %1: a bad escape in '%2' (use \\r, \\n, \\\\ or "
                                          "\\xHH)"),
                        lineNo, {std::to_string(lineNo), std::string(ascii)});
        return false;
    }
    if (bar == std::string_view::npos)
        return true;
    std::string fromHex;
    if (!unhex(trimmed(rest.substr(bar + 1)), fromHex) || fromHex != e.bytes) {
        error = message(QT_TRANSLATE_NOOP("SerialTrace",
                                          "line %1: the hex column does not match the text "
                                          "'%2': correct it or delete it (from the '|' on)"),
                        lineNo, {std::to_string(lineNo), std::string(ascii)});
        return false;
    }
    return true;
}

} // namespace

std::string englishText(const TraceMessage &m)
{
    if (!m.text)
        return {};
    std::string out;
    const std::string_view t(m.text);
    for (std::size_t i = 0; i < t.size(); ++i) {
        if (t[i] == '%' && i + 1 < t.size() && t[i + 1] >= '1' && t[i + 1] <= '9') {
            const auto n = static_cast<std::size_t>(t[i + 1] - '1');
            out += n < m.args.size() ? m.args[n] : std::string();
            ++i;
        } else {
            out += t[i];
        }
    }
    return out;
}

std::string SerialTrace::value(std::string_view key, std::string_view fallback) const
{
    for (const auto &[k, v] : header) {
        if (k == key)
            return v;
    }
    return std::string(fallback);
}

void SerialTrace::set(const std::string &key, const std::string &v)
{
    for (auto &[k, old] : header) {
        if (k == key) {
            old = v;
            return;
        }
    }
    header.emplace_back(key, v);
}

std::string escapeTraceBytes(std::string_view bytes)
{
    std::string out;
    for (const char c : bytes) {
        const auto u = static_cast<unsigned char>(c);
        if (c == '\r')
            out += "\\r";
        else if (c == '\n')
            out += "\\n";
        else if (c == '\\')
            out += "\\\\";
        else if (u < 0x20 || u >= 0x7F || c == '|') {
            char hex[8];
            std::snprintf(hex, sizeof hex, "\\x%02X", u);
            out += hex;
        } else {
            out += c;
        }
    }
    return out;
}

std::string hexTraceBytes(std::string_view bytes)
{
    std::string out;
    for (const char c : bytes) {
        char hex[4];
        std::snprintf(hex, sizeof hex, "%02X", static_cast<unsigned char>(c));
        if (!out.empty())
            out += ' ';
        out += hex;
    }
    return out;
}

std::string formatTraceEntry(const TraceEntry &e)
{
    char time[32];
    std::snprintf(time, sizeof time, "%14.6f", e.timeMs);
    std::string line = std::string(time) + ' ' + directionChar(e.direction) + ' ';
    if (e.direction == TraceDirection::Event)
        return line + e.bytes;
    return line + escapeTraceBytes(e.bytes) + " | " + hexTraceBytes(e.bytes);
}

std::string formatTrace(const SerialTrace &trace)
{
    std::string out = std::string(kTraceMagic) + '\n';
    for (const auto &[k, v] : trace.header)
        out += "# " + k + ": " + v + '\n';
    out += "#\n#        time_ms dir bytes (> to the unit, < from the unit, = shown by the driver)"
           " | hex\n";
    for (const TraceEntry &e : trace.entries)
        out += formatTraceEntry(e) + '\n';
    return out;
}

bool parseTrace(std::string_view text, SerialTrace &trace, TraceMessage &error)
{
    trace = {};
    int lineNo = 0;
    std::size_t pos = 0;
    while (pos <= text.size()) {
        auto nl = text.find('\n', pos);
        if (nl == std::string_view::npos)
            nl = text.size();
        std::string_view line = text.substr(pos, nl - pos);
        pos = nl + 1;
        ++lineNo;
        if (!line.empty() && line.back() == '\r')
            line.remove_suffix(1);
        if (lineNo == 1) {
            if (trimmed(line) != kTraceMagic) {
                error = message(QT_TRANSLATE_NOOP("SerialTrace",
                                                  "line 1: not a Frezka serial trace (it must "
                                                  "start with '%1')"),
                                1, {std::string(kTraceMagic)});
                return false;
            }
            continue;
        }
        if (trimmed(line).empty())
            continue;
        if (line.front() == '#') {
            std::string key, value;
            if (headerLine(line, key, value))
                trace.set(key, value);
            continue;
        }
        TraceEntry e;
        if (!parseEntry(line, lineNo, e, error))
            return false;
        trace.entries.push_back(std::move(e));
    }
    return true;
}

} // namespace frezka::emulator
