// The planner's walk over the toolpath: steps, soft limits, synchronisation points and the
// emission of unit commands (docs/planner.md). Vertex speeds: chainplanner.cpp.
#include "machine/planner.h"

#include "machine/chainparts.h"
#include "machine/chainplanner.h"
#include "machine/softlimits.h"
#include "machine/steps.h"
#include "machine/unitmodel.h"
#include "machine/unitwire.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdlib>

namespace frezka::machine {

namespace {

using gcode::EventKind;
using gcode::MotionKind;
using gcode::Point4;

constexpr std::size_t kMaxErrors = 100;

std::string fmt(double v)
{
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v, std::chars_format::fixed, 3);
    return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

double coord(const Point4 &p, int i)
{
    return i == 0 ? p.x : i == 1 ? p.y : i == 2 ? p.z : p.a;
}

class Planner
{
public:
    Planner(const gcode::Toolpath &toolpath, const MachineConfig &config,
            const PlanOptions &options)
        : m_path(toolpath)
        , m_config(config)
        , m_options(options)
    {}

    PlanResult run()
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
            if (m_path.isMotion(i))
                motion(i);
            else
                event(i);
        }
        flush();
        feedCapWarning();
        if (!m_result.errors.empty())
            m_result.program.commands.clear();
        finishStats();
        return std::move(m_result);
    }

private:
    // VK unless the rotary axis moves (VK's path length leaves A out) or the firmware lacks it.
    // With VK the unit's speed is the length of the step vector per second, so its ratio to the
    // path speed in mm changes smoothly with the direction even when the axis scales differ;
    // with VN it follows the major axis, whose ratio has kinks: measured, VK keeps the path
    // speed closer to the program's (docs/planner.md §6).
    bool chooseVk() const
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

    void error(PlanErrorCode code, std::uint32_t line, const std::string &what)
    {
        if (m_result.errors.size() < kMaxErrors)
            m_result.errors.push_back({code, line, "line " + std::to_string(line) + ": " + what});
    }
    void warning(std::uint32_t line, const std::string &what)
    {
        if (m_result.warnings.size() < kMaxErrors)
            m_result.warnings.push_back(
                {PlanErrorCode::Unsupported, line, "line " + std::to_string(line) + ": " + what});
    }

