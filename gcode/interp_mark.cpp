// Run from a line: the interpreter's state where the chosen line begins (gcode/linestate.h).
//
// The start line is the first line at or after Options::startLine that is about to run at the
// program's top level. A line reached inside a subroutine call does not count (the program runs
// it only when called); a loop open around it means the program runs it more than once; a skip
// over it (a sub's body at its definition, a branch or loop body not taken) means it never runs
// from there. Each of these refuses with the line to choose instead.
#include "interpreter.h"

namespace frezka::gcode {

namespace {

std::string labelOf(const std::string &label)
{
    return label.empty() || (label[0] >= '0' && label[0] <= '9') ? label : "<" + label + ">";
}

} // namespace

LineState Interpreter::lineState() const
{
    LineState s;
    s.machineMm = m_pos;
    s.programMm = m_prog;
    s.metric = m_metric;
    s.plane = m_plane;
    s.absolute = m_absolute;
    s.arcAbsolute = m_arcAbsolute;
    s.inverseTime = m_inverseTime;
    s.coordinateSystem = m_coord;
    s.workOffsetMm = m_origin[std::size_t(m_coord)];
    s.g92Mm = m_g92;
    s.tool = m_tool;
    s.selectedTool = m_selectedTool;
    s.toolLengthMm = m_toolOffset[2];
    s.speedRpm = m_speed;
    s.spindle = m_spindle;
    s.mist = m_mist;
    s.flood = m_flood;
    s.feedMmPerMin = feedMm();
    s.motion = m_motion;
    s.pathMode = m_pathMode;
    s.pathToleranceMm = m_pathP;
    s.pathQMm = m_pathQ;
    return s;
}

void Interpreter::markBefore()
{
    const std::uint32_t asked = m_options.startLine;
    for (const Frame &f : m_frames) {
        if (f.kind != FrameKind::Call)
            continue;
        // Inside a call: the line counts only at the top level. A call running the very line
        // asked for names the call, in case the program never reaches it otherwise.
        if (m_line == asked && m_callLine == 0) {
            m_callLine = f.line; // the outermost call: its line is at the top level
            m_callLabel = labelOf(f.label);
        }
        return;
    }
    m_marked = true;
    m_mark.askedLine = asked;
    if (m_skipRefusal != LineMarkRefusal::None) {
        m_mark.refusal = m_skipRefusal;
        m_mark.refLine = m_skipLine;
        m_mark.label = m_skipLabel;
        return;
    }
    for (const Frame &f : m_frames) {
        if (f.kind == FrameKind::While || f.kind == FrameKind::Do || f.kind == FrameKind::Repeat) {
            m_mark.refusal = LineMarkRefusal::InLoop;
            m_mark.refLine = f.kind == FrameKind::While ? f.line + 1 : f.line;
            m_mark.label = labelOf(f.label);
            return;
        }
    }
    if (m_comp.on()) { // the compensated path depends on the moves before the line
        m_mark.refusal = LineMarkRefusal::InCutterComp;
        m_mark.refLine = m_comp.onLine;
        return;
    }
    m_mark.line = m_line;
    m_mark.entry = m_toolpath.size();
    m_mark.state = lineState();
}

void Interpreter::noteSkipped(std::uint32_t from, OKind opening, const std::string &label)
{
    const std::uint32_t asked = m_options.startLine;
    if (asked == 0 || m_marked || m_lookingAhead || m_skipRefusal != LineMarkRefusal::None)
        return;
    if (m_source != 0)
        return; // lines of a subroutine file, not the program's
    if (asked <= from || asked > m_line)
        return;
    m_skipRefusal =
        opening == OKind::Sub ? LineMarkRefusal::InSubroutine : LineMarkRefusal::NotTaken;
    m_skipLine = from;
    m_skipLabel = labelOf(label);
}

void Interpreter::finishMark(LineMark *mark) const
{
    if (m_options.startLine == 0)
        return;
    if (m_marked) {
        *mark = m_mark;
        return;
    }
    mark->askedLine = m_options.startLine;
    if (m_skipRefusal != LineMarkRefusal::None) {
        mark->refusal = m_skipRefusal;
        mark->refLine = m_skipLine;
        mark->label = m_skipLabel;
    } else if (m_callLine != 0) {
        mark->refusal = LineMarkRefusal::InCall;
        mark->refLine = m_callLine;
        mark->label = m_callLabel;
    } else {
        mark->refusal = LineMarkRefusal::NotReached;
        mark->refLine = m_line;
    }
}

} // namespace frezka::gcode
