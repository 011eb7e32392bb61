#include "parser.h"

#include <cmath>
#include <cstring>

namespace frezka::gcode {

namespace {

const char *const kOkindNames[] = {"",       "sub",       "endsub", "call",    "return",   "if",
                                   "elseif", "else",      "endif",  "while",   "endwhile", "do",
                                   "repeat", "endrepeat", "break",  "continue"};

} // namespace

const char *okindName(OKind kind)
{
    return kOkindNames[static_cast<int>(kind)];
}

Parser::Parser(Parameters &params)
    : m_params(params)
{
    m_buffer.resize(256);
}

std::uint32_t Parser::columnAt(std::size_t pos) const
{
    // Walk the source line with normalize()'s rules until the pos-th kept character.
    const std::size_t target = pos + (m_blockDelete ? 1 : 0);
    std::size_t kept = 0;
    std::size_t last = 0;
    const char *s = m_raw.data();
    const std::size_t n = m_raw.size();
    for (std::size_t i = 0; i < n; ++i) {
        const char c = s[i];
        if (c == ' ' || c == '\t' || c == '\r')
            continue;
        if (c == ';')
            break;
        if (c == '(') {
            while (i < n && s[i] != ')')
                ++i;
            continue;
        }
        if (kept == target)
            return static_cast<std::uint32_t>(i + 1);
        ++kept;
        last = i + 1;
    }
    return static_cast<std::uint32_t>(last + 1);
}

bool Parser::fail(ErrorCode code, std::size_t pos, std::string detail, Error *error) const
{
    error->code = code;
    error->line = m_line;
    error->column = columnAt(pos);
    error->detail = std::move(detail);
    error->file.clear(); // the interpreter names a subroutine file
    return false;
}

bool Parser::readLineNumber(Error *error)
{
    // N followed by digits (LinuxCNC allows a decimal point in line numbers).
    const std::size_t start = m_pos;
    ++m_pos;
    const std::size_t digits = m_pos;
    while (m_pos < m_text.size() &&
           ((m_text[m_pos] >= '0' && m_text[m_pos] <= '9') || m_text[m_pos] == '.'))
        ++m_pos;
    if (m_pos == digits)
        return fail(ErrorCode::NumberExpected, start, "N", error);
    return true;
}

bool Parser::parse(Block &block, std::vector<Assignment> &assignments, Error *error)
{
    block.letters = 0;
    block.gMask = 0;
    block.mMask = 0;
    block.oKind = OKind::None;
    assignments.clear();
    m_pos = 0;
    const std::size_t n = m_text.size();
    if (m_pos < n && m_text[m_pos] == 'n' && !readLineNumber(error))
        return false;
    if (m_pos < n && m_text[m_pos] == 'o')
        return readOword(block, error);
    if (m_pos < n && m_text[m_pos] == '$') { // grbl's system commands ($H, $X, $$, $J=...)
        if (m_text.size() == m_pos + 2 && m_text[m_pos + 1] == 'h')
            return fail(ErrorCode::GrblHoming, m_pos, {}, error);
        std::string command = "$";
        for (std::size_t i = m_pos + 1; i < n && i < m_pos + 12; ++i)
            command += static_cast<char>(m_text[i] >= 'a' && m_text[i] <= 'z' ? m_text[i] - 32
                                                                              : m_text[i]);
        return fail(ErrorCode::GrblCommand, m_pos, command, error);
    }
    if (m_blockDelete && m_pos == 0 && n > 0 && m_text[0] == '/') { // "//" at the line start
        fail(ErrorCode::SlashComment, 0, {}, error);
        error->column -= 1;
        return false;
    }
    while (m_pos < n) {
        const char c = m_text[m_pos];
        if (c == 'g') {
            if (!readGCode(block, error))
                return false;
        } else if (c == 'm') {
            if (!readMCode(block, error))
                return false;
        } else if (c == '#') {
            if (!readAssignment(assignments, error))
                return false;
        } else if (c >= 'a' && c <= 'z') {
            const std::size_t at = m_pos;
            if (c == 'n' || c == 'o')
                return fail(ErrorCode::BadCharacter, at,
                            c == 'n' ? "N (line numbers go first)" : "O (O-words go first)", error);
            if (c == 'b' || c == 'c' || c == 'u' || c == 'v' || c == 'w')
                return fail(ErrorCode::UnsupportedAxis, at, std::string(1, c - 32), error);
            if (c == 'e') {
                if (m_skipUnsupported) {
                    ++m_pos;
                    double ignored = 0;
                    if (!readRealValue(&ignored, error))
                        return false;
                    continue;
                }
                return fail(ErrorCode::UnsupportedWord, at, std::string(1, c - 32), error);
            }
            const std::uint32_t bit = 1u << (c - 'a');
            if (block.letters & bit)
                return fail(ErrorCode::RepeatedWord, at, std::string(1, c - 32), error);
            ++m_pos;
            double v = 0;
            if (!readRealValue(&v, error)) {
                if (error->code == ErrorCode::NumberExpected && error->detail.empty()) {
                    error->detail = std::string(1, c - 32);
                    error->column = columnAt(at);
                }
                return false;
            }
            if (!(std::fabs(v) < 1e12))
                return fail(ErrorCode::ValueOutOfRange, at, std::string(1, c - 32), error);
            block.letters |= bit;
            block.value[c - 'a'] = v;
            block.column[c - 'a'] = static_cast<std::uint32_t>(at);
        } else if (c == '@' || c == '^') { // LinuxCNC's polar radius and angle
            const std::size_t at = m_pos;
            const int index = c == '@' ? Block::kRadius : Block::kAngle;
            if (block.hasWord(index))
                return fail(ErrorCode::RepeatedWord, at, std::string(1, c), error);
            ++m_pos;
            double v = 0;
            if (!readRealValue(&v, error))
                return false;
            if (!(std::fabs(v) < 1e12))
                return fail(ErrorCode::ValueOutOfRange, at, std::string(1, c), error);
            block.letters |= 1u << index;
            block.value[index] = v;
            block.column[index] = static_cast<std::uint32_t>(at);
        } else if (c == '/' && m_pos + 1 < n && m_text[m_pos + 1] == '/') {
            return fail(ErrorCode::SlashComment, m_pos, {}, error);
        } else {
            return fail(ErrorCode::BadCharacter, m_pos, std::string(1, c), error);
        }
    }
    return true;
}

bool Parser::parseSkippingUnsupported(Block &block, std::vector<Assignment> &assignments,
                                      Error *error)
{
    m_skipUnsupported = true;
    const bool ok = parse(block, assignments, error);
    m_skipUnsupported = false;
    return ok;
}

bool Parser::readGCode(Block &block, Error *error)
{
    const std::size_t at = m_pos;
    ++m_pos;
    double v = 0;
    if (!readRealValue(&v, error)) {
        if (error->code == ErrorCode::NumberExpected && error->detail.empty())
            error->detail = "G";
        return false;
    }
    const double scaled = v * 10.0;
    if (!(scaled > -0.5 && scaled < 9999.5))
        return fail(ErrorCode::UnknownGCode, at, "G" + std::to_string(v), error);
    int code = static_cast<int>(std::floor(scaled));
    if (scaled - code > 0.999)
        code = static_cast<int>(std::ceil(scaled));
    else if (scaled - code > 0.001)
        return fail(ErrorCode::UnknownGCode, at, "G" + std::to_string(v), error);
    if (code < 0 || code > 999)
        return fail(ErrorCode::UnknownGCode, at, gName(code), error);
    bool supported = true;
    const char *reason = "";
    const int group = gGroup(code, &supported, &reason);
    if (group < 0)
        return fail(ErrorCode::UnknownGCode, at, gName(code), error);
    if (!supported && m_skipUnsupported)
        return true;
    if (!supported)
        return fail(ErrorCode::UnsupportedGCode, at, gName(code) + " (" + reason + ")", error);
    if (block.hasG(group)) {
        // LinuxCNC ignores G80 in a block with another motion code (the Fanuc-style safety line
        // "G00 G17 G21 G40 G49 G80 G90"); Frezka does so beside G0..G3, not beside a cycle.
        const int other = block.g[group];
        const auto plainMotion = [](int g) { return g == 0 || g == 10 || g == 20 || g == 30; };
        if (group == kGMotion && code == 800 && plainMotion(other))
            return true;
        if (group != kGMotion || other != 800 || !plainMotion(code))
            return fail(ErrorCode::ModalGroupConflict, at, gName(code), error);
    }
    block.gMask |= 1u << group;
    block.g[group] = static_cast<std::int16_t>(code);
    block.gColumn[group] = static_cast<std::uint32_t>(at);
    return true;
}

bool Parser::readMCode(Block &block, Error *error)
{
    const std::size_t at = m_pos;
    ++m_pos;
    double v = 0;
    if (!readInteger(&v, at, error)) {
        if (error->code == ErrorCode::NumberExpected && error->detail.empty())
            error->detail = "M";
        return false;
    }
    if (!(v >= 0 && v <= 99999))
        return fail(ErrorCode::UnknownMCode, at, "M" + std::to_string(v), error);
    const int code = static_cast<int>(v);
    const std::string name = "M" + std::to_string(code);
    if (code < 0)
        return fail(ErrorCode::UnknownMCode, at, name, error);
    if (code == 29)
        return m_skipUnsupported || fail(ErrorCode::FanucRigidTapping, at, name, error);
    bool supported = true;
    const char *reason = "";
    const int group = mGroup(code, &supported, &reason);
    if (group < 0)
        return fail(ErrorCode::UnknownMCode, at, name, error);
    if (!supported)
        return m_skipUnsupported ||
               fail(ErrorCode::UnsupportedMCode, at, name + " (" + reason + ")", error);
    if (block.hasM(group))
        return fail(ErrorCode::ModalGroupConflict, at, name, error);
    block.mMask |= 1u << group;
    block.m[group] = static_cast<std::int16_t>(code);
    block.mColumn[group] = static_cast<std::uint32_t>(at);
    return true;
}

bool Parser::readAssignment(std::vector<Assignment> &assignments, Error *error)
{
    const std::size_t at = m_pos;
    Assignment a;
    a.column = columnAt(at);
    if (!readParameterRef(&a.index, &a.name, error))
        return false;
    if (m_pos >= m_text.size() || m_text[m_pos] != '=')
        return fail(ErrorCode::BadCharacter, m_pos,
                    m_pos < m_text.size() ? std::string(1, m_text[m_pos]) : "end of line (=)",
                    error);
    ++m_pos;
    if (a.index != 0 && m_params.isReadOnly(a.index))
        return fail(ErrorCode::ReadOnlyParameter, at, "#" + std::to_string(a.index), error);
    if (a.index == 0 && m_params.isSystemName(a.name))
        return fail(ErrorCode::ReadOnlyParameter, at, "#<" + std::string(a.name) + ">", error);
    if (!readRealValue(&a.value, error))
        return false;
    assignments.push_back(a);
    return true;
}

std::size_t Parser::skipComputedLabel(std::size_t p) const
{
    while (p < m_text.size() && m_text[p] == '#')
        ++p;
    if (p < m_text.size() && m_text[p] == '<') {
        const std::size_t end = m_text.find('>', p);
        return end == std::string::npos ? m_text.size() : end + 1;
    }
    if (p < m_text.size() && m_text[p] == '[') {
        int depth = 0;
        for (; p < m_text.size(); ++p) {
            depth += m_text[p] == '[' ? 1 : m_text[p] == ']' ? -1 : 0;
            if (depth == 0)
                return p + 1;
        }
        return p;
    }
    while (p < m_text.size() && ((m_text[p] >= '0' && m_text[p] <= '9') || m_text[p] == '.'))
        ++p;
    return p;
}

bool Parser::readOwordHead(std::size_t *pos, OKind *kind, std::string *label, std::uint32_t *col,
                           bool evaluate, Error *error)
{
    const std::size_t at = *pos;
    *col = static_cast<std::uint32_t>(at);
    std::size_t p = at + 1;
    label->clear();
    if (p < m_text.size() && m_text[p] == '<') {
        const std::size_t end = m_text.find('>', p);
        if (end == std::string::npos || end == p + 1)
            return fail(ErrorCode::OwordSyntax, at, "O<", error);
        label->assign(m_text, p + 1, end - p - 1);
        p = end + 1;
    } else if (p < m_text.size() && (m_text[p] == '#' || m_text[p] == '[') && !evaluate) {
        // Skipping: the value is not computed (no error from a parameter the skipped code
        // would set), and the label matches no block.
        p = skipComputedLabel(p);
    } else if (p < m_text.size() && (m_text[p] == '#' || m_text[p] == '[')) {
        // A computed number (LinuxCNC): o#<sub> call, o[#1+1] call, any integer value.
        const std::size_t saved = m_pos;
        m_pos = p;
        double v = 0;
        const bool ok = readInteger(&v, p, error);
        p = m_pos;
        m_pos = saved;
        if (!ok)
            return false;
        label->assign(std::to_string(static_cast<long long>(v)));
    } else {
        const std::size_t digits = p;
        while (p < m_text.size() && m_text[p] >= '0' && m_text[p] <= '9')
            ++p;
        if (p == digits)
            return fail(ErrorCode::OwordSyntax, at, "O", error);
        // o0100 and o100 are the same label.
        std::size_t first = digits;
        while (first + 1 < p && m_text[first] == '0')
            ++first;
        label->assign(m_text, first, p - first);
    }
    // The longest keyword the text starts with: spaces are gone, so "o1endifg0x1" must read
    // as endif followed by other words (an error reported by the caller).
    const std::size_t word = p;
    const std::string_view rest = std::string_view(m_text).substr(p);
    *kind = OKind::None;
    std::size_t best = 0;
    for (int k = 1; k < static_cast<int>(std::size(kOkindNames)); ++k) {
        const std::string_view name = kOkindNames[k];
        if (name.size() > best && rest.substr(0, name.size()) == name) {
            *kind = static_cast<OKind>(k);
            best = name.size();
        }
    }
    if (*kind == OKind::None) {
        std::size_t end = p;
        while (end < m_text.size() && m_text[end] >= 'a' && m_text[end] <= 'z')
            ++end;
        return fail(ErrorCode::OwordUnknownKeyword, word,
                    end == p ? std::string("(none)") : std::string(m_text, p, end - p), error);
    }
    p += best;
    *pos = p;
    return true;
}

bool Parser::readOword(Block &block, Error *error)
{
    if (!readOwordHead(&m_pos, &block.oKind, &block.oLabel, &block.oColumn, true, error))
        return false;
    block.oArgsPos = m_pos;
    return true;
}

bool Parser::peekOword(OKind *kind, std::string *label, Error *error)
{
    std::size_t p = 0;
    if (p < m_text.size() && m_text[p] == 'n') {
        m_pos = 0;
        if (!readLineNumber(error))
            return false;
        p = m_pos;
    }
    if (p >= m_text.size() || m_text[p] != 'o')
        return false;
    std::uint32_t col = 0;
    return readOwordHead(&p, kind, label, &col, false, error);
}

bool Parser::owordArgs(const Block &block, std::vector<double> *args, Error *error)
{
    args->clear();
    m_pos = block.oArgsPos;
    while (m_pos < m_text.size()) {
        if (m_text[m_pos] != '[')
            return fail(ErrorCode::OwordWithOtherWords, m_pos, {}, error);
        double v = 0;
        if (!readExpression(&v, error))
            return false;
        args->push_back(v);
    }
    return true;
}

} // namespace frezka::gcode
