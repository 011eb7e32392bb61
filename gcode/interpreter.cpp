#include "interpreter.h"

#include <QFile>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace frezka::gcode {

namespace {

constexpr std::uint32_t kAxisBits =
    (1u << ('x' - 'a')) | (1u << ('y' - 'a')) | (1u << ('z' - 'a')) | (1u << ('a' - 'a'));
constexpr char kAxisLetters[4] = {'x', 'y', 'z', 'a'};

bool isCycle(int motion)
{
    return motion == 730 || (motion >= 810 && motion <= 890);
}

bool isArc(int motion)
{
    return motion == 20 || motion == 30;
}

} // namespace

Interpreter::Interpreter(Options options)
    : m_options(std::move(options))
    , m_parser(m_params)
{
    m_params.setSystem(this);
    m_origin = m_options.workOffsetsMm;
    m_coord = std::clamp(m_options.coordinateSystem, 0, 8);
    m_pos = m_options.startMm;
}

Interpreter::~Interpreter() = default;

bool Interpreter::fail(ErrorCode code, char word, std::string detail, Error *error) const
{
    return failAt(code, word ? m_block.col(word) : 0, std::move(detail), error);
}

bool Interpreter::failAt(ErrorCode code, std::uint32_t pos, std::string detail, Error *error) const
{
    *error = {code, m_line, m_parser.columnAt(pos), std::move(detail)};
    return false;
}

double Interpreter::offset(int axis) const
{
    return m_origin[m_coord][axis] + m_g92[axis] + (axis == 2 ? m_toolZ : 0.0);
}

Point4 Interpreter::programPosition() const
{
    return {m_pos.x - offset(0), m_pos.y - offset(1), m_pos.z - offset(2), m_pos.a - offset(3)};
}

// ---- reading -------------------------------------------------------------------------------

bool Interpreter::nextLine(std::string_view *line)
{
    if (m_next >= m_text.size())
        return false;
    const char *base = m_text.data();
    const std::size_t left = m_text.size() - m_next;
    const char *nl = static_cast<const char *>(std::memchr(base + m_next, '\n', left));
    const std::size_t end = nl ? static_cast<std::size_t>(nl - base) : m_text.size();
    m_lineStart = m_next;
    *line = std::string_view(base + m_next, end - m_next);
    m_next = nl ? end + 1 : m_text.size();
    ++m_line;
    return true;
}

void Interpreter::jump(std::size_t offset, std::uint32_t lineBefore)
{
    m_next = offset;
    m_line = lineBefore;
}

Result Interpreter::run(std::string_view text, const std::function<void(std::size_t)> &consumed)
{
    constexpr std::size_t kReleaseStep = 1u << 20;
    std::size_t releaseMark = kReleaseStep;
    m_text = text;
    m_next = 0;
    m_line = 0;
    Result result;
    // One entry per line is the common case; reserving it keeps the arrays from doubling.
    std::size_t lines = 1;
    for (const char *p = text.data(), *e = text.data() + text.size();
         (p = static_cast<const char *>(std::memchr(p, '\n', static_cast<std::size_t>(e - p))));
         ++p)
        ++lines;
    m_toolpath.reserve(lines + 16);
    m_toolpath.setOrigin(m_pos);

    std::string_view raw;
    Error error;
    while (!m_ended && nextLine(&raw)) {
        if (m_next >= releaseMark && consumed) {
            consumed(releaseMark - kReleaseStep);
            releaseMark += kReleaseStep;
        }
        if (m_options.progress && (m_line & 0xFFFF) == 0)
            m_options.progress(m_next, text.size());
        if (++m_executed > m_options.maxBlocks) {
            result.errors.push_back(
                {ErrorCode::TooManyBlocks, m_line, 1, std::to_string(m_options.maxBlocks)});
            break;
        }
        if (processLine(raw, &error))
            continue;
        result.errors.push_back(error);
        if (!m_options.collectAllErrors || result.errors.size() >= m_options.maxErrors)
            break;
    }
    const bool stopped = !result.errors.empty() && !m_options.collectAllErrors;
    if (!m_ended && !stopped && result.errors.size() < m_options.maxErrors) {
        if (!m_frames.empty()) {
            const Frame &f = m_frames.back();
            const char *what = f.kind == FrameKind::Call ? "call" : "o";
            result.errors.push_back(
                {ErrorCode::OwordNotClosed, f.line + 1, 1, std::string(what) + " " + f.label});
        } else if (m_percentStarted) {
            result.errors.push_back(
                {ErrorCode::FileEndedWithoutPercent, std::max(m_line, 1u), 1, {}});
        } else {
            result.errors.push_back({ErrorCode::FileEndedWithoutEnd, std::max(m_line, 1u), 1, {}});
        }
    }
    result.linesRead = m_line;
    result.ended = m_ended;
    result.toolpath = std::move(m_toolpath);
    m_toolpath = Toolpath{};
    return result;
}

