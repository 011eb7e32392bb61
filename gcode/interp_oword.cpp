// O-word control flow (LinuxCNC semantics): sub/endsub/call/return, if/elseif/else/endif,
// while/endwhile, do/while, repeat/endrepeat, break/continue. Blocks are matched by their
// O label, as in rs274ngc. Skipping reads lines with only their O word looked at (no
// expression is evaluated while skipping); loops and calls jump back by byte offset.
#include "interpreter.h"

#include <algorithm>
#include <cmath>

namespace frezka::gcode {

namespace {

constexpr std::size_t kMaxCallDepth = 100;

std::string labelText(const std::string &label)
{
    return "o" +
           (label.empty() || (label[0] >= '0' && label[0] <= '9') ? label : "<" + label + ">");
}

} // namespace

bool Interpreter::owordCondition(double *value, Error *error)
{
    if (!m_parser.owordArgs(m_block, &m_args, error))
        return false;
    if (m_args.size() != 1)
        return failAt(ErrorCode::ExpressionExpected, m_block.oColumn,
                      std::string("after ") + okindName(m_block.oKind), error);
    *value = m_args[0];
    return true;
}

bool Interpreter::skipTo(const std::string &label, std::initializer_list<OKind> kinds, OKind *found,
                         Error *error)
{
    const std::uint32_t startLine = m_line;
    const OKind opening = m_block.oKind;
    std::string_view raw;
    std::string seen;
    OKind kind = OKind::None;
    while (nextLine(&raw)) {
        if (!m_parser.normalize(raw, m_line, error))
            return false;
        error->line = 0;
        if (!m_parser.peekOword(&kind, &seen, error)) {
            if (error->line == m_line) // a malformed O word
                return false;
            continue;
        }
        if (seen != label)
            continue;
        for (OKind k : kinds) {
            if (k == kind) {
                *found = kind;
                noteSkipped(startLine, opening, label);
                // Leave the parser holding this line fully parsed, for its arguments.
                return m_parser.parse(m_block, m_assignments, error);
            }
        }
    }
    *error = {
        ErrorCode::OwordNotClosed, startLine, 1, labelText(label) + " " + okindName(opening), {}};
    return false;
}

// One case per O-word kind (sub, call, if, while, repeat, ...): a dispatch table, each case a few
// lines, kept whole so that the control-flow words are read together.
bool Interpreter::executeOword(Error *error)
{
    const std::string label = m_block.oLabel;
    const std::uint32_t col = m_block.oColumn;
    const OKind kind = m_block.oKind;
    const std::string what = labelText(label) + " " + okindName(kind);
    auto topIs = [&](FrameKind k) {
        return !m_frames.empty() && m_frames.back().kind == k && m_frames.back().label == label;
    };
    OKind found = OKind::None;
    const bool takesArguments = kind == OKind::If || kind == OKind::ElseIf ||
                                kind == OKind::While || kind == OKind::Repeat ||
                                kind == OKind::Call || kind == OKind::Return ||
                                kind == OKind::EndSub;
    if (!takesArguments && m_block.oArgsPos != m_parser.text().size())
        return failAt(ErrorCode::OwordWithOtherWords, static_cast<std::uint32_t>(m_block.oArgsPos),
                      {}, error);
    switch (kind) {
    case OKind::Sub:
        if (!checkNestedSub(label, error))
            return false;
        m_subs[label] = {m_next, m_line, m_source};
        return skipTo(label, {OKind::EndSub}, &found, error);
    case OKind::Call:
        return callSub(error);
    case OKind::EndSub:
    case OKind::Return:
        return returnFromSub(error);
    case OKind::If:
        return owordIf(label, error);
    case OKind::ElseIf:
    case OKind::Else:
        if (!topIs(FrameKind::If))
            return failAt(ErrorCode::OwordUnmatched, col, what, error);
        m_frames.pop_back();
        return skipTo(label, {OKind::EndIf}, &found, error);
    case OKind::EndIf:
        if (!topIs(FrameKind::If))
            return failAt(ErrorCode::OwordUnmatched, col, what, error);
        m_frames.pop_back();
        return true;
    case OKind::Do:
        m_frames.push_back({FrameKind::Do, label, m_next, m_line, 0, oColumn()});
        return true;
    case OKind::While:
        return owordWhile(label, error);
    case OKind::EndWhile:
        if (!topIs(FrameKind::While))
            return failAt(ErrorCode::OwordUnmatched, col, what, error);
        ++m_frames.back().turns;
        jump(m_frames.back().offset, m_frames.back().line);
        return true;
    case OKind::Repeat: {
        double c = 0;
        if (!owordCondition(&c, error))
            return false;
        const auto count = static_cast<std::int64_t>(std::floor(std::min(c, 1e15) + 0.5));
        if (count <= 0)
            return skipTo(label, {OKind::EndRepeat}, &found, error);
        m_frames.push_back({FrameKind::Repeat, label, m_next, m_line, count, oColumn()});
        return true;
    }
    case OKind::EndRepeat:
        if (!topIs(FrameKind::Repeat))
            return failAt(ErrorCode::OwordUnmatched, col, what, error);
        if (--m_frames.back().remaining > 0) {
            ++m_frames.back().turns;
            jump(m_frames.back().offset, m_frames.back().line);
        } else
            m_frames.pop_back();
        return true;
    case OKind::Break:
    case OKind::Continue:
        return loopJump(kind == OKind::Break, error);
    case OKind::None:
        break;
    }
    return true;
}

bool Interpreter::owordIf(const std::string &label, Error *error)
{
    double c = 0;
    if (!owordCondition(&c, error))
        return false;
    OKind found = OKind::None;
    while (c == 0.0) {
        if (!skipTo(label, {OKind::ElseIf, OKind::Else, OKind::EndIf}, &found, error))
            return false;
        if (found == OKind::EndIf)
            return true;
        if (found == OKind::Else)
            break;
        if (!owordCondition(&c, error))
            return false;
    }
    m_frames.push_back({FrameKind::If, label, 0, m_line, 0});
    return true;
}

// A while line opens a loop, re-tests it when endwhile jumps back, or closes a do loop.
bool Interpreter::owordWhile(const std::string &label, Error *error)
{
    double c = 0;
    if (!owordCondition(&c, error))
        return false;
    auto topIs = [&](FrameKind k) {
        return !m_frames.empty() && m_frames.back().kind == k && m_frames.back().label == label;
    };
    if (topIs(FrameKind::Do)) {
        if (c != 0.0) {
            ++m_frames.back().turns;
            jump(m_frames.back().offset, m_frames.back().line);
        } else
            m_frames.pop_back();
        return true;
    }
    const bool again = topIs(FrameKind::While) && m_frames.back().offset == m_lineStart;
    if (c == 0.0) {
        if (again)
            m_frames.pop_back();
        OKind found = OKind::None;
        return skipTo(label, {OKind::EndWhile}, &found, error);
    }
    if (!again)
        m_frames.push_back({FrameKind::While, label, m_lineStart, m_line - 1, 0, oColumn()});
    return true;
}

bool Interpreter::callSub(Error *error)
{
    const std::string label = m_block.oLabel;
    if (!m_parser.owordArgs(m_block, &m_args, error))
        return false;
    const std::uint32_t col = m_block.oColumn;
    const std::uint32_t column = oColumn();
    auto it = m_subs.find(label);
    std::string file;
    if (it == m_subs.end() && subFileFor(label, &file)) {
        if (!loadSubFile(label, file, column, error))
            return false;
        it = m_subs.find(label);
    } else if (it == m_subs.end() && m_source != 0) {
        // LinuxCNC looks further down only in the program itself: a subroutine file holds its
        // own subroutine.
        return failAt(ErrorCode::SubroutineNotFound, col,
                      labelText(label) + kDetailSeparator + label + ".ngc", error);
    } else if (it == m_subs.end()) {
        // Like rs274ngc, look for the definition further down the file (subroutines are often
        // written after M2) without executing anything on the way.
        const std::size_t next = m_next, start = m_lineStart;
        const std::uint32_t line = m_line;
        OKind found = OKind::None;
        Error ignored;
        m_lookingAhead = true;
        const bool defined = skipTo(label, {OKind::Sub}, &found, &ignored);
        m_lookingAhead = false;
        if (defined)
            it = m_subs.emplace(label, SubDef{m_next, m_line, 0}).first;
        m_next = next;
        m_lineStart = start;
        m_line = line;
        if (!defined) {
            m_parser.normalize(m_text.substr(start, next - start), line, &ignored);
            return failAt(ErrorCode::SubroutineUndefined, col, labelText(label), error);
        }
    }
    std::size_t calls = 0;
    for (const Frame &f : m_frames)
        calls += f.kind == FrameKind::Call;
    if (calls >= kMaxCallDepth)
        return failAt(ErrorCode::CallTooDeep, col, {}, error);
    m_params.pushScope();
    for (int i = 0; i < Parameters::kArgCount; ++i)
        m_params.setNumbered(i + 1, i < static_cast<int>(m_args.size()) ? m_args[i] : 0.0);
    m_frames.push_back({FrameKind::Call, label, m_next, m_line, 0, column, 0, m_source});
    contextHere() = {}; // the call level starts with no saved state
    if (m_source == 0 && it->second.source != 0)
        m_fileCallLine = m_line;
    enterSource(it->second.source);
    jump(it->second.offset, it->second.line);
    return true;
}

bool Interpreter::returnFromSub(Error *error)
{
    const std::string label = m_block.oLabel;
    const std::string what = labelText(label) + " " + okindName(m_block.oKind);
    if (!m_parser.owordArgs(m_block, &m_args, error))
        return false;
    // Leave every if/loop opened inside the subroutine. As rs274, return and endsub end the
    // running call whatever their label (o1010 return inside o1010 if of o1000 sub returns from
    // o1000); outside a call they are an error.
    std::size_t i = m_frames.size();
    while (i > 0 && m_frames[i - 1].kind != FrameKind::Call)
        --i;
    if (i == 0)
        return failAt(ErrorCode::ReturnOutsideSub, m_block.oColumn, what, error);
    m_valueReturned = !m_args.empty();
    m_value = m_valueReturned ? m_args[0] : 0.0; // #<_value> is 0 after a plain return
    const Frame call = m_frames[i - 1];
    m_frames.resize(i - 1);
    m_params.popScope();
    enterSource(call.source);
    jump(call.offset, call.line);
    return leaveCallContext(error);
}

bool Interpreter::loopJump(bool isBreak, Error *error)
{
    const std::string label = m_block.oLabel;
    const std::string what = labelText(label) + " " + okindName(m_block.oKind);
    std::size_t i = m_frames.size();
    while (i > 0) {
        const Frame &f = m_frames[i - 1];
        if (f.kind == FrameKind::Call)
            break;
        if (f.label == label &&
            (f.kind == FrameKind::While || f.kind == FrameKind::Do || f.kind == FrameKind::Repeat))
            break;
        --i;
    }
    if (i == 0 || m_frames[i - 1].kind == FrameKind::Call)
        return failAt(ErrorCode::BreakOutsideLoop, m_block.oColumn, what, error);
    m_frames.resize(i); // drop the ifs opened inside the loop
    Frame &loop = m_frames.back();
    OKind found = OKind::None;
    if (loop.kind == FrameKind::While) {
        if (isBreak) {
            m_frames.pop_back();
            return skipTo(label, {OKind::EndWhile}, &found, error);
        }
        ++loop.turns;
        jump(loop.offset, loop.line); // re-evaluates the condition
        return true;
    }
    if (loop.kind == FrameKind::Repeat) {
        if (!isBreak && --loop.remaining > 0) {
            ++loop.turns;
            jump(loop.offset, loop.line);
            return true;
        }
        m_frames.pop_back();
        return skipTo(label, {OKind::EndRepeat}, &found, error);
    }
    // do ... while: break leaves after the closing while, continue evaluates it.
    if (!skipTo(label, {OKind::While}, &found, error))
        return false;
    if (isBreak) {
        m_frames.pop_back();
        return true;
    }
    return executeOword(error);
}

// Which loop never ends is a guess, but a good one: the loop whose current run has turned most
// (an endless outer loop keeps turning while the finite inner ones start afresh; an endless
// inner loop keeps turning while the outer one waits). Without a loop that turns, a recursion:
// the first call of a subroutine from inside itself. The error stands on that line, with the
// line the program had reached.
Error Interpreter::boundError(ErrorCode plain, ErrorCode inLoop, std::uint64_t bound) const
{
    const Frame *at = nullptr;
    for (const Frame &f : m_frames) {
        const bool loop =
            f.kind == FrameKind::While || f.kind == FrameKind::Do || f.kind == FrameKind::Repeat;
        if (loop && (!at || f.turns >= at->turns))
            at = &f;
    }
    const auto recursive = [this](std::size_t i) {
        return m_frames[i].kind == FrameKind::Call &&
               std::any_of(m_frames.begin(), m_frames.begin() + std::ptrdiff_t(i),
                           [&](const Frame &f) {
                               return f.kind == FrameKind::Call && f.label == m_frames[i].label;
                           });
    };
    bool turning = at && at->turns > 0;
    for (std::size_t i = 0; !turning && i < m_frames.size(); ++i) {
        if (recursive(i)) {
            at = &m_frames[i];
            turning = true;
        }
    }
    const std::string limit = std::to_string(bound);
    if (!at)
        return {plain, m_line, 1, limit, {}};
    const OKind kind = at->kind == FrameKind::While  ? OKind::While
                       : at->kind == FrameKind::Do   ? OKind::Do
                       : at->kind == FrameKind::Call ? OKind::Call
                                                     : OKind::Repeat;
    // A while frame is kept at the line before its while line (the jump re-reads it).
    const std::uint32_t line = at->kind == FrameKind::While ? at->line + 1 : at->line;
    return {inLoop,
            line,
            at->column,
            limit + kDetailSeparator + std::to_string(m_line) + kDetailSeparator +
                labelText(at->label) + " " + okindName(kind),
            {}};
}

} // namespace frezka::gcode
