#pragma once
// Private state of Unit, shared by unit.cpp (framing, replies, clock, inputs) and
// unit_commands.cpp (the command set). Not part of the public API.

#include "driver/emulator/eeprom.h"
#include "driver/emulator/motion.h"
#include "driver/emulator/readings.h"
#include "driver/emulator/safetywatch.h"
#include "driver/emulator/unit.h"

#include <optional>
#include <string>
#include <vector>

namespace frezka::emulator {

using Reply = readings::ReplyParts;

struct Unit::Impl
{
    explicit Impl(UnitOptions opts);

    // ---- configuration
    UnitOptions options;
    const protocol::VariantInfo *info;
    std::string firmware;        // the '?' reply
    protocol::Features features; // what this firmware understands
    int maxRate;

    // ---- link
    enum class Rx { Idle, InLine, AfterCr };
    Rx rx = Rx::Idle;
    std::string line; // bytes after '!' of the line being received
    bool lineOverlong = false;
    double lineStart = 0; // time of the '!' of the current line
    std::string backlog;  // bytes received while a deferred reply is pending
    std::string tx;
    bool checksums = false;
    int index = 0;         // @: index of the last command, mod 256
    std::string lastReply; // bytes of the last reply, for '>'
    double deafUntil = -1; // after J
    enum class Deferred { None, Halt, Homing };
    Deferred deferred = Deferred::None;
    // packet being collected between *S and *E
    struct PacketLine
    {
        std::string body;
        int failCode = 0; // bad checksum etc. found on reception
    };
    bool packetOpen = false;
    std::vector<PacketLine> packet;
    double packetLastLine = 0;

    // ---- machine state
    MotionEngine engine;
    Eeprom eeprom;
    std::string eepromError;
    int accelK = 20;                       // A, thousands of pulses/s^2
    int speed = 1000;                      // V
    int brake = 35000;                     // B
    std::int64_t shortSteps = 512;         // $
    int pauseMs = readings::kResetPauseMs; // T
    bool velocityCorrection = readings::kResetModeIsVk;
    SpeedLimits limits;
    std::uint8_t st[6] = {}; // ST0..ST5
    bool inta = false, intcom = false, stopBit = false, freeBit = false;
    enum class Mpg { Off, Reporting, Silent };
    Mpg mpg = Mpg::Off;
    std::uint8_t outputs = 0xFF;
    int spindle = 0;
    bool kept = false;
    MotionEngine::Saved keptQueue;
    std::uint8_t keptSt[3] = {};
    bool keptInta = false, keptIntcom = false;
    std::uint64_t serial = 0;
    // inputs
    std::uint16_t manualInputs = 0;
    std::uint16_t prevActive = 0;
    std::vector<PositionSwitch> switches;
    // homing (W)
    struct Homing
    {
        int axis = 0;
        std::int64_t seekSteps = 0, backSteps = 0;
        int seekRate = 0, backRate = 0;
        bool backingOff = false;
        bool fromInput = false; // started by the EEPROM 0x07 input: no reply, counter set
    };
    std::optional<Homing> homing;
    Stats stats;
    SafetyWatch safety;
    // EEPROM-driven behaviour (unit_eeprom.cpp, unit_mpg.cpp)
    UnitSettings cfg;                      // decoded at start and after every EEPROM write
    std::array<int, 4> wiring{1, 1, 1, 1}; // DIR sign of the EEPROM at start (see axisSign)
    bool highBaudRange = false;            // 0x0D as read at power-on
    double brakeReleaseAt = 0;             // power-on or J + 0xFD
    struct Wheel
    {
        int axis = 0;       // axis switch: 0..3 = X, Y, Z, 4th
        int multiplier = 1; // step switch
        double lastTurnAt = -1;
        bool moving = false; // the queue holds wheel moves
        std::array<std::int64_t, 4> target{};
    };
    Wheel wheel;
    double homingInputSince = -1; // the 0x07 input active (and homing armed) since
    bool homingInputUsed = false; // this press has started homing: release it first

    // ---- unit.cpp
    void resetState(bool powerOn);
    void feed(char c);
    void lineComplete();
    void handleLine(int address, std::string_view body);
    // Address 7 is this unit's: the variant has it and the unit has the line's spindle.
    bool answersSpindle() const { return info->hasSpindleAddress7 && options.spindleAddress; }
    void sendReply(const Reply &r);
    std::string formatReply(const Reply &r) const;
    void advanceBy(double seconds);
    double nextEventIn() const;
    double watchdogAt() const;
    void fireWatchdog();
    void processBacklog();
    std::uint16_t inputLevels() const;
    void checkInterrupts();
    void updateWatches();
    void onStopped();
    std::uint8_t st6() const;
    bool runBit() const;
    bool spindleTurning() const;
    void noteSpindle();   // the spindle's state after !7V, O0 or J, for the safety counters
    void observeSafety(); // at every event: the job held while the machine stands?

    // ---- unit_eeprom.cpp (unit_mpg.cpp, unit_homing.cpp)
    static constexpr double kHomingInputHoldS = 1.0; // "déle než 1 s" (GVE64 manual 12.3)
    void settingsChanged();                          // after an EEPROM write (and at start)
    void latchPowerOn();                             // 0x0D and 0xFD, at power-on and J
    std::uint8_t relayPort() const;
    std::array<std::int64_t, 4> counters() const; // as P4 reports them (A slaving)
    std::array<std::int64_t, 4> motorPosition() const;
    // The motor's direction against the counter: the DIR bit now against the one the machine
    // was wired for (the EEPROM the unit started with).
    int axisSign(int axis) const { return (cfg.dirReversed[axis] ? -1 : 1) * wiring[axis]; }
    bool mpgOn() const { return mpg != Mpg::Off; }
    std::uint16_t interruptMask(bool polarity) const;
    // ---- unit_mpg.cpp
    bool turnWheel(int detents);
    double wheelEventAt() const; // the MPG delay, the 1 s of the homing input
    void checkWheel();
    // ---- unit_homing.cpp
    bool homeSwitchPressed() const;
    void checkHoming();
    void finishHoming(int code);
    bool inputHomingArmed() const;
    void checkInputHoming(std::uint16_t active);
    void startInputHoming();

    // ---- unit_commands.cpp
    Reply execute(int address, std::string_view body);
    std::optional<Reply> executeLink(std::string_view body);
    Reply executeSpindle(std::string_view body);
    Reply executePacket(int declaredCount);
    Reply cmdVector(char kind, std::string_view args);
    Reply cmdSpeeds(std::string_view mnemonic, std::string_view args);
    Reply cmdExchange(std::string_view args);
    Reply cmdPosition(std::string_view body);
    Reply cmdNull(std::string_view args);
    Reply cmdHoming(std::string_view args);
    Reply cmdQueue(char c);
    Reply cmdEeprom(std::string_view body);
    Reply cmdStatus(std::string_view body);
    Reply cmdIo(std::string_view body);
    Reply cmdMpg(std::string_view body);
    bool hasFourAxes() const { return info->axisCount == 4; }
};

} // namespace frezka::emulator