bool Interpreter::processLine(std::string_view raw, Error *error)
{
    if (!m_parser.normalize(raw, m_line, error))
        return false;
    if (m_parser.isPercent()) {
        // % opens the program only as its first line (blank lines aside) and then closes it.
        if (!m_sawContent) {
            m_sawContent = true;
            m_percentStarted = true;
        } else if (m_percentStarted) {
            m_ended = true;
        } else {
            return failAt(ErrorCode::BadCharacter, 0, "%", error);
        }
        return true;
    }
    if (!m_sawContent)
        m_sawContent = raw.find_first_not_of(" \t\r") != std::string_view::npos;
    if (m_parser.isEmpty())
        return true;
    if (m_parser.hasBlockDelete() && m_options.blockDelete)
        return true;
    if (!m_parser.parse(m_block, m_assignments, error))
        return false;
    if (m_block.oKind != OKind::None)
        return executeOword(error);
    return executeBlock(error);
}

// ---- block checks --------------------------------------------------------------------------

int Interpreter::motionToBe(Error *error)
{
    const bool axes = m_block.letters & kAxisBits;
    const int mode0 = m_block.hasG(kGNonModal) ? m_block.g[kGNonModal] : -1;
    const int mode1 = m_block.hasG(kGMotion) ? m_block.g[kGMotion] : -1;
    const bool coversAxes = mode0 == 100 || mode0 == 280 || mode0 == 300 || mode0 == 920;
    if (mode1 == 800) {
        if (axes && !coversAxes) {
            failAt(ErrorCode::AxisWordsWithG80, m_block.gColumn[kGMotion], {}, error);
            return -2;
        }
        if (!axes && mode0 == 920) {
            failAt(ErrorCode::AxisWordsMissing, m_block.gColumn[kGNonModal], "G92", error);
            return -2;
        }
        return 800;
    }
    if (mode1 != -1) {
        if (coversAxes) {
            failAt(ErrorCode::TwoAxisCodes, m_block.gColumn[kGNonModal], gName(mode0), error);
            return -2;
        }
        return mode1;
    }
    if (coversAxes) {
        if (!axes && mode0 == 920) {
            failAt(ErrorCode::AxisWordsMissing, m_block.gColumn[kGNonModal], "G92", error);
            return -2;
        }
        return -1;
    }
    if (axes) {
        if (m_motion == 800) {
            const char first = m_block.has('x')   ? 'x'
                               : m_block.has('y') ? 'y'
                               : m_block.has('z') ? 'z'
                                                  : 'a';
            fail(ErrorCode::AxisWordsWithoutMotion, first, {}, error);
            return -2;
        }
        return m_motion;
    }
    return -1;
}

