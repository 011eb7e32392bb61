// Tools as LinuxCNC's rs274ngc treats them with a non-random tool changer: T selects a tool of
// the table, M6 puts it in the spindle, M61 Q says which tool is there without a change; G43
// takes the offsets of the tool in the spindle (G43 H of any tool, H0 the spindle's), G43.1 sets
// offsets given in the block, G43.2 adds a tool's or the block's offsets, G49 cancels. G10 L1
// writes a tool's offsets as given, L10 and L11 so that the current position would read the
// given values in the active work system (L10) or in G59.3 without G92 (L11); the offsets in
// force change only with the next G43, as in LinuxCNC.
#include "interpreter.h"

#include <cmath>

namespace frezka::gcode {

bool Interpreter::toolNumber(char word, int *tool, Error *error) const
{
    const double v = m_block.get(word);
    if (v < 0)
        return fail(ErrorCode::NegativeValue, word, std::string(1, char(word - 32)), error);
    if (v != std::floor(v) || v > 1e9)
        return fail(ErrorCode::NonIntegerValue, word, std::string(1, char(word - 32)), error);
    *tool = static_cast<int>(v);
    return true;
}

bool Interpreter::findTool(int tool, char word, ToolEntry *entry, Error *error) const
{
    if (const ToolEntry *e = m_tools.find(tool)) {
        *entry = *e;
        return true;
    }
    if (m_toolsStrict)
        return fail(ErrorCode::ToolNotInTable, word, std::to_string(tool), error);
    *entry = ToolEntry{};
    entry->tool = tool;
    const auto it = m_options.toolLengthMm.find(tool);
    entry->offsetMm[2] = it == m_options.toolLengthMm.end() ? 0.0 : it->second;
    return true;
}

ToolEntry Interpreter::spindleTool() const
{
    if (m_tool == 0)
        return ToolEntry{};
    if (const ToolEntry *e = m_tools.find(m_tool))
        return *e;
    ToolEntry e;
    e.tool = m_tool;
    if (const auto it = m_options.toolLengthMm.find(m_tool); it != m_options.toolLengthMm.end())
        e.offsetMm[2] = it->second;
    return e;
}

bool Interpreter::selectTool(Error *error)
{
    const Block &b = m_block;
    if (!b.has('t') && !b.hasM(kMToolChange))
        return true; // most blocks: no ToolEntry (with its comment string) made and dropped
    ToolEntry e;
    if (b.has('t')) {
        int t = 0;
        if (!toolNumber('t', &t, error) || (t != 0 && !findTool(t, 't', &e, error)))
            return false;
        m_selectedTool = t;
    }
    if (!b.hasM(kMToolChange))
        return true;
    if (b.m[kMToolChange] == 6) {
        if (m_comp.on())
            return failAt(ErrorCode::CompNotAllowed, b.mColumn[kMToolChange], "M6", error);
        // rs274ngc reads the position back after a tool change: after G40 the programmed point
        // (where the next move would have started) gives way to where the tool is.
        if (!(m_pos == m_toolpath.last())) {
            m_pos = m_toolpath.last();
            m_prog = toProgram(m_pos);
        }
        m_tool = m_selectedTool;
        event(EventKind::ToolChange, m_tool);
        return true;
    }
    // M61 Q: the tool in the spindle, no change (no prompt, no event).
    if (!b.has('q'))
        return failAt(ErrorCode::ToolNumberMissing, b.mColumn[kMToolChange],
                      std::string("M61") + kDetailSeparator + "Q", error);
    int q = 0;
    if (!toolNumber('q', &q, error) || (q != 0 && !findTool(q, 'q', &e, error)))
        return false;
    m_tool = q;
    return true;
}

bool Interpreter::toolLengthOffset(Error *error)
{
    const Block &b = m_block;
    const int g = b.g[kGToolLength];
    m_toolLengthG = g;
    std::array<double, 4> next = m_toolOffset;
    auto fromEntry = [](const ToolEntry &e) {
        return std::array<double, 4>{e.offsetMm[0], e.offsetMm[1], e.offsetMm[2], e.offsetMm[3]};
    };
    auto toolOf = [&](ToolEntry *e) {
        int h = 0;
        if (!toolNumber('h', &h, error))
            return false;
        if (h == 0) { // H0 is the tool in the spindle (LinuxCNC's index 0)
            *e = spindleTool();
            return true;
        }
        return findTool(h, 'h', e, error);
    };
    const bool axes = b.letters & kAxisBits;
    ToolEntry e = spindleTool();
    if (g == 490) {
        next = {};
    } else if (g == 430) {
        if (b.has('h') && !toolOf(&e))
            return false;
        next = fromEntry(e);
    } else if (g == 431 || !b.has('h')) { // G43.1, or G43.2 with axis words
        if (g == 432 && !axes)
            return failAt(ErrorCode::ToolOffsetWords, b.gColumn[kGToolLength], "G43.2", error);
        for (int i = 0; i < 4; ++i) {
            const char c = kAxisLetters[i];
            if (b.has(c))
                next[i] = (g == 432 ? next[i] : 0.0) + (i < 3 ? lengthWord(c) : b.get(c));
        }
    } else { // G43.2 H
        if (axes)
            return failAt(ErrorCode::ToolOffsetWords, b.gColumn[kGToolLength], "G43.2", error);
        if (!toolOf(&e))
            return false;
        const auto add = fromEntry(e);
        for (int i = 0; i < 4; ++i)
            next[i] += add[i];
    }
    const auto before = offsets();
    m_toolOffset = next;
    shiftProgram(before);
    return true;
}

bool Interpreter::setToolEntry(int l, Error *error)
{
    const Block &b = m_block;
    const std::string code = "G10 L" + std::to_string(l);
    if (!b.has('p'))
        return failAt(ErrorCode::ToolNumberMissing, b.gColumn[kGNonModal],
                      code + kDetailSeparator + "P", error);
    int tool = 0;
    ToolEntry e;
    if (!toolNumber('p', &tool, error))
        return false;
    if (tool == 0 || !findTool(tool, 'p', &e, error))
        return tool == 0 ? fail(ErrorCode::ToolNotInTable, 'p', "0", error) : false;
    const bool axes = b.letters & kAxisBits;
    if (!axes && !b.has('r') && !b.has('q') && !b.has('i') && !b.has('j'))
        return failAt(ErrorCode::G10L1NoOffsets, b.gColumn[kGNonModal], code, error);
    if (b.has('q')) {
        const double q = b.get('q');
        if (q != std::floor(q))
            return fail(ErrorCode::NonIntegerValue, 'q', "Q", error);
        if (q < 0 || q > 9)
            return fail(ErrorCode::ValueOutOfRange, 'q', "Q", error);
        e.orientation = static_cast<int>(q);
    }
    // L10/L11: the position without tool offsets in the target system (L11: G59.3, no G92).
    const int system = l == 11 ? 8 : m_coord;
    const double *pos = &m_pos.x;
    for (int i = 0; i < 4; ++i) {
        const char c = kAxisLetters[i];
        if (!b.has(c))
            continue;
        const double v = i < 3 ? lengthWord(c) : b.get(c);
        const double here = pos[i] - m_origin[system][i] - (l == 11 ? 0.0 : m_g92[i]);
        e.offsetMm[static_cast<std::size_t>(i)] = l == 1 ? v : here - v;
    }
    if (b.has('r'))
        e.diameterMm = 2 * lengthWord('r');
    if (b.has('i'))
        e.frontAngle = b.get('i');
    if (b.has('j'))
        e.backAngle = b.get('j');
    if (ToolEntry *slot = m_tools.find(tool))
        *slot = e;
    else
        m_tools.tools.push_back(e); // no table given: the program's own entry
    m_toolsChanged = true;
    return true;
}

} // namespace frezka::gcode