    void emit(UnitOp op, std::int64_t value, std::uint32_t line, std::int32_t aux = 0)
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
    bool checkPoint(const Point4 &p, std::uint32_t line)
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
                          fmt(a.softMinMm) + " .. " + fmt(a.softMaxMm) +
                          " mm; check the work offset and the program");
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

    void motion(std::size_t i)
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
        std::vector<Point4> points;
        if (kind == MotionKind::Arc)
            points = gcode::chordArc(m_path.start(i), m_path.end(i), m_path.arc(i),
                                     m_config.motion.chordToleranceMm);
        else
            points.push_back(m_path.end(i));
        for (const Point4 &p : points)
            addPoint(p, kind == MotionKind::Rapid, feed, line);
    }

    void addPoint(const Point4 &p, bool rapid, double feedMmPerS, std::uint32_t line)
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
        m.endSteps = target;
        m.pathDelta = {p.x - m_posMm.x, p.y - m_posMm.y, p.z - m_posMm.z, p.a - m_posMm.a};
        m.feedMmPerS = feedMmPerS;
        m.rapid = rapid;
        m.stopAfter = m_exactStop;
        m.junctionDeviationMm = m_jd;
        m.line = line;
        m_moves.push_back(m);
        m_steps = target;
        m_posMm = p;
    }

    void probe(std::size_t i, double feed)
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
        m.endSteps = target;
        m.pathDelta = {p.x - m_posMm.x, p.y - m_posMm.y, p.z - m_posMm.z, p.a - m_posMm.a};
        m.feedMmPerS = feed;
        m.line = line;
        const detail::RunOutcome run = detail::planRun({m}, m_config, m_options, m_vk);
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

    void setModal(UnitOp op, std::int64_t &current, std::int64_t value, std::uint32_t line)
    {
        if (current == value)
            return;
        current = value;
        emit(op, value, line);
    }

    // Plans and emits the moves collected since the last synchronisation point.
    void flush()
    {
        if (m_moves.empty())
            return;
        const detail::RunOutcome run = detail::planRun(m_moves, m_config, m_options, m_vk);
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
            c.endSteps = m.endSteps;
            m_result.program.commands.push_back(c);
            m_emitted = m.endSteps;
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
        s.maxVertexJumpMmPerS = std::max(s.maxVertexJumpMmPerS, run.maxJumpMmPerS);
        s.maxJumpRatio = std::max(s.maxJumpRatio, run.maxJumpRatio);
        s.jumpOverLimit += run.jumpOverLimit;
        s.maxCurveAccelRatio = std::max(s.maxCurveAccelRatio, run.maxCurveAccelRatio);
        s.curveAccelOverLimit += run.curveAccelOverLimit;
        m_moves.clear();
    }

    void event(std::size_t i);
    void spindle(std::uint32_t line, bool on, double rpm);
    void outputs(std::uint32_t line, std::uint8_t clearBits, std::uint8_t setBits);
    void wait(std::uint32_t line, double seconds);
    void finishStats();
    void feedCapWarning();
    struct RestCosts
    {
        double linkS = 0;      // the link's part of the rests, beyond the unit's T pauses
        double unitPauseS = 0; // the unit's T pauses after them (what dwells did not cover)
    };
    RestCosts restCosts() const;
    // restCosts: the driver's status poll interval (driver/link CoreOptions::pollIntervalS) and
    // the bytes of one command and its reply.
    static constexpr double kStatusPollS = 0.05;
    static constexpr double kExchangeBytes = 20;

    const gcode::Toolpath &m_path;
    const MachineConfig &m_config;
    const PlanOptions &m_options;
    PlanResult m_result;
    bool m_vk = false;
    Point4 m_posMm;     // intended position (mm) of the last vector's end
    Steps4 m_steps{};   // absolute steps after the last collected move
    Steps4 m_emitted{}; // absolute steps after the last emitted motion command
    std::vector<detail::Move> m_moves;
    bool m_exactStop = false;
    double m_jd = 0;
    std::int64_t m_accel = -1, m_speed = -1, m_brake = -1; // modal values sent, -1 = unknown
    bool m_spindleOn = false;
    std::int64_t m_spindlePermille = 0;
    std::uint8_t m_port0 = 0xFF; // outputs, active low: all off
    double m_bound = 0;
    double m_waitS = 0;
    detail::FeedCap m_firstFeedCap; // the first move whose feed the axes cap
    std::size_t m_feedCapLines = 0;
};

void Planner::wait(std::uint32_t line, double seconds)
{
    const auto ms = static_cast<std::int64_t>(std::llround(seconds * 1000));
    if (ms <= 0)
        return;
    emit(UnitOp::Dwell, ms, line);
    m_waitS += static_cast<double>(ms) / 1000.0;
}

void Planner::outputs(std::uint32_t line, std::uint8_t clearBits, std::uint8_t setBits)
{
    auto port = static_cast<std::uint8_t>((m_port0 & ~clearBits) | setBits); // active low
    if (m_config.unit.variant != protocol::Variant::Gve84)
        port = static_cast<std::uint8_t>(m_spindleOn ? port & ~kSpindleOutputBit
                                                     : port | kSpindleOutputBit);
    if (port == m_port0)
        return;
    flush();
    m_port0 = port;
    emit(UnitOp::Output, port, line);
}