bool Interpreter::checkWords(int motion, Error *error)
{
    const int mode0 = m_block.hasG(kGNonModal) ? m_block.g[kGNonModal] : -1;
    const bool arcMove = isArc(motion);
    const bool cycleMove = isCycle(motion);
    auto unused = [&](char c) {
        return fail(ErrorCode::WordNotUsed, c, std::string(1, c - 32), error);
    };
    for (char c : {'i', 'j', 'k'}) {
        if (m_block.has(c) && !arcMove)
            return unused(c);
    }
    if (m_block.has('r') && !arcMove && !cycleMove) {
        if (mode0 == 100)
            return fail(ErrorCode::UnsupportedRotation, 'r', {}, error);
        return unused('r');
    }
    if (m_block.has('l') && !cycleMove && mode0 != 100)
        return unused('l');
    const bool g64 = m_block.hasG(kGPathControl) && m_block.g[kGPathControl] == 640;
    if (m_block.has('p') &&
        !(mode0 == 40 || mode0 == 100 || g64 || arcMove || motion == 820 || motion == 890))
        return unused('p');
    if (m_block.has('q') && !(g64 || motion == 730 || motion == 830))
        return unused('q');
    if (m_block.has('h') && !(m_block.hasG(kGToolLength) && m_block.g[kGToolLength] == 430))
        return unused('h');
    if (m_block.has('a') && cycleMove)
        return unused('a');
    if (m_block.hasG(kGNonModal) && m_block.g[kGNonModal] == 530) {
        if (motion != 0 && motion != 10)
            return failAt(ErrorCode::G53NeedsG0OrG1, m_block.gColumn[kGNonModal], {}, error);
        const bool incremental =
            m_block.hasG(kGDistance) ? m_block.g[kGDistance] == 910 : !m_absolute;
        if (incremental)
            return failAt(ErrorCode::G53Incremental, m_block.gColumn[kGNonModal], {}, error);
    }
    if (mode0 == 40 && !m_block.has('p'))
        return failAt(ErrorCode::DwellMissingP, m_block.gColumn[kGNonModal], {}, error);
    return true;
}

// ---- execution -----------------------------------------------------------------------------

bool Interpreter::executeBlock(Error *error)
{
    const int motion = motionToBe(error);
    if (motion == -2)
        return false;
    if (!checkWords(motion, error))
        return false;
    for (const Assignment &a : m_assignments) {
        if (a.index)
            m_params.setNumbered(a.index, a.value);
        else
            m_params.setNamed(a.name, a.value);
    }
    if (!executeModes(error) || !executeNonModal(error))
        return false;
    if (motion >= 0 && motion != 800) {
        if (!executeMotion(motion, error))
            return false;
    } else if (motion == 800) {
        m_motion = 800;
        m_cycleIlValid = false;
    }
    return executeStops();
}

void Interpreter::event(EventKind kind, double value, double p, double q)
{
    m_toolpath.appendEvent({kind, value, p, q}, m_feed * (m_inverseTime ? 0.0 : unit()), m_line);
}

