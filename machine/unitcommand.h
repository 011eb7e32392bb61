#pragma once
// UnitCommand: one command of a unit program (unitprogram.h), with its ops.
//
// UnitProgram: the planner's output and the driver's input (docs/architecture).
//
// A sequence of unit commands in the order they go to the unit, each tagged with the G-code
// source line it came from and, for motion, the absolute step position it ends at, so that the
// driver can show progress against the program and resume after a stop without re-deriving any
// geometry. Steps exist only from here on.
//
// Speed semantics follow docs/gve-protocol.md §4: V, B in pulses/s (per the mode set by
// SpeedMode), A in thousands of pulses/s², T in ms, $ in steps.
//
// What the planner emits (docs/planner.md), and what a driver may rely on:
// - The program opens with SpeedModeVk or SpeedModeVn, ShortThreshold and Pause (line 0).
// - A, V and B are sent only when they change; each C captures the values current when it is
//   queued. The program never relies on the unit's reset values.
// - A run of C vectors is planned to flow: the driver must keep the queue filled. Where the
//   motion must rest (before I/O, a dwell, an operator stop, a probe, the end), a WaitIdle comes
//   first; the last C before it brakes to 0 because nothing follows it in the queue.
// - Output, Spindle, Dwell, OperatorStop, Probe and ProgramEnd always follow a WaitIdle (or
//   come before any motion), so they act at the programmed place.
// - Line is used only by the exact-stop baseline plan (each L from and to rest).
// - endSteps of a non-motion command is the position after the motion before it.
// - L/C may leave the A component out on the wire when it is 0 (machine/unitwire.h).

#include <array>
#include <cstdint>
#include <string>
#include <vector>

namespace frezka::machine {

using Steps4 = std::array<std::int64_t, 4>; // absolute steps X, Y, Z, A

enum class UnitOp : std::uint8_t {
    Line,           // !0L dx,dy,dz[,da]  stand-alone move (queue must be empty)
    Vector,         // !0C dx,dy,dz[,da]  continuous vector
    Brake,          // !0B n    brake speed, pulses/s
    Speed,          // !0V n    speed, pulses/s
    Accel,          // !0A n    acceleration, thousands of pulses/s²
    Pause,          // !0T n    pause between non-continuous moves, ms
    ShortThreshold, // !0$ n    steps
    SpeedModeVk,    // !0VK     path speeds
    SpeedModeVn,    // !0VN     major-axis speeds
    Output,         // !0O0,hh  output port 0 (active low), value = byte
    Spindle,        // !7V n    spindle ‰ (0 = off)
    WaitIdle,       // PC side: wait until the queue has drained (L0,0,0 accepted)
    Dwell,          // PC side: wait idle, then value milliseconds (G4, spindle spin-up)
    OperatorStop,   // PC side: M0 / M1 / M6, value = StopReason, tool number in aux
    Probe,          // PC side: G38.x probe move, delta in d, gcode::ProbeKind in aux; A and V
                    // for it are set just before. The commands after it were planned from its
                    // programmed end: after a probe that stopped elsewhere the driver must not
                    // send them as they are (re-plan the rest from the measured position).
    ProgramEnd,     // PC side: end of program (M2/M30); spindle and coolant are off before it
};

// UnitOp::OperatorStop reasons (UnitCommand::value); the tool number rides in aux.
enum class StopReason : std::int64_t {
    Pause = 0,         // M0: wait for the operator
    OptionalPause = 1, // M1: wait if the operator enabled optional stops
    ToolChange = 2,    // M6: change to tool aux, then continue
};

struct UnitCommand
{
    UnitOp op = UnitOp::Line;
    std::array<std::int32_t, 4> d{}; // relative steps for Line/Vector/Probe (A = 0 on 3 axes)
    std::int64_t value = 0;          // the scalar argument of the other ops
    std::int32_t aux = 0;            // op-specific extra (see UnitOp)
    std::uint32_t sourceLine = 0;    // 1-based G-code line; 0 = generated (setup)
    Steps4 endSteps{};               // absolute step position after this command
    friend bool operator==(const UnitCommand &, const UnitCommand &) = default;
};

} // namespace frezka::machine
