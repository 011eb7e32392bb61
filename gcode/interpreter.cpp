#include "interpreter.h"

#include <QFile>
#include <QFileInfo>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <set>
#include <tuple>

#ifdef __linux__
#include <sys/mman.h>
#endif

namespace frezka::gcode {

namespace {

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
    m_toolsStrict = m_options.toolTable.has_value();
    if (m_toolsStrict)
        m_tools = *m_options.toolTable;
    m_prog = toProgram(m_pos);
}

Interpreter::~Interpreter() = default;

bool Interpreter::fail(ErrorCode code, char word, std::string detail, Error *error) const
{
    return failAt(code, word ? m_block.col(word) : 0, std::move(detail), error);
}

bool Interpreter::failAt(ErrorCode code, std::uint32_t pos, std::string detail, Error *error) const
{
    *error = {code, m_line, m_parser.columnAt(pos), std::move(detail), sourcePath()};
    return false;
}

void Interpreter::warnAt(ErrorCode code, std::uint32_t pos, std::string detail)
{
    warn(code, m_line, m_parser.columnAt(pos), std::move(detail));
}

void Interpreter::warn(ErrorCode code, std::uint32_t line, std::uint32_t column, std::string detail)
{
    const int limit = severity(code) == Severity::Note ? 1 : 10;
    if (m_warnings.size() >= m_options.maxWarnings || ++m_warningCount[int(code)] > limit) {
        ++m_warningsNotShown;
        return;
    }
    m_warnings.push_back({code, line, column, std::move(detail), sourcePath()});
}

std::array<double, 4> Interpreter::offsets() const
{
    return {offset(0), offset(1), offset(2), offset(3)};
}

void Interpreter::shiftProgram(const std::array<double, 4> &oldOffsets)
{
    m_prog.x += oldOffsets[0] - offset(0);
    m_prog.y += oldOffsets[1] - offset(1);
    m_prog.z += oldOffsets[2] - offset(2);
    m_prog.a += oldOffsets[3] - offset(3);
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

// Long (about 110 lines) on purpose: the per-line order of the checks (pages released,
// progress, the lines-executed bound, cancel, the start line, the block, the moves bound, the
// error) and the end-of-file checks that depend on how the loop ended read best in one place.
Result Interpreter::run(std::string_view text, const std::function<void(std::size_t)> &consumed)
{
    constexpr std::size_t kReleaseStep = 1u << 20;
    std::size_t releaseMark = kReleaseStep;
    m_text = m_program = text;
    m_source = 0;
    m_next = 0;
    m_line = 0;
    Result result;
    // One entry per line is the common case; reserving it keeps the arrays from doubling.
    m_toolpath.reserve(1 + countNewlines(text) + 16);
    m_toolpath.setOrigin(m_pos);

    std::set<std::tuple<std::uint32_t, std::uint32_t, int>> seen; // an error repeated by a loop
    auto report = [&](Error e) {
        if (e.file.empty())
            e.file = sourcePath();
        if (!seen.insert({e.line, e.column, int(e.code)}).second)
            return;
        if (result.errors.size() < m_options.maxErrors)
            result.errors.push_back(std::move(e));
        else
            ++result.errorsNotShown;
    };
    std::string_view raw;
    Error error;
    bool bounded = false; // a bound of Options stopped the program (no end-of-file errors)
    while (!m_ended && nextLine(&raw)) {
        if (m_source == 0 && m_next >= releaseMark && consumed) {
            consumed(releaseMark - kReleaseStep);
            releaseMark += kReleaseStep;
        }
        if (m_options.progress && m_source == 0 && (m_line & 0xFFFF) == 0)
            m_options.progress(m_next, text.size());
        if (++m_executed > m_options.maxBlocks) {
            report(boundError(ErrorCode::TooManyBlocks, ErrorCode::LoopNeverEnds,
                              m_options.maxBlocks));
            bounded = true;
            break;
        }
        if ((m_executed & 0xFFF) == 0 && m_options.cancel && m_options.cancel->load()) {
            result.cancelled = true;
            break;
        }
        if (m_options.startLine != 0 && !m_marked && m_source == 0 && m_line >= m_options.startLine)
            markBefore();
        const bool done = processLine(raw, &error);
        if (m_toolpath.size() > m_options.maxMoves) {
            report(boundError(ErrorCode::TooManyMoves, ErrorCode::LoopMovesNeverEnd,
                              m_options.maxMoves));
            bounded = true;
            break;
        }
        if (done)
            continue;
        report(error);
        if (!m_options.collectAllErrors)
            break;
        recoverBlock();
    }
    const bool stopped = !result.errors.empty() && !m_options.collectAllErrors;
    if (!m_ended && !stopped && !bounded && !result.cancelled && !m_nurbs.empty()) {
        report({ErrorCode::NurbsNotEnded, m_nurbsLine, 1, std::to_string(m_nurbsLine), {}});
        m_nurbs.clear(); // not carried into the next text (the console's next line)
    }
    if (!m_ended && !stopped && !bounded && !result.cancelled) {
        if (!m_frames.empty()) {
            const Frame &f = m_frames.back();
            const char *what = f.kind == FrameKind::Call ? "call" : "o";
            if (m_source != 0) { // a subroutine file ended inside its subroutine
                const auto sub =
                    std::find_if(m_frames.rbegin(), m_frames.rend(),
                                 [](const Frame &c) { return c.kind == FrameKind::Call; });
                const std::string &label = sub->label;
                report({ErrorCode::OwordNotClosed, m_subs[label].line, 1, "o<" + label + "> sub",
                        sourcePath()});
            } else
                report({ErrorCode::OwordNotClosed,
                        f.line + 1,
                        1,
                        std::string(what) + " " + f.label,
                        {}});
        } else if (m_options.acceptMissingEnd) {
            const std::uint32_t last = std::max(m_line, 1u);
            warn(ErrorCode::ImpliedProgramEnd, last, 1, {});
            m_toolpath.appendEvent({EventKind::ProgramEnd, 0, 0, 0}, feedMm(), last);
        } else if (m_percentStarted) {
            report({ErrorCode::FileEndedWithoutPercent, std::max(m_line, 1u), 1, {}, {}});
        } else {
            report({ErrorCode::FileEndedWithoutEnd, std::max(m_line, 1u), 1, {}, {}});
        }
    }
    // File order (a subroutine defined below its call reports its errors when called); the
    // program's own first, then each subroutine file's.
    const auto fileOrder = [](const Error &a, const Error &b) {
        return std::tie(a.file, a.line, a.column) < std::tie(b.file, b.line, b.column);
    };
    std::stable_sort(result.errors.begin(), result.errors.end(), fileOrder);
    std::stable_sort(m_warnings.begin(), m_warnings.end(), fileOrder);
    result.warnings = std::move(m_warnings);
    result.warningsNotShown = m_warningsNotShown;
    result.linesRead = m_line;
    result.ended = m_ended;
    finishMark(&result.mark);
    result.toolTable = m_tools;
    result.provisionalEntry = m_provisionalEntry;
    result.provisionalLine = m_provisionalLine;
    result.probes = m_probes;
    result.toolTableChanged = m_toolsChanged;
    result.workOffsetsMm = m_origin;
    result.workOffsetsChanged = m_origin != m_options.workOffsetsMm;
    result.toolpath = std::move(m_toolpath);
    m_toolpath = Toolpath{};
    return result;
}

bool Interpreter::processLine(std::string_view raw, Error *error)
{
    m_parsed = false;
    // The line is a view into m_text (nextLine): what follows it there may be read, not used.
    const auto textBegin = reinterpret_cast<std::uintptr_t>(m_text.data());
    const auto textEnd = textBegin + m_text.size();
    const auto rawBegin = reinterpret_cast<std::uintptr_t>(raw.data());
    const auto rawEnd = rawBegin + raw.size();
    const std::size_t readableAfter =
        rawBegin >= textBegin && rawEnd <= textEnd ? textEnd - rawEnd : 0;
    if (!m_parser.normalize(raw, m_line, error, readableAfter))
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
    if (m_parser.abortColumn() != 0 && !(m_parser.hasBlockDelete() && m_options.blockDelete)) {
        // LinuxCNC ends the program at an (abort, ...) comment: nothing after it runs.
        m_ended = true;
        *error = {ErrorCode::ProgramAborted, m_line, m_parser.abortColumn(), m_parser.abortText(),
                  sourcePath()};
        return false;
    }
    if (m_parser.isEmpty())
        return true;
    if (m_parser.hasBlockDelete() && m_options.blockDelete)
        return true;
    if (!m_parser.parse(m_block, m_assignments, error))
        return false;
    if (m_block.oKind != OKind::None)
        return executeOword(error);
    m_parsed = true;
    if (m_block.hasM(kMState))
        return modalState(error);
    return executeBlock(error);
}

void Interpreter::recoverBlock()
{
    Error ignored;
    if (m_parser.abortColumn() != 0)
        return; // the program ended there
    if (!m_parsed) {
        // A parse error: the line again without its unsupported codes and words (G41 D1 ...),
        // executed with its errors dropped (the first one was reported).
        if (m_parser.isEmpty() ||
            !m_parser.parseSkippingUnsupported(m_block, m_assignments, &ignored) ||
            m_block.oKind != OKind::None)
            return; // the block cannot be read: its state is unknown
        if (executeBlock(&ignored))
            return;
    }
    adoptTarget();
}

void Interpreter::adoptTarget()
{
    const int mode0 = m_block.hasG(kGNonModal) ? m_block.g[kGNonModal] : -1;
    const int mode1 = m_block.hasG(kGMotion) ? m_block.g[kGMotion] : -1;
    const int motion = mode1 >= 0 ? mode1 : m_motion;
    const bool plain =
        motion == 0 || motion == 10 || isArc(motion) || (motion >= 382 && motion <= 385);
    if (!plain || mode0 == 100 || mode0 == 280 || mode0 == 300 || mode0 == 920)
        return; // a cycle or G10/G28/G30/G92: where it would end is not the axis words
    m_motion = motion;
    if (!(m_block.letters & kAxisBits))
        return;
    // A straight stand-in keeps the toolpath continuous (it is not run: the program has errors).
    const Target target = targetOf(mode0 == 530);
    if (motion == 0)
        m_toolpath.appendRapid(target.machine, feedMm(), pathLine());
    else
        m_toolpath.appendFeed(target.machine, feedMm(), pathLine());
    moveTo(target);
}

// ---- block checks --------------------------------------------------------------------------

int Interpreter::motionToBe(Error *error)
{
    const bool axes = (m_block.letters & kAxisBits) || m_block.hasPolar();
    const int mode0 = m_block.hasG(kGNonModal) ? m_block.g[kGNonModal] : -1;
    const int mode1 = m_block.hasG(kGMotion) ? m_block.g[kGMotion] : -1;
    // G43.1/G43.2 take axis words as offsets; as in rs274ngc a motion or G92 in the same block
    // uses the same words again, and without one the block does not move.
    const int mode8 = m_block.hasG(kGToolLength) ? m_block.g[kGToolLength] : -1;
    const bool toolAxes = (mode8 == 431 || mode8 == 432) && axes;
    const bool coversAxes = mode0 == 100 || mode0 == 280 || mode0 == 300 || mode0 == 920;
    if (mode1 == 800) {
        if (axes && !coversAxes && !toolAxes) {
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
    if (axes && !toolAxes) {
        if (m_motion == 800 && !(m_block.letters & kAxisBits)) { // only @ or ^
            const int word = m_block.hasWord(Block::kRadius) ? Block::kRadius : Block::kAngle;
            failAt(ErrorCode::AxisWordsWithoutMotion, m_block.column[word],
                   word == Block::kRadius ? "@" : "^", error);
            return -2;
        }
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
    // G10 L1/L10/L11 take R (radius), I, J (angles) and Q (orientation) for a tool.
    const double l = m_block.has('l') ? m_block.get('l') : 0;
    const bool toolG10 = mode0 == 100 && (l == 1 || l == 10 || l == 11);
    const int mode8 = m_block.hasG(kGToolLength) ? m_block.g[kGToolLength] : -1;
    const bool m61 = m_block.hasM(kMToolChange) && m_block.m[kMToolChange] == 61;
    const bool ijSpline = motion == 50 || motion == 51;
    for (char c : {'i', 'j', 'k'}) {
        if (m_block.has(c) && !arcMove && !((toolG10 || ijSpline) && c != 'k'))
            return unused(c);
    }
    // G10 L2 (and L20, which refuses it as rs274 does) take R, the system's rotation.
    if (m_block.has('r') && !arcMove && !cycleMove && !toolG10 && mode0 != 100)
        return unused('r');
    if (m_block.has('l') && !cycleMove && mode0 != 100 && motion != 52)
        return unused('l');
    const bool g64 = m_block.hasG(kGPathControl) && m_block.g[kGPathControl] == 640;
    if (m_block.has('p') && !(mode0 == 40 || mode0 == 100 || g64 || arcMove || motion == 820 ||
                              motion == 890 || motion == 50 || motion == 52))
        return unused('p');
    if (m_block.has('q') &&
        !(g64 || motion == 730 || motion == 830 || toolG10 || m61 || motion == 50))
        return unused('q');
    if (m_block.has('h') && mode8 != 430 && mode8 != 432)
        return unused('h');
    if (m_block.has('d') && !(m_block.hasG(kGCutterComp) && m_block.g[kGCutterComp] != 400))
        return unused('d');
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
    if (mode0 == 53 && !nurbsEndAlone(error))
        return false;
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
    // Between G5.2 and G5.3 only control points may move (a G5.3 in the block ends it first).
    if (!m_nurbs.empty() && motion >= 0 &&
        !(m_block.hasG(kGNonModal) && m_block.g[kGNonModal] == 53) && !nurbsPending(motion, error))
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
    return executeStops(error);
}

// ---- entry points --------------------------------------------------------------------------

Result interpretText(std::string_view text, const Options &options)
{
    Interpreter interpreter(options);
    return interpreter.run(text);
}

Result interpretFile(const std::string &path, const Options &given)
{
    Options options = given;
    if (options.programDirectory.empty())
        options.programDirectory =
            QFileInfo(QString::fromStdString(path)).absolutePath().toStdString();
    QFile file(QString::fromStdString(path));
    if (!file.open(QIODevice::ReadOnly)) {
        Result r;
        r.errors.push_back({ErrorCode::FileOpenFailed, 0, 0, path, {}});
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
