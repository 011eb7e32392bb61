// Splitting a planned 4-axis program between the machine's unit and a rotary unit. See
// rotarysplit.h.

#include "machine/rotarysplit.h"

#include "machine/leadin.h"

#include <algorithm>
#include <cmath>
#include <cstdlib>

namespace frezka::machine {

namespace {

constexpr std::int64_t kMinSpeed = 10; // pulses/s, the unit's slowest V and B (§4)

std::int64_t major(const std::array<std::int32_t, 4> &d)
{
    std::int64_t m = 0;
    for (std::int32_t v : d)
        m = std::max<std::int64_t>(m, std::llabs(v));
    return m;
}

bool movesA(const UnitCommand &c)
{
    return (c.op == UnitOp::Vector || c.op == UnitOp::Line) && c.d[3] != 0;
}

// One unit's program being built: its position and the A, V, B it holds.
class UnitOut
{
public:
    UnitOut(const UnitProgram &planned, bool rotary)
        : m_rotary(rotary)
    {
        m_out.program.axisCount = planned.axisCount;
        m_out.program.startSteps = planned.startSteps;
        for (int k = 0; k < 4; ++k)
            if ((k == 3) != rotary)
                m_out.program.startSteps[static_cast<std::size_t>(k)] = 0;
        m_at = m_out.program.startSteps;
    }

    void copy(UnitCommand c)
    {
        c.endSteps = m_at;
        m_out.program.commands.push_back(c);
    }
    // This unit's part of a planned motion at the planned A, V, B scaled to its major axis;
    // false when the part is empty.
    bool motion(UnitCommand c, std::int64_t accel, std::int64_t speed, std::int64_t brake)
    {
        for (std::size_t k = 0; k < 4; ++k)
            if ((k == 3) != m_rotary)
                c.d[k] = 0;
        const std::int64_t part = major(c.d);
        if (part == 0)
            return false;
        const std::int64_t whole = major(m_whole);
        const double s = whole > 0 ? double(part) / double(whole) : 1.0;
        const auto scaled = [s](std::int64_t v, std::int64_t lo) {
            return s == 1.0 ? v : std::max(lo, static_cast<std::int64_t>(std::llround(v * s)));
        };
        modal(UnitOp::Accel, m_accel, scaled(accel, 1), c.sourceLine);
        modal(UnitOp::Speed, m_speed, scaled(speed, kMinSpeed), c.sourceLine);
        if (c.op == UnitOp::Vector)
            modal(UnitOp::Brake, m_brake, scaled(brake, kMinSpeed), c.sourceLine);
        for (std::size_t k = 0; k < 4; ++k)
            m_at[k] += c.d[k];
        copy(c);
        return true;
    }
    void setWhole(const std::array<std::int32_t, 4> &d) { m_whole = d; }
    void sync(bool held) { m_out.syncs.push_back({m_out.program.commands.size(), held}); }
    // Marks the last sync point held (the unit moved in the block that starts there).
    void holdLast() { m_out.syncs.back().held = true; }
    SyncedProgram take() { return std::move(m_out); }

private:
    void modal(UnitOp op, std::int64_t &held, std::int64_t value, std::uint32_t line)
    {
        if (held == value)
            return;
        held = value;
        UnitCommand c;
        c.op = op;
        c.value = value;
        c.sourceLine = line;
        copy(c);
    }

    bool m_rotary;
    SyncedProgram m_out;
    Steps4 m_at{};
    std::array<std::int32_t, 4> m_whole{};
    std::int64_t m_accel = -1, m_speed = -1, m_brake = -1;
};

// The pieces of the program: each ends at a command where the unit rests (inclusive).
std::vector<std::pair<std::size_t, std::size_t>> pieces(const UnitCommands &cmds, std::size_t from)
{
    std::vector<std::pair<std::size_t, std::size_t>> out;
    std::size_t begin = from;
    for (std::size_t i = from; i < cmds.size(); ++i) {
        if (restsAt(cmds.op(i)) && cmds.op(i) != UnitOp::Line) {
            out.emplace_back(begin, i + 1);
            begin = i + 1;
        }
    }
    if (begin < cmds.size())
        out.emplace_back(begin, cmds.size());
    return out;
}

bool isSetup(UnitOp op)
{
    return op == UnitOp::SpeedModeVk || op == UnitOp::SpeedModeVn || op == UnitOp::ShortThreshold ||
           op == UnitOp::Pause;
}

} // namespace

MachineConfig withRotaryA(const MachineConfig &machine, const MachineConfig &rotary)
{
    MachineConfig c = machine;
    c.axes[3] = rotary.axes[3];
    c.axes[3].present = true;
    return c;
}

// One pass over the planned commands, piece by piece (a piece ends where the unit rests). Kept
// whole (about 60 lines): which unit gets which command reads in one place.
RotarySplit splitRotaryA(const UnitProgram &planned)
{
    RotarySplit r;
    UnitOut machine(planned, false), rotary(planned, true);
    const UnitCommands &cmds = planned.commands;
    std::size_t first = 0;
    while (first < cmds.size() && isSetup(cmds.op(first))) {
        machine.copy(cmds[first]);
        rotary.copy(cmds[first]);
        ++first;
    }
    std::int64_t accel = -1, speed = -1, brake = -1;
    bool afterSync = false; // the piece before was a sync block: a barrier at its end
    for (const auto &[begin, end] : pieces(cmds, first)) {
        bool sync = false;
        int motions = 0;
        for (std::size_t i = begin; i < end; ++i) {
            sync = sync || movesA(cmds[i]);
            motions += cmds[i].op == UnitOp::Vector || cmds[i].op == UnitOp::Line ? 1 : 0;
        }
        if (sync && motions > 1) { // one vector a block: its parts' speed ratios stay fixed
            r.errorCode = RotarySplit::Error::NotRestAroundA;
            r.errorLine = cmds[begin].sourceLine;
            r.error = "the program was not planned with a rest around each move that turns A "
                      "(PlanOptions::restAroundA)";
            return r;
        }
        if (sync)
            ++r.blocks;
        if (sync || afterSync) { // the block's barrier, or the one after a block
            machine.sync(false);
            rotary.sync(false);
        }
        for (std::size_t i = begin; i < end; ++i) {
            const UnitCommand c = cmds[i];
            const bool motion = c.op == UnitOp::Vector || c.op == UnitOp::Line;
            if (c.op == UnitOp::Accel)
                accel = c.value;
            else if (c.op == UnitOp::Speed)
                speed = c.value;
            else if (c.op == UnitOp::Brake)
                brake = c.value;
            else if (motion) {
                machine.setWhole(c.d);
                rotary.setWhole(c.d);
                if (machine.motion(c, accel, speed, brake) && sync)
                    machine.holdLast();
                if (rotary.motion(c, accel, speed, brake))
                    rotary.holdLast();
            } else if (c.op == UnitOp::Probe && c.d[3] != 0) {
                r.errorCode = RotarySplit::Error::ProbeTurnsA;
                r.errorLine = c.sourceLine;
                r.error = "a probe move that turns A cannot run with A on its own unit";
                return r;
            } else {
                machine.copy(c);
                if (sync && c.op == UnitOp::WaitIdle)
                    rotary.copy(c);
            }
        }
        afterSync = sync;
    }
    r.machine = machine.take();
    r.rotary = rotary.take();
    return r;
}

} // namespace frezka::machine
