#pragma once
// The driver's messages as codes (issue 13 item 4), modelled on gcode/error.h: every refusal,
// error and hold reason the driver reports is a stable DriverCode with its arguments (the line,
// the axis, the command, the unit's reply ...), never finished prose. Each code has an English
// template (%1, %2 ... for the arguments) and a hint on what to do, both marked with
// QT_TRANSLATE_NOOP("frezka::driver", ...) so that lupdate finds them; the front ends word a
// message in the user's language with translatedText(). Arguments that are themselves fixed
// driver phrases (an action such as "pausing (H)", the unit's reply "queue full", a mode name)
// are translated too when the catalogue knows them; numbers, commands and replies stay as they
// are. The English text (englishText) is what logs and the tests' assertions read. The table of
// codes is documented in docs/gui.md ("Driver messages"); never renumber a code.

#include <QString>

#include <cstdint>
#include <string>
#include <vector>

namespace frezka::driver {

enum class DriverCode : std::uint16_t {
    None = 0,
    // Refusals: nothing was sent (1xx)
    NotNow = 100,                   // %1 the action, %2 the machine's mode
    JobNeedsIdle = 101,             // %1 mode
    ProgressBeingChecked = 102,     //
    LowerToolFirst = 103,           //
    NoHomedAxis = 104,              //
    AxisNotHomed = 105,             //
    HomeAllTogether = 106,          // %1 firmware version
    JogOutsideLimits = 107,         //
    JogAtLimit = 108,               //
    NoSuchAxis = 109,               //
    NoSuchAxisOrDirection = 110,    //
    ProgramAxisCount = 111,         // %1 axes
    ProgramFourAxes = 112,          // %1 the unit's name
    ProgramStartsElsewhere = 113,   // %1 planned steps, %2 axis, %3 steps now
    ProgramNeedsVk = 114,           // %1 line, %2 firmware version
    InvalidCommand = 115,           // %1 line, %2 why (detail: a 5xx code)
    LiftOffPath = 116,              //
    NoLiftHeight = 117,             //
    LiftAtLimit = 118,              //
    MpgNeedsFirmware = 119,         // %1 firmware version
    NoMpg = 120,                    //
    SpindleOutOfRange = 121,        // %1 rpm asked, %2 the profile's maximum
    NoOverride = 122,               //
    OverrideInvalid = 123,          // %1 why (detail: a 5xx code)
    EmptyCommand = 124,             //
    NotACommand = 125,              // %1 the text, %2 why (detail: a 5xx code)
    CommandDisturbsJob = 126,       // %1 the text
    SpeedInvalid = 127,             // %1 why (detail: a 5xx code)
    OverrideNeedsFirmware = 128,    // %1 firmware version
    HomingNeedsFirmware = 129,      // %1 firmware version (W needs IP64MPG v10)
    SpindleStarting = 130,          //
    JogBeyondLimits = 131,          // %1 target mm, %2 soft minimum, %3 soft maximum
    JogTooShort = 132,              //
    ToolStillMoving = 133,          //
    OverrideAboveWithoutVl = 134,   //
    NewFeedNeedsXm = 135,           //
    MpgReportsUnsupported = 136,    //
    ContinuousJogWhileLifted = 137, //
    NoPlannedSpeed = 138,           //
    NoSuchOutput = 139,             // %1 the output's number
    SpindleOverrideRange = 140,     // %1 percent asked, %2 minimum, %3 maximum
    NoSpindleOverride = 141,        //
    // The unit and the link (2xx)
    UnitAnswered = 200,       // %1 the action, %2 the unit's reply
    LinkFailed = 201,         // %1 the action, %2 why
    UnitRefused = 202,        // %1 line, %2 command, %3 the unit's reply
    LinkLostJobKept = 203,    // %1 why
    LinkLost = 204,           // %1 why
    CannotConnect = 205,      // %1 why
    WrongVariant = 206,       // %1 firmware, %2 the profile's unit
    FirmwareTooOld = 207,     // %1 the unit's version, %2 the profile's version
    UnknownOperation = 208,   // %1 line
    HomeSwitchNotFound = 209, // %1 axis
    HomingInvalid = 210,      // %1 axis, %2 why (detail: a 5xx code)
    // 211 retired (LinkFailedAtLine: the link's reasons are LinkGaveUp ... with "line N")
    HomingLegStopped = 212,    // %1 axis
    LiftPointMissed = 213,     // %1 the counters, %2 the lift point
    LinkGaveUp = 214,          // %1 action, %2 command, %3 what went wrong, %4 reply, %5 attempts
    LinkIndexUnknown = 215,    // %1 action, %2 command
    LinkIndexUnexpected = 216, // %1 action, %2 command, %3 the unit's index, %4/%5 expected
    // The job (3xx)
    ProbeAlreadyTripped = 300,   // %1 line
    ProbeNotTripped = 301,       // %1 line
    ProbeTrippedElsewhere = 302, // %1 line, %2 the counters
    CountersMatchNothing = 303,  //
    CountersMatchSeveral = 304,  //
    ReturnFailed = 305,          // %1 attempts
    OffPath = 306,               // %1 what the counters read, %2 the line it returns to
    // Why a job is held (4xx)
    HoldPaused = 400,          //
    HoldProgramStop = 401,     // %1 line (M0)
    HoldOptionalStop = 402,    // %1 line (M1)
    HoldToolChange = 403,      // %1 line, %2 tool (M6)
    HoldInterrupt = 404,       //
    HoldInput = 405,           // %1 the inputs' names
    HoldStopButton = 406,      // %1 the inputs' names (the STOP button among them)
    HoldToolLifted = 407,      //
    HoldToolLowered = 408,     //
    HoldReturning = 409,       //
    HoldLinkRestored = 410,    //
    HoldSpindleStarting = 411, //
    HoldToolLowering = 412,    //
    // Why a command cannot be sent (5xx): the protocol's check (protocol::CommandProblem) and
    // parse (protocol::ParseProblem) as the detail of a refusal; %1 is the command or line
    CommandAddressRange = 500,      //
    CommandNoSpindleAddress = 501,  // %2 unit
    CommandNotOnAddress7 = 502,     //
    CommandSpindleOnAddress7 = 503, //
    CommandAddressZeroOnly = 504,   // %2 unit
    CommandComponents3 = 505,       // %2 components, %3 unit
    CommandComponents34 = 506,      // %2 components, %3 unit
    CommandOutOfRange = 507,        // %2 the argument, %3 value, %4 lowest, %5 highest
    CommandNotFinite = 508,         //
    CommandZeroTravel = 509,        //
    CommandNoSuchAxis = 510,        // %2 unit, %3 axis
    CommandNoSuchCommand = 511,     // %2 unit, %3 mnemonic
    CommandNotInPacket = 512,       //
    CommandEmptyPacket = 513,       //
    LineNoAddress = 520,            //
    LineBadChecksum = 521,          //
    LineUnknownCommand = 522,       //
    LineMissingNumber = 523,        //
    LineNumberTooLarge = 524,       // %2 the parameter
    LineNotDecimal = 525,           // %2 the parameter
    LineNotHexByte = 526,           // %2 the parameter
    LineNotANumber = 527,           // %2 the parameter
    LineParameterCount = 528,       //
    LineHomeNeedsAxis = 529,        //
    LineOutputNeedsByte = 530,      //
    LineUnexpectedParameters = 531, //
};

// A code with its arguments: a hold reason, a refusal, an error. A refusal whose reason is a
// message of its own (why the protocol's check refuses a command) carries it as `detail`,
// worded in place of the argument after the last of `args`.
struct DriverMessage
{
    DriverMessage() = default;
    DriverMessage(DriverCode c, std::vector<std::string> a = {})
        : code(c)
        , args(std::move(a))
    {}
    DriverMessage(DriverCode c, std::vector<std::string> a, DriverMessage why)
        : code(c)
        , args(std::move(a))
        , detail{std::move(why)}
    {}
    DriverCode code = DriverCode::None;
    std::vector<std::string> args;
    std::vector<DriverMessage> detail; // none or one
    bool empty() const { return code == DriverCode::None; }
    friend bool operator==(const DriverMessage &, const DriverMessage &) = default;
};

// Stable identifier of a code ("HoldToolChange"), for logs and tests.
const char *driverCodeName(DriverCode code);
// English template (%1 ... for the arguments) and the hint on what to do.
const char *driverTemplate(DriverCode code);
const char *driverHint(DriverCode code);
// Every code of the table, in order (tests walk it).
std::vector<DriverCode> allDriverCodes();
// The English text, arguments filled in; "text. hint" when withHint (MachineError::message),
// the text alone otherwise (holdText).
std::string englishText(const DriverMessage &message, bool withHint = false);
// The text in the user's language (QCoreApplication::translate, context "frezka::driver"),
// arguments filled in and translated where they are fixed phrases; with the hint after it when
// withHint.
QString translatedText(const DriverMessage &message, bool withHint = false);
// A fixed driver phrase (an action, a reply, a mode name) in the user's language; anything the
// catalogue does not know comes back unchanged.
QString translatedPhrase(const std::string &phrase);

// Numbers for arguments: no trailing zeros ("10", "12.5").
std::string numberText(double value);

} // namespace frezka::driver
