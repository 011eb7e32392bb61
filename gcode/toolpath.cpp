#include "toolpath.h"

#include <algorithm>
#include <bit>
#include <cmath>
#include <numbers>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace frezka::gcode {

namespace {

// Asks for transparent huge pages (2 MB) under a reserved array of several MB: a million moves
// then fault their ~50 MB in about 25 page faults instead of 12 000 (a tenth of the CLI's time
// on the 1M-line benchmark went to those faults). Only whole 2 MB blocks inside the array are
// advised, so no memory beyond the reservation is touched. A hint: without THP nothing changes.
template<typename T>
void adviseHugePages(const std::vector<T> &v)
{
#ifdef __linux__
    constexpr std::uintptr_t kHuge = std::uintptr_t{2} << 20;
    const std::size_t bytes = v.capacity() * sizeof(T);
    if (bytes < 2 * kHuge)
        return;
    const auto data = reinterpret_cast<std::uintptr_t>(v.data());
    const std::uintptr_t begin = (data + kHuge - 1) & ~(kHuge - 1);
    const std::uintptr_t end = (data + bytes) & ~(kHuge - 1);
    if (end > begin)
        ::madvise(reinterpret_cast<void *>(begin), end - begin, MADV_HUGEPAGE);
#else
    (void)v;
#endif
}

} // namespace

void Toolpath::reserve(std::size_t n)
{
    m_kind.reserve(n);
    m_x.reserve(n);
    m_y.reserve(n);
    m_z.reserve(n);
    m_a.reserve(n);
    m_line.reserve(n);
    adviseHugePages(m_kind);
    adviseHugePages(m_x);
    adviseHugePages(m_y);
    adviseHugePages(m_z);
    adviseHugePages(m_a);
    adviseHugePages(m_line);
}

void Toolpath::clear()
{
    *this = Toolpath{};
}

void Toolpath::push(MotionKind kind, const Point4 &end, double feed, std::uint32_t line,
                    std::uint32_t aux)
{
    m_kind.push_back(kind);
    m_x.push_back(end.x);
    m_y.push_back(end.y);
    m_z.push_back(end.z);
    m_a.push_back(end.a);
    m_line.push_back(line);
    // A new run where the feed differs to the bit (a zero's sign included): feedMmPerMin gives
    // back exactly what was pushed.
    if (m_feedValue.empty() ||
        std::bit_cast<std::uint64_t>(m_feedValue.back()) != std::bit_cast<std::uint64_t>(feed)) {
        m_feedFrom.push_back(static_cast<std::uint32_t>(m_kind.size() - 1));
        m_feedValue.push_back(feed);
    }
    if (aux != kNone) {
        m_auxAt.push_back(static_cast<std::uint32_t>(m_kind.size() - 1));
        m_aux.push_back(aux);
    }
}

double Toolpath::feedMmPerMin(std::size_t i) const
{
    const auto run = std::upper_bound(m_feedFrom.begin(), m_feedFrom.end(), i);
    return m_feedValue[static_cast<std::size_t>(run - m_feedFrom.begin()) - 1];
}

std::uint32_t Toolpath::aux(std::size_t i) const
{
    const auto at = std::lower_bound(m_auxAt.begin(), m_auxAt.end(), i);
    return at != m_auxAt.end() && *at == i ? m_aux[static_cast<std::size_t>(at - m_auxAt.begin())]
                                           : kNone;
}

void Toolpath::appendRapid(const Point4 &end, double feedMmPerMin, std::uint32_t line)
{
    push(MotionKind::Rapid, end, feedMmPerMin, line, kNone);
}

void Toolpath::appendFeed(const Point4 &end, double feedMmPerMin, std::uint32_t line)
{
    push(MotionKind::Feed, end, feedMmPerMin, line, kNone);
}

void Toolpath::appendArc(const Point4 &end, const ArcInfo &arc, double feedMmPerMin,
                         std::uint32_t line)
{
    const Point4 &c = arc.centre;
    switch (arc.plane) {
    case Plane::XY:
        m_arcs.push_back({c.x, c.y, arc.turns, arc.plane});
        break;
    case Plane::XZ:
        m_arcs.push_back({c.z, c.x, arc.turns, arc.plane});
        break;
    case Plane::YZ:
        m_arcs.push_back({c.y, c.z, arc.turns, arc.plane});
        break;
    }
    push(MotionKind::Arc, end, feedMmPerMin, line, static_cast<std::uint32_t>(m_arcs.size() - 1));
}

void Toolpath::appendProbe(const Point4 &end, ProbeKind kind, double feedMmPerMin,
                           std::uint32_t line)
{
    push(MotionKind::Probe, end, feedMmPerMin, line, static_cast<std::uint32_t>(kind));
}

void Toolpath::appendEvent(const Event &event, double feedMmPerMin, std::uint32_t line)
{
    m_events.push_back(event);
    push(event.kind == EventKind::Dwell ? MotionKind::Dwell : MotionKind::Event, last(),
         feedMmPerMin, line, static_cast<std::uint32_t>(m_events.size() - 1));
}

void Toolpath::setEnd(std::size_t i, const Point4 &end)
{
    m_x[i] = end.x;
    m_y[i] = end.y;
    m_z[i] = end.z;
    m_a[i] = end.a;
}

