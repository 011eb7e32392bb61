// The table of every error code with its English message and hint (about 450 of its 530 lines):
// one table on purpose, in code order, so that docs/gcode.md's table
// (tests/gcode/gen_error_table.py) and lupdate read it whole; the few functions below only look
// codes up in it.
#include "error.h"

#include <QCoreApplication>

#include <QStringList>

#include <array>
#include <cstring>
#include <vector>

namespace frezka::gcode {

namespace {

struct ErrorInfo
{
    ErrorCode code;
    const char *name;
    const char *text; // English template, %1 = detail
    const char *hint; // what the user should do
};

constexpr ErrorInfo kErrors[] = {
    {ErrorCode::FileOpenFailed, "FileOpenFailed",
     QT_TRANSLATE_NOOP("frezka::gcode", "Cannot read the file %1"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Check that the file exists and is readable.")},
    {ErrorCode::BadCharacter, "BadCharacter",
     QT_TRANSLATE_NOOP("frezka::gcode", "Unexpected character '%1'"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Remove it or put it inside a comment ( ).")},
    {ErrorCode::UnclosedComment, "UnclosedComment",
     QT_TRANSLATE_NOOP("frezka::gcode", "Comment is not closed"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Add ')' at the end of the comment.")},
    {ErrorCode::NestedComment, "NestedComment",
     QT_TRANSLATE_NOOP("frezka::gcode", "Comment inside a comment"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Close the first comment before opening another one.")},
    {ErrorCode::NumberExpected, "NumberExpected",
     QT_TRANSLATE_NOOP("frezka::gcode", "A number is expected after %1"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Write a number, a #parameter or an [expression] after the letter.")},
    {ErrorCode::NonIntegerValue, "NonIntegerValue",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 needs a whole number"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use an integer value here.")},
    {ErrorCode::RepeatedWord, "RepeatedWord",
     QT_TRANSLATE_NOOP("frezka::gcode", "Word %1 appears twice in one block"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Keep one of them or split the block into two lines.")},
    {ErrorCode::UnsupportedWord, "UnsupportedWord",
     QT_TRANSLATE_NOOP("frezka::gcode", "Word %1 is not supported"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Remove the word; Frezka does not use it.")},
    {ErrorCode::UnsupportedAxis, "UnsupportedAxis",
     QT_TRANSLATE_NOOP("frezka::gcode", "Axis %1 is not supported"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Frezka machines have the axes X, Y, Z and A.")},
    {ErrorCode::FileEndedWithoutEnd, "FileEndedWithoutEnd",
     QT_TRANSLATE_NOOP("frezka::gcode", "The file ended without M2, M30 or %"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "End the program with M2 or M30 (or enclose it in % lines).")},
    {ErrorCode::FileEndedWithoutPercent, "FileEndedWithoutPercent",
     QT_TRANSLATE_NOOP("frezka::gcode", "The program starts with % but has no closing %"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Add a line with % at the end of the program.")},
    {ErrorCode::LineTooLong, "LineTooLong",
     QT_TRANSLATE_NOOP("frezka::gcode", "Line is too long (%1 characters)"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Split the line; at most 65535 characters are allowed.")},
    {ErrorCode::GrblHoming, "GrblHoming",
     QT_TRANSLATE_NOOP("frezka::gcode", "$H is grbl's homing command, not G-code"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Home the machine from Frezka (Home all) before starting the program, and "
                       "delete this line.")},
    {ErrorCode::GrblCommand, "GrblCommand",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 is a grbl system command, not G-code"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Delete the line; grbl's $ settings and commands have no meaning here (set "
                       "the machine up in Frezka's machine profile, home and jog from Frezka).")},
    {ErrorCode::SlashComment, "SlashComment",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "'//' comments are not RS274/NGC G-code (they come from other "
                       "controllers' dialects, e.g. Beckhoff TwinCAT)"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Write the comment in parentheses ( ) or after a semicolon ;.")},
    {ErrorCode::FileWriteFailed, "FileWriteFailed",
     QT_TRANSLATE_NOOP("frezka::gcode", "Cannot write the file %1: %2"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Check that the folder exists and is writable and that the disk is not "
                       "full; the old file is kept unchanged.")},
    {ErrorCode::ToolTableSyntax, "ToolTableSyntax",
     QT_TRANSLATE_NOOP("frezka::gcode", "Tool table entry cannot be read at '%1'"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Each line is T<tool> P<pocket> with optional X Y Z A B C U V W offsets, "
                       "D diameter, I J angles and Q orientation (0-9), each letter once, then "
                       "an optional ; comment, as in LinuxCNC's .tbl files. Correct the line in "
                       "Machine > Tool table or in a text editor.")},
    {ErrorCode::ToolTableDuplicate, "ToolTableDuplicate",
     QT_TRANSLATE_NOOP("frezka::gcode", "Tool %1 is listed twice in the tool table"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Keep one line per tool number; delete or renumber the other.")},
    {ErrorCode::ProgramAborted, "ProgramAborted",
     QT_TRANSLATE_NOOP("frezka::gcode", "The program aborts here: %1"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "An (abort, ...) comment ends the program, as in LinuxCNC. Change the "
                       "program so that it does not reach this line.")},
    {ErrorCode::UnknownGCode, "UnknownGCode",
     QT_TRANSLATE_NOOP("frezka::gcode", "Unknown G code %1"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Check the number; see the list of supported codes.")},
    {ErrorCode::UnsupportedGCode, "UnsupportedGCode",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 is not supported"),
     QT_TRANSLATE_NOOP(
         "frezka::gcode",
         "Remove it or post-process the program without it (see the supported codes).")},
    {ErrorCode::UnknownMCode, "UnknownMCode",
     QT_TRANSLATE_NOOP("frezka::gcode", "Unknown M code %1"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Check the number; see the list of supported codes.")},
    {ErrorCode::UnsupportedMCode, "UnsupportedMCode",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 is not supported"),
     QT_TRANSLATE_NOOP(
         "frezka::gcode",
         "Remove it or post-process the program without it (see the supported codes).")},
    {ErrorCode::ModalGroupConflict, "ModalGroupConflict",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "%1 conflicts with another code of the same group in this block"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use one code of each modal group per block.")},
    {ErrorCode::TooManyMCodes, "TooManyMCodes",
     QT_TRANSLATE_NOOP("frezka::gcode", "Too many M codes in one block"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use at most four M codes per block.")},
    {ErrorCode::WordNotUsed, "WordNotUsed",
     QT_TRANSLATE_NOOP("frezka::gcode", "Word %1 is not used by any code in this block"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Remove the word or add the code that uses it.")},
    {ErrorCode::AxisWordsWithG80, "AxisWordsWithG80",
     QT_TRANSLATE_NOOP("frezka::gcode", "Axis words are given with G80"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "G80 cancels the motion mode; give the axis words with G0 or G1.")},
    {ErrorCode::AxisWordsWithoutMotion, "AxisWordsWithoutMotion",
     QT_TRANSLATE_NOOP("frezka::gcode", "Axis words are given but no motion mode is active"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Add G0, G1, G2 or G3 to the block.")},
    {ErrorCode::TwoAxisCodes, "TwoAxisCodes",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 and a motion code both use the axis words"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Put them on separate lines.")},
    {ErrorCode::AxisWordsMissing, "AxisWordsMissing",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 needs at least one axis word"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Add the axis words (X, Y, Z or A).")},
    {ErrorCode::NegativeValue, "NegativeValue",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 must not be negative"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use zero or a positive value.")},
    {ErrorCode::G53NeedsG0OrG1, "G53NeedsG0OrG1",
     QT_TRANSLATE_NOOP("frezka::gcode", "G53 needs G0 or G1"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Write G53 together with G0 or G1 on the same line.")},
    {ErrorCode::G53Incremental, "G53Incremental",
     QT_TRANSLATE_NOOP("frezka::gcode", "G53 cannot be used in G91 mode"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Switch to G90 before moving in machine coordinates.")},
    {ErrorCode::DwellMissingP, "DwellMissingP",
     QT_TRANSLATE_NOOP("frezka::gcode", "G4 needs the dwell time P"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Add P with the dwell time in seconds.")},
    {ErrorCode::G10BadL, "G10BadL", QT_TRANSLATE_NOOP("frezka::gcode", "G10 %1 is not supported"),
     QT_TRANSLATE_NOOP(
         "frezka::gcode",
         "Use G10 L2 or G10 L20 to set a work offset, G10 L1, L10 or L11 to set a tool's "
         "offsets.")},
    {ErrorCode::G10BadP, "G10BadP",
     QT_TRANSLATE_NOOP("frezka::gcode", "G10 needs P0 to P9 (got %1)"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "P0 is the active coordinate system, P1 to P9 are G54 to G59.3.")},
    {ErrorCode::UnsupportedRotation, "UnsupportedRotation",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "%1 is not supported under a coordinate system rotation (G10 L2 R)"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Arcs outside G17 and cutter radius compensation need the rotation off: "
                       "set R0 (G10 L2 P0 R0) for that part, or rotate the part in the CAM.")},
    {ErrorCode::ValueOutOfRange, "ValueOutOfRange",
     QT_TRANSLATE_NOOP("frezka::gcode", "Value of %1 is out of range"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Values must be finite and below 1e12 in size; check the expression.")},
    {ErrorCode::CutterCompensation, "CutterCompensation",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "%1 with tool %2, a lathe tool (orientation %3): the compensation of a "
                       "lathe tool's nose radius is not supported"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Give a mill tool orientation 0 in Machine > Tool table, or post the "
                       "program again from the CAM with the compensation computed there.")},
    {ErrorCode::ToolNotInTable, "ToolNotInTable",
     QT_TRANSLATE_NOOP("frezka::gcode", "Tool %1 is not in the tool table"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Add the tool with its length and diameter in Machine > Tool table, or "
                       "correct the T, H or P number.")},
    {ErrorCode::ToolOffsetWords, "ToolOffsetWords",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 needs either H or axis words, not both or none"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "G43.2 Hn adds tool n's offsets, G43.2 Z.. adds the given values; G43.1 "
                       "takes axis words only.")},
    {ErrorCode::G10L1NoOffsets, "G10L1NoOffsets",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 without offsets has no effect"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Give the values to set, e.g. Z for the tool length and R for its radius.")},
    {ErrorCode::ToolNumberMissing, "ToolNumberMissing",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 needs the tool number in %2"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Write the number of a tool of the tool table, e.g. M61 Q3 or G10 L1 P3 "
                       "Z25.")},
    {ErrorCode::FanucRigidTapping, "FanucRigidTapping",
     QT_TRANSLATE_NOOP("frezka::gcode", "M29 is the rigid tapping code of Fanuc-style controllers"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Frezka has no spindle-synchronised tapping (the GVE units have no spindle "
                       "encoder): tap with a floating tap holder or by hand, and post the program "
                       "without M29 and G84.")},
    {ErrorCode::CompPlane, "CompPlane",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "%1: cutter radius compensation works only in the XY (G17) and XZ (G18) "
                       "planes"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Select G17 or G18 before turning the compensation on.")},
    {ErrorCode::CompAlreadyOn, "CompAlreadyOn",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 while cutter radius compensation is already on"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Turn it off with G40 first, as LinuxCNC requires.")},
    {ErrorCode::CompNotAllowed, "CompNotAllowed",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 is not allowed while cutter radius compensation is on"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Turn the compensation off with G40 before this block and on again after "
                       "it, as LinuxCNC requires.")},
    {ErrorCode::CompMissingD, "CompMissingD",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 needs D, the diameter of the tool"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Write the tool's diameter in D, e.g. %1 D6.")},
    {ErrorCode::PolarNotAllowed, "PolarNotAllowed",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Polar coordinates (@ radius, ^ angle) cannot be used here (%1)"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Use @ and ^ only in the XY plane (G17), without X and Y words and without "
                       "G53; at X0 Y0 give the angle ^ with an absolute radius @ (G90).")},
    {ErrorCode::ModalStateNotAlone, "ModalStateNotAlone",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 shares its line with other words"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Put M70, M71, M72 and M73 on a line of their own (LinuxCNC runs them in "
                       "the middle of the line's other codes).")},
    {ErrorCode::ModalStateNotSaved, "ModalStateNotSaved",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 restores a state that was not saved at this level"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Save the modal state with M70 (or M73) in the same subroutine, or at the "
                       "top level, before M72, and do not invalidate it with M71 in between.")},
    {ErrorCode::ZeroFeedRate, "ZeroFeedRate",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 with zero feed rate"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Set a feed rate with F before the first feed move.")},
    {ErrorCode::InverseTimeFeedMissing, "InverseTimeFeedMissing",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 in inverse time mode (G93) needs an F word"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Give F on every feed move in G93, or switch to G94.")},
    {ErrorCode::ArcMissingCentre, "ArcMissingCentre",
     QT_TRANSLATE_NOOP("frezka::gcode", "Arc without I, J, K or R"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Give the centre with I/J/K or the radius with R.")},
    {ErrorCode::ArcMixedRAndIjk, "ArcMixedRAndIjk",
     QT_TRANSLATE_NOOP("frezka::gcode", "Arc with both R and I/J/K"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use either the centre (I/J/K) or the radius (R).")},
    {ErrorCode::ArcWrongPlaneWord, "ArcWrongPlaneWord",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 is not in the arc's plane"),
     QT_TRANSLATE_NOOP("frezka::gcode", "G17 uses I and J, G18 uses I and K, G19 uses J and K.")},
    {ErrorCode::ArcMissingAbsoluteCentre, "ArcMissingAbsoluteCentre",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 is missing for an arc with absolute centre (G90.1)"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Give both centre coordinates in G90.1 mode.")},
    {ErrorCode::ArcZeroRadius, "ArcZeroRadius",
     QT_TRANSLATE_NOOP("frezka::gcode", "Arc with zero radius %1"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Check the centre offsets I/J/K.")},
    {ErrorCode::ArcRadiusMismatch, "ArcRadiusMismatch",
     QT_TRANSLATE_NOOP("frezka::gcode", "Arc end point is not on the circle: %1"),
     QT_TRANSLATE_NOOP(
         "frezka::gcode",
         "Check the end point and the centre; the radii to start and end must match.")},
    {ErrorCode::ArcRadiusTooSmall, "ArcRadiusTooSmall",
     QT_TRANSLATE_NOOP("frezka::gcode", "Arc radius is too small to reach the end point %1"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Use a radius of at least half the distance between start and end.")},
    {ErrorCode::ArcEndEqualsStart, "ArcEndEqualsStart",
     QT_TRANSLATE_NOOP("frezka::gcode", "Arc given by R ends where it starts"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use I/J/K to program a full circle.")},
    {ErrorCode::ArcMissingEndWords, "ArcMissingEndWords",
     QT_TRANSLATE_NOOP("frezka::gcode", "Arc given by R has no end point in its plane"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Give the end point, or use I/J/K for a full circle.")},
    {ErrorCode::ArcBadTurns, "ArcBadTurns",
     QT_TRANSLATE_NOOP("frezka::gcode", "Arc turns P must be a positive integer (got %1)"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use P1 or more, or leave P out.")},
    {ErrorCode::ProbeNoMotion, "ProbeNoMotion",
     QT_TRANSLATE_NOOP("frezka::gcode", "Probe move does not move"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Give an end point different from the current position.")},
    {ErrorCode::ProbeInverseTime, "ProbeInverseTime",
     QT_TRANSLATE_NOOP("frezka::gcode", "Probe move in inverse time mode (G93)"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Switch to G94 before probing.")},
    {ErrorCode::CycleMissingR, "CycleMissingR",
     QT_TRANSLATE_NOOP("frezka::gcode", "Canned cycle %1 needs R"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Give the retract plane R on the first block of the cycle.")},
    {ErrorCode::CycleMissingDepth, "CycleMissingDepth",
     QT_TRANSLATE_NOOP("frezka::gcode", "Canned cycle %1 needs its depth"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Give the hole depth (Z in G17) on the first block of the cycle.")},
    {ErrorCode::CycleRBelowDepth, "CycleRBelowDepth",
     QT_TRANSLATE_NOOP("frezka::gcode", "Canned cycle retract plane R is below the hole depth"),
     QT_TRANSLATE_NOOP("frezka::gcode", "R must be above the bottom of the hole.")},
    {ErrorCode::CycleMissingP, "CycleMissingP",
     QT_TRANSLATE_NOOP("frezka::gcode", "Canned cycle %1 needs the dwell P"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Give P (seconds) on the first block of the cycle.")},
    {ErrorCode::CycleMissingQ, "CycleMissingQ",
     QT_TRANSLATE_NOOP("frezka::gcode", "Canned cycle %1 needs the peck Q"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Give Q (peck depth) on the first block of the cycle.")},
    {ErrorCode::CycleBadQ, "CycleBadQ",
     QT_TRANSLATE_NOOP("frezka::gcode", "Peck depth Q must be positive"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use a positive Q.")},
    {ErrorCode::CycleBadL, "CycleBadL",
     QT_TRANSLATE_NOOP("frezka::gcode", "Canned cycle repeat L must be a positive integer"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use L1 or more, or leave L out.")},
    {ErrorCode::CycleInverseTime, "CycleInverseTime",
     QT_TRANSLATE_NOOP("frezka::gcode", "Canned cycle in inverse time mode (G93)"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Switch to G94 before a canned cycle.")},
    {ErrorCode::CompEntryTooShort, "CompEntryTooShort",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "The move that starts the cutter radius compensation is not longer than "
                       "the tool radius (%1)"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Start the compensation from a point farther from the path than the tool "
                       "radius, e.g. with a lead-in move from outside the part.")},
    {ErrorCode::CompToolTooBig, "CompToolTooBig",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "The tool radius (%1) is not smaller than the radius of this arc, which "
                       "the tool follows on its inside"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Use a smaller tool (D), or make the arc larger than the tool.")},
    {ErrorCode::CompGouge, "CompGouge",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "The compensated tool (radius %1) cannot reach this corner without "
                       "cutting into the part"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Use a smaller tool, or change the path so that the tool fits into the "
                       "inside corner (LinuxCNC refuses it too).")},
    {ErrorCode::CompArcAfterExit, "CompArcAfterExit",
     QT_TRANSLATE_NOOP("frezka::gcode", "The move just after G40 must be straight, not an arc"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Add a straight move (G0 or G1) after G40, before the arc.")},
    {ErrorCode::SplinePlane, "SplinePlane",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1: splines work only in the XY plane (G17)"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Select G17 before the spline, as LinuxCNC requires, or re-post the curve "
                       "as arcs or lines in its plane.")},
    {ErrorCode::SplineAxisWord, "SplineAxisWord",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 cannot move %2: a spline moves X and Y only"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Move Z or A in a G1 block of its own before or after the spline.")},
    {ErrorCode::SplineMissingWords, "SplineMissingWords",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 needs %2"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "G5.1 X Y I J: I J is the control point, relative to the start. G5 X Y I "
                       "J P Q: I J is the first control point, relative to the start (leave both "
                       "out after a G5 to continue it smoothly), P Q the second, relative to the "
                       "end.")},
    {ErrorCode::NurbsMissingXy, "NurbsMissingXy",
     QT_TRANSLATE_NOOP("frezka::gcode", "A NURBS control point needs both X and Y (%1)"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Give X, Y and the weight P on every line from G5.2 to G5.3; P alone is "
                       "allowed only on the G5.2 line, as the start point's weight.")},
    {ErrorCode::NurbsBadWeight, "NurbsBadWeight",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "A NURBS control point needs a weight P from 0.000001 to 1000000 (%1)"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Give P on every control point (P1 for an ordinary B-spline point; "
                       "LinuxCNC takes -1 when it is missing).")},
    {ErrorCode::NurbsBadOrder, "NurbsBadOrder",
     QT_TRANSLATE_NOOP("frezka::gcode", "NURBS order L%1 is not supported"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Give a whole L from 3 (quadratic, also when L is left out) to 10; L4 "
                       "is cubic.")},
    {ErrorCode::NurbsTooFewPoints, "NurbsTooFewPoints",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "The NURBS has %1 control points, fewer than its order L%2"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Give at least as many control points (the start point counts) as the "
                       "order L before G5.3, or a lower L.")},
    {ErrorCode::NurbsNotStarted, "NurbsNotStarted",
     QT_TRANSLATE_NOOP("frezka::gcode", "G5.3 without G5.2 first"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Start the control points with G5.2 X Y P L, or remove this G5.3.")},
    {ErrorCode::NurbsNotEnded, "NurbsNotEnded",
     QT_TRANSLATE_NOOP("frezka::gcode", "The NURBS started on line %1 is not ended by G5.3"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "End its control points with G5.3 before another motion or the program "
                       "end (LinuxCNC would drop the curve without cutting it).")},
    {ErrorCode::NurbsOnlyControlPoints, "NurbsOnlyControlPoints",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 in the block of G5.3"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Between G5.2 and G5.3 only further G5.2 control points may come; put "
                       "other motions on a line of their own after G5.3.")},
    {ErrorCode::NurbsInverseTime, "NurbsInverseTime",
     QT_TRANSLATE_NOOP("frezka::gcode", "A G5.2 NURBS in inverse time mode (G93)"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Switch to G94 and give the feed with F before G5.2 (LinuxCNC does not "
                       "define how long a NURBS takes in G93).")},
    {ErrorCode::UnclosedBracket, "UnclosedBracket",
     QT_TRANSLATE_NOOP("frezka::gcode", "Expression is not closed"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Add the missing ']'.")},
    {ErrorCode::UnknownOperator, "UnknownOperator",
     QT_TRANSLATE_NOOP("frezka::gcode", "Unknown operator %1"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use + - * / ** MOD AND OR XOR EQ NE GT GE LT LE.")},
    {ErrorCode::UnknownFunction, "UnknownFunction",
     QT_TRANSLATE_NOOP("frezka::gcode", "Unknown function %1"),
     QT_TRANSLATE_NOOP(
         "frezka::gcode",
         "See the list of functions (ABS, ACOS, ASIN, ATAN, COS, EXP, FIX, FUP, LN, ROUND, "
         "SIN, SQRT, TAN, EXISTS).")},
    {ErrorCode::DivisionByZero, "DivisionByZero",
     QT_TRANSLATE_NOOP("frezka::gcode", "Division by zero"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Check the divisor.")},
    {ErrorCode::DomainError, "DomainError",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 of a value outside its domain"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Check the argument (e.g. SQRT of a negative number).")},
    {ErrorCode::NegativePower, "NegativePower",
     QT_TRANSLATE_NOOP("frezka::gcode", "Negative number raised to a non-integer power"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Check the operands of **.")},
    {ErrorCode::ParameterOutOfRange, "ParameterOutOfRange",
     QT_TRANSLATE_NOOP("frezka::gcode", "Parameter number %1 is out of range"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use parameters #1 to #5601.")},
    {ErrorCode::NamedParameterUndefined, "NamedParameterUndefined",
     QT_TRANSLATE_NOOP("frezka::gcode", "Parameter %1 is not defined"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Assign it a value before reading it.")},
    {ErrorCode::ReadOnlyParameter, "ReadOnlyParameter",
     QT_TRANSLATE_NOOP("frezka::gcode", "Parameter %1 is read-only"),
     QT_TRANSLATE_NOOP(
         "frezka::gcode",
         "System parameters are set by codes (e.g. G10 L2, G92), not by assignment.")},
    {ErrorCode::BadParameterName, "BadParameterName",
     QT_TRANSLATE_NOOP("frezka::gcode", "Bad parameter name %1"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Write named parameters as #<name>.")},
    {ErrorCode::ExpressionExpected, "ExpressionExpected",
     QT_TRANSLATE_NOOP("frezka::gcode", "An expression is expected %1"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Write the value in brackets, e.g. [#1 + 2].")},
    {ErrorCode::OwordSyntax, "OwordSyntax",
     QT_TRANSLATE_NOOP("frezka::gcode", "Malformed O word %1"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Write O-words as o100 if [...] or o<name> sub.")},
    {ErrorCode::OwordUnknownKeyword, "OwordUnknownKeyword",
     QT_TRANSLATE_NOOP("frezka::gcode", "Unknown O-word keyword %1"),
     QT_TRANSLATE_NOOP(
         "frezka::gcode",
         "Use sub, endsub, call, return, if, elseif, else, endif, while, endwhile, do, repeat, "
         "endrepeat, break or continue.")},
    {ErrorCode::OwordWithOtherWords, "OwordWithOtherWords",
     QT_TRANSLATE_NOOP("frezka::gcode", "An O-word line has other words"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Put the other words on their own line.")},
    {ErrorCode::OwordUnmatched, "OwordUnmatched",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 without its opening O-word"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Check the O numbers; they must match the opening line.")},
    {ErrorCode::OwordNotClosed, "OwordNotClosed",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 is never closed"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Add the matching end line (endsub, endif, endwhile, endrepeat or while).")},
    {ErrorCode::SubroutineUndefined, "SubroutineUndefined",
     QT_TRANSLATE_NOOP("frezka::gcode", "Subroutine %1 is not defined"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Define it in this file with o<name> sub ... o<name> endsub, or in a file "
                       "name.ngc beside the program or in a folder of the machine profile's "
                       "program.subroutinePath (Settings › Machine profile › Program).")},
    {ErrorCode::CallTooDeep, "CallTooDeep",
     QT_TRANSLATE_NOOP("frezka::gcode", "Subroutine calls nested too deeply"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Check for unbounded recursion.")},
    {ErrorCode::BreakOutsideLoop, "BreakOutsideLoop",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 outside a loop with this O number"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use break and continue only inside their own loop.")},
    {ErrorCode::ReturnOutsideSub, "ReturnOutsideSub",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 outside a subroutine"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Use return and endsub only inside a subroutine.")},
    {ErrorCode::TooManyBlocks, "TooManyBlocks",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "The program has executed %1 lines and has not ended; it was stopped here"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "If the program is really this long, raise the machine profile's "
                       "program.maxLinesExecuted (Settings › Machine profile › Program).")},
    {ErrorCode::TooManyMoves, "TooManyMoves",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "The program has made %1 moves and has not ended; it was stopped here"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "If the program really has more moves, raise the machine profile's "
                       "program.maxMoves (Settings › Machine profile › Program); a million moves "
                       "take about 50 MB of memory to check, more to plan and show.")},
    {ErrorCode::LoopNeverEnds, "LoopNeverEnds",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "%3 has not ended after %1 lines executed (it was stopped at line %2)"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Check what ends it (its condition, its count, the exit of a recursion); "
                       "if it is meant to run this long, raise the machine profile's "
                       "program.maxLinesExecuted (Settings › Machine profile › Program).")},
    {ErrorCode::LoopMovesNeverEnd, "LoopMovesNeverEnd",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "%3 has not ended after %1 moves (it was stopped at line %2)"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Check what ends it (its condition, its count, the exit of a recursion); "
                       "if it is meant to make more moves, raise the machine profile's "
                       "program.maxMoves (Settings › Machine profile › Program).")},
    {ErrorCode::IniSyntax, "IniSyntax",
     QT_TRANSLATE_NOOP("frezka::gcode", "This INI line is not [SECTION] nor NAME = VALUE: %1"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Fix the line or make it a comment (starting with # or ;).")},
    {ErrorCode::NestedSubDefinition, "NestedSubDefinition",
     QT_TRANSLATE_NOOP("frezka::gcode", "%1 sub is defined inside the running subroutine %2"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Move the definition out of %2: define it before or after it (in its own "
                       "file name.ngc when %2 is in a file), as LinuxCNC requires.")},
    {ErrorCode::SubroutineNotFound, "SubroutineNotFound",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Subroutine %1 is not defined yet and there is no file %2 on the "
                       "subroutine path"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "A subroutine file holds only its own subroutine (as in LinuxCNC): put %1 "
                       "in a file %2 beside the program or in a folder of the machine profile's "
                       "program.subroutinePath, or define it in the program.")},
    {ErrorCode::SubroutineFileWithoutSub, "SubroutineFileWithoutSub",
     QT_TRANSLATE_NOOP("frezka::gcode", "The file %2 has no line %1 sub"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "A file name.ngc found for o<name> call must define o<name> sub ... "
                       "o<name> endsub; rename the file or fix its sub line.")},
    {ErrorCode::FeedUnitsChanged, "FeedUnitsChanged",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "F%1 was read in %2 (line %3) before this change of units: the feed moves "
                       "after it run at %1 %2 (%4 %5), as in LinuxCNC, not at %1 %5 (%6 %2)"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "LinuxCNC reads F before G20/G21, also on the same line; if %1 %5 was "
                       "meant, give F again after the change of units.")},
    {ErrorCode::ImpliedProgramEnd, "ImpliedProgramEnd",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "The file ends without M2, M30 or %: the program is taken to end here, "
                       "with the spindle and coolant switched off as at M2"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Check that the file is complete (not cut short when it was copied); "
                       "end the program with M2 or M30.")},
    {ErrorCode::DwellLooksLikeMilliseconds, "DwellLooksLikeMilliseconds",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "G4 P%1 dwells %1 seconds (%2), as in LinuxCNC; if the post meant "
                       "milliseconds (as Mach3 and UCCNC can), that is %3 s"),
     QT_TRANSLATE_NOOP("frezka::gcode", "Frezka reads P in seconds; write P%3 if %3 s was meant.")},
    {ErrorCode::CompZeroRadius, "CompZeroRadius",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "%1 with tool %2, whose diameter is 0: the path is not compensated"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Enter the tool's diameter in Machine > Tool table; as it is, the tool "
                       "follows the programmed path, off the part's contour by its radius.")},
    {ErrorCode::IgnoredArcWord, "IgnoredArcWord",
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "%1 has no effect on an arc in the %2 plane and is ignored"),
     QT_TRANSLATE_NOOP("frezka::gcode",
                       "Some posts (e.g. FreeCAD's grbl post) write it; LinuxCNC refuses it, and "
                       "any value other than 0 is an error.")},
};

const ErrorInfo *info(ErrorCode code)
{
    for (const ErrorInfo &e : kErrors) {
        if (e.code == code)
            return &e;
    }
    return nullptr;
}

} // namespace

const char *errorName(ErrorCode code)
{
    const ErrorInfo *e = info(code);
    return e ? e->name : "Unknown";
}

bool errorCodeFromName(const std::string &name, ErrorCode *code)
{
    for (const ErrorInfo &e : kErrors) {
        if (name == e.name) {
            *code = e.code;
            return true;
        }
    }
    return false;
}

const char *errorTemplate(ErrorCode code)
{
    const ErrorInfo *e = info(code);
    return e ? e->text : "Error %1";
}

const char *errorHint(ErrorCode code)
{
    const ErrorInfo *e = info(code);
    return e ? e->hint : "";
}

Severity severity(ErrorCode code)
{
    const int n = static_cast<int>(code);
    return n >= 700 ? Severity::Note : n >= 600 ? Severity::Warning : Severity::Error;
}

} // namespace frezka::gcode
