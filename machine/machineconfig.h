#pragma once
// Machine configuration: everything Frezka knows about one machine and its GVE unit.
//
// Stored as a human-editable JSON profile (docs/machine-profile.md lists every key, its unit,
// range and default). Loading validates the whole profile and reports every problem with the key
// it concerns, the allowed range and what to do; a key missing from the file takes its default,
// a key the profile does not know is an error (a typo must not silently fall back to a default).
//
// Units: lengths mm (the A axis: degrees), speeds mm/min for feeds and axis limits, mm/s for
// homing, jumps and the MPG, accelerations mm/s², times ms.

#include "protocol/variant.h"

#include <array>
#include <cstdint>
#include <optional>
#include <string>
#include <vector>

namespace frezka::machine {

enum class Axis : std::uint8_t { X, Y, Z, A };
inline constexpr int kAxisCount = 4;
inline constexpr std::array<char, 4> kAxisLetters{'X', 'Y', 'Z', 'A'};

struct HomingConfig
{
    int order = 0;             // 0 = not homed; 1 = first, 2 = second, ... (equal = together)
    int direction = -1;        // -1 switch toward negative, +1 toward positive
    double travelMm = 500;     // max travel searching the switch
    double towardMmPerS = 10;  // speed toward the switch
    double offMmPerS = 1;      // speed backing off the switch
    double backOffMm = 10;     // max travel backing off the switch
    double homePositionMm = 0; // machine position set when homing has finished
    friend bool operator==(const HomingConfig &, const HomingConfig &) = default;
};

struct AxisConfig
{
    bool present = true;
    double stepsPerMm = 200;      // steps per mm (A: per degree), 1..10 000
    bool invertDirection = false; // DIR polarity (written to EEPROM 0x05)
    double softMinMm = 0;         // soft limits, machine coordinates
    double softMaxMm = 300;
    double maxSpeedMmPerMin = 3000; // never exceeded by any move
    double rapidMmPerMin = 3000;    // G0 speed (<= maxSpeedMmPerMin)
    double accelMmPerS2 = 300;
    double maxJumpMmPerS = 4; // largest instantaneous speed step at a vertex
    HomingConfig homing;
    friend bool operator==(const AxisConfig &, const AxisConfig &) = default;
};

struct UnitConfig
{
    protocol::Variant variant = protocol::Variant::Gve64;
    int maxPulseRate = 50000; // pulses/s, one of the variant's orderable rates
    int firmwareVersion = 19; // features: MPG v10+, EEPROM float v10+, VL/VK/XM v19+ (GVE64)
    // The machine's START button: 3..7 = that input (GVE64 IN3, GVE114 IN6) starts a loaded,
    // checked program or resumes a held one; 0 = the machine has none. Active at the level of
    // its bit in eeprom.polarity (0 = active low, the button grounds the input).
    int startInput = 0;
    // The unit's address on the line, 0..6: fixed when the unit is ordered (GVE114 manual
    // §13.3, §13.6); other than 0 for a unit that shares its line with others (GVE114 only).
    int address = 0;
    friend bool operator==(const UnitConfig &, const UnitConfig &) = default;
};

struct LinkConfig
{
    std::string port = "emulator"; // "/dev/ttyUSB0", a pty path, or "emulator" (in-process)
    int baud = 115200;
    bool checksums = true;
    bool packets = true;  // the driver fills each packet up to the unit's byte limit
    double latencyMs = 8; // one way, of the serial adapter (USB converters: 1-16 ms), 0..100
    friend bool operator==(const LinkConfig &, const LinkConfig &) = default;
};

enum class SpeedModeChoice : std::uint8_t { Auto, Vk, Vn };

struct MotionConfig
{
    double junctionDeviationMm = 0.01; // corner rounding allowed at a vertex (0 = exact stop)
    double chordToleranceMm = 0.002;   // max sagitta when arcs are chorded
    int pauseMs = 10;                  // T: pause between non-continuous moves, 1..24
    SpeedModeChoice speedMode = SpeedModeChoice::Auto; // Auto: VK when it is exact, else VN
    double toolLiftMm = 5; // lift of Z for a manual stop (driver), 0 = none
    // false: a run before the machine is homed asks for homing first; true: it runs, with a
    // warning (machine/softlimits.h).
    bool runBeforeHoming = false;
    friend bool operator==(const MotionConfig &, const MotionConfig &) = default;
};

struct SpindleConfig
{
    double maxRpm = 24000; // rpm at 1000 ‰ (10 V / 100 % PWM)
    int spinUpMs = 2000;   // wait after start / speed change before cutting
    // Whether the driver switches the spindle and coolant off when a job holds at M0 / M1 and at
    // M6 (on again, with the spin-up, before it continues). Issue 14.
    bool stopAtProgramStop = true;
    bool stopAtToolChange = true;
    friend bool operator==(const SpindleConfig &, const SpindleConfig &) = default;
};

// A fixed tool-length sensor (issue 19 item 1; docs/probing.md "Tool length"): the tool goes up
// to clearanceZMm, across to (xMm, yMm), probes down at feedMmPerMin (at most travelMm below
// the clearance), backs off by retractMm, probes again at slowFeedMmPerMin and goes back up to
// the clearance. The tool's length is the slow trip's machine Z minus referenceZMm, the Z at
// which the reference tool (length 0; the one the work zero was set with, or a gauge) trips.
// Machine coordinates throughout; the probe input is the one G38.2 reads.
struct ToolSensorConfig
{
    bool enabled = false;
    double xMm = 0, yMm = 0;
    double clearanceZMm = 0;
    double travelMm = 50;
    double feedMmPerMin = 200;
    double slowFeedMmPerMin = 25;
    double retractMm = 2;
    double referenceZMm = 0;
    friend bool operator==(const ToolSensorConfig &, const ToolSensorConfig &) = default;
};

struct ToolsConfig
{
    // The tool table (LinuxCNC's .tbl format, lengths in mm, gcode/tooltable.h): a path, relative
    // to the profile's folder (like LinuxCNC's TOOL_TABLE beside the INI file). Empty: no table
    // (every tool number accepted with length 0, as before tool tables).
    std::string tableFile = "tool.tbl";
    ToolSensorConfig sensor;
    friend bool operator==(const ToolsConfig &, const ToolsConfig &) = default;
};

// Bounds on a program that never ends (an o-word loop or a recursion without an exit): when
// the check has executed this many lines, or made this many toolpath entries (moves, dwells,
// events; about 50 bytes each), it stops with the loop's line named (gcode::Options::maxBlocks
// and maxMoves, the same defaults). A 5 M-line program stays well inside them, and the check of
// a program stopped at the default entries stays under 800 MB of memory.
struct ProgramConfig
{
    int maxLinesExecuted = 50'000'000;
    int maxMoves = 10'000'000;
    // Folders searched for subroutine files (o<name> call of name.ngc) after the program's own
    // folder, separated by ':' as LinuxCNC's [RS274NGC]SUBROUTINE_PATH; relative ones from the
    // profile's folder. Empty: the program's folder only.
    std::string subroutinePath;
    friend bool operator==(const ProgramConfig &, const ProgramConfig &) = default;
};

// Functions of the unit's outputs, EEPROM codes of docs/gve-protocol.md §12.
enum class OutputFunction : std::uint8_t {
    Unused = 0x10,
    Spindle = 0x00, // GVE84 relay only
    Laser = 0x01,
    Coolant = 0x02,
    AirBlow = 0x03,
    CoverLock = 0x04,
    ToolRelease = 0x05,
    ToolCoverOpen = 0x06,
    Brake = 0x08,
    Interrupt = 0x09,
};

struct OutputConfig
{
    // out[0] = OUT1 (GVE84: the relay), out[1] = OUT2, out[2] = OUT3 (GVE64/GVE114).
    std::array<OutputFunction, 3> out{OutputFunction::Coolant, OutputFunction::AirBlow,
                                      OutputFunction::Brake};
    OutputFunction mist = OutputFunction::AirBlow; // what M7 switches (M8 switches Coolant)
    friend bool operator==(const OutputConfig &, const OutputConfig &) = default;
};

enum class MpgMode : std::uint8_t { Off, On, OnWithLimits, OnRotaryA, OnRotaryAWithLimits };

// The STEP edge the motor drivers act on (EEPROM 0x05). UnitDefault leaves the unit's factory
// bits (FF): the falling edge on a GVE84/GVE64 (a PHANTOM's is fixed there), the rising edge on
// a GVE114 (docs/gve-protocol.md §12, adopted reading).
enum class StepEdge : std::uint8_t { UnitDefault, Falling, Rising };

// Unit EEPROM settings Frezka keeps in sync (docs/gve-protocol.md §12). Limits, steps per mm,
// DIR polarity and homing speeds come from the axes.
struct EepromConfig
{
    bool sync = true; // compare on connect and offer to write differences
    MpgMode mpg = MpgMode::On;
    double mpgAccelMmPerS2 = 200;
    double mpgMaxSpeedMmPerS = 20;
    int mpgDelayMs = 200;
    double mpgStepMultiplier = 1;            // GVE114 only
    int homingInput = 0;                     // 3..7 = that input starts homing, 0 = off
    std::uint8_t interruptEnable = 0x00;     // IN0-7, 1 = enabled
    std::uint8_t interruptEnableHigh = 0x00; // IN14 (bit6), IN15 (bit7)
    std::uint8_t polarity = 0x00;            // IN0-7, 0 = active low
    std::uint8_t polarityHigh = 0x00;        // IN14/IN15
    int aSlavedTo = 0;                       // 0 independent, 1 X, 2 Y, 3 Z
    bool pwmBreakout = false;                // 0x04: breakout-board signal instead of standard PWM
    StepEdge stepEdge = StepEdge::UnitDefault; // the STEP edge the drivers act on
    int defaultSpindlePermille = 500;
    double brakeReleaseDelayS = 1.0; // 0xFD, 0..5 s
    friend bool operator==(const EepromConfig &, const EepromConfig &) = default;
};

// A unit on the profile's serial line (key line.units; GVE114 manual §9.5, §13.6: several
// units on one RS232 line through the EXT branch cable, each at its own address).
enum class LineUnitRole : std::uint8_t {
    Machine,   // the unit of this profile's machine (exactly one per list)
    Auxiliary, // another machine or device on the line, described by its own profile
    RotaryA,   // a rotary table driving the program's A axis (reserved for that case)
};

struct LineUnitConfig
{
    int address = 0; // 0..6 (7 is the spindle's), distinct on the line
    protocol::Variant variant = protocol::Variant::Gve114;
    std::string name; // shown to the operator, not empty
    LineUnitRole role = LineUnitRole::Auxiliary;
    // Auxiliary (required) and RotaryA (optional): the unit's own profile, relative to the
    // folder of this profile (an absolute path as it is). Machine: empty (this profile).
    std::string profile;
    friend bool operator==(const LineUnitConfig &, const LineUnitConfig &) = default;
};

struct LineConfig
{
    // Empty: one unit on the line, at unit.address (as a profile without the key).
    std::vector<LineUnitConfig> units;
    friend bool operator==(const LineConfig &, const LineConfig &) = default;
};

struct MachineConfig
{
    std::string name = "GVE64 mill";
    UnitConfig unit;
    LinkConfig link;
    std::array<AxisConfig, 4> axes{};
    MotionConfig motion;
    SpindleConfig spindle;
    OutputConfig outputs;
    EepromConfig eeprom;
    ToolsConfig tools;
    ProgramConfig program;
    LineConfig line;

