#pragma once
// The emulator's readings of the GVE protocol, one place each.
//
// Part 1 are the "Adopted readings" of docs/gve-protocol.md (binding for the emulator and the
// driver). Part 2 are choices the emulator has to make where both the manuals and the reference
// are silent; they are marked "emulator choice" and listed in docs/emulator.md so the reference
// can adopt or change them. Each is used from exactly one place in the emulator; tests in
// tests/driver/emulator/readings_test.cpp pin every one of them.

#include "protocol/lines.h"
#include "protocol/variant.h"

#include <array>
#include <cstdint>
#include <string>
#include <string_view>

namespace frezka::emulator::readings {

// ---- Part 1: adopted readings of docs/gve-protocol.md ------------------------------------------

// §2: the unit ignores a LF that follows CR.
inline constexpr bool kIgnoreLfAfterCr = true;

// §2: motion, speed and position numbers are decimal; O, E* addresses, byte values and status
// bytes are hex, two upper-case digits in replies.
inline constexpr int kMotionNumberBase = 10;
inline constexpr int kByteNumberBase = 16;

// §2.1: a bad checksum is answered with code 4 and does not advance the command index.
inline constexpr int kBadChecksumCode = 4;
inline constexpr bool kBadChecksumAdvancesIndex = false;

// §2.2: a failing command in a packet stops the rest; the reply is that command's code and the
// number of commands accepted before it ("1,6").
struct ReplyParts
{
    int code = 0;       // 0..7, INTA is added when the reply is sent
    std::string values; // text after the first comma, "" for none
};
ReplyParts packetReply(int code, int acceptedCount);

// §4: VL values are pulses/s (not thousands).
inline constexpr double kVelocityLimitUnitPulsesPerS = 1.0;

// §4: after reset the speed mode is VN (V and B are the major-axis step rate).
inline constexpr bool kResetModeIsVk = false;

// §4: on 4-axis units the A component of L/C/VL may be left out (= 0); fewer than three
// components is a syntax error; a 4-value vector on a 3-axis unit is a syntax error.
// Returns the reply code (0 = acceptable) for a vector with `count` components.
int vectorComponentCountCode(int count, int axisCount);

// §6: switch not found within n2 -> the axis stops and the reply is code 5; success -> 0.
inline constexpr int kHomingNotFoundCode = 5;

// §8: every complete, checksum-valid command addressed to the unit advances the index, whatever
// its result, except '@' and '>' themselves. `mnemonic` is the command without address.
bool advancesIndex(std::string_view mnemonic);

// §12: EFW/EUW values and EFR/EUR replies travel as decimal text; addresses are hex.
std::string formatEepromFloat(float value);

// §13: Y+ reports are not documented; the emulator sends no unsolicited lines.
inline constexpr bool kMpgSendsReports = false;

// ---- Part 2: emulator choices (manuals and reference silent) -----------------------------------

// Watchdog (code 2): a command must be complete (CR) within this time after its '!', and the
// lines of a packet must follow each other within it.
inline constexpr double kWatchdogSeconds = 0.1;

// Longest command line accepted (bytes between '!' and CR), the codec's line limit; longer
// lines are answered code 4 once their CR arrives and do not advance the index.
inline constexpr std::size_t kMaxLineLength = protocol::kMaxLineLength;

// Bytes that arrive while H or W is still to be answered wait in a receive buffer of this size
// and are handled after the reply; more are lost.
inline constexpr std::size_t kReceiveBufferBytes = 1024;

// After J the unit is deaf for this long (manual: "about 2 s"); bytes received meanwhile are lost.
inline constexpr double kResetSeconds = 2.0;

// T (pause between non-continuous moves) after reset, ms; the manuals' reset list omits T.
inline constexpr int kResetPauseMs = 10;

// A zero vector (L0,0,0) given to an idle unit is done at once, without the T pause, so that
// "L0,0,0 answered 0" really means "nothing queued" and N or W may follow immediately.
inline constexpr bool kZeroVectorDoneAtOnce = true;

// Y reply: the code and the echoed command as one value: "!0Y-" -> "0,Y-".
ReplyParts mpgReply(int code, std::string_view echoedCommand);

// Vectors (L, C) and N refused while the MPG is on (RUN=1): code 7.
inline constexpr int kMpgRefusalCode = 7;

// C while KEEP holds the queue (only L may be sent): code 1.
inline constexpr int kContinuousWhileKeptCode = 1;

// K a second time without R, or R without K: code 7.
inline constexpr int kKeepRestoreMisuseCode = 7;

// G when INTA=1 but nothing is left to run: flags cleared, code 6.
inline constexpr int kGoNothingLeftCode = 6;

// Commands other than C and B inside a packet fail the packet at that point with this code.
inline constexpr int kForeignCommandInPacketCode = 4;

// Long vs short (§4 '$'): compared on the major-axis step count of the vector.
std::int64_t shortnessMeasure(const std::array<std::int64_t, 4> &steps);

// Short vectors cruise at min(V, B); long ones at V. Exit speed target is never above cruise.
double cruiseSpeed(bool isShort, double v, double b);

// XM scales V only; above 100 % the boost is capped per axis by VL but never below V itself.
double multipliedSpeed(double v, int xmPercent, double vlCapForVector);

// Interrupts fire on the edge from inactive to active while enabled; an input counts as active
// when its level equals its polarity bit (ST2/ST3: 0 = active low).
inline bool inputActive(bool level, bool polarityActiveHigh)
{
    return level == polarityActiveHigh;
}

// A (thousands of pulses/s^2) and XM (percent): the manuals give no range, so any positive
// 32-bit number is accepted (0 would mean no motion: 5). The pulse rate and VL cap the result.
inline constexpr std::int64_t kAccelMaxK = 2147483647;
inline constexpr std::int64_t kMultiplierMaxPercent = 2147483647;

// Brake-violation tolerance: an arrival faster than the allowed exit speed by more than this
// (pulses/s, plus 1e-9 relative) counts as a violation; below it is floating-point noise.
// Rounding cannot reach it. The last brake is planned from v^2 - 2A*remaining vs e^2, with a
// slack of 1e-9 * max(v^2, cruise^2, A*length) (motion.cpp): a vector short by less than
// 5e-10 of its length - under one step for any 32-bit vector - brakes onto e exactly, while
// the rounding of the path position is a few ulps of the length (1e-16 relative), a million
// times below that slack. A vector one step too short arrives faster by sqrt(e^2 + 2A) - e:
// 200 pulses/s braking to a stop at the smallest A (A20), never less than A/e = 0.04 pulses/s
// (A20 into e = 500 000). So 0.01 pulses/s (one step per 100 s) counts every violation of a
// step or more and no rounding. Pinned by Rounding.* and Motion.BrakeViolation*.
inline constexpr double kBrakeViolationTolerance = 0.01;

// ---- Part 3: the machine behind the unit (safety counters, issue 14; emulator choices) ---------

// An axis counts as over its maximum speed when faster than it by more than this (pulses/s): the
// rounding of a V to whole pulses/s stays below it.
inline constexpr double kAxisOverMaxTolerance = 1.0;

// The spindle may stand on while the job is held (INTA or KEEP) and the machine stands for this
// long after the stop (time for the PC to switch it off), or for its spin-up time plus this after
// it was switched on during the hold (it must be at speed before the tool goes back into the
// work); longer counts once as spindle_on_while_held.
inline constexpr double kHeldSpindleGraceS = 0.5;

// The index and the last reply are shared by addresses 0 and 7 (one processor).
inline constexpr bool kIndexSharedByAddresses = true;

} // namespace frezka::emulator::readings
