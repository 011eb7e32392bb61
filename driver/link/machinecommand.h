#pragma once
// MachineCommand: one request of a front end (GUI, CLI, tests) to the machine core.
//
// The one declaration of the operations the driver offers: MachineController's slots build one
// of these and queue it to the link thread, LinkWorker hands it to MachineCore::execute, which
// either accepts it (its effect shows in later MachineState snapshots) or refuses it with a
// MachineError and changes nothing. Plain values (copyable, operator==), so they cross threads
// by copy. Connecting, disconnecting and the machine profile are not commands: they concern
// the transport and the core's configuration, not the machine.

#include "machine/unitprogram.h"

#include <cstdint>
#include <string>
#include <variant>

namespace frezka::driver {

namespace op {

// Stream a planned program; its first command runs from the current position. Idle only.
struct Run
{
    machine::UnitProgram program;
    friend bool operator==(const Run &, const Run &) = default;
};
struct Pause // H: brake along the ramp, keep the queue; then spindle and coolant off if asked
{
    bool stopSpindle = false;
    friend bool operator==(const Pause &, const Pause &) = default;
};
// While a job is held (Paused): the spindle and coolant off (stop) or on again as they were
// (after the spin-up the job may continue). The operator's "Stop the spindle" box.
struct HoldSpindle
{
    bool stop = true;
    friend bool operator==(const HoldSpindle &, const HoldSpindle &) = default;
};
struct Resume // G (after a pause, an interrupt, M0/M1/M6); off the path: return to it
{
    friend bool operator==(const Resume &, const Resume &) = default;
};
struct Abort // H, D (R first when the tool is lifted), spindle and coolant off: the job ends
{
    friend bool operator==(const Abort &, const Abort &) = default;
};
// While paused: K, Z up by the profile's toolLiftMm (within the soft limit), spindle and coolant
// off (always: issue 14). While lifted, JogStep moves the tool away and back.
struct ToolLift
{
    bool stopSpindle = true; // the operator's box, for the log; the lift stops the spindle anyway
    friend bool operator==(const ToolLift &, const ToolLift &) = default;
};
// Spindle and coolant on again (the spin-up waited), back to the lift point, Z down, R; a new
// feed when speedPulsesPerS > 0: the feed override (XM) from here on, that speed over the
// planned one at the tool (units with XM only).
struct ToolLower
{
    int speedPulsesPerS = 0;
    friend bool operator==(const ToolLower &, const ToolLower &) = default;
};
// W per axis in the profile's order, then the counters; bit a of axisMask = axis a.
struct Home
{
    unsigned axisMask = 0xF;
    friend bool operator==(const Home &, const Home &) = default;
};
// Incremental jog in mm (A: degrees), clipped to the soft limits.
struct JogStep
{
    int axis = 0;
    double distanceMm = 0;
    double speedMmPerMin = 0;
    friend bool operator==(const JogStep &, const JogStep &) = default;
};
// Jog toward the soft limit in `direction` (+1 / -1) until JogStop.
struct JogContinuous
{
    int axis = 0;
    int direction = 0;
    double speedMmPerMin = 0;
    friend bool operator==(const JogContinuous &, const JogContinuous &) = default;
};
struct JogStop
{
    friend bool operator==(const JogStop &, const JogStop &) = default;
};
struct SetMpg
{
    bool on = false;
    friend bool operator==(const SetMpg &, const SetMpg &) = default;
};
struct SetSpindleRpm // !7V, per mille of the profile's maximum
{
    double rpm = 0;
    friend bool operator==(const SetSpindleRpm &, const SetSpindleRpm &) = default;
};
// The spindle override (issue 16 item 5): every spindle speed sent from now on (!7V, the job's,
// the buttons', a hold's restart) is scaled by it, and a turning spindle at once.
struct SetSpindleOverride
{
    int percent = 100;
    friend bool operator==(const SetSpindleOverride &, const SetSpindleOverride &) = default;
};
struct SetOutput // output OUTn on or off (the driver finds its port bit), the others kept
{
    int output = 0;
    bool on = false;
    friend bool operator==(const SetOutput &, const SetOutput &) = default;
};
struct SetOverride // XM
{
    int percent = 100;
    friend bool operator==(const SetOverride &, const SetOverride &) = default;
};
struct OverrideStep // XU (up) / XD
{
    bool up = true;
    friend bool operator==(const OverrideStep &, const OverrideStep &) = default;
};
// A console line such as "!0PF" or "PF" (address 0 assumed), validated for the variant.
struct SendRaw
{
    std::string text;
    friend bool operator==(const SendRaw &, const SendRaw &) = default;
};
struct WriteEeprom // the profile's EEPROM settings to the unit, then compared again. Idle only.
{
    friend bool operator==(const WriteEeprom &, const WriteEeprom &) = default;
};

} // namespace op

using MachineCommand =
    std::variant<op::Run, op::Pause, op::Resume, op::Abort, op::ToolLift, op::ToolLower, op::Home,
                 op::JogStep, op::JogContinuous, op::JogStop, op::SetMpg, op::SetSpindleRpm,
                 op::SetOutput, op::SetOverride, op::OverrideStep, op::SendRaw, op::WriteEeprom,
                 op::HoldSpindle, op::SetSpindleOverride>;

} // namespace frezka::driver