void Toolpath::appendEntries(const Toolpath &from, std::size_t first, std::size_t end)
{
    end = std::min(end, from.size());
    reserve(size() + (end > first ? end - first : 0));
    for (std::size_t i = first; i < end; ++i) {
        std::uint32_t aux = from.aux(i);
        switch (from.m_kind[i]) {
        case MotionKind::Arc:
            m_arcs.push_back(from.m_arcs[aux]);
            aux = static_cast<std::uint32_t>(m_arcs.size() - 1);
            break;
        case MotionKind::Dwell:
        case MotionKind::Event:
            m_events.push_back(from.m_events[aux]);
            aux = static_cast<std::uint32_t>(m_events.size() - 1);
            break;
        default:
            break; // rapid, feed: no aux; probe: its kind
        }
        push(from.m_kind[i], from.end(i), from.feedMmPerMin(i), from.m_line[i], aux);
    }
}

std::size_t Toolpath::memoryBytes() const
{
    return m_kind.capacity() * sizeof(MotionKind) +
           (m_x.capacity() + m_y.capacity() + m_z.capacity() + m_a.capacity() +
            m_feedValue.capacity()) *
               sizeof(double) +
           (m_line.capacity() + m_feedFrom.capacity() + m_auxAt.capacity() + m_aux.capacity()) *
               sizeof(std::uint32_t) +
           m_arcs.capacity() * sizeof(StoredArc) + m_events.capacity() * sizeof(Event);
}

ArcInfo Toolpath::arc(std::size_t i) const
{
    const StoredArc &s = m_arcs[aux(i)];
    ArcInfo arc;
    arc.centre = start(i);
    arc.plane = s.plane;
    arc.turns = s.turns;
    switch (s.plane) {
    case Plane::XY:
        arc.centre.x = s.u;
        arc.centre.y = s.v;
        break;
    case Plane::XZ:
        arc.centre.z = s.u;
        arc.centre.x = s.v;
        break;
    case Plane::YZ:
        arc.centre.y = s.u;
        arc.centre.z = s.v;
        break;
    }
    return arc;
}

namespace {

// In-plane (u, v) and normal (w) coordinates of a point, per the arc convention in the header.
struct PlaneCoords
{
    double u, v, w;
};

PlaneCoords toPlane(const Point4 &p, Plane plane)
{
    switch (plane) {
    case Plane::XY:
        return {p.x, p.y, p.z};
    case Plane::XZ:
        return {p.z, p.x, p.y};
    case Plane::YZ:
        return {p.y, p.z, p.x};
    }
    return {p.x, p.y, p.z};
}

Point4 fromPlane(const PlaneCoords &c, double a, Plane plane)
{
    switch (plane) {
    case Plane::XY:
        return {c.u, c.v, c.w, a};
    case Plane::XZ:
        return {c.v, c.w, c.u, a};
    case Plane::YZ:
        return {c.w, c.u, c.v, a};
    }
    return {c.u, c.v, c.w, a};
}

} // namespace

std::vector<Point4> chordArc(const Point4 &start, const Point4 &end, const ArcInfo &arc,
                             double toleranceMm)
{
    const PlaneCoords s = toPlane(start, arc.plane);
    const PlaneCoords e = toPlane(end, arc.plane);
    const PlaneCoords c = toPlane(arc.centre, arc.plane);
    const double radius = std::hypot(s.u - c.u, s.v - c.v);
    const double a0 = std::atan2(s.v - c.v, s.u - c.u);
    const double a1 = std::atan2(e.v - c.v, e.u - c.u);
    constexpr double kTwoPi = 2 * std::numbers::pi;
    const bool ccw = arc.turns > 0;
    double sweep = ccw ? a1 - a0 : a0 - a1; // positive angle travelled in the turning direction
    while (sweep <= 1e-12)
        sweep += kTwoPi;
    while (sweep > kTwoPi + 1e-12)
        sweep -= kTwoPi;
    sweep += kTwoPi * (std::abs(arc.turns) - 1);

    // Largest chord angle whose sagitta r(1 - cos(theta/2)) stays within the tolerance.
    // At most kMaxPoints points: an arc needing more (a radius of kilometres) is not real.
    constexpr double kMaxPoints = 1e7;
    std::size_t n = 1;
    if (radius > toleranceMm && toleranceMm > 0 && std::isfinite(sweep)) {
        const double maxStep = 2 * std::acos(1 - toleranceMm / radius);
        const double count = maxStep > 0 ? std::ceil(sweep / maxStep) : kMaxPoints;
        n = static_cast<std::size_t>(std::clamp(count, 1.0, kMaxPoints));
    }
    // The end radius may differ slightly from the start radius (within the interpreter's check):
    // blend the radius so the last point lands exactly on the programmed end.
    const double endRadius = std::hypot(e.u - c.u, e.v - c.v);
    std::vector<Point4> points;
    points.reserve(n);
    for (std::size_t k = 1; k < n; ++k) {
        const double t = static_cast<double>(k) / static_cast<double>(n);
        const double angle = a0 + (ccw ? 1 : -1) * sweep * t;
        const double r = radius + (endRadius - radius) * t;
        const PlaneCoords p{c.u + r * std::cos(angle), c.v + r * std::sin(angle),
                            s.w + (e.w - s.w) * t};
        points.push_back(fromPlane(p, start.a + (end.a - start.a) * t, arc.plane));
    }
    points.push_back(end);
    return points;
}

} // namespace frezka::gcode
