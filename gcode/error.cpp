#include "error.h"

#include <QCoreApplication>

#include <array>
#include <cstring>

namespace frezka::gcode {

namespace {

struct ErrorInfo
{
    ErrorCode code;
    const char *name;
    const char *text; // English template, %1 = detail
    const char *hint; // what the user should do
};

#define FZ_TR(s) QT_TRANSLATE_NOOP("frezka::gcode", s)

// clang-format off
constexpr ErrorInfo kErrors[] = {
    {ErrorCode::FileOpenFailed, "FileOpenFailed", FZ_TR("Cannot read the file %1"),
     FZ_TR("Check that the file exists and is readable.")},
    {ErrorCode::BadCharacter, "BadCharacter", FZ_TR("Unexpected character '%1'"),
     FZ_TR("Remove it or put it inside a comment ( ).")},
    {ErrorCode::UnclosedComment, "UnclosedComment", FZ_TR("Comment is not closed"),
     FZ_TR("Add ')' at the end of the comment.")},
    {ErrorCode::NestedComment, "NestedComment", FZ_TR("Comment inside a comment"),
     FZ_TR("Close the first comment before opening another one.")},
    {ErrorCode::NumberExpected, "NumberExpected", FZ_TR("A number is expected after %1"),
     FZ_TR("Write a number, a #parameter or an [expression] after the letter.")},
    {ErrorCode::NonIntegerValue, "NonIntegerValue", FZ_TR("%1 needs a whole number"),
     FZ_TR("Use an integer value here.")},
    {ErrorCode::RepeatedWord, "RepeatedWord", FZ_TR("Word %1 appears twice in one block"),
     FZ_TR("Keep one of them or split the block into two lines.")},
    {ErrorCode::UnsupportedWord, "UnsupportedWord", FZ_TR("Word %1 is not supported"),
     FZ_TR("Remove the word; Frezka does not use it.")},
    {ErrorCode::UnsupportedAxis, "UnsupportedAxis", FZ_TR("Axis %1 is not supported"),
     FZ_TR("Frezka machines have the axes X, Y, Z and A.")},
    {ErrorCode::FileEndedWithoutEnd, "FileEndedWithoutEnd",
     FZ_TR("The file ended without M2, M30 or %"),
     FZ_TR("End the program with M2 or M30 (or enclose it in % lines).")},
    {ErrorCode::FileEndedWithoutPercent, "FileEndedWithoutPercent",
     FZ_TR("The program starts with % but has no closing %"),
     FZ_TR("Add a line with % at the end of the program.")},
    {ErrorCode::LineTooLong, "LineTooLong", FZ_TR("Line is too long (%1 characters)"),
     FZ_TR("Split the line; at most 65535 characters are allowed.")},
    {ErrorCode::UnknownGCode, "UnknownGCode", FZ_TR("Unknown G code %1"),
     FZ_TR("Check the number; see the list of supported codes.")},
    {ErrorCode::UnsupportedGCode, "UnsupportedGCode", FZ_TR("%1 is not supported"),
     FZ_TR("Remove it or post-process the program without it (see the supported codes).")},
    {ErrorCode::UnknownMCode, "UnknownMCode", FZ_TR("Unknown M code %1"),
     FZ_TR("Check the number; see the list of supported codes.")},
    {ErrorCode::UnsupportedMCode, "UnsupportedMCode", FZ_TR("%1 is not supported"),
     FZ_TR("Remove it or post-process the program without it (see the supported codes).")},
    {ErrorCode::ModalGroupConflict, "ModalGroupConflict",
     FZ_TR("%1 conflicts with another code of the same group in this block"),
     FZ_TR("Use one code of each modal group per block.")},
    {ErrorCode::TooManyMCodes, "TooManyMCodes", FZ_TR("Too many M codes in one block"),
     FZ_TR("Use at most four M codes per block.")},
    {ErrorCode::WordNotUsed, "WordNotUsed", FZ_TR("Word %1 is not used by any code in this block"),
     FZ_TR("Remove the word or add the code that uses it.")},
    {ErrorCode::AxisWordsWithG80, "AxisWordsWithG80", FZ_TR("Axis words are given with G80"),
     FZ_TR("G80 cancels the motion mode; give the axis words with G0 or G1.")},
    {ErrorCode::AxisWordsWithoutMotion, "AxisWordsWithoutMotion",
     FZ_TR("Axis words are given but no motion mode is active"),
     FZ_TR("Add G0, G1, G2 or G3 to the block.")},
    {ErrorCode::TwoAxisCodes, "TwoAxisCodes", FZ_TR("%1 and a motion code both use the axis words"),
     FZ_TR("Put them on separate lines.")},
    {ErrorCode::AxisWordsMissing, "AxisWordsMissing", FZ_TR("%1 needs at least one axis word"),
     FZ_TR("Add the axis words (X, Y, Z or A).")},
    {ErrorCode::NegativeValue, "NegativeValue", FZ_TR("%1 must not be negative"),
     FZ_TR("Use zero or a positive value.")},
    {ErrorCode::G53NeedsG0OrG1, "G53NeedsG0OrG1", FZ_TR("G53 needs G0 or G1"),
     FZ_TR("Write G53 together with G0 or G1 on the same line.")},
    {ErrorCode::G53Incremental, "G53Incremental", FZ_TR("G53 cannot be used in G91 mode"),
     FZ_TR("Switch to G90 before moving in machine coordinates.")},
    {ErrorCode::DwellMissingP, "DwellMissingP", FZ_TR("G4 needs the dwell time P"),
     FZ_TR("Add P with the dwell time in seconds.")},
    {ErrorCode::G10BadL, "G10BadL", FZ_TR("G10 %1 is not supported"),
     FZ_TR("Use G10 L2 or G10 L20 to set a work offset.")},
    {ErrorCode::G10BadP, "G10BadP", FZ_TR("G10 needs P0 to P9 (got %1)"),
     FZ_TR("P0 is the active coordinate system, P1 to P9 are G54 to G59.3.")},
    {ErrorCode::UnsupportedRotation, "UnsupportedRotation",
     FZ_TR("Coordinate system rotation (G10 R) is not supported"),
     FZ_TR("Remove the R word.")},
    {ErrorCode::ValueOutOfRange, "ValueOutOfRange", FZ_TR("Value of %1 is out of range"),
     FZ_TR("Values must be finite and below 1e12 in size; check the expression.")},
    {ErrorCode::ZeroFeedRate, "ZeroFeedRate", FZ_TR("%1 with zero feed rate"),
     FZ_TR("Set a feed rate with F before the first feed move.")},
    {ErrorCode::InverseTimeFeedMissing, "InverseTimeFeedMissing",
     FZ_TR("%1 in inverse time mode (G93) needs an F word"),
     FZ_TR("Give F on every feed move in G93, or switch to G94.")},
    {ErrorCode::ArcMissingCentre, "ArcMissingCentre", FZ_TR("Arc without I, J, K or R"),
     FZ_TR("Give the centre with I/J/K or the radius with R.")},
    {ErrorCode::ArcMixedRAndIjk, "ArcMixedRAndIjk", FZ_TR("Arc with both R and I/J/K"),
     FZ_TR("Use either the centre (I/J/K) or the radius (R).")},
    {ErrorCode::ArcWrongPlaneWord, "ArcWrongPlaneWord", FZ_TR("%1 is not in the arc's plane"),
     FZ_TR("G17 uses I and J, G18 uses I and K, G19 uses J and K.")},
    {ErrorCode::ArcMissingAbsoluteCentre, "ArcMissingAbsoluteCentre",
     FZ_TR("%1 is missing for an arc with absolute centre (G90.1)"),
     FZ_TR("Give both centre coordinates in G90.1 mode.")},
    {ErrorCode::ArcZeroRadius, "ArcZeroRadius", FZ_TR("Arc with zero radius %1"),
     FZ_TR("Check the centre offsets I/J/K.")},
    {ErrorCode::ArcRadiusMismatch, "ArcRadiusMismatch",
     FZ_TR("Arc end point is not on the circle: %1"),
     FZ_TR("Check the end point and the centre; the radii to start and end must match.")},
    {ErrorCode::ArcRadiusTooSmall, "ArcRadiusTooSmall",
     FZ_TR("Arc radius is too small to reach the end point %1"),
     FZ_TR("Use a radius of at least half the distance between start and end.")},
    {ErrorCode::ArcEndEqualsStart, "ArcEndEqualsStart",
     FZ_TR("Arc given by R ends where it starts"),
     FZ_TR("Use I/J/K to program a full circle.")},
    {ErrorCode::ArcMissingEndWords, "ArcMissingEndWords",
     FZ_TR("Arc given by R has no end point in its plane"),
     FZ_TR("Give the end point, or use I/J/K for a full circle.")},
    {ErrorCode::ArcBadTurns, "ArcBadTurns", FZ_TR("Arc turns P must be a positive integer (got %1)"),
     FZ_TR("Use P1 or more, or leave P out.")},
    {ErrorCode::ProbeNoMotion, "ProbeNoMotion", FZ_TR("Probe move does not move"),
     FZ_TR("Give an end point different from the current position.")},
    {ErrorCode::ProbeInverseTime, "ProbeInverseTime",
     FZ_TR("Probe move in inverse time mode (G93)"), FZ_TR("Switch to G94 before probing.")},
    {ErrorCode::CycleMissingR, "CycleMissingR", FZ_TR("Canned cycle %1 needs R"),
     FZ_TR("Give the retract plane R on the first block of the cycle.")},
    {ErrorCode::CycleMissingDepth, "CycleMissingDepth", FZ_TR("Canned cycle %1 needs its depth"),
     FZ_TR("Give the hole depth (Z in G17) on the first block of the cycle.")},
    {ErrorCode::CycleRBelowDepth, "CycleRBelowDepth",
     FZ_TR("Canned cycle retract plane R is below the hole depth"),
     FZ_TR("R must be above the bottom of the hole.")},
    {ErrorCode::CycleMissingP, "CycleMissingP", FZ_TR("Canned cycle %1 needs the dwell P"),
     FZ_TR("Give P (seconds) on the first block of the cycle.")},
    {ErrorCode::CycleMissingQ, "CycleMissingQ", FZ_TR("Canned cycle %1 needs the peck Q"),
     FZ_TR("Give Q (peck depth) on the first block of the cycle.")},
    {ErrorCode::CycleBadQ, "CycleBadQ", FZ_TR("Peck depth Q must be positive"),
     FZ_TR("Use a positive Q.")},
    {ErrorCode::CycleBadL, "CycleBadL", FZ_TR("Canned cycle repeat L must be a positive integer"),
     FZ_TR("Use L1 or more, or leave L out.")},
    {ErrorCode::CycleInverseTime, "CycleInverseTime",
     FZ_TR("Canned cycle in inverse time mode (G93)"),
     FZ_TR("Switch to G94 before a canned cycle.")},
    {ErrorCode::UnclosedBracket, "UnclosedBracket", FZ_TR("Expression is not closed"),
     FZ_TR("Add the missing ']'.")},
    {ErrorCode::UnknownOperator, "UnknownOperator", FZ_TR("Unknown operator %1"),
     FZ_TR("Use + - * / ** MOD AND OR XOR EQ NE GT GE LT LE.")},
    {ErrorCode::UnknownFunction, "UnknownFunction", FZ_TR("Unknown function %1"),
     FZ_TR("See the list of functions (ABS, ACOS, ASIN, ATAN, COS, EXP, FIX, FUP, LN, ROUND, "
           "SIN, SQRT, TAN, EXISTS).")},
    {ErrorCode::DivisionByZero, "DivisionByZero", FZ_TR("Division by zero"),
     FZ_TR("Check the divisor.")},
    {ErrorCode::DomainError, "DomainError", FZ_TR("%1 of a value outside its domain"),
     FZ_TR("Check the argument (e.g. SQRT of a negative number).")},
    {ErrorCode::NegativePower, "NegativePower",
     FZ_TR("Negative number raised to a non-integer power"), FZ_TR("Check the operands of **.")},
    {ErrorCode::ParameterOutOfRange, "ParameterOutOfRange",
     FZ_TR("Parameter number %1 is out of range"), FZ_TR("Use parameters #1 to #5601.")},
    {ErrorCode::NamedParameterUndefined, "NamedParameterUndefined",
     FZ_TR("Parameter %1 is not defined"), FZ_TR("Assign it a value before reading it.")},
    {ErrorCode::ReadOnlyParameter, "ReadOnlyParameter", FZ_TR("Parameter %1 is read-only"),
     FZ_TR("System parameters are set by codes (e.g. G10 L2, G92), not by assignment.")},
    {ErrorCode::BadParameterName, "BadParameterName", FZ_TR("Bad parameter name %1"),
     FZ_TR("Write named parameters as #<name>.")},
    {ErrorCode::ExpressionExpected, "ExpressionExpected", FZ_TR("An expression is expected %1"),
     FZ_TR("Write the value in brackets, e.g. [#1 + 2].")},
    {ErrorCode::OwordSyntax, "OwordSyntax", FZ_TR("Malformed O word %1"),
     FZ_TR("Write O-words as o100 if [...] or o<name> sub.")},
    {ErrorCode::OwordUnknownKeyword, "OwordUnknownKeyword", FZ_TR("Unknown O-word keyword %1"),
     FZ_TR("Use sub, endsub, call, return, if, elseif, else, endif, while, endwhile, do, repeat, "
           "endrepeat, break or continue.")},
    {ErrorCode::OwordWithOtherWords, "OwordWithOtherWords",
     FZ_TR("An O-word line has other words"), FZ_TR("Put the other words on their own line.")},
    {ErrorCode::OwordUnmatched, "OwordUnmatched", FZ_TR("%1 without its opening O-word"),
     FZ_TR("Check the O numbers; they must match the opening line.")},
    {ErrorCode::OwordNotClosed, "OwordNotClosed", FZ_TR("%1 is never closed"),
     FZ_TR("Add the matching end line (endsub, endif, endwhile, endrepeat or while).")},
    {ErrorCode::SubroutineUndefined, "SubroutineUndefined",
     FZ_TR("Subroutine %1 is not defined"),
     FZ_TR("Define it in this file with o<name> sub ... o<name> endsub.")},
    {ErrorCode::CallTooDeep, "CallTooDeep", FZ_TR("Subroutine calls nested too deeply"),
     FZ_TR("Check for unbounded recursion.")},
    {ErrorCode::BreakOutsideLoop, "BreakOutsideLoop", FZ_TR("%1 outside a loop with this O number"),
     FZ_TR("Use break and continue only inside their own loop.")},
    {ErrorCode::ReturnOutsideSub, "ReturnOutsideSub", FZ_TR("%1 outside a subroutine"),
     FZ_TR("Use return and endsub only inside a subroutine.")},
    {ErrorCode::TooManyBlocks, "TooManyBlocks",
     FZ_TR("The program executes more than %1 blocks"),
     FZ_TR("Check the loops; one of them may never end.")},
};
// clang-format on

#undef FZ_TR

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

std::string englishMessage(const Error &error)
{
    std::string text = errorTemplate(error.code);
    const auto pos = text.find("%1");
    if (pos != std::string::npos)
        text.replace(pos, 2, error.detail);
    text += ". ";
    text += errorHint(error.code);
    return text;
}

QString translatedMessage(const Error &error)
{
    QString text = QCoreApplication::translate("frezka::gcode", errorTemplate(error.code));
    if (text.contains(QLatin1String("%1")))
        text = text.arg(QString::fromStdString(error.detail));
    return text + QStringLiteral(". ") +
           QCoreApplication::translate("frezka::gcode", errorHint(error.code));
}

QString formatError(const QString &file, const Error &error)
{
    if (error.line == 0)
        return QStringLiteral("%1: %2").arg(file, translatedMessage(error));
    return QStringLiteral("%1:%2:%3: %4")
        .arg(file)
        .arg(error.line)
        .arg(error.column)
        .arg(translatedMessage(error));
}

} // namespace frezka::gcode
