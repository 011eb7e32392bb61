// The planner's walk over the toolpath: steps, soft limits, synchronisation points and the
// emission of unit commands (docs/planner.md). Vertex speeds: chainplanner.cpp; the program's
// events: planevents.cpp; the estimate and the bound: planstats.cpp.
#include "machine/planner.h"

#include "machine/chainparts.h"
#include "machine/chainplanner.h"
#include "machine/planner_internal.h"
#include "machine/softlimits.h"
#include "machine/steps.h"
#include "machine/unitwire.h"

#include <algorithm>
#include <bit>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace frezka::machine {

namespace detail {

namespace {

using gcode::MotionKind;
using gcode::Point4;

constexpr std::size_t kMaxErrors = 100;

double coord(const Point4 &p, int i)
{
    return i == 0 ? p.x : i == 1 ? p.y : i == 2 ? p.z : p.a;
}

bool sameBits(double a, double b)
{
    return std::bit_cast<std::uint64_t>(a) == std::bit_cast<std::uint64_t>(b);
}

} // namespace

// A move's modes are the last move's where they are the same to the bit (a zero's sign
// included): the planner reads exactly what it was given.
void Moves::push_back(Move m, const MoveModes &modes)
{
    const bool same = !m_modes.empty() && sameBits(m_modes.back().feedMmPerS, modes.feedMmPerS) &&
                      sameBits(m_modes.back().junctionDeviationMm, modes.junctionDeviationMm) &&
                      m_modes.back().rapid == modes.rapid &&
                      m_modes.back().stopAfter == modes.stopAfter;
    if (!same)
        m_modes.push_back(modes);
    m.modes = static_cast<std::uint32_t>(m_modes.size() - 1);
    m_moves.push_back(m);
}

void Moves::clear()
{
    m_moves.clear();
    m_modes.clear();
}

std::string fmt(double v)
{
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 3);
    return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

PlanResult Planner::run()
{
    m_vk = chooseVk();
    m_result.stats.speedModeVk = m_vk;
    m_posMm = m_path.origin();
    m_steps = stepsOf(m_posMm, m_config);
    m_emitted = m_steps;
    m_result.program.axisCount = wireAxisCount(m_config);
    m_result.program.startSteps = m_steps;
    m_jd = m_config.motion.junctionDeviationMm;
    emit(m_vk ? UnitOp::SpeedModeVk : UnitOp::SpeedModeVn, 0, 0);
    emit(UnitOp::ShortThreshold, m_options.shortThreshold, 0);
    emit(UnitOp::Pause, m_config.motion.pauseMs, 0);
    for (std::size_t i = 0; i < m_path.size(); ++i) {
        if (m_path.isMotion(i)) {
            const bool ownChain = m_options.restAroundA && m_path.start(i).a != m_path.end(i).a;
            if (ownChain)
                flush();
            reserveMoves(i);
            motion(i);
            if (ownChain)
                flush();
        } else {
            event(i);
        }
    }
    flush();
    feedCapWarning();
    if (!m_result.errors.empty())
        m_result.program.commands.clear();
    finishStats();
    return std::move(m_result);
}

// VK unless the rotary axis moves (VK's path length leaves A out) or the firmware lacks it.
// With VK the unit's speed is the length of the step vector per second, so its ratio to the
// path speed in mm changes smoothly with the direction even when the axis scales differ;
// with VN it follows the major axis, whose ratio has kinks: measured, VK keeps the path
// speed closer to the program's (docs/planner.md §6).
bool Planner::chooseVk() const
{
    const SpeedModeChoice mode = m_config.motion.speedMode;
    if (mode != SpeedModeChoice::Auto)
        return mode == SpeedModeChoice::Vk;
    const auto &info = protocol::variantInfo(m_config.unit.variant);
    const bool is64 = m_config.unit.variant == protocol::Variant::Gve64;
    if (!info.hasVlVkXmNa || (is64 && m_config.unit.firmwareVersion < 19))
        return false;
    const double a0 = m_path.origin().a;
    for (std::size_t i = 0; i < m_path.size(); ++i) {
        if (m_path.isMotion(i) && m_path.end(i).a != a0)
            return false;
    }
    return true;
}

void Planner::error(PlanErrorCode code, std::uint32_t line, const std::string &what)
{
    if (m_result.errors.size() < kMaxErrors)
        m_result.errors.push_back({code, line, "line " + std::to_string(line) + ": " + what});
}

void Planner::warning(std::uint32_t line, const std::string &what)
{
    if (m_result.warnings.size() < kMaxErrors)
        m_result.warnings.push_back(
            {PlanErrorCode::Unsupported, line, "line " + std::to_string(line) + ": " + what});
}

void Planner::emit(UnitOp op, std::int64_t value, std::uint32_t line, std::int32_t aux)
{
    UnitCommand c;
    c.op = op;
    c.value = value;
    c.aux = aux;
    c.sourceLine = line;
    c.endSteps = m_emitted;
    m_result.program.commands.push_back(c);
}

// Checks a target point; false when it must not be reached.
bool Planner::checkPoint(const Point4 &p, std::uint32_t line)
{
    bool ok = true;
    for (int i = 0; i < kAxisCount; ++i) {
        const AxisConfig &a = m_config.axes[static_cast<std::size_t>(i)];
        const double v = coord(p, i);
        const char axis = kAxisLetters[static_cast<std::size_t>(i)];
        if (!a.present) {
            if (v != coord(m_path.origin(), i)) {
                error(PlanErrorCode::AbsentAxis, line,
                      std::string("moves axis ") + axis +
                          ", which this machine does not have; remove the " + axis +
                          " word or enable the axis in the machine profile");
                ok = false;
            }
            continue;
        }
        if (!withinSoftLimits(a, v)) { // the one soft-limit policy (softlimits.h)
            error(PlanErrorCode::SoftLimit, line,
                  std::string(1, axis) + " " + fmt(v) + " is outside the soft limits " +
                      fmt(a.softMinMm) + " .. " + fmt(a.softMaxMm) + (i == 3 ? " deg" : " mm") +
                      "; check the work offset and the program");
            ok = false;
        }
        if (std::abs(stepsOf(v, a.stepsPerMm)) > kMaxCounter) {
            error(PlanErrorCode::CounterOverflow, line,
                  std::string(1, axis) + " " + fmt(v) + " is beyond the unit's step counter");
            ok = false;
        }
    }
    return ok;
}

// Room for the moves of the run that starts at toolpath entry i: its motions up to the next
// event (a lower bound: an arc chords into several, and an event may not end the run). A run of
// millions of moves grown by doubling copies them over and over and may hold nearly twice
// their room while it is planned (issue 17: 5 M moves, 72 bytes each).
void Planner::reserveMoves(std::size_t i)
{
    if (!m_moves.empty() || i < m_reservedTo)
        return;
    std::size_t end = i;
    while (end < m_path.size() && m_path.isMotion(end))
        ++end;
    m_reservedTo = end;
    m_moves.reserve(end - i);
}

void Planner::motion(std::size_t i)
{
    const MotionKind kind = m_path.kind(i);
    const std::uint32_t line = m_path.line(i);
    const double feed = m_path.feedMmPerMin(i) / 60.0;
    if (kind != MotionKind::Rapid && !(feed > 0)) {
        error(PlanErrorCode::NoFeed, line, "feed move without a feed rate; program an F word");
        return;
    }
    if (kind == MotionKind::Probe) {
        probe(i, feed);
        return;
    }
    if (kind != MotionKind::Arc) {
        addPoint(m_path.end(i), kind == MotionKind::Rapid, feed, line);
        return;
    }
    const std::vector<Point4> points = gcode::chordArc(
        m_path.start(i), m_path.end(i), m_path.arc(i), m_config.motion.chordToleranceMm);
    // With the rotary table on its own unit each chord that turns A is a block of its own: the
    // two units' parts of consecutive chords have different speed ratios, so they cannot flow
    // into each other on both units at once (machine/rotarysplit.h).
    const bool chordByChord = m_options.restAroundA && m_path.start(i).a != m_path.end(i).a;
    for (const Point4 &p : points) {
        addPoint(p, false, feed, line);
        if (chordByChord)
            flush();
    }
}

void Planner::addPoint(const Point4 &p, bool rapid, double feedMmPerS, std::uint32_t line)
{
    if (!checkPoint(p, line))
        return;
    const Steps4 target = stepsOf(p, m_config);
    detail::Move m;
    bool any = false;
    for (int k = 0; k < 4; ++k) {
        if (std::llabs(target[k] - m_steps[k]) > kMaxCounter) {
            error(PlanErrorCode::CounterOverflow, line,
                  std::string("the move on ") + kAxisLetters[static_cast<std::size_t>(k)] +
                      " is longer than one unit vector can be (2147483647 steps)");
            return;
        }
        m.d[k] = static_cast<std::int32_t>(target[k] - m_steps[k]);
        any = any || m.d[k] != 0;
    }
    if (!any)
        return; // no step: nothing to send; the intended position waits for the next one
    m.pathDelta = {p.x - m_posMm.x, p.y - m_posMm.y, p.z - m_posMm.z, p.a - m_posMm.a};
    m.line = line;
    m_moves.push_back(m, {feedMmPerS, m_jd, rapid, m_exactStop});
    m_steps = target;
    m_posMm = p;
}

void Planner::probe(std::size_t i, double feed)
{
    const Point4 p = m_path.end(i);
    const std::uint32_t line = m_path.line(i);
    if (!checkPoint(p, line))
        return;
    flush();
    const Steps4 target = stepsOf(p, m_config);
    detail::Move m;
    bool any = false;
    for (int k = 0; k < 4; ++k) {
        m.d[k] = static_cast<std::int32_t>(target[k] - m_steps[k]);
        any = any || m.d[k] != 0;
    }
    if (!any) {
        error(PlanErrorCode::Unsupported, line,
              "the probe move has no length (not a single step); program a probe target "
              "away from the current position");
        return;
    }
    m.pathDelta = {p.x - m_posMm.x, p.y - m_posMm.y, p.z - m_posMm.z, p.a - m_posMm.a};
    m.line = line;
    detail::Moves alone;
    alone.push_back(m, {feed, 0, false, false});
    const detail::RunOutcome run = detail::planRun(alone, m_config, m_options, m_vk);
    if (run.vectors.empty())
        return;
    setModal(UnitOp::Accel, m_accel, run.vectors[0].accel, line);
    setModal(UnitOp::Speed, m_speed, run.vectors[0].speed, line);
    m_steps = target;
    m_posMm = p;
    UnitCommand c;
    c.op = UnitOp::Probe;
    c.d = m.d;
    c.aux = static_cast<std::int32_t>(m_path.probe(i));
    c.sourceLine = line;
    c.endSteps = target;
    m_result.program.commands.push_back(c);
    m_emitted = target;
    // A probe ends where it touches: its time is in neither the estimate nor the bound.
}

void Planner::setModal(UnitOp op, std::int64_t &current, std::int64_t value, std::uint32_t line)
{
    if (current == value)
        return;
    current = value;
    emit(op, value, line);
}

// Plans and emits the moves collected since the last synchronisation point. The run starts where
// the last motion emitted ended (every move before it was emitted), so each move ends at that
// position plus the moves up to it.
void Planner::flush()
{
    if (m_moves.empty())
        return;
    const detail::RunOutcome run = detail::planRun(m_moves, m_config, m_options, m_vk);
    reserveCommands(run);
    for (std::size_t k = 0; k < run.vectors.size(); ++k) {
        const detail::PlannedVector &v = run.vectors[k];
        const detail::Move &m = m_moves[k];
        setModal(UnitOp::Accel, m_accel, v.accel, m.line);
        setModal(UnitOp::Speed, m_speed, v.speed, m.line);
        if (!v.line)
            setModal(UnitOp::Brake, m_brake, v.brake, m.line);
        UnitCommand c;
        c.op = v.line ? UnitOp::Line : UnitOp::Vector;
        c.d = m.d;
        c.sourceLine = m.line;
        for (std::size_t i = 0; i < 4; ++i)
            m_emitted[i] += m.d[i];
        c.endSteps = m_emitted;
        m_result.program.commands.push_back(c);
        if (v.chainEnd && !v.line)
            emit(UnitOp::WaitIdle, 0, m.line);
    }
    if (!run.vectors.empty() && run.vectors.back().line)
        emit(UnitOp::WaitIdle, 0, m_moves.back().line);
    m_bound += run.boundS;
    if (run.feedCapLines > 0) {
        if (m_feedCapLines == 0)
            m_firstFeedCap = run.firstFeedCap;
        m_feedCapLines += run.feedCapLines;
    }
    for (std::uint32_t line : run.slowLines)
        warning(line, "the feed is below the unit's slowest speed (10 pulses/s) for this "
                      "move; it runs at that speed instead");
    PlanStats &s = m_result.stats;
    s.chains += run.chains;
    s.movePlans += static_cast<std::size_t>(run.plans) * run.vectors.size();
    s.mostPlans = std::max(s.mostPlans, run.plans);
    s.maxVertexJumpMmPerS = std::max(s.maxVertexJumpMmPerS, run.maxJumpMmPerS);
    s.maxJumpRatio = std::max(s.maxJumpRatio, run.maxJumpRatio);
    s.jumpOverLimit += run.jumpOverLimit;
    s.maxCurveAccelRatio = std::max(s.maxCurveAccelRatio, run.maxCurveAccelRatio);
    s.curveAccelOverLimit += run.curveAccelOverLimit;
    m_moves.clear();
    if (m_moves.capacity() > kKeptMoves)
        m_moves.shrink_to_fit(); // a huge run's moves are not kept for the next (small) one
}

// Room for the commands a run emits, counted beforehand as flush() emits them: a run of millions
// of vectors would otherwise grow the program by doubling, and hold the old and the new copy at
// once while it moves (up to three times the program's size at the peak).
void Planner::reserveCommands(const detail::RunOutcome &run)
{
    std::int64_t accel = m_accel, speed = m_speed, brake = m_brake;
    std::size_t count = 0;
    for (const detail::PlannedVector &v : run.vectors) {
        count += 1 + (v.accel != accel ? 1 : 0) + (v.speed != speed ? 1 : 0) +
                 (!v.line && v.brake != brake ? 1 : 0) + (v.chainEnd && !v.line ? 1 : 0);
        accel = v.accel;
        speed = v.speed;
        brake = v.line ? brake : v.brake;
    }
    UnitCommands &commands = m_result.program.commands;
    const std::size_t needed = commands.size() + count + 1;
    if (needed > commands.capacity())
        commands.reserve(std::max(needed, commands.capacity() + commands.capacity() / 2));
}

} // namespace detail

PlanResult plan(const gcode::Toolpath &toolpath, const MachineConfig &config,
                const PlanOptions &options)
{
    return detail::Planner(toolpath, config, options).run();
}

} // namespace frezka::machine