void Planner::spindle(std::uint32_t line, bool on, double rpm)
{
    if (m_config.unit.variant == protocol::Variant::Gve84) {
        const std::uint8_t bit = outputBit(m_config, OutputFunction::Spindle);
        if (bit == 0) {
            warning(line, "no output switches the spindle (outputs.out1 is not \"spindle\"); "
                          "the spindle command is not sent");
            return;
        }
        const bool wasOn = m_spindleOn;
        m_spindleOn = on;
        outputs(line, on ? bit : 0, on ? 0 : bit);
        if (on && !wasOn)
            wait(line, m_config.spindle.spinUpMs / 1000.0);
        return;
    }
    std::int64_t permille = 0;
    if (on) {
        if (rpm > m_config.spindle.maxRpm * (1 + 1e-9)) {
            error(PlanErrorCode::SpindleTooFast, line,
                  "S" + fmt(rpm) + " is above the spindle's " + fmt(m_config.spindle.maxRpm) +
                      " rpm (spindle.maxRpm); lower the S word");
            return;
        }
        permille = std::clamp<std::int64_t>(std::llround(rpm / m_config.spindle.maxRpm * 1000),
                                            rpm > 0 ? 1 : 0, 1000);
    }
    if (permille == m_spindlePermille && on == m_spindleOn)
        return; // an S or M3 that changes nothing keeps the chain going
    flush();
    const bool speedUp = permille > m_spindlePermille;
    m_spindleOn = permille > 0;
    m_spindlePermille = permille;
    emit(UnitOp::Spindle, permille, line);
    m_port0 = static_cast<std::uint8_t>(m_spindleOn ? m_port0 & ~kSpindleOutputBit
                                                    : m_port0 | kSpindleOutputBit);
    if (speedUp)
        wait(line, m_config.spindle.spinUpMs / 1000.0);
}

void Planner::event(std::size_t i)
{
    const std::uint32_t line = m_path.line(i);
    const gcode::Event &e = m_path.event(i);
    if (m_path.kind(i) == MotionKind::Dwell || e.kind == EventKind::Dwell) {
        flush();
        wait(line, e.value);
        return;
    }
    const std::uint8_t coolant = outputBit(m_config, OutputFunction::Coolant);
    const std::uint8_t mist = outputBit(m_config, m_config.outputs.mist);
    switch (e.kind) {
    case EventKind::SpindleCw:
        spindle(line, true, e.value);
        break;
    case EventKind::SpindleCcw:
        error(PlanErrorCode::Unsupported, line,
              "M4 (spindle counter-clockwise): the unit has no spindle direction output; use M3");
        break;
    case EventKind::SpindleSpeed:
        if (m_spindleOn)
            spindle(line, true, e.value);
        break;
    case EventKind::SpindleOff:
        spindle(line, false, 0);
        break;
    case EventKind::CoolantFlood:
    case EventKind::CoolantMist: {
        const std::uint8_t bit = e.kind == EventKind::CoolantFlood ? coolant : mist;
        if (bit == 0)
            warning(line, std::string(e.kind == EventKind::CoolantFlood ? "M8" : "M7") +
                              ": no output has this function in the machine profile "
                              "(outputs); not switched");
        else
            outputs(line, bit, 0);
        break;
    }
    case EventKind::CoolantOff:
        outputs(line, 0, static_cast<std::uint8_t>(coolant | mist));
        break;
    case EventKind::ToolChange:
        flush();
        emit(UnitOp::OperatorStop, static_cast<std::int64_t>(StopReason::ToolChange), line,
             static_cast<std::int32_t>(e.value));
        break;
    case EventKind::Pause:
    case EventKind::OptionalPause:
        flush();
        emit(UnitOp::OperatorStop,
             static_cast<std::int64_t>(e.kind == EventKind::Pause ? StopReason::Pause
                                                                  : StopReason::OptionalPause),
             line);
        break;
    case EventKind::ProgramEnd:
        spindle(line, false, 0);
        outputs(line, 0, static_cast<std::uint8_t>(coolant | mist));
        flush();
        emit(UnitOp::ProgramEnd, 0, line);
        break;
    case EventKind::PathMode:
        m_exactStop = e.value < 2;
        m_jd = (e.value >= 2 && e.p > 0) ? e.p : m_config.motion.junctionDeviationMm;
        if (e.value >= 2 && e.q > 0)
            warning(line, "G64 Q (collinear merging) is not used: every segment is planned");
        break;
    case EventKind::Dwell:
        break;
    }
}

