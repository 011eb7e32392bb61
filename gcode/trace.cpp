#include "trace.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstring>
#include <limits>
#include <numbers>
#include <vector>

namespace frezka::gcode {

namespace {

constexpr std::size_t kMaxEntryChars = 512; // bound of one JSON object (11 numbers at most)

// "00" .. "99": two digits at a time.
constexpr char kDigitPairs[201] =
    "00010203040506070809101112131415161718192021222324252627282930313233"
    "34353637383940414243444546474849505152535455565758596061626364656667"
    "6869707172737475767778798081828384858687888990919293949596979899";

// Writes the decimal digits of v (at least one) at p, right to left in place, two at a time.
template<typename Unsigned>
char *writeDigitsOf(char *p, Unsigned v)
{
    int len = 1;
    for (Unsigned bound = 10; len < std::numeric_limits<Unsigned>::digits10 + 1 && v >= bound;
         bound *= 10)
        ++len;
    char *const end = p + len;
    char *d = end;
    while (v >= 100) {
        d -= 2;
        std::memcpy(d, kDigitPairs + 2 * (v % 100), 2);
        v /= 100;
    }
    if (v >= 10)
        std::memcpy(d - 2, kDigitPairs + 2 * v, 2);
    else
        d[-1] = static_cast<char>('0' + v);
    return end;
}

// Line numbers and the like fit 32 bits, whose divisions are cheaper.
char *writeDigits(char *p, std::uint64_t v)
{
    return v <= std::numeric_limits<std::uint32_t>::max()
               ? writeDigitsOf(p, static_cast<std::uint32_t>(v))
               : writeDigitsOf(p, v);
}

// Writes v with 4 decimals (half away from zero) at p; JSON has no NaN/inf: null.
char *writeFixed4(char *p, double value)
{
    const double scaled = value * 10000.0;
    if (!(std::fabs(scaled) < 9.0e15)) {
        if (std::isnan(value) || std::isinf(value)) {
            std::memcpy(p, "null", 4);
            return p + 4;
        }
        return p + std::snprintf(p, 32, "%.4e", value);
    }
    // std::round without the library call: below 2^53 the truncated part is exact and so is
    // scaled minus it (above 2^52 every double is whole), so this is round-half-away exactly.
    auto n = static_cast<long long>(scaled);
    const double rest = scaled - static_cast<double>(n);
    if (rest >= 0.5)
        ++n;
    else if (rest <= -0.5)
        --n;
    if (n < 0) {
        *p++ = '-';
        n = -n;
    }
    const auto u = static_cast<unsigned long long>(n);
    unsigned frac = 0;
    if (u < 100'000'000) {
        // Below 10 000 (every coordinate and most feeds): 32-bit arithmetic, digits in pairs.
        const auto small = static_cast<unsigned>(u);
        const unsigned whole = small / 10000;
        frac = small % 10000;
        if (whole < 10) {
            *p++ = static_cast<char>('0' + whole);
        } else if (whole < 100) {
            std::memcpy(p, kDigitPairs + 2 * whole, 2);
            p += 2;
        } else if (whole < 1000) {
            *p = static_cast<char>('0' + whole / 100);
            std::memcpy(p + 1, kDigitPairs + 2 * (whole % 100), 2);
            p += 3;
        } else {
            std::memcpy(p, kDigitPairs + 2 * (whole / 100), 2);
            std::memcpy(p + 2, kDigitPairs + 2 * (whole % 100), 2);
            p += 4;
        }
    } else {
        p = writeDigits(p, u / 10000);
        frac = static_cast<unsigned>(u % 10000);
    }
    p[0] = '.';
    std::memcpy(p + 1, kDigitPairs + 2 * (frac / 100), 2);
    std::memcpy(p + 3, kDigitPairs + 2 * (frac % 100), 2);
    return p + 5;
}

template<std::size_t N>
char *writeLiteral(char *p, const char (&text)[N])
{
    std::memcpy(p, text, N - 1);
    return p + N - 1;
}

char *writeText(char *p, const char *text)
{
    const std::size_t len = std::strlen(text);
    std::memcpy(p, text, len);
    return p + len;
}

const char *eventName(EventKind k)
{
    switch (k) {
    case EventKind::Dwell:
        return "dwell";
    case EventKind::SpindleCw:
        return "m3";
    case EventKind::SpindleCcw:
        return "m4";
    case EventKind::SpindleOff:
        return "m5";
    case EventKind::SpindleSpeed:
        return "s";
    case EventKind::CoolantMist:
        return "m7";
    case EventKind::CoolantFlood:
        return "m8";
    case EventKind::CoolantOff:
        return "m9";
    case EventKind::ToolChange:
        return "m6";
    case EventKind::Pause:
        return "m0";
    case EventKind::OptionalPause:
        return "m1";
    case EventKind::ProgramEnd:
        return "m2";
    case EventKind::PathMode:
        return "path_mode";
    }
    return "event";
}

// The fields of an event entry after its type, and the closing brace.
char *writeEvent(char *p, const Event &e)
{
    p = writeLiteral(p, ",\"event\":\"");
    p = writeText(p, eventName(e.kind));
    p = writeLiteral(p, "\",\"value\":");
    p = writeFixed4(p, e.value);
    if (e.kind == EventKind::PathMode) {
        p = writeLiteral(p, ",\"p\":");
        p = writeFixed4(p, e.p);
        p = writeLiteral(p, ",\"q\":");
        p = writeFixed4(p, e.q);
    }
    *p++ = '}';
    return p;
}

// An arc's centre, plane and turns.
char *writeArc(char *p, const ArcInfo &arc)
{
    p = writeLiteral(p, ",\"cx\":");
    p = writeFixed4(p, arc.centre.x);
    p = writeLiteral(p, ",\"cy\":");
    p = writeFixed4(p, arc.centre.y);
    p = writeLiteral(p, ",\"cz\":");
    p = writeFixed4(p, arc.centre.z);
    p = writeLiteral(p, ",\"plane\":\"");
    p = writeText(p, arc.plane == Plane::XY ? "XY" : arc.plane == Plane::XZ ? "XZ" : "YZ");
    p = writeLiteral(p, "\",\"turns\":");
    if (arc.turns < 0)
        *p++ = '-';
    return writeDigits(p, static_cast<std::uint64_t>(std::abs(arc.turns)));
}

// The text of the last value written in one field (x, y, z, a, f): consecutive moves repeat
// most of them (a, f, one of x/y on a raster), and a copy is cheaper than formatting again.
struct RecentNumber
{
    std::uint64_t bits = 0; // the double's bits (-0 and 0 differ: both write 0.0000)
    bool valid = false;
    std::uint8_t length = 0;
    char text[24]; // writeFixed4 writes at most 18 characters (or "null", or %.4e's 12)
};
using RecentFields = std::array<RecentNumber, 5>;

char *writeRecent(char *p, double value, RecentNumber &recent)
{
    std::uint64_t bits = 0;
    std::memcpy(&bits, &value, sizeof bits);
    if (recent.valid && bits == recent.bits) {
        std::memcpy(p, recent.text, sizeof recent.text); // past length: overwritten next
        return p + recent.length;
    }
    char *const end = writeFixed4(p, value);
    const auto length = static_cast<std::size_t>(end - p);
    recent.valid = length <= sizeof recent.text;
    if (recent.valid) {
        std::memcpy(recent.text, p, sizeof recent.text); // a fixed copy: p has the room
        recent.bits = bits;
        recent.length = static_cast<std::uint8_t>(length);
    }
    return end;
}

// Writes entry i at p (at most kMaxEntryChars); returns p unchanged for a skipped event.
char *writeEntry(char *p, const Toolpath &tp, std::size_t i, bool withEvents, RecentFields &recent)
{
    // The type and its closing quote, padded to 8 bytes so that one fixed copy writes it.
    static constexpr char kTypes[][9] = {"rapid\"  ", "feed\"   ", "arc\"    ",
                                         "probe\"  ", "dwell\"  ", "event\"  "};
    static constexpr std::uint8_t kTypeLength[] = {6, 5, 4, 6, 6, 6};
    const MotionKind kind = tp.kind(i);
    if (kind == MotionKind::Event && !withEvents)
        return p;
    p = writeLiteral(p, "{\"line\":");
    p = writeDigits(p, tp.line(i));
    p = writeLiteral(p, ",\"type\":\"");
    std::memcpy(p, kTypes[static_cast<int>(kind)], 8);
    p += kTypeLength[static_cast<int>(kind)];
    if (kind == MotionKind::Event)
        return writeEvent(p, tp.event(i));
    const Point4 e = tp.end(i);
    p = writeLiteral(p, ",\"x\":");
    p = writeRecent(p, e.x, recent[0]);
    p = writeLiteral(p, ",\"y\":");
    p = writeRecent(p, e.y, recent[1]);
    p = writeLiteral(p, ",\"z\":");
    p = writeRecent(p, e.z, recent[2]);
    p = writeLiteral(p, ",\"a\":");
    p = writeRecent(p, e.a, recent[3]);
    p = writeLiteral(p, ",\"f\":");
    p = writeRecent(p, tp.feedMmPerMin(i), recent[4]);
    if (kind == MotionKind::Arc) {
        p = writeArc(p, tp.arc(i));
    } else if (kind == MotionKind::Dwell) {
        p = writeLiteral(p, ",\"seconds\":");
        p = writeFixed4(p, tp.event(i).value);
    } else if (kind == MotionKind::Probe) {
        p = writeLiteral(p, ",\"probe\":\"G38.");
        p = writeDigits(p, static_cast<std::uint64_t>(tp.probe(i)) + 2);
        *p++ = '"';
    }
    *p++ = '}';
    return p;
}

} // namespace

void appendFixed4(std::string &out, double value)
{
    char buf[64];
    out.append(buf, static_cast<std::size_t>(writeFixed4(buf, value) - buf));
}

bool appendJsonLine(std::string &out, const Toolpath &toolpath, std::size_t i, bool withEvents)
{
    char buf[kMaxEntryChars];
    RecentFields recent;
    char *end = writeEntry(buf, toolpath, i, withEvents, recent);
    if (end == buf)
        return false;
    out.append(buf, static_cast<std::size_t>(end - buf));
    return true;
}

bool writeJsonLines(const Toolpath &toolpath, std::FILE *out, bool withEvents)
{
    constexpr std::size_t kChunk = 1 << 20;
    std::vector<char> buffer(kChunk + kMaxEntryChars + 1);
    char *const begin = buffer.data();
    char *p = begin;
    RecentFields recent;
    for (std::size_t i = 0; i < toolpath.size(); ++i) {
        char *end = writeEntry(p, toolpath, i, withEvents, recent);
        if (end != p) {
            *end++ = '\n';
            p = end;
        }
        if (static_cast<std::size_t>(p - begin) >= kChunk) {
            const auto len = static_cast<std::size_t>(p - begin);
            if (std::fwrite(begin, 1, len, out) != len)
                return false;
            p = begin;
        }
    }
    const auto len = static_cast<std::size_t>(p - begin);
    if (len && std::fwrite(begin, 1, len, out) != len)
        return false;
    return std::fflush(out) == 0;
}

std::string jsonLines(const Toolpath &toolpath, bool withEvents)
{
    std::string out;
    for (std::size_t i = 0; i < toolpath.size(); ++i) {
        if (appendJsonLine(out, toolpath, i, withEvents))
            out += '\n';
    }
    return out;
}

namespace {

void grow(Summary &s, const Point4 &p)
{
    if (!s.hasMotion) {
        s.min = s.max = p;
        s.hasMotion = true;
        return;
    }
    s.min = {std::min(s.min.x, p.x), std::min(s.min.y, p.y), std::min(s.min.z, p.z),
             std::min(s.min.a, p.a)};
    s.max = {std::max(s.max.x, p.x), std::max(s.max.y, p.y), std::max(s.max.z, p.z),
             std::max(s.max.a, p.a)};
}

double distance(const Point4 &a, const Point4 &b)
{
    return std::sqrt((a.x - b.x) * (a.x - b.x) + (a.y - b.y) * (a.y - b.y) +
                     (a.z - b.z) * (a.z - b.z));
}

} // namespace

Summary summarize(const Toolpath &tp, double rapidMmPerMin)
{
    Summary s;
    for (std::size_t i = 0; i < tp.size(); ++i) {
        const MotionKind kind = tp.kind(i);
        const Point4 a = tp.start(i), b = tp.end(i);
        double length = 0;
        switch (kind) {
        case MotionKind::Rapid:
            ++s.rapids;
            length = distance(a, b);
            s.rapidLengthMm += length;
            if (rapidMmPerMin > 0)
                s.timeSeconds += length / rapidMmPerMin * 60.0;
            break;
        case MotionKind::Feed:
        case MotionKind::Probe:
            ++(kind == MotionKind::Feed ? s.feeds : s.probes);
            length = distance(a, b);
            break;
        case MotionKind::Arc: {
            ++s.arcs;
            Point4 prev = a;
            for (const Point4 &p : chordArc(a, b, tp.arc(i), 0.001)) {
                length += distance(prev, p);
                grow(s, p);
                prev = p;
            }
            break;
        }
        case MotionKind::Dwell:
            ++s.dwells;
            s.timeSeconds += tp.event(i).value;
            continue;
        case MotionKind::Event:
            ++s.events;
            continue;
        }
        if (kind != MotionKind::Rapid) {
            s.feedLengthMm += length;
            if (tp.feedMmPerMin(i) > 0)
                s.timeSeconds += length / tp.feedMmPerMin(i) * 60.0;
        }
        grow(s, a);
        grow(s, b);
    }
    return s;
}

} // namespace frezka::gcode
