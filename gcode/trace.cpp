#include "trace.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <numbers>

namespace frezka::gcode {

void appendFixed4(std::string &out, double value)
{
    const double scaled = std::round(value * 10000.0);
    if (!(std::fabs(scaled) < 9.0e15)) { // NaN, inf or huge: printf handles them
        char buf[64];
        const int n = std::snprintf(buf, sizeof buf, "%.4f", value);
        out.append(buf, static_cast<std::size_t>(n));
        return;
    }
    auto n = static_cast<long long>(scaled);
    char buf[32];
    char *end = buf + sizeof buf;
    char *p = end;
    const bool negative = n < 0;
    unsigned long long u =
        negative ? static_cast<unsigned long long>(-n) : static_cast<unsigned long long>(n);
    for (int i = 0; i < 4; ++i) {
        *--p = static_cast<char>('0' + u % 10);
        u /= 10;
    }
    *--p = '.';
    do {
        *--p = static_cast<char>('0' + u % 10);
        u /= 10;
    } while (u);
    if (negative)
        *--p = '-';
    out.append(p, static_cast<std::size_t>(end - p));
}

namespace {

void appendUInt(std::string &out, std::uint64_t v)
{
    char buf[24];
    char *end = buf + sizeof buf;
    char *p = end;
    do {
        *--p = static_cast<char>('0' + v % 10);
        v /= 10;
    } while (v);
    out.append(p, static_cast<std::size_t>(end - p));
}

void appendField(std::string &out, const char *name, double v)
{
    out += ",\"";
    out += name;
    out += "\":";
    appendFixed4(out, v);
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

} // namespace

bool appendJsonLine(std::string &out, const Toolpath &tp, std::size_t i, bool withEvents)
{
    static constexpr const char *kTypes[] = {"rapid", "feed", "arc", "probe", "dwell", "event"};
    const MotionKind kind = tp.kind(i);
    if (kind == MotionKind::Event && !withEvents)
        return false;
    out += "{\"line\":";
    appendUInt(out, tp.line(i));
    out += ",\"type\":\"";
    out += kTypes[static_cast<int>(kind)];
    out += '"';
    if (kind == MotionKind::Event) {
        const Event &e = tp.event(i);
        out += ",\"event\":\"";
        out += eventName(e.kind);
        out += '"';
        appendField(out, "value", e.value);
        if (e.kind == EventKind::PathMode) {
            appendField(out, "p", e.p);
            appendField(out, "q", e.q);
        }
        out += '}';
        return true;
    }
    const Point4 p = tp.end(i);
    appendField(out, "x", p.x);
    appendField(out, "y", p.y);
    appendField(out, "z", p.z);
    appendField(out, "a", p.a);
    appendField(out, "f", tp.feedMmPerMin(i));
    if (kind == MotionKind::Arc) {
        const ArcInfo &arc = tp.arc(i);
        appendField(out, "cx", arc.centre.x);
        appendField(out, "cy", arc.centre.y);
        appendField(out, "cz", arc.centre.z);
        out += arc.plane == Plane::XY   ? ",\"plane\":\"XY\""
               : arc.plane == Plane::XZ ? ",\"plane\":\"XZ\""
                                        : ",\"plane\":\"YZ\"";
        out += ",\"turns\":";
        if (arc.turns < 0)
            out += '-';
        appendUInt(out, static_cast<std::uint64_t>(std::abs(arc.turns)));
    } else if (kind == MotionKind::Dwell) {
        appendField(out, "seconds", tp.event(i).value);
    } else if (kind == MotionKind::Probe) {
        out += ",\"probe\":\"G38.";
        appendUInt(out, static_cast<std::uint64_t>(tp.probe(i)) + 2);
        out += '"';
    }
    out += '}';
    return true;
}

bool writeJsonLines(const Toolpath &toolpath, std::FILE *out, bool withEvents)
{
    std::string buffer;
    buffer.reserve(1 << 20);
    for (std::size_t i = 0; i < toolpath.size(); ++i) {
        if (appendJsonLine(buffer, toolpath, i, withEvents))
            buffer += '\n';
        if (buffer.size() > (1 << 20) - 512) {
            if (std::fwrite(buffer.data(), 1, buffer.size(), out) != buffer.size())
                return false;
            buffer.clear();
        }
    }
    if (std::fwrite(buffer.data(), 1, buffer.size(), out) != buffer.size())
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
