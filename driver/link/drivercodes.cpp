// The driver's code table (drivererror.h): every DriverCode with its stable name, its English
// template and its hint, and the lookups by code. The wording is in drivererror.cpp.

#include "drivererror.h"

namespace frezka::driver {

namespace {

struct CodeInfo
{
    DriverCode code;
    const char *name;
    const char *text; // English template, %1 ... = arguments
    const char *hint; // what the operator should do ("" = nothing to add)
};

using C = DriverCode;

constexpr CodeInfo kCodes[] = {
    // Refusals
    {C::NotNow, "NotNow",
     QT_TRANSLATE_NOOP("frezka::driver", "%1 is not possible now (the machine is %2)"),
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "Wait until the machine is in a state that allows it, or stop what it is doing.")},
    {C::JobNeedsIdle, "JobNeedsIdle",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "A job can start only when the machine is ready (it is %1)"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Wait until the machine is ready, then start the job again.")},
    {C::ProgressBeingChecked, "ProgressBeingChecked",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "The job's progress is still being checked against the unit's counters"),
     QT_TRANSLATE_NOOP("frezka::driver", "Wait a moment, then continue.")},
    {C::LowerToolFirst, "LowerToolFirst",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "The tool is lifted and the job's queue is kept in the unit (K)"),
     QT_TRANSLATE_NOOP("frezka::driver", "Lower the tool first, then abort.")},
    {C::NoHomedAxis, "NoHomedAxis",
     QT_TRANSLATE_NOOP("frezka::driver", "The machine profile homes no axis"),
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "Set a homing order for the axes (axes.*.homing.order) in the machine profile.")},
    {C::AxisNotHomed, "AxisNotHomed",
     QT_TRANSLATE_NOOP("frezka::driver", "The machine profile does not home that axis"),
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "Give the axis a homing order (axes.*.homing.order) in the machine profile.")},
    {C::HomeAllTogether, "HomeAllTogether",
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "This unit's firmware (v%1) cannot set one axis's counter (N<axis> needs v19), and N "
         "zeroes every counter"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Home all the machine's axes together, each with home position 0.")},
    {C::JogOutsideLimits, "JogOutsideLimits",
     QT_TRANSLATE_NOOP("frezka::driver", "The axis is outside its soft limits"),
     QT_TRANSLATE_NOOP("frezka::driver", "Home the machine first.")},
    {C::JogAtLimit, "JogAtLimit",
     QT_TRANSLATE_NOOP("frezka::driver", "The axis is at its soft limit"),
     QT_TRANSLATE_NOOP("frezka::driver", "Jog in the other direction.")},
    {C::NoSuchAxis, "NoSuchAxis",
     QT_TRANSLATE_NOOP("frezka::driver", "This machine has no such axis"),
     QT_TRANSLATE_NOOP("frezka::driver", "Use one of the axes the machine profile has.")},
    {C::NoSuchAxisOrDirection, "NoSuchAxisOrDirection",
     QT_TRANSLATE_NOOP("frezka::driver", "This machine has no such axis or direction"),
     QT_TRANSLATE_NOOP("frezka::driver", "Use one of the axes the machine profile has.")},
    {C::ProgramAxisCount, "ProgramAxisCount",
     QT_TRANSLATE_NOOP("frezka::driver", "The unit program has %1 axes"),
     QT_TRANSLATE_NOOP("frezka::driver", "Plan the program again for this machine.")},
    {C::ProgramFourAxes, "ProgramFourAxes",
     QT_TRANSLATE_NOOP("frezka::driver", "The unit program has 4 axes but the %1 has 3"),
     QT_TRANSLATE_NOOP("frezka::driver", "Plan the program again for this machine.")},
    {C::ProgramStartsElsewhere, "ProgramStartsElsewhere",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "The program was planned from %1 steps on axis %2 but the machine is at %3"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Jog back to where it starts, or plan it again from here.")},
    {C::ProgramNeedsVk, "ProgramNeedsVk",
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "Line %1: the plan uses VK, which this unit's firmware (v%2) lacks (it needs v19)"),
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "Plan in VN (motion.speedMode \"vn\"), or set unit.firmwareVersion in the profile.")},
    {C::InvalidCommand, "InvalidCommand",
     QT_TRANSLATE_NOOP("frezka::driver", "Line %1: the command cannot be sent: %2"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Check the machine profile's limits and plan the program again.")},
    {C::LiftOffPath, "LiftOffPath",
     QT_TRANSLATE_NOOP("frezka::driver", "Off the planned path the unit holds no queue to keep"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Continue (it lifts the tool and returns to the path) or abort.")},
    {C::NoLiftHeight, "NoLiftHeight",
     QT_TRANSLATE_NOOP("frezka::driver", "The machine profile sets no tool lift height"),
     QT_TRANSLATE_NOOP("frezka::driver", "Set motion.toolLiftMm in the machine profile.")},
    {C::LiftAtLimit, "LiftAtLimit",
     QT_TRANSLATE_NOOP("frezka::driver", "Z is at its upper soft limit: no room to lift the tool"),
     QT_TRANSLATE_NOOP("frezka::driver", "Continue without lifting, or abort the job.")},
    {C::MpgNeedsFirmware, "MpgNeedsFirmware",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "This unit's firmware (v%1) has no MPG handwheel; it needs v10"),
     QT_TRANSLATE_NOOP("frezka::driver", "Jog with the buttons or the keyboard instead.")},
    {C::NoMpg, "NoMpg", QT_TRANSLATE_NOOP("frezka::driver", "This unit has no MPG handwheel"),
     QT_TRANSLATE_NOOP("frezka::driver", "Jog with the buttons or the keyboard instead.")},
    {C::SpindleOutOfRange, "SpindleOutOfRange",
     QT_TRANSLATE_NOOP("frezka::driver", "Spindle speed %1 rpm is outside 0 … %2 rpm"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Enter a speed within the machine profile's range (spindle.maxRpm).")},
    {C::NoOverride, "NoOverride",
     QT_TRANSLATE_NOOP("frezka::driver", "This unit has no feed override (XM)"),
     QT_TRANSLATE_NOOP("frezka::driver", "Change the feed in the program instead.")},
    {C::HomingNeedsFirmware, "HomingNeedsFirmware",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "This unit's firmware (v%1) has no W: homing to a switch comes with "
                       "IP64MPG v10"),
     QT_TRANSLATE_NOOP("frezka::driver", "Set the position by hand (G92) or update the unit.")},
    {C::SpindleStarting, "SpindleStarting",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "The spindle is starting: the job continues after its spin-up"),
     QT_TRANSLATE_NOOP("frezka::driver", "Wait for the spin-up; the job then goes on by itself.")},
    {C::JogBeyondLimits, "JogBeyondLimits",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "The jog would end at %1 mm, outside the soft limits %2 .. %3 mm"),
     QT_TRANSLATE_NOOP("frezka::driver", "Jog a shorter distance.")},
    {C::JogTooShort, "JogTooShort",
     QT_TRANSLATE_NOOP("frezka::driver", "The jog is shorter than one step"),
     QT_TRANSLATE_NOOP("frezka::driver", "Choose a larger jog step.")},
    {C::OverrideAboveWithoutVl, "OverrideAboveWithoutVl",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "This unit has no axis speed limits (VL): above 100 % an axis could run "
                       "over its maximum"),
     QT_TRANSLATE_NOOP("frezka::driver", "Raise the feed in the program instead.")},
    {C::NewFeedNeedsXm, "NewFeedNeedsXm",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "This unit has no XM: a new feed would change only the queued vectors"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Lower the tool with the feed unchanged, then use the feed buttons (XD), "
                       "which change the rest of the job.")},
    {C::MpgReportsUnsupported, "MpgReportsUnsupported",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Y+ is not sent: the unit's reports come unasked, in a form the manuals do "
                       "not give, and would be taken for replies"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Use Y& (the MPG on, silent); the position is read with P4/PF.")},
    {C::ContinuousJogWhileLifted, "ContinuousJogWhileLifted",
     QT_TRANSLATE_NOOP("frezka::driver", "While the tool is lifted it moves by steps only"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Choose a jog step (0.01 to 10 mm) and press the axis button; the tool "
                       "returns to the lift point before it is lowered.")},
    {C::ToolStillMoving, "ToolStillMoving",
     QT_TRANSLATE_NOOP("frezka::driver", "The lifted tool is still moving"),
     QT_TRANSLATE_NOOP("frezka::driver", "Wait until it stands, then try again.")},
    {C::OverrideNeedsFirmware, "OverrideNeedsFirmware",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "This unit's firmware (v%1) has no XM feed override; it needs v19"),
     QT_TRANSLATE_NOOP("frezka::driver", "Change the feed in the program instead.")},
    {C::OverrideInvalid, "OverrideInvalid",
     QT_TRANSLATE_NOOP("frezka::driver", "The feed override cannot be set: %1"),
     QT_TRANSLATE_NOOP("frezka::driver", "Choose a value within the unit's range.")},
    {C::EmptyCommand, "EmptyCommand", QT_TRANSLATE_NOOP("frezka::driver", "Empty command"),
     QT_TRANSLATE_NOOP("frezka::driver", "Type a unit command after '!'.")},
    {C::NotACommand, "NotACommand",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1' cannot be sent to the unit: %2"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::CommandDisturbsJob, "CommandDisturbsJob",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1' would disturb the running job"),
     QT_TRANSLATE_NOOP("frezka::driver", "Send it when the job has ended.")},
    {C::SpeedInvalid, "SpeedInvalid",
     QT_TRANSLATE_NOOP("frezka::driver", "The new speed cannot be set: %1"),
     QT_TRANSLATE_NOOP("frezka::driver", "Enter a lower feed, or leave it unchanged.")},
    {C::NoPlannedSpeed, "NoPlannedSpeed",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "The new feed cannot be set: no speed is planned where the tool stands"),
     QT_TRANSLATE_NOOP("frezka::driver", "Lower the tool with the feed unchanged.")},
    {C::NoSuchOutput, "NoSuchOutput",
     QT_TRANSLATE_NOOP("frezka::driver", "This unit has no output OUT%1"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Switch one of the outputs the unit has (a GVE84 has its relay only).")},
    {C::SpindleOverrideRange, "SpindleOverrideRange",
     QT_TRANSLATE_NOOP("frezka::driver", "Spindle override %1 % is outside %2 … %3 %"),
     QT_TRANSLATE_NOOP("frezka::driver", "Choose a spindle override within that range.")},
    {C::NoSpindleOverride, "NoSpindleOverride",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "This unit switches its spindle with a relay: its speed cannot be "
                       "overridden"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Set the speed on the spindle's drive, or use a unit with a spindle "
                       "output at address 7 (GVE64, GVE114).")},
    // The unit and the link
    {C::UnitAnswered, "UnitAnswered",
     QT_TRANSLATE_NOOP("frezka::driver", "%1: the unit answered: %2"),
     QT_TRANSLATE_NOOP("frezka::driver", "Check the machine and the connection, then try again.")},
    {C::LinkFailed, "LinkFailed", QT_TRANSLATE_NOOP("frezka::driver", "%1: the link failed: %2"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Check the cable and that the unit is on, then connect again.")},
    {C::UnitRefused, "UnitRefused",
     QT_TRANSLATE_NOOP("frezka::driver", "Line %1: the unit refused '%2' (%3)"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Check the machine profile against the unit (variant, firmware, limits).")},
    {C::LinkLostJobKept, "LinkLostJobKept",
     QT_TRANSLATE_NOOP("frezka::driver", "The link was lost: %1"),
     QT_TRANSLATE_NOOP("frezka::driver", "The job is kept: reconnect, then continue.")},
    {C::LinkLost, "LinkLost", QT_TRANSLATE_NOOP("frezka::driver", "The link was lost: %1"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Check the cable and that the unit is on, then connect again.")},
    {C::CannotConnect, "CannotConnect", QT_TRANSLATE_NOOP("frezka::driver", "Cannot connect: %1"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Check the port in the settings, the cable, and that the unit is on.")},
    {C::WrongVariant, "WrongVariant",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "The unit reports firmware '%1' but the machine profile is for a %2"),
     QT_TRANSLATE_NOOP("frezka::driver", "Choose the matching machine profile.")},
    {C::FirmwareTooOld, "FirmwareTooOld",
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "The unit reports firmware v%1 but the machine profile says v%2; plans for the "
         "profile's firmware may use what this one lacks (MPG and EEPROM floats need v10; VK, VL, "
         "XM and setting one axis's counter v19)"),
     QT_TRANSLATE_NOOP("frezka::driver", "Set unit.firmwareVersion to %1 in the machine profile.")},
    {C::UnknownOperation, "UnknownOperation",
     QT_TRANSLATE_NOOP("frezka::driver", "Line %1: unknown unit program operation"),
     QT_TRANSLATE_NOOP("frezka::driver", "Plan the program again.")},
    {C::HomeSwitchNotFound, "HomeSwitchNotFound",
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "Homing axis %1: the home switch was not found within the configured travel"),
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "Check the switch and its wiring, and the axis's homing travel in the profile.")},
    {C::HomingInvalid, "HomingInvalid", QT_TRANSLATE_NOOP("frezka::driver", "Homing axis %1: %2"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Check the axis's homing settings in the machine profile.")},
    {C::LinkGaveUp, "LinkGaveUp",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "%1: %2 got no valid answer (%3%4); gave up after %5 attempts"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Check the cable and that the unit is on, then connect again; a job is "
                       "kept and continues after the reconnect.")},
    {C::LinkIndexUnknown, "LinkIndexUnknown",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "%1: the reply to %2 was lost and the unit's command index was unknown"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Check the cable and that the unit is on, then connect again; a job is "
                       "kept and continues after the reconnect.")},
    {C::LinkIndexUnexpected, "LinkIndexUnexpected",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "%1: after %2 the unit's command index is %3, expected %4 or %5"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Check the cable and that the unit is on, then connect again; a job is "
                       "kept and continues after the reconnect.")},
    {C::HomingLegStopped, "HomingLegStopped",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Homing axis %1: stopped before the end of its search leg (an input "
                       "interrupt, or the home switch did not release within homing.backOffMm)"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Check the inputs and the switch, then home again; the axis is not homed.")},
    {C::LiftPointMissed, "LiftPointMissed",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "The tool did not arrive back at the lift point (%1 instead of %2)"),
     QT_TRANSLATE_NOOP("frezka::driver", "Abort the job and check the machine.")},
    // The job
    {C::ProbeAlreadyTripped, "ProbeAlreadyTripped",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Line %1: the probe input is already in the state the probe move waits for"),
     QT_TRANSLATE_NOOP("frezka::driver", "Check the probe and its wiring.")},
    {C::ProbeNotTripped, "ProbeNotTripped",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Line %1: the probe move ended without the probe tripping"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Check the probe and the workpiece, then run the job again.")},
    {C::ProbeTrippedElsewhere, "ProbeTrippedElsewhere",
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "Line %1: the probe tripped at %2 steps; the rest of the program was planned from the "
         "probe's end point"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Check the probe and the workpiece, then plan it again from here.")},
    {C::CountersMatchNothing, "CountersMatchNothing",
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "The unit's counters match no point the job has reached; the job cannot resume "
         "exactly"),
     QT_TRANSLATE_NOOP("frezka::driver", "Home the machine and start the job again.")},
    {C::CountersMatchSeveral, "CountersMatchSeveral",
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "The unit's counters match several points of the job; cannot tell how far it got"),
     QT_TRANSLATE_NOOP("frezka::driver", "Abort the job.")},
    {C::ReturnFailed, "ReturnFailed",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "The machine did not arrive back on the planned path after %1 attempts"),
     QT_TRANSLATE_NOOP("frezka::driver", "Abort the job and check the machine.")},
    {C::OffPath, "OffPath",
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "The machine left the planned path: %1. A command was damaged on the serial line in a "
         "way its checksum cannot show"),
     QT_TRANSLATE_NOOP(
         "frezka::driver",
         "Check the workpiece. Continue lifts the tool, returns to line %2 and runs the job on "
         "from there; or abort the job.")},
    // Holds
    {C::HoldPaused, "HoldPaused", QT_TRANSLATE_NOOP("frezka::driver", "Paused"),
     QT_TRANSLATE_NOOP("frezka::driver", "Continue, or lift the tool to change or clean it.")},
    {C::HoldProgramStop, "HoldProgramStop",
     QT_TRANSLATE_NOOP("frezka::driver", "Program stop (M0) at line %1"),
     QT_TRANSLATE_NOOP("frezka::driver", "Do what the program asks, then continue.")},
    {C::HoldOptionalStop, "HoldOptionalStop",
     QT_TRANSLATE_NOOP("frezka::driver", "Optional stop (M1) at line %1"),
     QT_TRANSLATE_NOOP("frezka::driver", "Do what the program asks, then continue.")},
    {C::HoldToolChange, "HoldToolChange",
     QT_TRANSLATE_NOOP("frezka::driver", "Tool change (M6) at line %1: change to tool %2"),
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Lift the tool, change it to tool %2, lower it and continue.")},
    {C::HoldInterrupt, "HoldInterrupt",
     QT_TRANSLATE_NOOP("frezka::driver", "An input interrupt stopped the machine"),
     QT_TRANSLATE_NOOP("frezka::driver", "Check the machine; when it is safe, continue or abort.")},
    {C::HoldInput, "HoldInput", QT_TRANSLATE_NOOP("frezka::driver", "Stopped by input %1"),
     QT_TRANSLATE_NOOP("frezka::driver", "Check the machine; when it is safe, continue or abort.")},
    {C::HoldStopButton, "HoldStopButton",
     QT_TRANSLATE_NOOP("frezka::driver", "Stopped by input %1 (STOP button)"),
     QT_TRANSLATE_NOOP("frezka::driver", "Check the machine; when it is safe, continue or abort.")},
    {C::HoldToolLifted, "HoldToolLifted", QT_TRANSLATE_NOOP("frezka::driver", "Tool lifted"),
     QT_TRANSLATE_NOOP("frezka::driver", "Change or clean the tool, then lower it.")},
    {C::HoldToolLowered, "HoldToolLowered", QT_TRANSLATE_NOOP("frezka::driver", "Tool lowered"),
     QT_TRANSLATE_NOOP("frezka::driver", "Continue or abort.")},
    {C::HoldReturning, "HoldReturning",
     QT_TRANSLATE_NOOP("frezka::driver", "Returning to the planned path"),
     QT_TRANSLATE_NOOP("frezka::driver", "Wait until the machine is back on the path.")},
    {C::HoldLinkRestored, "HoldLinkRestored",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "Link restored: checking the job's progress against the counters"),
     QT_TRANSLATE_NOOP("frezka::driver", "Wait until the check has finished, then continue.")},
    {C::HoldSpindleStarting, "HoldSpindleStarting",
     QT_TRANSLATE_NOOP("frezka::driver", "The spindle starts; the job continues after its spin-up"),
     QT_TRANSLATE_NOOP("frezka::driver", "Keep clear of the tool.")},
    {C::HoldToolLowering, "HoldToolLowering",
     QT_TRANSLATE_NOOP("frezka::driver", "Lowering the tool"),
     QT_TRANSLATE_NOOP("frezka::driver", "Keep clear of the tool.")},
    // Why a command cannot be sent (the detail of a refusal)
    {C::CommandAddressRange, "CommandAddressRange",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': address must be 0..7"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::CommandNoSpindleAddress, "CommandNoSpindleAddress",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': %2 has no address 7 (spindle)"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::CommandNotOnAddress7, "CommandNotOnAddress7",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': not a command of address 7"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::CommandSpindleOnAddress7, "CommandSpindleOnAddress7",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': the spindle speed goes to address 7"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::CommandAddressZeroOnly, "CommandAddressZeroOnly",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': %2 answers on address 0 only"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::CommandComponents3, "CommandComponents3",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': %2 components, %3 takes 3"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::CommandComponents34, "CommandComponents34",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': %2 components, %3 takes 3 or 4"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::CommandOutOfRange, "CommandOutOfRange",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': %2 %3 is outside %4..%5"),
     QT_TRANSLATE_NOOP("frezka::driver", "Choose a value within the unit's range.")},
    {C::CommandNotFinite, "CommandNotFinite",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': value is not a finite number"),
     QT_TRANSLATE_NOOP("frezka::driver", "Choose a value within the unit's range.")},
    {C::CommandZeroTravel, "CommandZeroTravel",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': travel toward the switch must not be 0"),
     QT_TRANSLATE_NOOP("frezka::driver", "Choose a value within the unit's range.")},
    {C::CommandNoSuchAxis, "CommandNoSuchAxis",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': %2 has no axis %3"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::CommandNoSuchCommand, "CommandNoSuchCommand",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': %2 has no command %3"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::CommandNotInPacket, "CommandNotInPacket",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': only C and B belong in a packet"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::CommandEmptyPacket, "CommandEmptyPacket",
     QT_TRANSLATE_NOOP("frezka::driver", "a packet needs at least one command"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::LineNoAddress, "LineNoAddress",
     QT_TRANSLATE_NOOP("frezka::driver",
                       "'%1': not a unit command (it starts with '!' and an address 0..7)"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::LineBadChecksum, "LineBadChecksum",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': missing or wrong checksum"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::LineUnknownCommand, "LineUnknownCommand",
     QT_TRANSLATE_NOOP("frezka::driver", "unknown command '%1'"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::LineMissingNumber, "LineMissingNumber",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': missing number"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::LineNumberTooLarge, "LineNumberTooLarge",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': number out of range: %2"),
     QT_TRANSLATE_NOOP("frezka::driver", "Choose a value within the unit's range.")},
    {C::LineNotDecimal, "LineNotDecimal",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': not a decimal number: %2"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::LineNotHexByte, "LineNotHexByte",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': not a hex byte: %2"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::LineNotANumber, "LineNotANumber",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': not a number: %2"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::LineParameterCount, "LineParameterCount",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': wrong number of parameters"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::LineHomeNeedsAxis, "LineHomeNeedsAxis",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': W needs an axis X, Y, Z or A"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::LineOutputNeedsByte, "LineOutputNeedsByte",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': O0 needs ',hh'"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
    {C::LineUnexpectedParameters, "LineUnexpectedParameters",
     QT_TRANSLATE_NOOP("frezka::driver", "'%1': unexpected parameters"),
     QT_TRANSLATE_NOOP("frezka::driver", "See the unit's command list (docs/gve-protocol.md).")},
};

const CodeInfo *info(DriverCode code)
{
    for (const CodeInfo &c : kCodes) {
        if (c.code == code)
            return &c;
    }
    return nullptr;
}

} // namespace

const char *driverCodeName(DriverCode code)
{
    const CodeInfo *c = info(code);
    return c ? c->name : "None";
}

const char *driverTemplate(DriverCode code)
{
    const CodeInfo *c = info(code);
    return c ? c->text : "";
}

const char *driverHint(DriverCode code)
{
    const CodeInfo *c = info(code);
    return c ? c->hint : "";
}

std::vector<DriverCode> allDriverCodes()
{
    std::vector<DriverCode> out;
    for (const CodeInfo &c : kCodes)
        out.push_back(c.code);
    return out;
}

} // namespace frezka::driver
