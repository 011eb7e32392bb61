#pragma once
// SerialTrace: a record of a serial line both ways, in the text format of docs/serial-trace.md.
//
// One entry per line of the protocol (a command up to and including its CR, a reply up to its
// CR), with its direction and the time since the start of the record in milliseconds, plus
// optional event entries (what the driver showed: its mode, an error) that a replay ignores and
// the regression helper compares. The header names the unit, the line and what was being done.
// Pure C++ so that both the driver (recording, replay transport) and gve-emu (--replay) use it.

#include <string>
#include <string_view>

#ifndef QT_TRANSLATE_NOOP // the same definition as Qt's: lupdate finds the texts, std code uses
                          // them
#define QT_TRANSLATE_NOOP(scope, x) x
#endif
#include <utility>
#include <vector>

namespace frezka::emulator {

enum class TraceDirection : unsigned char {
    ToUnit, // '>' the PC wrote it
    ToPc,   // '<' the unit sent it
    Event,  // '=' what the driver showed at that moment (not on the wire)
};

struct TraceEntry
{
    TraceDirection direction = TraceDirection::ToUnit;
    double timeMs = 0; // since the start of the record
    std::string bytes; // the raw bytes (ToUnit, ToPc) or the event text (Event)
    int fileLine = 0;  // the line of the trace file it was read from (0 = not read from a file)
    friend bool operator==(const TraceEntry &, const TraceEntry &) = default;
};

struct SerialTrace
{
    // Header keys in file order ("frezka", "variant", "baud", "port", "operation", ...).
    std::vector<std::pair<std::string, std::string>> header;
    std::vector<TraceEntry> entries;

    // The value of a header key, or `fallback` when it is absent.
    std::string value(std::string_view key, std::string_view fallback = {}) const;
    void set(const std::string &key, const std::string &value);
};

// A message for the operator: an English template with %1, %2 ... marked for translation in the
// context "SerialTrace" (the Qt side translates `text`, then fills in `args`), and the line of the
// trace file it is about (0 = none).
struct TraceMessage
{
    const char *text = nullptr; // null: no message
    std::vector<std::string> args;
    int line = 0;
    explicit operator bool() const { return text != nullptr; }
};
// The template with its arguments filled in, in English.
std::string englishText(const TraceMessage &message);

// The first line of every trace file; the format's version is its last word.
inline constexpr std::string_view kTraceMagic = "# frezka-serial-trace 1";

// The bytes as the ASCII column shows them: printable characters as they are, CR as \r, LF as
// \n, a backslash as \\, '|' and every other byte as \xHH.
std::string escapeTraceBytes(std::string_view bytes);
// The bytes as the hex column shows them: "21 30 3F 0D".
std::string hexTraceBytes(std::string_view bytes);

// One entry as a line of the file (no newline at the end).
std::string formatTraceEntry(const TraceEntry &entry);
// The whole file: the magic line, the header, a column legend, the entries.
std::string formatTrace(const SerialTrace &trace);

// Reads a trace file. On error returns false and sets `error` (its line is the file's line).
// Event entries and the hex column are optional; when the hex column is there it must match the
// ASCII column.
bool parseTrace(std::string_view text, SerialTrace &trace, TraceMessage &error);

} // namespace frezka::emulator
