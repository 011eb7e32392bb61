#pragma once
// An emulated GVE interpolator (GVE84, GVE64, GVE64 PHANTOM, GVE114) as a pure, deterministic
// state machine: bytes from the PC go in with receive(), the bytes the unit sends come out of
// takeTransmit(), and time moves only when the caller calls advance(). See docs/emulator.md
// and docs/gve-protocol.md; the readings it relies on are in readings.h.
//
// Typical use (the planner benchmark, tests):
//     Unit unit({.variant = Variant::Gve64});
//     unit.receive("!0Y-\r");  unit.takeTransmit();      // "0,Y-\r"
//     unit.receive("!0C1000,0,0\r");                      // queued -> "0\r"
//     unit.advance(unit.nextEventIn());                   // event-driven virtual clock

#include "driver/emulator/motion.h"
#include "driver/emulator/safetywatch.h"
#include "driver/emulator/surface.h"
#include "driver/emulator/unitsettings.h"
#include "protocol/variant.h"

#include <array>
#include <cstdint>
#include <memory>
#include <string>
#include <string_view>
#include <vector>

namespace frezka::emulator {

// An input driven by an axis position: a home switch (IN0..IN3 for X..A) or a limit switch.
// The input reads 1 (contact open: a normally closed switch actuated) while the counter of
// `axis` is at or beyond `positionSteps` on `side` (-1: at or below, +1: at or above).
struct PositionSwitch
{
    int input = 0; // 0..15 (IN0..IN7, IN8..IN15)
    int axis = 0;  // 0..3 = X, Y, Z, A
    std::int64_t positionSteps = 0;
    int side = -1;
    bool operator==(const PositionSwitch &) const = default;
};

// An EEPROM value the unit holds from the start, as if a configuration tool had written it.
struct EepromPreset
{
    enum class Kind { Byte, Float, Uint32 };
    int address = 0;
    Kind kind = Kind::Byte;
    double value = 0;
    bool operator==(const EepromPreset &) const = default;
};

struct UnitOptions
{
    protocol::Variant variant = protocol::Variant::Gve64;
    int address = 0; // 0..7; address 7 is the spindle on GVE64/114
    // Whether the unit answers address 7 (its spindle output, GVE64/114). On a line shared by
    // several units (Simulation with more units) only the unit that has the spindle does.
    bool spindleAddress = true;
    int maxPulseRate = 0; // pulses/s; 0 = the variant's default
    std::vector<PositionSwitch> switches{};
    std::string eepromFile{}; // "" = not persisted; else loaded at start, saved on write
    std::vector<EepromPreset> eepromPreset{}; // over the factory contents; a file overrides
    bool trace = false;                       // record TracePoints at every motion event
    // The '?' reply; "" = the variant's. Its version number gates what the unit understands
    // (protocol::featuresOf): an older GVE64 answers 3 (unknown) to VL/VK/VN/XM/N<axis> below
    // v19 and to Y and the EEPROM float/uint32 commands below v10.
    std::string firmware{};
    // The reply code to a command with a wrong checksum; -1 = the adopted reading
    // (readings::kBadChecksumCode, 4). Another code plays a unit that reads the manual
    // otherwise (gve-emu --bad-checksum-code), for the commissioning assistant's tests.
    int badChecksumCode = -1;
    // The machine behind the unit: spin-up, axis maxima, the work, for the safety counters.
    MachineModel machine{};
    // The work's top for probing (surface.h); Kind::None: the probe input only as set.
    ProbeSurface surface{};
    // The board's ANA/PWM jumper (the analog output's kind, unitsettings.h).
    AnalogJumper analogJumper = AnalogJumper::Analog;
    // The COM SPEED switch, 0..3 (sw1 sw2 OFF OFF .. ON ON); with EEPROM 0x0D it sets the
    // unit's line speed at power-on (lineBaud()). -1: not modelled, the unit hears any speed.
    int baudSwitch = -1;
    bool operator==(const UnitOptions &) const = default;
};

struct Stats
{
    MotionStats motion;              // vectors, brake violations, starvation, peak speeds
    std::int64_t commands = 0;       // complete lines addressed to the unit
    std::int64_t checksumErrors = 0; // answered code 4 for a bad checksum
    std::int64_t watchdogs = 0;      // answered code 2
    std::int64_t discardedBytes = 0; // outside any command, cut off by '!', or lost in reset
    std::int64_t interrupts = 0;     // input interrupts accepted
    SafetyStats safety;              // cuts without the spindle, spindle on while held
    bool operator==(const Stats &) const = default;
};

class Unit
{
public:
    explicit Unit(UnitOptions options = {});
    ~Unit();
    Unit(Unit &&) noexcept;
    Unit &operator=(Unit &&) noexcept;

