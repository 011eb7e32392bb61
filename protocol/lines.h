#pragma once
// Incremental line assembly for both directions of the GVE link (docs/gve-protocol.md §2).
//
// Bytes arrive in any split (one at a time, several lines at once). A line ends with CR; a LF
// right after a CR is ignored (adopted reading §2). A line that grows past kMaxLineLength without
// a CR is reported once as overlong (its first kMaxLineLength bytes kept as raw text) and the rest
// up to the next CR is discarded: memory stays bounded whatever the line carries.

#include <cstddef>
#include <deque>
#include <string>
#include <string_view>

namespace frezka::protocol {

// Longer than any valid command or reply (4 x 11-digit components + checksum is ~56 bytes).
inline constexpr std::size_t kMaxLineLength = 128;

struct Line
{
    std::string text;      // without CR; for an overlong line its first kMaxLineLength bytes
    bool overlong = false; // no CR within kMaxLineLength bytes
    friend bool operator==(const Line &, const Line &) = default;
};

class LineAssembler
{
public:
    // Appends received bytes; complete lines become available through next().
    void feed(std::string_view bytes);
    bool hasLine() const { return !m_ready.empty(); }
    // The oldest complete line, or an empty optional-like Line with hasLine() false.
    // Call only when hasLine(); returns {} otherwise.
    Line next();
    // Bytes of the line being received (empty while discarding an overlong tail).
    const std::string &pending() const { return m_current; }
    // Drops pending and ready lines (after a reconnect).
    void clear();

private:
    std::deque<Line> m_ready;
    std::string m_current;
    bool m_discarding = false; // inside an overlong line, waiting for its CR
    bool m_lastWasCr = false;
};

} // namespace frezka::protocol
