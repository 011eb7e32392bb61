#include "programmodes.h"

#include "gcode/parameters.h"

#include <QStringList>

namespace frezka::session {
namespace {

// LinuxCNC's order of the active G codes.
constexpr int kShownGroups[] = {gcode::kGMotion,      gcode::kGPlane,      gcode::kGCutterComp,
                                gcode::kGUnits,       gcode::kGDistance,   gcode::kGFeedMode,
                                gcode::kGCoordSystem, gcode::kGToolLength, gcode::kGRetract,
                                gcode::kGPathControl, gcode::kGArcDistance};

// No interpreter behind the parser: system parameters read as unknown.
struct NoSystem final : gcode::SystemParameters
{
    bool systemNumbered(int, double *) const override { return false; }
    bool systemNamed(std::string_view, double *) const override { return false; }
};

} // namespace

struct ModalScanner::Reader
{
    Reader() { params.setSystem(&system); }
    NoSystem system;
    gcode::Parameters params;
    gcode::Parser parser{params};
    gcode::Block block;
    std::vector<gcode::Assignment> assignments;
};

QString ProgramModes::gText() const
{
    QStringList codes;
    for (int group : kShownGroups)
        if (g[std::size_t(group)] >= 0)
            codes << QString::fromStdString(gcode::gName(g[std::size_t(group)]));
    return codes.join(QLatin1Char(' '));
}

QString ProgramModes::mText() const
{
    QStringList codes;
    codes << (spindle > 0   ? QStringLiteral("M3")
              : spindle < 0 ? QStringLiteral("M4")
                            : QStringLiteral("M5"));
    if (mist)
        codes << QStringLiteral("M7");
    if (flood)
        codes << QStringLiteral("M8");
    if (!mist && !flood)
        codes << QStringLiteral("M9");
    return codes.join(QLatin1Char(' '));
}

ProgramModes startModes(int coordinateSystem)
{
    ProgramModes m;
    m.g.fill(-1);
    m.g[gcode::kGMotion] = 800;
    m.g[gcode::kGPlane] = 170;
    m.g[gcode::kGCutterComp] = 400;
    m.g[gcode::kGUnits] = 210;
    m.g[gcode::kGDistance] = 900;
    m.g[gcode::kGFeedMode] = 940;
    m.g[gcode::kGCoordSystem] = std::int16_t(coordinateSystem < 6 ? 540 + 10 * coordinateSystem
                                                                  : 590 + (coordinateSystem - 5));
    m.g[gcode::kGToolLength] = 490;
    m.g[gcode::kGRetract] = 990;
    m.g[gcode::kGPathControl] = 640;
    m.g[gcode::kGArcDistance] = 911;
    return m;
}

ModalScanner::ModalScanner(std::shared_ptr<const ProgramText> text, int coordinateSystem)
    : m_text(std::move(text))
    , m_coordinateSystem(coordinateSystem)
{
    restart();
}

ModalScanner::~ModalScanner() = default;

void ModalScanner::restart()
{
    m_reader = std::make_unique<Reader>();
    m_modes = startModes(m_coordinateSystem);
    m_selected = 0;
    m_line = 0;
}

const ProgramModes &ModalScanner::at(std::uint32_t line)
{
    if (line < m_line)
        restart();
    const std::uint32_t last = m_text ? std::min<std::uint32_t>(line, m_text->lineCount()) : 0;
    while (m_line < last) {
        const QByteArray raw = m_text->line(int(m_line)).toUtf8();
        ++m_line;
        gcode::Error error;
        Reader &r = *m_reader;
        const std::string_view text(raw.constData(), std::size_t(raw.size()));
        if (!r.parser.normalize(text, m_line, &error) || r.parser.isEmpty() ||
            r.parser.isPercent() || !r.parser.parse(r.block, r.assignments, &error))
            continue;
        apply(r.block);
    }
    return m_modes;
}

// One block's modal words, in the interpreter's order (T before M6).
void ModalScanner::apply(const gcode::Block &b)
{
    for (int group : kShownGroups) {
        if (b.hasG(group))
            m_modes.g[std::size_t(group)] = b.g[group];
    }
    if (b.has('t'))
        m_selected = int(b.get('t'));
    if (b.hasM(gcode::kMToolChange) && b.m[gcode::kMToolChange] == 6)
        m_modes.tool = m_selected;
    if (b.hasM(gcode::kMSpindle)) {
        const int m = b.m[gcode::kMSpindle];
        m_modes.spindle = m == 3 ? 1 : m == 4 ? -1 : 0;
    }
    if (b.hasM(gcode::kMCoolant)) {
        const int m = b.m[gcode::kMCoolant];
        m_modes.mist = m == 7 || (m != 9 && m_modes.mist);
        m_modes.flood = m == 8 || (m != 9 && m_modes.flood);
    }
}

} // namespace frezka::session