    // Bytes from the PC at the current time. Replies go to the transmit buffer at once, except
    // H and W which reply during a later advance().
    void receive(std::string_view bytesFromPc);
    // Bytes the unit has sent since the last call.
    std::string takeTransmit();
    // Moves the virtual clock by `seconds` (>= 0), event by event. An event at most a few
    // ulps of the clock beyond `seconds` is taken too: advance(nextEventIn()) always takes the
    // event, whatever the rounding of now + seconds.
    void advance(double seconds);
    double now() const;
    // Seconds until the unit's state next changes by itself (motion event, deferred reply,
    // watchdog, end of reset); kNever when it would wait forever.
    double nextEventIn() const;

    Stats stats() const;
    std::array<std::int64_t, 4> position() const;
    double pathSpeed() const;        // pulses/s along the current vector
    std::size_t queueLength() const; // vectors executing or waiting
    bool isMoving() const;
    const std::vector<TracePoint> &trace() const;
    void clearTrace();

    // Inputs as the PC reads them (I1 = bits 0..7, I2 = IN8..IN15 as bits 0..7).
    // setInput sets the level driven from outside (buttons, probe); position switches add to it.
    void setInput(int input, bool level);
    bool input(int input) const;
    void setSwitches(std::vector<PositionSwitch> switches);
    // STOP button (IN7 on GVE64/114) and tool probe (IN15), normally closed: pressed reads 1.
    void setStopButton(bool pressed) { setInput(7, pressed); }
    void setProbe(bool touching) { setInput(15, touching); }

    std::uint8_t outputs() const; // port 0 as written by O0 (active low)
    // The relays as they are switched, port 0's bit layout (active low): O0's bits, except
    // the outputs the unit drives by their EEPROM function (brake: released 0xFD after power-on
    // or J; interrupt signal: on with INTA).
    std::uint8_t relays() const;
    // The analog output: volts (ANA jumper) or PWM duty in percent, per EEPROM 0x04.
    double analogOutput() const;
    // The motors' positions: the counters through the DIR polarity of EEPROM 0x05 and the A
    // slaving of 0x0C. Position switches are placed in these coordinates.
    std::array<std::int64_t, 4> motorPosition() const;
    // The settings the EEPROM gives the unit now (unitsettings.h).
    const UnitSettings &settings() const;
    // Switch off and on: the reset state of §3, the EEPROM kept, 0x0D and 0xFD read again.
    void powerCycle();
    // The line speed the unit listens at (COM SPEED switch and 0x0D at power-on); 0 when the
    // switch is not modelled.
    int lineBaud() const;

    // The simulated MPG handwheel (GVE64/114): the axis switch (0..3 = X, Y, Z, 4th), the step
    // switch (1, 10, 100) and detents turned (signed). Moves only while the MPG is on (Y+/Y&)
    // and enabled in the EEPROM (0x06 and its parameters); returns false when ignored.
    void setWheelAxis(int position);
    void setWheelMultiplier(int multiplier);
    bool turnWheel(int detents);
    int wheelAxis() const;
    int wheelMultiplier() const;
    int spindlePermille() const;      // last !7V value
    bool spindleTurning() const;      // !7V > 0 with OUT0 on (GVE84: its relay, bit0, on)
    std::uint8_t status(int n) const; // ST0..ST6 as SRn would answer
    std::uint8_t eepromByte(int address) const;
    bool checksumsOn() const;
    const UnitOptions &options() const;
    const protocol::VariantInfo &variantInfo() const;
    // Non-empty when the EEPROM file could not be read or written.
    std::string eepromError() const;

private:
    struct Impl;
    std::unique_ptr<Impl> m_impl;
};

} // namespace frezka::emulator