bool Interpreter::executeModes(Error *error)
{
    const Block &b = m_block;
    if (b.hasG(kGFeedMode))
        m_inverseTime = b.g[kGFeedMode] == 930;
    if (b.has('f')) {
        if (b.get('f') < 0)
            return fail(ErrorCode::NegativeValue, 'f', "F", error);
        m_feed = b.get('f');
    }
    if (b.has('s')) {
        if (b.get('s') < 0)
            return fail(ErrorCode::NegativeValue, 's', "S", error);
        const bool changed = b.get('s') != m_speed;
        m_speed = b.get('s');
        const bool startsSpindle = b.hasM(kMSpindle) && b.m[kMSpindle] != 5;
        if (changed && m_spindle != 0 && !startsSpindle)
            event(EventKind::SpindleSpeed, m_speed);
    }
    if (b.has('t')) {
        const double t = b.get('t');
        if (t < 0)
            return fail(ErrorCode::NegativeValue, 't', "T", error);
        if (t != std::floor(t) || t > 1e9)
            return fail(ErrorCode::NonIntegerValue, 't', "T", error);
        m_selectedTool = static_cast<int>(t);
    }
    if (b.hasM(kMToolChange)) {
        m_tool = m_selectedTool;
        event(EventKind::ToolChange, m_tool);
    }
    if (b.hasM(kMSpindle)) {
        const int m = b.m[kMSpindle];
        m_spindle = m == 3 ? 1 : m == 4 ? -1 : 0;
        event(m == 3   ? EventKind::SpindleCw
              : m == 4 ? EventKind::SpindleCcw
                       : EventKind::SpindleOff,
              m == 5 ? 0 : m_speed);
    }
    if (b.hasM(kMCoolant)) {
        const int m = b.m[kMCoolant];
        if (m == 7)
            m_mist = true;
        else if (m == 8)
            m_flood = true;
        else
            m_mist = m_flood = false;
        event(m == 7   ? EventKind::CoolantMist
              : m == 8 ? EventKind::CoolantFlood
                       : EventKind::CoolantOff);
    }
    if (b.hasG(kGNonModal) && b.g[kGNonModal] == 40) {
        if (b.get('p') < 0)
            return fail(ErrorCode::NegativeValue, 'p', "P", error);
        m_toolpath.appendEvent({EventKind::Dwell, b.get('p'), 0, 0},
                               m_feed * (m_inverseTime ? 0.0 : unit()), m_line);
    }
    if (b.hasG(kGPlane))
        m_plane = b.g[kGPlane];
    if (b.hasG(kGUnits))
        m_metric = b.g[kGUnits] == 210;
    if (b.hasG(kGToolLength)) {
        if (b.g[kGToolLength] == 490) {
            m_toolZ = 0;
        } else {
            int tool = m_tool;
            if (b.has('h')) {
                const double h = b.get('h');
                if (h < 0 || h > 1e9 || h != std::floor(h))
                    return fail(ErrorCode::NonIntegerValue, 'h', "H", error);
                tool = static_cast<int>(h);
            }
            const auto it = m_options.toolLengthMm.find(tool);
            m_toolZ = it == m_options.toolLengthMm.end() ? 0.0 : it->second;
        }
    }
    if (b.hasG(kGCoordSystem)) {
        const int g = b.g[kGCoordSystem];
        m_coord = g < 590 ? (g - 540) / 10 : 5 + (g - 590);
    }
    if (b.hasG(kGPathControl)) {
        const int g = b.g[kGPathControl];
        m_pathMode = g == 610 ? 0 : g == 611 ? 1 : 2;
        m_pathP = g == 640 && b.has('p') ? lengthWord('p') : 0;
        m_pathQ = g == 640 && b.has('q') ? lengthWord('q') : 0;
        event(EventKind::PathMode, m_pathMode, m_pathP, m_pathQ);
    }
    if (b.hasG(kGDistance))
        m_absolute = b.g[kGDistance] == 900;
    if (b.hasG(kGArcDistance))
        m_arcAbsolute = b.g[kGArcDistance] == 901;
    if (b.hasG(kGRetract))
        m_retractToR = b.g[kGRetract] == 990;
    return true;
}

bool Interpreter::executeNonModal(Error *error)
{
    if (!m_block.hasG(kGNonModal))
        return true;
    const int g = m_block.g[kGNonModal];
    switch (g) {
    case 100:
        return setOffsets(error);
    case 280:
    case 300:
        return homeMove(g == 300, error);
    case 281:
        m_g28 = {m_pos.x, m_pos.y, m_pos.z, m_pos.a};
        return true;
    case 301:
        m_g30 = {m_pos.x, m_pos.y, m_pos.z, m_pos.a};
        return true;
    case 920: {
        double *p = &m_pos.x;
        for (int i = 0; i < 4; ++i) {
            const char c = kAxisLetters[i];
            if (!m_block.has(c))
                continue;
            const double v = i < 3 ? lengthWord(c) : m_block.get(c);
            m_g92[i] = p[i] - m_origin[m_coord][i] - (i == 2 ? m_toolZ : 0.0) - v;
        }
        m_g92Saved = m_g92;
        m_g92Enabled = true;
        return true;
    }
    case 921:
        m_g92 = {};
        m_g92Saved = {};
        m_g92Enabled = false;
        return true;
    case 922:
        m_g92 = {};
        m_g92Enabled = false;
        return true;
    case 923:
        m_g92 = m_g92Saved;
        m_g92Enabled = true;
        return true;
    default: // G4 (executed with the modes), G53 (with the motion)
        return true;
    }
}

