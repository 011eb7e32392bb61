#pragma once
// Helpers shared by MachineCore and its activities (not part of the driver's API).

#include "driver/link/commandrefusal.h"
#include "driver/link/linkengine.h"
#include "driver/link/machinestate.h"
#include "machine/unitprogram.h"

#include <string>

namespace frezka::driver::detail {

inline bool isMotion(machine::UnitOp op)
{
    return op == machine::UnitOp::Vector || op == machine::UnitOp::Line;
}

// Commands whose value stays in force for the following vectors (re-sent when resuming).
inline bool isModal(machine::UnitOp op)
{
    using machine::UnitOp;
    switch (op) {
    case UnitOp::Brake:
    case UnitOp::Speed:
    case UnitOp::Accel:
    case UnitOp::Pause:
    case UnitOp::ShortThreshold:
    case UnitOp::SpeedModeVk:
    case UnitOp::SpeedModeVn:
        return true;
    default:
        return false;
    }
}

// "line 12" or "setup", for messages.
inline std::string lineText(const machine::UnitCommand &c)
{
    return c.sourceLine ? "line " + std::to_string(c.sourceLine) : "setup";
}

// "120, -40, 7" for the first `axes` counters, for messages.
inline std::string stepsText(const machine::Steps4 &s, int axes)
{
    std::string t;
    for (int a = 0; a < axes; ++a)
        t += (a ? ", " : "") + std::to_string(s[static_cast<std::size_t>(a)]);
    return t;
}

// An operation refused before anything was sent (a code with its arguments, drivererror.h).
inline MachineError refusal(DriverCode code, std::vector<std::string> args = {})
{
    MachineError e;
    e.reason = DriverMessage{code, std::move(args)};
    e.message = englishText(e.reason, true);
    return e;
}

// The same with the protocol's reason as its detail (commandrefusal.h), worded in place of the
// argument after the last of `args`.
inline MachineError refusal(DriverCode code, std::vector<std::string> args, DriverMessage why)
{
    MachineError e;
    e.reason = DriverMessage{code, std::move(args), std::move(why)};
    e.message = englishText(e.reason, true);
    return e;
}

// A transaction the link gave up on, while doing `action` (a phrase, or lineText()): the
// engine's reason as a code with arguments, so that the front ends word it in the user's
// language (the English Outcome::error stays for the log).
inline DriverMessage linkFailure(const std::string &action, const Outcome &o)
{
    std::vector<std::string> args{action};
    args.insert(args.end(), o.failureArgs.begin(), o.failureArgs.end());
    switch (o.failure) {
    case LinkFailure::GaveUp:
        return {DriverCode::LinkGaveUp, std::move(args)};
    case LinkFailure::IndexUnknown:
        return {DriverCode::LinkIndexUnknown, std::move(args)};
    case LinkFailure::IndexUnexpected:
        return {DriverCode::LinkIndexUnexpected, std::move(args)};
    case LinkFailure::None:
        break;
    }
    return {DriverCode::LinkFailed, {action, o.error}};
}

// An operation that failed (MachineCore::fail): the reason with its English text and hint, and
// what the outcome `o` (if any) says: the command (a packet's first, with its size), the reply as
// it came and the unit's code.
inline MachineError failure(const DriverMessage &reason, const Outcome *o)
{
    MachineError e;
    e.reason = reason;
    e.message = englishText(reason, true);
    if (o) {
        if (!o->commands.empty())
            e.command = o->packet ? protocol::encodeBody(o->commands.front()) + " (packet of " +
                                        std::to_string(o->commands.size()) + ")"
                                  : protocol::encodeBody(o->commands.front());
        e.reply = o->raw;
        if (o->status == OutcomeStatus::Ok)
            e.unitCode = static_cast<int>(o->reply.code);
    }
    return e;
}

inline MachineError notNow(const char *what, MachineMode mode)
{
    return refusal(DriverCode::NotNow, {what, machineModeName(mode)});
}

// "12" or "setup": the line argument of a message.
inline std::string lineArg(const machine::UnitCommand &c)
{
    return c.sourceLine ? std::to_string(c.sourceLine) : "setup";
}

// The job is held (or the hold ends with HoldReason::None): the reason, its words and the
// program line it belongs to.
inline void setHold(MachineState &state, HoldReason reason, DriverMessage message,
                    std::uint32_t line)
{
    state.hold = reason;
    state.holdText = message.empty() ? std::string() : englishText(message);
    state.holdMessage = std::move(message);
    state.holdLine = line;
}

// The unit's status byte (F) into the state: RUN, INTA and queue full.
inline void setFlags(MachineState &state, std::uint8_t flags)
{
    state.flags = flags;
    state.run = (flags & 0x40) != 0;
    state.inta = (flags & 0x80) != 0;
    state.queueFull = (flags & 0x20) != 0;
}

// The visitor of several lambdas (MachineCore::execute over a MachineCommand).
template<class... F>
struct Overloaded : F...
{
    using F::operator()...;
};
template<class... F>
Overloaded(F...) -> Overloaded<F...>;

} // namespace frezka::driver::detail
