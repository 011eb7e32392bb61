#pragma once
// Toolpath: the interpreter's output and the planner's and the viewer's input.
//
// A sequence of entries in machine coordinates (mm; A in degrees) with every offset applied.
// Each entry is a motion (rapid, feed, arc, probe) ending at end(i) and starting at end(i-1)
// (or origin() for the first), or a non-motion entry (dwell, event) that leaves the position
// where it was. Every entry carries its 1-based source line and the modal feed (mm/min).
//
// Storage is struct-of-arrays so that a million moves take well under 100 bytes each.
// Arc convention: the arc turns in its plane's (u, v) coordinates, where XY -> (x, y),
// XZ (G18) -> (z, x), YZ (G19) -> (y, z). turns > 0 is counter-clockwise (angle from u toward v,
// G3), turns < 0 clockwise (G2); |turns| - 1 extra full circles are made (G2/G3 P word).
// The third (normal) axis and A move linearly along the arc (helix).

#include <cstdint>
#include <limits>
#include <string>
#include <vector>

namespace frezka::gcode {

struct Point4
{
    double x = 0;
    double y = 0;
    double z = 0;
    double a = 0;
    friend bool operator==(const Point4 &, const Point4 &) = default;
};

enum class MotionKind : std::uint8_t { Rapid, Feed, Arc, Probe, Dwell, Event };
enum class Plane : std::uint8_t { XY, XZ, YZ };

struct ArcInfo
{
    Point4 centre; // only the two in-plane coordinates matter; the normal one is the start's
    Plane plane = Plane::XY;
    std::int32_t turns = 1; // signed, |turns| >= 1
    friend bool operator==(const ArcInfo &, const ArcInfo &) = default;
};

enum class ProbeKind : std::uint8_t {
    TowardErrorIfNoContact, // G38.2
    Toward,                 // G38.3
    AwayErrorIfNoLoss,      // G38.4
    Away,                   // G38.5
};

enum class EventKind : std::uint8_t {
    Dwell,         // value = seconds
    SpindleCw,     // M3, value = rpm (S)
    SpindleCcw,    // M4, value = rpm
    SpindleOff,    // M5
    SpindleSpeed,  // S changed while the spindle runs, value = rpm
    CoolantMist,   // M7
    CoolantFlood,  // M8
    CoolantOff,    // M9
    ToolChange,    // M6, value = tool number
    Pause,         // M0
    OptionalPause, // M1
    ProgramEnd,    // M2 / M30
    PathMode,      // G61 (value = 0), G61.1 (value = 1), G64 (value = 2, p = P tol mm, q = Q mm)
};

struct Event
{
    EventKind kind = EventKind::Dwell;
    double value = 0;
    double p = 0;
    double q = 0;
    friend bool operator==(const Event &, const Event &) = default;
};

class Toolpath
{
public:
    static constexpr std::uint32_t kNone = std::numeric_limits<std::uint32_t>::max();

    std::size_t size() const { return m_kind.size(); }
    bool empty() const { return m_kind.empty(); }
    void reserve(std::size_t n);
    void clear();

    // Position before the first entry (machine coordinates, mm).
    Point4 origin() const { return m_origin; }
    void setOrigin(const Point4 &p) { m_origin = p; }

    MotionKind kind(std::size_t i) const { return m_kind[i]; }
    Point4 end(std::size_t i) const { return {m_x[i], m_y[i], m_z[i], m_a[i]}; }
    Point4 start(std::size_t i) const { return i == 0 ? m_origin : end(i - 1); }
    // The feed in force at entry i (runs of equal feeds are kept once: a binary search).
    double feedMmPerMin(std::size_t i) const;
    std::uint32_t line(std::size_t i) const { return m_line[i]; }
    bool isMotion(std::size_t i) const { return m_kind[i] <= MotionKind::Probe; }

    // Only for kind(i) == Arc / Probe / Dwell or Event. The arc's centre is rebuilt from the
    // stored in-plane coordinates; its normal coordinate and A are the start point's.
    ArcInfo arc(std::size_t i) const;
    ProbeKind probe(std::size_t i) const { return static_cast<ProbeKind>(aux(i)); }
    const Event &event(std::size_t i) const { return m_events[aux(i)]; }

    void appendRapid(const Point4 &end, double feedMmPerMin, std::uint32_t line);
    void appendFeed(const Point4 &end, double feedMmPerMin, std::uint32_t line);
    void appendArc(const Point4 &end, const ArcInfo &arc, double feedMmPerMin, std::uint32_t line);
    void appendProbe(const Point4 &end, ProbeKind kind, double feedMmPerMin, std::uint32_t line);
    // A dwell (kind Dwell) or another event (kind Event) at the current position.
    void appendEvent(const Event &event, double feedMmPerMin, std::uint32_t line);

    // Appends the entries of `from` from index `first` up to `end` (exclusive; its end when
    // past it), as they are (run from a line: the program's rest after an approach that ends
    // where from.start(first) is; a program that probes for itself: up to its next probe).
    void appendEntries(const Toolpath &from, std::size_t first,
                       std::size_t end = std::numeric_limits<std::size_t>::max());

    // Moves the end of entry i (cutter radius compensation moves the end of a queued move once
    // the next move is known); an arc keeps its centre.
    void setEnd(std::size_t i, const Point4 &end);

    // Position after the last entry (origin() when empty).
    Point4 last() const { return empty() ? m_origin : end(size() - 1); }
    // Bytes held by the storage (capacity), for the memory benchmark.
    std::size_t memoryBytes() const;

    friend bool operator==(const Toolpath &, const Toolpath &) = default;

private:
    void push(MotionKind kind, const Point4 &end, double feed, std::uint32_t line,
              std::uint32_t aux);
    // The arc's, probe's or event's index of entry i (a binary search: only those entries
    // have one).
    std::uint32_t aux(std::size_t i) const;

    Point4 m_origin;
    std::vector<MotionKind> m_kind;
    std::vector<double> m_x, m_y, m_z, m_a;
    std::vector<std::uint32_t> m_line;
    // The feed as runs of equal values (issue 17: 8 bytes an entry where a program's F words
    // are modal): run r starts at entry m_feedFrom[r] (ascending, the first at 0).
    std::vector<std::uint32_t> m_feedFrom;
    std::vector<double> m_feedValue;
    // The aux index (arc, probe kind, event) of the entries that have one, by entry: 8 bytes
    // such an entry, none for a straight move (4 bytes each before).
    std::vector<std::uint32_t> m_auxAt; // ascending entry indices
    std::vector<std::uint32_t> m_aux;
    struct StoredArc // 24 bytes instead of ArcInfo's 40
    {
        double u = 0, v = 0; // centre in the plane's (u, v) coordinates
        std::int32_t turns = 1;
        Plane plane = Plane::XY;
        friend bool operator==(const StoredArc &, const StoredArc &) = default;
    };
    std::vector<StoredArc> m_arcs;
    std::vector<Event> m_events;
};

// Points along an arc from start to end (the end point included, the start not) such that no
// chord's sagitta exceeds toleranceMm (default 0.002 mm). The normal axis and A are
// interpolated linearly (helix). At least one point (the end) is always returned.
std::vector<Point4> chordArc(const Point4 &start, const Point4 &end, const ArcInfo &arc,
                             double toleranceMm = 0.002);

} // namespace frezka::gcode