bool Interpreter::setOffsets(Error *error)
{
    const Block &b = m_block;
    const std::uint32_t col = b.gColumn[kGNonModal];
    if (!b.has('l'))
        return failAt(ErrorCode::G10BadL, col, "without L", error);
    const double l = b.get('l');
    if (l != 2 && l != 20)
        return fail(ErrorCode::G10BadL, 'l', "L" + std::to_string(l), error);
    if (!b.has('p'))
        return failAt(ErrorCode::G10BadP, col, "none", error);
    const double p = b.get('p');
    if (p < 0 || p > 9 || p != std::floor(p))
        return fail(ErrorCode::G10BadP, 'p', std::to_string(p), error);
    const int system = p == 0 ? m_coord : static_cast<int>(p) - 1;
    const double *pos = &m_pos.x;
    for (int i = 0; i < 4; ++i) {
        const char c = kAxisLetters[i];
        if (!b.has(c))
            continue;
        const double v = i < 3 ? lengthWord(c) : b.get(c);
        if (l == 2)
            m_origin[system][i] = v;
        else
            m_origin[system][i] = pos[i] - m_g92[i] - (i == 2 ? m_toolZ : 0.0) - v;
    }
    return true;
}

bool Interpreter::homeMove(bool g30, Error *error)
{
    (void)error;
    // Rapid to the intermediate point (program coordinates, G90/G91 honoured), then to the
    // stored position: all axes when none is given, else only the given ones.
    const Point4 mid = targetOf(false);
    m_toolpath.appendRapid(mid, m_feed * unit(), m_line);
    m_pos = mid;
    const std::array<double, 4> &home = g30 ? m_g30 : m_g28;
    const bool all = !(m_block.letters & kAxisBits);
    double *p = &m_pos.x;
    for (int i = 0; i < 4; ++i) {
        if (all || m_block.has(kAxisLetters[i]))
            p[i] = home[i];
    }
    m_toolpath.appendRapid(m_pos, m_feed * unit(), m_line);
    return true;
}

bool Interpreter::executeStops()
{
    if (!m_block.hasM(kMStop))
        return true;
    const int m = m_block.m[kMStop];
    if (m == 0) {
        event(EventKind::Pause);
    } else if (m == 1) {
        event(EventKind::OptionalPause);
    } else {
        event(EventKind::ProgramEnd);
        m_ended = true;
    }
    return true;
}

// ---- system parameters ---------------------------------------------------------------------

bool Interpreter::systemNumbered(int index, double *value) const
{
    const double u = unit();
    auto length = [&](double mm, int axis) { return axis < 3 ? mm / u : mm; };
    auto axisOf = [](int i) { return i; }; // 0..3 = x y z a; b c u v w read as 0
    const Point4 prog = programPosition();
    const double progv[4] = {prog.x, prog.y, prog.z, prog.a};
    const double probe[4] = {m_probe.x, m_probe.y, m_probe.z, m_probe.a};
    if (index >= 5061 && index <= 5069) {
        const int i = index - 5061;
        *value = i < 4 ? length(probe[i], i) : 0;
        return true;
    }
    if (index == 5070) {
        *value = m_probed ? 1 : 0;
        return true;
    }
    if ((index >= 5161 && index <= 5169) || (index >= 5181 && index <= 5189)) {
        const int i = axisOf(index >= 5181 ? index - 5181 : index - 5161);
        const auto &home = index >= 5181 ? m_g30 : m_g28;
        *value = i < 4 ? length(home[i], i) : 0;
        return true;
    }
    if (index == 5210) {
        *value = m_g92Enabled ? 1 : 0;
        return true;
    }
    if (index >= 5211 && index <= 5219) {
        const int i = index - 5211;
        *value = i < 4 ? length(m_g92Saved[i], i) : 0;
        return true;
    }
    if (index == 5220) {
        *value = m_coord + 1;
        return true;
    }
    if (index >= 5221 && index <= 5390) {
        const int system = (index - 5221) / 20;
        const int i = (index - 5221) % 20;
        *value = i < 4 ? length(m_origin[system][i], i) : 0;
        return true;
    }
    if (index == 5400) {
        *value = m_tool;
        return true;
    }
    if (index >= 5401 && index <= 5409) {
        *value = index == 5403 ? m_toolZ / u : 0;
        return true;
    }
    if (index >= 5420 && index <= 5428) {
        const int i = index - 5420;
        *value = i < 4 ? length(progv[i], i) : 0;
        return true;
    }
    return false;
}

