// The planner's program events: dwells, the spindle (its speed and spin-up), the outputs
// (coolant), tool changes, pauses, the path mode and the program's end (docs/planner.md).
// Part of Planner (planner_internal.h).
#include "machine/planner_internal.h"

#include <algorithm>
#include <cmath>

namespace frezka::machine::detail {

using gcode::EventKind;
using gcode::MotionKind;

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

// One event of the toolpath: a flat switch with one case per event kind, each a call or two;
// kept whole (over 60 lines) so that what every event becomes on the unit reads in one place.
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

} // namespace frezka::machine::detail
