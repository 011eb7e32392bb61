#pragma once
// What the unit's EEPROM makes it do (docs/gve-protocol.md §12, the manuals' chapters 10-12):
// the bytes and floats decoded into the settings the emulated unit acts on. One function per
// reading, pure, so that the readings where the manuals are unclear live in one place each
// (docs/emulator.md, "EEPROM-driven behaviour", lists them with the manuals' sections).
//
// When the unit reads them: every setting takes effect when it is written (the unit reads its
// EEPROM when it uses a value), except the baud range 0x0D (read with the COM SPEED switch once
// at power-on, GVE114 manual 13.3) and the brake release delay 0xFD (counted from power-on or J).

#include "driver/emulator/eeprom.h"
#include "protocol/variant.h"

#include <array>
#include <cstdint>

namespace frezka::emulator {

// EEPROM output function codes (§12 "Output function codes"; manuals 11.2).
enum class OutputFunction : std::uint8_t {
    Spindle = 0x00, // GVE84 relay: the spindle; GVE64/114: unused
    Laser = 0x01,
    Coolant = 0x02,
    AirBlow = 0x03,
    CoverLock = 0x04,
    ToolRelease = 0x05,
    ToolCoverOpen = 0x06,
    Brake = 0x08,           // released (on) by the unit itself, 0xFD after power-on
    InterruptSignal = 0x09, // on by the unit while an interrupt is accepted (INTA)
};

// What the analog output carries (jumper ANA/PWM on the board, EEPROM 0x04; manuals 10.2, 11.3).
enum class AnalogJumper { Analog, Pwm };

struct MpgSettings
{
    bool enabled = false;    // 0x06 = 01/02/81/82 and every parameter in range (12.4-12.7)
    bool withLimits = false; // 02/82: the wheel stops at the lower/upper limits
    bool fourthIsA = false;  // 81/82 (GVE114): the 4th switch position drives A, else the spindle
    std::array<double, 4> lowerMm{}, upperMm{}, stepsPerMm{};
    double accelMmPerS2 = 0;
    double maxSpeedMmPerS = 0;
    double delayS = 0;    // 0x48: after the wheel stops, brake even if steps remain
    double stepMm = 0.01; // the x1 detent (GVE114 0x60: 0.01 mm x multiplier)
};

struct UnitSettings
{
    // OUT1..OUT3 (0x01..0x03); GVE84: [0] is its one relay.
    std::array<OutputFunction, 3> outputFunction{};
    bool pwmBreakout = false; // 0x04 = 01: the breakout-board signal
    // 0x05 decoded: per axis, does the DIR signal run the motor against the counter?
    std::array<bool, 4> dirReversed{};
    std::array<bool, 4> stepRisingEdge{};
    MpgSettings mpg;
    int homingInput = -1; // 0x07: 3..7, else -1 (off)
    // 0x08..0x0B as ST0..ST3 (IN14/IN15 in bits 6/7 of the high bytes).
    std::uint8_t interruptEnable = 0, interruptEnableHigh = 0, polarity = 0, polarityHigh = 0;
    int aSlavedTo = -1;            // 0x0C: 0..2 = X..Z, else -1 (independent)
    bool highBaudRange = false;    // 0x0D = 01 (GVE114)
    double brakeReleaseDelayS = 0; // 0xFD x 0.1 s, at most 5 s
    // GVE64: homing speed toward the switch X/Y/Z, mm/s (0x50/54/58; 0 = input homing off).
    std::array<double, 3> homingSpeedMmPerS{};
};

// The settings of `eeprom` for a unit of `variant` whose pulse rate is `maxPulseRate`.
UnitSettings decodeSettings(const Eeprom &eeprom, protocol::Variant variant, int maxPulseRate);

// The line speed selected by the COM SPEED switch (0..3: sw1 sw2 = OFF OFF .. ON ON) in the
// range of 0x0D (GVE114 manual 10.1; other variants: the low range only).
int switchBaud(int switchPosition, bool highRange);
// The switch position that gives `baud` in the low range, else in the high one; -1 for none.
int switchPositionFor(int baud);

// The analog output for a spindle command of `permille` (0..1000): volts on the ANA jumper,
// duty in percent on the PWM jumper. Adopted reading of 11.3 (the manuals name the breakout
// signal but do not describe it): the breakout-board signal is the inverted duty (the LPT
// breakout boards' opto inputs are active low), so on the ANA jumper it gives 10 V - v, the
// manual's "the analog output will not work correctly" unless 0x04 = FF.
double analogOutput(int permille, AnalogJumper jumper, bool breakout);

} // namespace frezka::emulator