bool Interpreter::systemNamed(std::string_view name, double *value) const
{
    const double u = unit();
    const Point4 prog = programPosition();
    struct Entry
    {
        const char *name;
        double value;
    };
    const Entry entries[] = {
        {"_x", prog.x / u},
        {"_y", prog.y / u},
        {"_z", prog.z / u},
        {"_a", prog.a},
        {"_b", 0},
        {"_c", 0},
        {"_u", 0},
        {"_v", 0},
        {"_w", 0},
        {"_line", static_cast<double>(m_line)},
        {"_motion_mode", m_motion / 10.0},
        {"_plane", static_cast<double>(m_plane)},
        {"_metric", m_metric ? 1.0 : 0.0},
        {"_imperial", m_metric ? 0.0 : 1.0},
        {"_absolute", m_absolute ? 1.0 : 0.0},
        {"_incremental", m_absolute ? 0.0 : 1.0},
        {"_ijk_absolute_mode", m_arcAbsolute ? 1.0 : 0.0},
        {"_inverse_time", m_inverseTime ? 1.0 : 0.0},
        {"_units_per_minute", m_inverseTime ? 0.0 : 1.0},
        {"_feed", m_feed},
        {"_rpm", m_speed},
        {"_current_tool", static_cast<double>(m_tool)},
        {"_selected_tool", static_cast<double>(m_selectedTool)},
        {"_coord_system", m_coord < 6 ? 540.0 + 10 * m_coord : 590.0 + (m_coord - 5)},
        {"_spindle_on", m_spindle != 0 ? 1.0 : 0.0},
        {"_spindle_cw", m_spindle == 1 ? 1.0 : 0.0},
        {"_mist", m_mist ? 1.0 : 0.0},
        {"_flood", m_flood ? 1.0 : 0.0},
        {"_retract_r_plane", m_retractToR ? 1.0 : 0.0},
        {"_retract_old_z", m_retractToR ? 0.0 : 1.0},
        {"_value", m_value},
        {"_value_returned", m_valueReturned ? 1.0 : 0.0},
        {"_task", 0.0},
    };
    for (const Entry &e : entries) {
        if (name == e.name) {
            *value = e.value;
            return true;
        }
    }
    return false;
}

// ---- entry points --------------------------------------------------------------------------

Result interpretText(std::string_view text, const Options &options)
{
    Interpreter interpreter(options);
    return interpreter.run(text);
}

Result interpretFile(const std::string &path, const Options &options)
{
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly)) {
        Result r;
        r.errors.push_back({ErrorCode::FileOpenFailed, 0, 0, path});
        return r;
    }
    const qint64 size = file.size();
    if (size == 0)
        return interpretText({}, options);
    if (uchar *data = file.map(0, size)) {
        Interpreter interpreter(options);
        // Pages already read are dropped from this process's memory as the interpreter moves
        // on (they stay in the page cache; a loop jumping back faults them in again).
        const auto release = [data](std::size_t upTo) {
#ifdef __linux__
            const std::size_t page = 4096;
            if (upTo >= page)
                ::madvise(data, upTo / page * page, MADV_DONTNEED);
#else
            (void)data;
            (void)upTo;
#endif
        };
        Result r = interpreter.run(
            {reinterpret_cast<const char *>(data), static_cast<std::size_t>(size)}, release);
        file.unmap(data);
        return r;
    }
    const QByteArray bytes = file.readAll(); // not mappable (pipe, special file)
    return interpretText({bytes.constData(), static_cast<std::size_t>(bytes.size())}, options);
}

} // namespace frezka::gcode
