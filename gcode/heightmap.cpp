// HeightMap: the grid, bilinear interpolation and the file format of docs/height-map.md.
#include "heightmap.h"

#include <QCoreApplication>
#include <QFile>
#include <QSaveFile>
#include <QStringList>

#include <algorithm>
#include <cmath>

namespace frezka::gcode {

namespace {

constexpr double kNodeTolerance = 0.001; // mm: a row's X/Y must name a node this closely

QString num(double v)
{
    return QString::number(v, 'f', 4);
}

} // namespace

HeightMap::HeightMap(double originX, double originY, double spacingX, double spacingY, int countX,
                     int countY)
    : m_originX(originX)
    , m_originY(originY)
    , m_spacingX(spacingX)
    , m_spacingY(spacingY)
    , m_countX(countX)
    , m_countY(countY)
    , m_z(static_cast<std::size_t>(std::max(0, countX) * std::max(0, countY)), 0.0)
{}

double HeightMap::minZ() const
{
    return m_z.empty() ? 0 : *std::min_element(m_z.begin(), m_z.end());
}

double HeightMap::maxZ() const
{
    return m_z.empty() ? 0 : *std::max_element(m_z.begin(), m_z.end());
}

bool HeightMap::contains(double x, double y) const
{
    constexpr double eps = 1e-6;
    return isValid() && x >= m_originX - eps && x <= endX() + eps && y >= m_originY - eps &&
           y <= endY() + eps;
}

double HeightMap::heightAt(double x, double y) const
{
    if (!isValid())
        return 0;
    const double u = std::clamp((x - m_originX) / m_spacingX, 0.0, double(m_countX - 1));
    const double v = std::clamp((y - m_originY) / m_spacingY, 0.0, double(m_countY - 1));
    const int i = std::min(static_cast<int>(std::floor(u)), m_countX - 2);
    const int j = std::min(static_cast<int>(std::floor(v)), m_countY - 2);
    const double fu = u - i;
    const double fv = v - j;
    const double bottom = z(i, j) * (1 - fu) + z(i + 1, j) * fu;
    const double top = z(i, j + 1) * (1 - fu) + z(i + 1, j + 1) * fu;
    return bottom * (1 - fv) + top * fv;
}

QString HeightMap::write() const
{
    QString out;
    out += QStringLiteral("# frezka-height-map %1\n").arg(kFormatVersion);
    out += QStringLiteral("# origin_x_mm: %1\n# origin_y_mm: %2\n")
               .arg(num(m_originX), num(m_originY));
    out += QStringLiteral("# spacing_x_mm: %1\n# spacing_y_mm: %2\n")
               .arg(num(m_spacingX), num(m_spacingY));
    out += QStringLiteral("# count_x: %1\n# count_y: %2\n").arg(m_countX).arg(m_countY);
    out += QStringLiteral("# reference_z_mm: %1\n").arg(num(m_probing.referenceZMm));
    out +=
        QStringLiteral("# clearance_mm: %1\n# depth_mm: %2\n# probe_feed_mm_min: %3\n")
            .arg(num(m_probing.clearanceMm), num(m_probing.depthMm), num(m_probing.feedMmPerMin));
    out += QStringLiteral("x_mm,y_mm,z_mm\n");
    for (int j = 0; j < m_countY; ++j)
        for (int i = 0; i < m_countX; ++i)
            out += QStringLiteral("%1,%2,%3\n").arg(num(nodeX(i)), num(nodeY(j)), num(z(i, j)));
    return out;
}

namespace {

struct Header
{
    double originX = NAN, originY = NAN, spacingX = NAN, spacingY = NAN;
    double countX = NAN, countY = NAN;
    HeightMapProbing probing;
};

// One "# key: value" line into the header; false with *error set when the key is unknown or the
// value is not a number.
bool readHeaderLine(const QString &line, int lineNo, Header &h, QString *error)
{
    const QString body = line.mid(1).trimmed();
    const qsizetype colon = body.indexOf(u':');
    if (colon < 0)
        return true; // a plain comment
    const QString key = body.left(colon).trimmed();
    bool ok = false;
    const double value = body.mid(colon + 1).trimmed().toDouble(&ok);
    double *slot = key == u"origin_x_mm"         ? &h.originX
                   : key == u"origin_y_mm"       ? &h.originY
                   : key == u"spacing_x_mm"      ? &h.spacingX
                   : key == u"spacing_y_mm"      ? &h.spacingY
                   : key == u"count_x"           ? &h.countX
                   : key == u"count_y"           ? &h.countY
                   : key == u"reference_z_mm"    ? &h.probing.referenceZMm
                   : key == u"clearance_mm"      ? &h.probing.clearanceMm
                   : key == u"depth_mm"          ? &h.probing.depthMm
                   : key == u"probe_feed_mm_min" ? &h.probing.feedMmPerMin
                                                 : nullptr;
    if (!slot) {
        *error = QCoreApplication::translate(
                     "frezka::gcode::HeightMap",
                     "Height map line %1: unknown key '%2'. Use the keys of docs/height-map.md "
                     "or make the line a plain comment without a colon.")
                     .arg(lineNo)
                     .arg(key);
        return false;
    }
    if (!ok || !std::isfinite(value)) {
        *error = QCoreApplication::translate(
                     "frezka::gcode::HeightMap",
                     "Height map line %1: '%2' is not a number. Write it as a number in "
                     "millimetres, such as 10 or -0.25.")
                     .arg(lineNo)
                     .arg(key);
        return false;
    }
    *slot = value;
    return true;
}

std::optional<HeightMap> mapOf(const Header &h, QString *error)
{
    for (double v : {h.originX, h.originY, h.spacingX, h.spacingY, h.countX, h.countY})
        if (std::isnan(v)) {
            *error = QCoreApplication::translate(
                "frezka::gcode::HeightMap",
                "The height map lacks a grid key. Its header needs origin_x_mm, "
                "origin_y_mm, spacing_x_mm, spacing_y_mm, count_x and count_y.");
            return std::nullopt;
        }
    if (h.spacingX <= 0 || h.spacingY <= 0 || h.countX < 2 || h.countY < 2 ||
        h.countX != std::floor(h.countX) || h.countY != std::floor(h.countY) ||
        h.countX * h.countY > 1e6) {
        *error = QCoreApplication::translate(
            "frezka::gcode::HeightMap",
            "The height map's grid is not usable: the spacings must be above 0 and the "
            "counts whole numbers of at least 2 (at most a million points). Probe the "
            "grid again or correct the header.");
        return std::nullopt;
    }
    HeightMap map(h.originX, h.originY, h.spacingX, h.spacingY, static_cast<int>(h.countX),
                  static_cast<int>(h.countY));
    map.setProbing(h.probing);
    return map;
}

} // namespace

// One pass over the lines: the version line, the header, then the rows. Long because each kind
// of bad line has its own message naming it.
std::optional<HeightMap> HeightMap::read(const QString &text, QString *error)
{
    QString scratch;
    if (!error)
        error = &scratch;
    const QStringList lines = text.split(u'\n');
    if (lines.isEmpty() ||
        lines.front().trimmed() != QStringLiteral("# frezka-height-map %1").arg(kFormatVersion)) {
        *error = QCoreApplication::translate(
                     "frezka::gcode::HeightMap",
                     "Height map line 1: not a height map of version %1 (the first line must be "
                     "'# frezka-height-map %1'). Probe the grid again with this version of "
                     "Frezka.")
                     .arg(kFormatVersion);
        return std::nullopt;
    }
    Header header;
    std::optional<HeightMap> map;
    std::vector<bool> seen;
    for (qsizetype n = 1; n < lines.size(); ++n) {
        const int lineNo = static_cast<int>(n + 1);
        const QString line = lines[n].trimmed();
        if (line.isEmpty() || line == u"x_mm,y_mm,z_mm")
            continue;
        if (line.startsWith(u'#')) {
            if (map) {
                *error = QCoreApplication::translate(
                             "frezka::gcode::HeightMap",
                             "Height map line %1: a header line after the first row. Move it "
                             "above the rows.")
                             .arg(lineNo);
                return std::nullopt;
            }
            if (!readHeaderLine(line, lineNo, header, error))
                return std::nullopt;
            continue;
        }
        if (!map) {
            map = mapOf(header, error);
            if (!map)
                return std::nullopt;
            seen.assign(map->m_z.size(), false);
        }
        const QStringList cells = line.split(u',');
        bool okX = false, okY = false, okZ = false;
        const double x = cells.size() == 3 ? cells[0].trimmed().toDouble(&okX) : 0;
        const double y = cells.size() == 3 ? cells[1].trimmed().toDouble(&okY) : 0;
        const double zv = cells.size() == 3 ? cells[2].trimmed().toDouble(&okZ) : 0;
        if (!okX || !okY || !okZ || !std::isfinite(zv)) {
            *error = QCoreApplication::translate(
                         "frezka::gcode::HeightMap",
                         "Height map line %1: expected three numbers X,Y,Z separated by commas. "
                         "Correct the row or probe the grid again.")
                         .arg(lineNo);
            return std::nullopt;
        }
        const double u = (x - map->m_originX) / map->m_spacingX;
        const double v = (y - map->m_originY) / map->m_spacingY;
        const long i = std::lround(u), j = std::lround(v);
        if (i < 0 || j < 0 || i >= map->m_countX || j >= map->m_countY ||
            std::abs(x - map->nodeX(int(i))) > kNodeTolerance ||
            std::abs(y - map->nodeY(int(j))) > kNodeTolerance) {
            *error = QCoreApplication::translate(
                         "frezka::gcode::HeightMap",
                         "Height map line %1: X %2, Y %3 is not a point of the grid in the "
                         "header. Correct the row or the header.")
                         .arg(lineNo)
                         .arg(x)
                         .arg(y);
            return std::nullopt;
        }
        const std::size_t k = static_cast<std::size_t>(j * map->m_countX + i);
        if (seen[k]) {
            *error = QCoreApplication::translate(
                         "frezka::gcode::HeightMap",
                         "Height map line %1: the point X %2, Y %3 is given twice. Remove one "
                         "of the rows.")
                         .arg(lineNo)
                         .arg(x)
                         .arg(y);
            return std::nullopt;
        }
        seen[k] = true;
        map->m_z[k] = zv;
    }
    if (!map) {
        map = mapOf(header, error);
        if (!map)
            return std::nullopt;
        seen.assign(map->m_z.size(), false);
    }
    const auto missing = std::find(seen.begin(), seen.end(), false);
    if (missing != seen.end()) {
        const int k = static_cast<int>(missing - seen.begin());
        *error = QCoreApplication::translate(
                     "frezka::gcode::HeightMap",
                     "The height map has no row for X %1, Y %2. Every point of the grid needs "
                     "one; probe the grid again.")
                     .arg(map->nodeX(k % map->m_countX))
                     .arg(map->nodeY(k / map->m_countX));
        return std::nullopt;
    }
    return map;
}

bool HeightMap::save(const QString &path, QString *error) const
{
    QSaveFile file(path);
    if (!file.open(QIODevice::WriteOnly | QIODevice::Text) || file.write(write().toUtf8()) < 0 ||
        !file.commit()) {
        if (error)
            *error = QCoreApplication::translate(
                         "frezka::gcode::HeightMap",
                         "Cannot write the height map %1: %2. Choose a folder you may write to.")
                         .arg(path, file.errorString());
        return false;
    }
    return true;
}

std::optional<HeightMap> HeightMap::load(const QString &path, QString *error)
{
    QFile file(path);
    if (!file.open(QIODevice::ReadOnly | QIODevice::Text)) {
        if (error)
            *error = QCoreApplication::translate(
                         "frezka::gcode::HeightMap",
                         "Cannot read the height map %1: %2. Check that the file exists and is "
                         "readable.")
                         .arg(path, file.errorString());
        return std::nullopt;
    }
    QString inner;
    auto map = read(QString::fromUtf8(file.readAll()), &inner);
    if (!map && error)
        *error = QStringLiteral("%1: %2").arg(path, inner);
    return map;
}

} // namespace frezka::gcode
