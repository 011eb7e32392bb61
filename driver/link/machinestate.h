#pragma once
// MachineState: the snapshot of the machine the driver publishes (GUI, CLI, tests).
//
// A plain value (std types only, operator==): the link thread owns the live state and sends a
// copy whenever something changed; nobody else keeps machine state. Positions come in steps (the
// unit's counters) and in mm (steps / steps-per-mm of the profile; A in degrees).

#include "driver/link/drivererror.h"
#include "driver/link/linkengine.h"
#include "machine/machineconfig.h"
#include "protocol/variant.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace frezka::driver {

// The feed override's range, percent (XM): the GUI's slider and the ± steps stay within it.
inline constexpr int kOverrideMinPercent = 10;
inline constexpr int kOverrideMaxPercent = 200;
// The spindle override's range, percent (issue 16 item 5): every !7V the driver sends is scaled.
inline constexpr int kSpindleOverrideMinPercent = 50;
inline constexpr int kSpindleOverrideMaxPercent = 150;
// The !7V value (per mille of the profile's maximum speed) for a speed asked at a spindle
// override: scaled, at most 1000 (the maximum), and a spindle asked to turn never stopped by
// the rounding.
int spindlePermilleAt(int askedPermille, int overridePercent);

// The operations state machine (issue 5 item 4). Exactly one at a time.
enum class MachineMode : std::uint8_t {
    Disconnected, // no port open
    Connecting,   // identify, checksums, setup (connect sequence)
    Idle,         // connected, nothing running
    Homing,       // W per axis in the configured order
    Jogging,      // a jog move runs (continuous or incremental)
    Running,      // a job is streaming / executing
    Stopping,     // H sent, the machine brakes along its ramp
    Paused,       // job held (user pause, interrupt, M0/M1/M6); resume or abort
    ToolLifted,   // job held, queue kept (K), tool lifted; lower to continue
    Alarm,        // the unit refused something or an input fired outside a job: needs the user
    LinkLost,     // port error / no reply; job progress kept for resuming after reconnecting
};

// English name ("Running"); the GUI maps modes to translated strings.
const char *machineModeName(MachineMode mode);

// The one activity of the core (issue 13): which of its parts drives the wire now. The mode says
// what the machine does as the operator sees it; the activity says which part of the driver is
// in charge, so that every transition of the core is observable (tests, logs).
enum class MachineActivity : std::uint8_t {
    None,             // disconnected, or connected with nothing in progress
    Connecting,       // the connect sequence (a job kept over a link loss waits meanwhile)
    Homing,           // W per axis, the counters set
    Jogging,          // a jog move
    Job,              // a job streams, waits for the machine (I/O, M0, dwell) or is held
    CheckingProgress, // the job's progress is re-established from the unit's counters
    Probing,          // the job waits for, runs and evaluates a G38 probe move
    PathFault,        // the job left the planned path: stopping, then held for the operator
    ReturnToPath,     // the job goes back to the last verified point of its path
    ToolLift,         // the job is held with its queue kept (K): lifting, lifted, lowering
};

// English name ("Return to path"), for logs and tests.
const char *machineActivityName(MachineActivity activity);

// A setting whose EEPROM value in the unit differs from the profile's: the entry (address, kind,
// the profile's value, its English name) and the unit's value.
struct EepromDifference
{
    machine::EepromEntry entry;
    double unitValue = 0;
    // The English line for the log: "steps per mm X: unit 200, profile 400"; bytes in hex as the
    // unit shows them: "polarity: unit 00, profile 5A".
    std::string text() const;
    friend bool operator==(const EepromDifference &, const EepromDifference &) = default;
};

struct MachineState;
// The unit accepted `c`: the spindle and port 0 as it drives them now (docs/gve-protocol.md §9:
// !7V0 also switches OUT0 off, !7V1..1000 on; a GVE84 switches its spindle with the profile's
// relay on port 0). Other commands change nothing. True when something changed.
bool noteOutputsAccepted(MachineState &state, const protocol::Command &c,
                         const machine::MachineConfig &config);

// Why a job is held (mode Paused / ToolLifted).
enum class HoldReason : std::uint8_t {
    None,
    User,         // pause()
    Interrupt,    // an enabled input fired (STOP button, limit, ...): see interruptInputs
    OperatorStop, // M0 / M1 / M6 in the program: see holdMessage and holdLine
    ProbeFailed,  // G38.2 / G38.4 ended without the expected contact change
    PathFault,    // the unit's position left the planned path (a command damaged on the line
                  // in a way its checksum cannot show): resume returns to the last verified
                  // point of the path and runs on from there
};

// The last error, with the command and the unit's reply (or what came back instead). The
// front ends word it from `reason` (a code with its arguments, drivererror.h) in the user's
// language; `message` is the same in English for logs.
struct MachineError
{
    std::string message; // English, complete: englishText(reason)
    std::string command; // the command text, e.g. "!0C697,30,0", empty when not command-related
    std::string reply;   // the raw reply line, empty when none came
    int unitCode = -1;   // the unit's error code 0..7 when it replied, else -1
    DriverMessage reason;
    friend bool operator==(const MachineError &, const MachineError &) = default;
};

// The position the front ends show: the polled counters, or, between the polls of a running
// job, the driver's model of the unit along the plan (LiveModel, issue 16 item 3). Only for
// showing: the path guard, the tracker and the ETA read the polled counters alone.
struct LivePosition
{
    bool modelled = false; // false: the polled counters
    std::array<std::int64_t, 4> steps{};
    std::array<double, 4> mm{};
    std::uint32_t sourceLine = 0; // the G-code line of the modelled command (0: none)
    std::int64_t command = -1;    // the program command modelled: always < commandsAcked
    double atS = 0;               // the driver's time of the figure
    friend bool operator==(const LivePosition &, const LivePosition &) = default;
};

