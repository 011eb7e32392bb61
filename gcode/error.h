#pragma once
// G-code errors, warnings and notes: a stable code, where it happened (1-based line and column of
// the offending word) and a detail (the word, the value; several values separated by
// kDetailSeparator fill %1, %2, ...). The English template of each code is marked with
// QT_TRANSLATE_NOOP("frezka::gcode", ...) so lupdate finds it; translatedMessage() returns the
// user's language. The table of codes is documented in docs/gcode.md; never renumber a code.
// Codes 6xx are warnings (the program runs, but the user should know), 7xx notes (a word of
// another dialect that has no effect was accepted).

#include <QString>

#include <cstdint>
#include <string>

namespace frezka::gcode {

enum class ErrorCode : std::uint16_t {
    // File and syntax (1xx)
    FileOpenFailed = 100,
    BadCharacter = 101,
    UnclosedComment = 102,
    NestedComment = 103,
    NumberExpected = 104,
    NonIntegerValue = 105,
    RepeatedWord = 106,
    UnsupportedWord = 107,
    UnsupportedAxis = 108,
    FileEndedWithoutEnd = 109,
    FileEndedWithoutPercent = 110,
    LineTooLong = 111,
    GrblHoming = 112,
    GrblCommand = 113,
    SlashComment = 114,
    FileWriteFailed = 115,
    ToolTableSyntax = 116,
    ToolTableDuplicate = 117,
    ProgramAborted = 118,
    IniSyntax = 119,
    // Codes and modal groups (2xx)
    UnknownGCode = 200,
    UnsupportedGCode = 201,
    UnknownMCode = 202,
    UnsupportedMCode = 203,
    ModalGroupConflict = 204,
    TooManyMCodes = 205,
    WordNotUsed = 206,
    AxisWordsWithG80 = 207,
    AxisWordsWithoutMotion = 208,
    TwoAxisCodes = 209,
    AxisWordsMissing = 210,
    NegativeValue = 211,
    G53NeedsG0OrG1 = 212,
    G53Incremental = 213,
    DwellMissingP = 214,
    G10BadL = 215,
    G10BadP = 216,
    UnsupportedRotation = 217,
    ValueOutOfRange = 218,
    FanucRigidTapping = 219,
    CutterCompensation = 220,
    ToolNotInTable = 221,
    ToolOffsetWords = 222,
    G10L1NoOffsets = 223,
    ToolNumberMissing = 224,
    CompPlane = 225,
    CompAlreadyOn = 226,
    CompNotAllowed = 227,
    CompMissingD = 228,
    PolarNotAllowed = 229,
    ModalStateNotAlone = 230,
    ModalStateNotSaved = 231,
    // Motion (3xx)
    ZeroFeedRate = 300,
    InverseTimeFeedMissing = 301,
    ArcMissingCentre = 302,
    ArcMixedRAndIjk = 303,
    ArcWrongPlaneWord = 304,
    ArcMissingAbsoluteCentre = 305,
    ArcZeroRadius = 306,
    ArcRadiusMismatch = 307,
    ArcRadiusTooSmall = 308,
    ArcEndEqualsStart = 309,
    ArcMissingEndWords = 310,
    ArcBadTurns = 311,
    ProbeNoMotion = 312,
    ProbeInverseTime = 313,
    CycleMissingR = 320,
    CycleMissingDepth = 321,
    CycleRBelowDepth = 322,
    CycleMissingP = 323,
    CycleMissingQ = 324,
    CycleBadQ = 325,
    CycleBadL = 326,
    CycleInverseTime = 327,
    CompEntryTooShort = 330,
    CompToolTooBig = 331,
    CompGouge = 332,
    CompArcAfterExit = 333,
    SplinePlane = 340,
    SplineAxisWord = 341,
    SplineMissingWords = 342,
    NurbsMissingXy = 343,
    NurbsBadWeight = 344,
    NurbsBadOrder = 345,
    NurbsTooFewPoints = 346,
    NurbsNotStarted = 347,
    NurbsNotEnded = 348,
    NurbsOnlyControlPoints = 349,
    NurbsInverseTime = 350,
    // Expressions and parameters (4xx)
    UnclosedBracket = 400,
    UnknownOperator = 401,
    UnknownFunction = 402,
    DivisionByZero = 403,
    DomainError = 404,
    NegativePower = 405,
    ParameterOutOfRange = 406,
    NamedParameterUndefined = 407,
    ReadOnlyParameter = 408,
    BadParameterName = 409,
    ExpressionExpected = 410,
    // O-words (5xx)
    OwordSyntax = 500,
    OwordUnknownKeyword = 501,
    OwordWithOtherWords = 502,
    OwordUnmatched = 503,
    OwordNotClosed = 504,
    SubroutineUndefined = 505,
    CallTooDeep = 506,
    BreakOutsideLoop = 507,
    ReturnOutsideSub = 508,
    TooManyBlocks = 509,
    TooManyMoves = 510,
    LoopNeverEnds = 511,
    LoopMovesNeverEnd = 512,
    NestedSubDefinition = 513,
    SubroutineNotFound = 514,
    SubroutineFileWithoutSub = 515,
    // Warnings (6xx): the program runs as LinuxCNC runs it; the user should check it.
    FeedUnitsChanged = 600,
    ImpliedProgramEnd = 601,
    DwellLooksLikeMilliseconds = 602,
    CompZeroRadius = 603,
    // Notes (7xx): a word of another dialect with no effect was accepted.
    IgnoredArcWord = 700,
};

enum class Severity : std::uint8_t { Error, Warning, Note };
Severity severity(ErrorCode code);

// Separates the values of a detail that fill %1, %2, ... of a template.
inline constexpr char kDetailSeparator = '\x1f';

struct Error
{
    ErrorCode code = ErrorCode::BadCharacter;
    std::uint32_t line = 0;   // 1-based source line, 0 if none
    std::uint32_t column = 0; // 1-based column (bytes) of the offending word, 0 if none
    std::string detail;       // the offending word or value, inserted into the message (%1)
    std::string file; // a subroutine file the error is in (o<name> call); empty: the program
    friend bool operator==(const Error &, const Error &) = default;
};

// Stable identifier of a code, e.g. "ArcRadiusMismatch" (used by the bad-program corpus).
const char *errorName(ErrorCode code);
// Parses an identifier made by errorName(); false if unknown.
bool errorCodeFromName(const std::string &name, ErrorCode *code);
// English message template (with %1 for the detail) and the hint on what to do.
const char *errorTemplate(ErrorCode code);
const char *errorHint(ErrorCode code);
// "message. hint" in English (detail filled in).
std::string englishMessage(const Error &error);
// The same in the user's language (QCoreApplication::translate, context "frezka::gcode").
QString translatedMessage(const Error &error);
// "FILE:LINE:COL: message" in the user's language ("FILE: message" without a line); warnings and
// notes say so ("FILE:LINE:COL: warning: message"). An error in a subroutine file names that file
// (Error::file) instead of FILE.
QString formatError(const QString &file, const Error &error);

} // namespace frezka::gcode