// One warning for the whole program: where the feed is first above what the axes allow, the
// feed asked for, the feed the machine will run there, and how many lines are capped.
void Planner::feedCapWarning()
{
    if (m_feedCapLines == 0)
        return;
    const detail::FeedCap &c = m_firstFeedCap;
    auto mmPerMin = [](double mmPerS) { return std::to_string(std::llround(mmPerS * 60)); };
    const std::string limit =
        c.limit == 'P' ? "the unit's " + std::to_string(m_config.unit.maxPulseRate) + " pulses/s"
                       : std::string(1, c.limit) + "'s maximum speed of " +
                             mmPerMin(c.limitMmPerS) + " mm/min";
    std::string what = "F" + mmPerMin(c.askedMmPerS) +
                       " mm/min is above what the axes allow along this move; the machine runs "
                       "it at " +
                       mmPerMin(c.runMmPerS) + " mm/min (" + limit + ")";
    if (m_feedCapLines == 2)
        what += "; 1 more line is capped the same way";
    else if (m_feedCapLines > 2)
        what += "; " + std::to_string(m_feedCapLines - 1) + " more lines are capped the same way";
    what += ". Lower the F word, or raise the axis maxima in the machine profile if the machine "
            "can go faster";
    m_result.warnings.push_back(
        {PlanErrorCode::FeedCapped, c.line, "line " + std::to_string(c.line) + ": " + what});
}

// The link's part of each rest (docs/planner.md §7): where the queue drains (the program's start,
// a wait for it to drain, a dwell, an operator stop, a probe) the driver learns that the unit
// stands from its next status poll (half the poll interval on average), reads the position
// (the path guard), sends the commands that cannot travel in a packet one round trip each, and
// the unit starts again when the first packet's first vector arrives.
Planner::RestCosts Planner::restCosts() const
{
    const LinkConfig &link = m_config.link;
    if (!m_options.wireLimited || link.baud <= 0)
        return {};
    const double exchangeS = detail::LinkTiming(m_config, m_options).nonPacketS(kExchangeBytes);
    RestCosts costs;
    bool atRest = true;
    bool moved = false;             // a chain ran before this rest: the unit pauses T after it
    double pauseS = kInitialPauseS; // T, as the unit model starts
    double dwellS = 0;              // PC-side dwell since the rest began
    int commands = 0;
    for (const UnitCommand &c : m_result.program.commands) {
        if (c.op == UnitOp::Vector || c.op == UnitOp::Line) {
            if (atRest) {
                // The unit's own T pause after the rest (what a dwell has not covered) runs
                // while the link does its part: the estimate counts the longer of the two.
                const double unitS = moved ? std::max(0.0, pauseS - dwellS) : 0.0;
                costs.linkS += std::max(0.0, kStatusPollS / 2 + (2 + commands) * exchangeS - unitS);
                costs.unitPauseS += unitS;
            }
            atRest = false;
            moved = true;
            commands = 0;
            dwellS = 0;
        } else if (c.op == UnitOp::Brake && link.packets) {
            // travels in the first packet
        } else if (wireCommand(c, m_result.program.axisCount)) {
            pauseS = c.op == UnitOp::Pause ? static_cast<double>(c.value) / 1000.0 : pauseS;
            commands += atRest ? 1 : 0;
        } else {
            atRest = true; // a PC-side wait: the queue drains
            dwellS += c.op == UnitOp::Dwell ? static_cast<double>(c.value) / 1000.0 : 0.0;
        }
    }
    return costs;
}

void Planner::finishStats()
{
    PlanStats &s = m_result.stats;
    const ModelResult model = runUnitModel(m_result.program, m_vk);
    s.vectors = model.vectors;
    s.brakeViolations = model.brakeViolations;
    // The unit's T pause after each PC-side rest is the program's (a wait, a dwell, a stop) or
    // the machine's (a reversal its jump limits cannot pass moving), not the plan's: the bound
    // pays it as the estimate does (seed 30: 181 such rests, the estimate 2.9 % above a bound
    // that left them out). Rests the plan chooses (exact stop's L moves) stay out of it.
    const RestCosts rests = restCosts();
    s.linkWaitS = rests.linkS;
    s.waitS = m_waitS;
    s.estimatedS = model.motionS + model.waitS + s.linkWaitS;
    s.boundS = m_bound + m_waitS + rests.unitPauseS + s.linkWaitS;
}

} // namespace

PlanResult plan(const gcode::Toolpath &toolpath, const MachineConfig &config,
                const PlanOptions &options)
{
    return Planner(toolpath, config, options).run();
}

} // namespace frezka::machine