struct MachineState
{
    MachineMode mode = MachineMode::Disconnected;
    HoldReason hold = HoldReason::None;
    std::string holdText;       // English: englishText(holdMessage), for logs and the CLI
    DriverMessage holdMessage;  // why it holds, with its arguments (line, tool, inputs ...)
    std::uint32_t holdLine = 0; // the program line the hold belongs to (M0/M6: its own line)
    MachineActivity activity = MachineActivity::None;

    // unit
    protocol::Variant variant = protocol::Variant::Gve64;
    std::string firmware;        // reply to '?'
    int firmwareVersion = 0;     // its version number, 0 when it has none
    protocol::Features features; // what the unit understands, by variant and firmware version
    std::string unitId;          // reply to 'Q'
    bool checksums = false;
    int axisCount = 3;
    std::vector<EepromDifference> eepromDifferences; // found on connecting (EepromSync)

    // position (instantaneous counters, polled)
    std::array<std::int64_t, 4> positionSteps{};
    std::array<double, 4> positionMm{};
    LivePosition live;          // what to show: these counters, or the model's between polls
    bool homed = false;         // every axis the profile homes has been homed
    std::uint8_t homedAxes = 0; // bit a: axis a (X=0 .. A=3) homed since connecting

    // status (F / ST6): RUN, INTA, queue full
    std::uint8_t flags = 0;
    bool run = false;
    bool inta = false;
    bool queueFull = false;
    std::uint8_t inputs1 = 0;          // I1: IN0..IN7
    std::uint8_t inputs2 = 0;          // I2: bit6 IN14, bit7 IN15
    std::uint16_t interruptInputs = 0; // ST4 | ST5 << 8 of the last interrupt
    // Outputs as the unit drives them: every accepted !7V and O0 (the job's, the buttons', the
    // console's, the holds'); the unit has no command that reads port 0 back (issue 14).
    std::uint8_t outputs = 0xFF; // port 0 (active low): bit0 OUT0, bit1 OUT3, bit2 OUT1, bit3 OUT2
    int spindlePermille = 0;     // last !7V (GVE84: as the buttons asked for it)
    double spindleRpm = 0;
    int spindleAskedPermille = 0;     // the speed asked (the program's S, the buttons'), ‰
    int spindleOverridePercent = 100; // the operator's spindle override: every !7V is scaled
    bool spindleOn = false;    // the spindle turns: !7V > 0 with OUT0 on, or the GVE84's relay on
    bool outputsHeld = false;  // a hold switched the spindle / coolant off: they go on again first
    int overridePercent = 100; // the operator's feed override (XM asked for)
    int overrideSentPercent = 100; // the last XM sent to the unit (JobOverride, the connect)
    // The override the unit runs where it is below the operator's: while a job streams, what the
    // link can feed (JobOverride; issue 14 item 5); 0 = the operator's.
    int overrideHeldPercent() const
    {
        return overrideSentPercent < overridePercent ? overrideSentPercent : 0;
    }
    bool mpgOn = false;

    // job
    bool jobActive = false;
    std::uint32_t sourceLine = 0;   // G-code line of the vector executing now (0 = none)
    std::int64_t commandsTotal = 0; // commands in the unit program
    std::int64_t commandsAcked = 0; // accepted by the unit
    std::int64_t vectorsAcked = 0;
    double progress = 0; // 0..1 by commands executed
    double etaS = -1;    // estimated seconds left, -1 unknown

    // link
    LinkStats link;
    double pollHz = 0; // achieved position/status poll rate over the last second

    // last G38 probe move: whether the probe tripped, and the counters where the move ended
    bool probeTripped = false;
    std::array<std::int64_t, 4> probeSteps{};

    std::optional<MachineError> lastError;

    // Logical inputs and outputs, decoded from the unit's ports here so that the front ends
    // never read port bits (issue 13 item 3).
    // Bit n: input INn (n = 0..7, 14, 15) at its high level as the unit last read it (I1, I2).
    std::uint16_t inputLevels() const;
    // Whether input INn is in its active state: its level against the profile's polarity
    // (eeprom.polarity for IN0..7, polarityHigh for IN14 and IN15).
    bool inputActive(const machine::MachineConfig &config, int n) const;
    // Bit n: output OUTn (n = 0..3) on. Port 0 is active low (bit0 OUT0, bit1 OUT3, bit2 OUT1,
    // bit3 OUT2); OUT0 is on while the spindle turns too (!7V1..1000 switches it in the unit,
    // docs/gve-protocol.md §9).
    std::uint8_t outputsOn() const;
    // Whether input INn is at its high level (n = 0..7, 14, 15).
    bool inputHigh(int n) const { return n >= 0 && n < 16 && ((inputLevels() >> n) & 1) != 0; }
    // Whether output OUTn (n = 0..3) is on.
    bool outputIsOn(int n) const { return n >= 0 && n < 4 && ((outputsOn() >> n) & 1) != 0; }
    // The position to show, mm: the model's between polls of a running job, else the counters'.
    const std::array<double, 4> &shownMm() const { return live.modelled ? live.mm : positionMm; }
    // Whether axis a (X = 0 .. A = 3) has been homed since connecting.
    bool axisHomed(int axis) const
    {
        return axis >= 0 && axis < 4 && ((homedAxes >> axis) & 1) != 0;
    }
    // Whether the output that carries `function` in `config` is on (false when none carries it).
    bool outputOn(const machine::MachineConfig &config, machine::OutputFunction function) const;

    friend bool operator==(const MachineState &, const MachineState &) = default;
};

} // namespace frezka::driver