    const AxisConfig &axis(Axis a) const { return axes[static_cast<std::size_t>(a)]; }
    AxisConfig &axis(Axis a) { return axes[static_cast<std::size_t>(a)]; }
    friend bool operator==(const MachineConfig &, const MachineConfig &) = default;
};

enum class ConfigErrorCode : std::uint8_t {
    FileUnreadable, // the file could not be opened / written
    Syntax,         // not valid JSON (line, column)
    WrongType,      // e.g. a string where a number belongs
    UnknownKey,     // a key the profile does not know (typo?)
    OutOfRange,     // a number outside its range
    BadChoice,      // a string that is none of the allowed names
    Inconsistent,   // keys that contradict each other or the unit variant
    Retired,        // a key of an older profile, read into its successor or ignored (a note)
};

struct ConfigError
{
    ConfigErrorCode code = ConfigErrorCode::Syntax;
    std::string key;     // dotted path, "axes.x.stepsPerMm"; empty for the whole file
    std::string message; // English, complete: what is wrong, the range, what to do
    friend bool operator==(const ConfigError &, const ConfigError &) = default;
};

struct ConfigResult
{
    std::optional<MachineConfig> config; // set only when errors is empty
    std::vector<ConfigError> errors;
    std::vector<ConfigError> notes; // retired keys: what became of each (not errors)
};

// Parses and validates a profile (JSON text). Collects every error, not only the first.
ConfigResult parseMachineConfig(const std::string &json);
// Reads and parses a profile file.
ConfigResult loadMachineConfig(const std::string &path);
// Checks a config built in code (the same rules the loader applies). Empty = valid.
std::vector<ConfigError> validateMachineConfig(const MachineConfig &config);
// The profile as indented JSON text with every key (parseMachineConfig(toJson(c)) == c).
std::string toJson(const MachineConfig &config);
// Writes toJson(config) to path; returns an error (code FileUnreadable) on failure.
std::optional<ConfigError> saveMachineConfig(const MachineConfig &config, const std::string &path);

// Built-in defaults for a variant, identical to the shipped profiles in resources/machines/.
MachineConfig defaultMachineConfig(protocol::Variant variant);

// The tool table file of a profile read from profilePath: tools.tableFile resolved against the
// profile's folder (an absolute path as it is); empty when the profile names none. A profile
// that was never saved (empty profilePath) resolves against the current directory.
std::string toolTablePath(const MachineConfig &config, const std::string &profilePath);
// The folders of program.subroutinePath, absolute (relative ones from the profile's folder).
std::vector<std::string> subroutineFolders(const MachineConfig &config,
                                           const std::string &profilePath);

// The profiles of every unit on the line of `config` (read from profilePath), in the order of
// line.units; one entry, `config` itself, when the profile lists no units. The machine's entry
// is `config`; an auxiliary unit's is its own profile (relative to profilePath's folder) with
// unit.address set to its entry's address; a rotary table without a profile gets the default
// GVE114 profile at its address. `errors` names every profile that cannot be read or does not
// fit its entry (its variant), each with what to do; configs is then empty.
struct LineProfiles
{
    std::vector<MachineConfig> configs;
    std::vector<ConfigError> errors;
};
LineProfiles loadLineProfiles(const MachineConfig &config, const std::string &profilePath);
// The index of the machine's entry in line.units (0 when the list is empty).
int machineUnitIndex(const MachineConfig &config);

// Number of interpolated axes the unit's L/C commands carry (3 or 4).
int wireAxisCount(const MachineConfig &config);

// ---- Outputs (docs/gve-protocol.md §10: port 0, active low) ----
// Bit of port 0 that drives the output carrying the function; 0 when no output carries it.
std::uint8_t outputBit(const MachineConfig &config, OutputFunction function);
// The output OUTn (its number n) that carries the function: outputs.out1..out3 are OUT1..OUT3,
// a GVE84's relay (outputs.out1) is OUT0; -1 when no output carries it.
int outputNumber(const MachineConfig &config, OutputFunction function);
// Bit of port 0 that drives output OUTn of the variant (bit0 OUT0, bit1 OUT3, bit2 OUT1, bit3
// OUT2; a GVE84 has only OUT0, its relay); 0 for an output the unit does not have.
std::uint8_t outputPortBit(protocol::Variant variant, int output);
inline constexpr std::uint8_t kSpindleOutputBit = 0x01; // OUT0 (GVE64/114, driven by !7V too)

// ---- EEPROM (docs/gve-protocol.md §12) ----
enum class EepromKind : std::uint8_t { Byte, Float, Uint32 };
struct EepromEntry
{
    std::uint8_t address = 0;
    EepromKind kind = EepromKind::Byte;
    double value = 0; // byte / float / uint32 value
    std::string what; // "steps per mm X", for a mismatch report
    friend bool operator==(const EepromEntry &, const EepromEntry &) = default;
};
// The EEPROM settings this config asks of the unit, in address order (variant-specific).
std::vector<EepromEntry> eepromEntries(const MachineConfig &config);

} // namespace frezka::machine
