#include "mdisession.h"

#include "gcode/interpreter.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>

namespace frezka::session {
namespace {

// Readback values arrive as G4 dwells; P must not be negative, so every value is shifted.
constexpr double kShift = 1000000;
constexpr const char *kShiftText = "1000000";
constexpr int kModalValues = 9;
constexpr int kValues = kModalValues + 4 + kWorkSystems * 4;

std::string num(double v)
{
    char buf[48];
    std::snprintf(buf, sizeof buf, "%.9f", v);
    return buf;
}

std::string axisWords(const Axes4 &v)
{
    return "X" + num(v[0]) + " Y" + num(v[1]) + " Z" + num(v[2]) + " A" + num(v[3]);
}

// A motion mode that can be restored by its G code alone on a line of its own.
constexpr const char *kRestoreMotion = "o9001 if [[#<_fz_mot> EQ 0] OR [#<_fz_mot> EQ 1] OR "
                                       "[#<_fz_mot> EQ 80]]\nG[#<_fz_mot>]\no9001 endif\n";

bool onlyMissingEnd(const gcode::Result &r)
{
    for (const gcode::Error &e : r.errors) {
        if (e.code != gcode::ErrorCode::FileEndedWithoutEnd)
            return false;
    }
    return true;
}

// The program position (active system + G92) of a machine position, in mm.
Axes4 programOf(const Axes4 &machineMm, const OffsetState &o)
{
    return o.workPosition(machineMm);
}

bool anyNonZero(const Axes4 &v)
{
    return v[0] != 0 || v[1] != 0 || v[2] != 0 || v[3] != 0;
}

} // namespace

QString ModalState::text() const
{
    const QString motionText = QString::number(motion);
    return QStringLiteral("G%1 G%2 G%3 G%4 G%5 %6 F%7 S%8")
        .arg(motionText)
        .arg(plane)
        .arg(metric ? 21 : 20)
        .arg(absolute ? 90 : 91)
        .arg(inverseTime ? 93 : 94)
        .arg(workSystemName(coordSystem))
        .arg(feed)
        .arg(rpm);
}

MdiSession::MdiSession() = default;
MdiSession::~MdiSession() = default;

void MdiSession::reset()
{
    m_interp.reset();
    m_modal = {};
    m_inSync = false;
}

bool MdiSession::start(const Axes4 &machineMm, const OffsetState &offsets)
{
    gcode::Options options;
    options.acceptMissingEnd = false; // a console line is no program: it never ends
    options.workOffsetsMm = offsets.systems;
    options.coordinateSystem = offsets.active;
    options.startMm = {machineMm[0], machineMm[1], machineMm[2], machineMm[3]};
    m_interp = std::make_unique<gcode::Interpreter>(options);
    m_modal = {};
    m_modal.coordSystem = offsets.active;
    m_at = machineMm;
    m_offsets = offsets;
    m_inSync = true;
    if (!anyNonZero(offsets.g92))
        return true;
    const std::string g92 = "G92 " + axisWords(programOf(machineMm, offsets)) + "\n";
    return onlyMissingEnd(m_interp->run(g92));
}

// Brings the live interpreter to the machine position and the offsets; its modes stay.
bool MdiSession::sync(const Axes4 &machineMm, const OffsetState &offsets)
{
    std::string s = "#<_fz_inc> = #<_incremental>\n#<_fz_mm> = #<_metric>\n"
                    "#<_fz_mot> = #<_motion_mode>\nG90 G21 G92.1\n";
    for (int i = 0; i < kWorkSystems; ++i)
        s += "G10 L2 P" + std::to_string(i + 1) + " " + axisWords(offsets.systems[std::size_t(i)]) +
             "\n";
    s += workSystemName(offsets.active).toStdString() + "\n";
    s += "G53 G0 " + axisWords(machineMm) + "\n";
    if (anyNonZero(offsets.g92))
        s += "G92 " + axisWords(programOf(machineMm, offsets)) + "\n";
    s += "G[90 + #<_fz_inc>] G[20 + #<_fz_mm>]\n";
    s += kRestoreMotion;
    if (!onlyMissingEnd(m_interp->run(s)))
        return false;
    m_at = machineMm;
    m_offsets = offsets;
    m_inSync = true;
    return true;
}

MdiSession::Outcome MdiSession::interpret(std::string_view line, const Axes4 &machineMm,
                                          const OffsetState &offsets)
{
    Outcome out;
    out.offsets = offsets;
    bool ready = m_interp && m_inSync && m_at == machineMm && m_offsets == offsets;
    if (!ready && m_interp)
        ready = sync(machineMm, offsets);
    if (!ready)
        ready = start(machineMm, offsets); // first line, or the sync failed: modes are lost
    gcode::Result r = m_interp->run(line);
    for (const gcode::Error &e : r.errors) {
        if (e.code != gcode::ErrorCode::FileEndedWithoutEnd)
            out.errors.push_back(e);
    }
    out.toolpath = std::move(r.toolpath);
    if (r.ended) { // M2 / M30: LinuxCNC's end of program resets the modes
        m_interp.reset();
        m_modal = {};
        return out;
    }
    if (!out.ok()) {
        m_inSync = false; // a half-executed line: bring it back to the machine next time
        return out;
    }
    m_at = {out.toolpath.last().x, out.toolpath.last().y, out.toolpath.last().z,
            out.toolpath.last().a};
    OffsetState after = offsets;
    if (!readBack(&after)) {
        m_inSync = false;
        return out;
    }
    m_offsets = after;
    out.offsetsChanged = !(after == offsets);
    out.offsets = after;
    return out;
}

// Reads the modes and the offsets from the interpreter's parameters.
bool MdiSession::readBack(OffsetState *offsets)
{
    static const char *kModal[kModalValues] = {"#<_metric>", "#<_absolute>",    "#<_inverse_time>",
                                               "#<_plane>",  "#<_motion_mode>", "#<_feed>",
                                               "#<_rpm>",    "#5220",           "#5210"};
    std::string s;
    for (const char *p : kModal)
        s += std::string("G4 P[") + p + " + " + kShiftText + "]\n";
    for (int i = 0; i < 4; ++i)
        s += "G4 P[#" + std::to_string(5211 + i) + " + " + kShiftText + "]\n";
    for (int sys = 0; sys < kWorkSystems; ++sys)
        for (int i = 0; i < 4; ++i)
            s += "G4 P[#" + std::to_string(5221 + 20 * sys + i) + " + " + kShiftText + "]\n";
    const gcode::Result r = m_interp->run(s);
    if (!onlyMissingEnd(r) || r.toolpath.size() != std::size_t(kValues))
        return false;
    std::vector<double> v(kValues);
    for (std::size_t i = 0; i < v.size(); ++i)
        v[i] = r.toolpath.event(i).value - kShift;
    ModalState m;
    m.metric = v[0] > 0.5;
    m.absolute = v[1] > 0.5;
    m.inverseTime = v[2] > 0.5;
    m.plane = int(std::lround(v[3])) / 10;
    m.motion = std::round(v[4] * 10) / 10;
    m.feed = std::round(v[5] * 1e6) / 1e6;
    m.rpm = std::round(v[6] * 1e6) / 1e6;
    m.coordSystem = std::clamp(int(std::lround(v[7])) - 1, 0, kWorkSystems - 1);
    m_modal = m;
    const double unit = m.metric ? 1.0 : 25.4;
    // A value read back within a nanometre of the one given is the one given (no drift).
    auto update = [&](double *held, double value, int axis) {
        const double mm = axis < 3 ? value * unit : value;
        if (std::abs(mm - *held) > 1e-6)
            *held = mm;
    };
    const bool g92On = v[8] > 0.5;
    for (int i = 0; i < 4; ++i)
        update(&offsets->g92[std::size_t(i)], g92On ? v[std::size_t(9 + i)] : 0.0, i);
    for (int sys = 0; sys < kWorkSystems; ++sys)
        for (int i = 0; i < 4; ++i)
            update(&offsets->systems[std::size_t(sys)][std::size_t(i)],
                   v[std::size_t(13 + sys * 4 + i)], i);
    offsets->active = m.coordSystem;
    return true;
}

} // namespace frezka::session
