// LinuxCNC's modal state save and restore (M70 save, M71 invalidate, M72 restore, M73 save and
// restore when the subroutine returns), one saved state per call level, as rs274ngc keeps it in
// its call frames. A restore runs what rs274ngc's restore_settings runs: G20/G21 first when the
// units differ, then one block "F<saved, 1 decimal> S<saved, whole> <each differing G mode>
// <G64 P Q when G64 was saved>" and one line per differing M3/M4/M5, M7/M9, M8/M9; the motion
// mode is not restored. So the same canonical calls (feeds rounded as rs274ngc rounds them,
// spindle events) come out. M70 to M73 stand on a line of their own here (rs274ngc executes them
// between M3-M5 and M7-M9 of a block; a block with other codes would depend on that order).
#include "interpreter.h"

#include <cmath>
#include <cstdio>

namespace frezka::gcode {

namespace {

std::string gText(int code10)
{
    return code10 % 10 ? "G" + std::to_string(code10 / 10) + "." + std::to_string(code10 % 10)
                       : "G" + std::to_string(code10 / 10);
}

std::string fixed(const char *format, double v)
{
    char buf[64];
    std::snprintf(buf, sizeof buf, format, v);
    return buf;
}

} // namespace

Interpreter::ModalContext Interpreter::modalNow() const
{
    ModalContext c;
    c.valid = true;
    c.metric = m_metric;
    c.codes = {m_plane,
               m_comp.on() ? (m_comp.side == CompSide::Left ? 410 : 420) : 400,
               m_absolute ? 900 : 910,
               m_inverseTime ? 930 : 940,
               m_coord < 6 ? 540 + 10 * m_coord : 590 + (m_coord - 5),
               m_toolLengthG == 490 ? 490 : 430,
               m_retractToR ? 990 : 980,
               m_arcAbsolute ? 901 : 911,
               m_g92Enabled ? 923 : 922};
    c.pathMode = m_pathMode;
    c.pathP = m_pathP / unit();
    c.pathQ = m_pathQ / unit();
    c.feed = m_feed;
    c.speed = m_speed;
    c.spindle = m_spindle;
    c.mist = m_mist;
    c.flood = m_flood;
    return c;
}

std::size_t Interpreter::callDepth() const
{
    std::size_t calls = 0;
    for (const Frame &f : m_frames)
        calls += f.kind == FrameKind::Call;
    return calls;
}

Interpreter::ModalContext &Interpreter::contextHere()
{
    const std::size_t depth = callDepth();
    if (m_contexts.size() <= depth)
        m_contexts.resize(depth + 1);
    return m_contexts[depth];
}

bool Interpreter::modalState(Error *error)
{
    const Block &b = m_block;
    const int m = b.m[kMState];
    const std::uint32_t col = b.mColumn[kMState];
    if (b.letters != 0 || b.gMask != 0 || b.mMask != (1u << kMState) || !m_assignments.empty())
        return failAt(ErrorCode::ModalStateNotAlone, col, "M" + std::to_string(m), error);
    ModalContext &here = contextHere();
    if (m == 70 || m == 73) {
        here = modalNow();
        // rs274ngc: M73 at the top level stores the state but has nothing to return to.
        here.restoreOnReturn = m == 73 && callDepth() > 0;
        return true;
    }
    if (m == 71) {
        here.valid = false;
        return true;
    }
    if (!here.valid)
        return failAt(ErrorCode::ModalStateNotSaved, col, "M72", error);
    const ModalContext saved = here;
    return restoreModal(saved, error);
}

bool Interpreter::restoreModal(const ModalContext &saved, Error *error)
{
    const ModalContext now = modalNow();
    if (saved.metric != now.metric && !runStateLine(saved.metric ? "G21" : "G20", error))
        return false;
    std::string cmd = fixed(" F%.1f", saved.feed) + fixed(" S%.0f", saved.speed);
    for (std::size_t i = 0; i < saved.codes.size(); ++i) {
        if (saved.codes[i] != now.codes[i])
            cmd += " " + gText(saved.codes[i]);
    }
    if (saved.pathMode == 2) {
        cmd += " G64";
        if (saved.pathP > 0)
            cmd += fixed(" P%f", saved.pathP);
        if (saved.pathP > 0 && saved.pathQ > 0)
            cmd += fixed(" Q%f", saved.pathQ);
    } else if (saved.pathMode != now.pathMode) {
        cmd += saved.pathMode == 0 ? " G61" : " G61.1";
    }
    if (!runStateLine(cmd, error))
        return false;
    if (saved.spindle != m_spindle && !runStateLine(saved.spindle > 0   ? "M3"
                                                    : saved.spindle < 0 ? "M4"
                                                                        : "M5",
                                                    error))
        return false;
    if (saved.mist != m_mist && !runStateLine(saved.mist ? "M7" : "M9", error))
        return false;
    return saved.flood == m_flood || runStateLine(saved.flood ? "M8" : "M9", error);
}

bool Interpreter::runStateLine(const std::string &text, Error *error)
{
    // The line stands in for the M72 (or return) line: its errors are reported there.
    if (!m_parser.normalize(text, m_line, error) || !m_parser.parse(m_block, m_assignments, error))
        return false;
    return executeBlock(error);
}

bool Interpreter::leaveCallContext(Error *error)
{
    const std::size_t leaving = callDepth() + 1; // the call frame is already gone
    if (m_contexts.size() <= leaving)
        return true;
    const ModalContext saved = m_contexts[leaving];
    m_contexts.resize(leaving);
    return !(saved.valid && saved.restoreOnReturn) || restoreModal(saved, error);
}

} // namespace frezka::gcode
