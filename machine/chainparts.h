#pragma once
// Internal to frezka_machine: what the parts of the chain planner share (docs/planner.md §4-§5):
// the unit's speed limits, the figures derived once from each move (Derived), and the serial
// link's timing (LinkTiming: how long commands take on the wire, in packets and on their own).

#include "machine/machineconfig.h"
#include "machine/planner.h"
#include "protocol/command.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <utility>

namespace frezka::machine::detail {

inline constexpr double kInf = std::numeric_limits<double>::infinity();
inline constexpr std::int64_t kMinSpeed = 10; // smallest V / B the unit takes, pulses/s
// Largest A sent, thousands of pulses/s²: the manuals give no bound; the emulator accepts up to
// this (readings of driver/emulator), and a lower A is always safe.
inline constexpr std::int64_t kMaxAccel = 100000;

using Vec4 = std::array<double, 4>;

// floor() that forgives floating-point noise (1e-9 relative): a value the exact arithmetic
// puts on an integer must not lose a whole unit.
inline double floorUnits(double x)
{
    return std::floor(x + 1e-9 * std::max(1.0, std::abs(x)));
}

// A B cap that does not bind (Derived::wireCap, speedCap): above every speed the unit takes.
inline constexpr std::int32_t kNoCap = std::numeric_limits<std::int32_t>::max();

// Everything the passes need about one move, derived once. Its directions (what the vertex caps
// are made of) are not kept: the caps that follow from them are (RunPlanner::m_geoCap), and the
// directions are derived again where the final statistics need them (RunPlanner::Directions).
// V, A and the B caps are whole numbers at most the unit's pulse rate (A at most kMaxAccel), so
// 32 bits, and a C command's bytes fit 8: 64 bytes a move, not 88 (issue 17: the plan's peak holds
// one for every move of a run).
struct Derived
{
    double f = 0;              // speed units per path mm (VN: major steps/mm, VK: step length/mm)
    double units = 0;          // distance in speed units
    double vMm = 0;            // cruise cap, mm/s
    double aMm = 0;            // acceleration cap, mm/s²
    std::int64_t twoAU = 0;    // 2 · A · usable distance, integer pulses²/s², floored
    std::int32_t speed = 0;    // V
    std::int32_t accel = 0;    // A (thousands)
    std::int32_t ownSpeed = 0; // the vector's own V cap (its feed and axis limits)
    std::int32_t wireCap = kNoCap; // B cap at both its ends so that it keeps the link's pace, units
    std::int32_t speedCap = kNoCap; // B cap at both its ends where V lies above its own cap, units
    // The C command on the serial line, bytes: a letter, four 32-bit step counts of at most 11
    // characters, separators and a checksum, under 70 (8 bits).
    std::uint8_t wireBytes = 0;
    std::uint8_t widestBytes = 0; // the widest C within the wire window either side (wirePace)
    bool isShort = false;
    bool restBefore = false; // the unit stands when it begins (the run's start, a forced rest)
};
static_assert(sizeof(Derived) <= 64, "Derived is held for every move of a run");

// The serial link's timing for the link's pace (PlanOptions::wireLimited, docs/planner.md §4),
// from the profile's link keys: its baud rate, latency, checksums and packets.
class LinkTiming
{
public:
    LinkTiming(const MachineConfig &config, const PlanOptions &options)
        : m_config(config)
        , m_options(options)
    {}

    // The unit's queue, and the windows over which the pace evens out a vector's bytes.
    std::size_t queueVectors() const;
    std::size_t brakeWindow() const { return std::clamp<std::size_t>(queueVectors() / 3, 8, 128); }
    std::size_t wireWindow() const { return std::min<std::size_t>(16, brakeWindow() / 2); }
    // Wire time of a vector of `bytes` in a packet (or alone, with packets off), with its share
    // of the packet's round trip; seconds.
    double vectorWireS(double bytes) const;
    // The same without the pace's margins: what the vector takes of the link on average.
    double bareVectorWireS(double bytes) const;
    // The two of a C command's whole bytes (Derived::wireBytes, widestBytes), memoised: the pace
    // asks for them at every move of every plan of a run.
    double vectorWireS(std::uint8_t bytes) const { return wholeBytes(bytes).first; }
    double bareVectorWireS(std::uint8_t bytes) const { return wholeBytes(bytes).second; }
    // The vectors of a packet that costs one round trip, as the pace counts them.
    double packetVectors() const;
    double roundTripS() const { return 2 * m_config.link.latencyMs / 1000.0 + kReplyS; }
    // A command sent on its own (A, V: they cannot travel in a packet): its bytes and a round trip.
    double nonPacketS(double bytes) const;
    // Link time of a B command (it travels in a packet, unless packets are off).
    double commandS(double bytes) const;
    // Bytes of commands as they go on the wire (the codec's own encoding).
    double vectorWireBytes(const std::array<std::int32_t, 4> &d) const;
    double brakeWireBytes(std::int64_t value) const;
    double wireBytes(const protocol::Command &command) const;
    // A V command of the largest value the unit takes (its bytes barely depend on the value).
    double speedWireBytes() const;
    // What a V or an A command costs the link (its bytes and a round trip; an A is no longer
    // than the largest V): the price the plan weighs against a shared V or A.
    double modalChangeS() const { return nonPacketS(speedWireBytes()); }
    // What the packet after a V or A change inside a chain needs once the change has gone out:
    // its first B and C on the wire and a round trip, and at least twice their wire time (the
    // driver sizes a packet to half of what the unit holds when it holds little,
    // driver/link/job.cpp, sendPacket). vectorBytes: that C command's bytes.
    double changeLeadS(double vectorBytes) const;

    static constexpr double kReplyS = 0.002;     // a packet's reply and the unit's turnaround
    static constexpr double kShortQueue = 128;   // see packetVectors
    static constexpr double kSteadyHeldS = 0.25; // see vectorWireS
    static constexpr double kBrakeBytes = 12;    // changeLeadS: a B command's bytes, about
    static constexpr double kPacedWireS = 0.005; // ... the driver's least packet budget

private:
    const std::pair<double, double> &wholeBytes(std::uint8_t bytes) const
    {
        auto &slot = m_wholeMemo[bytes];
        if (slot.first < 0)
            slot = {vectorWireS(static_cast<double>(bytes)),
                    bareVectorWireS(static_cast<double>(bytes))};
        return slot;
    }

    const MachineConfig &m_config;
    const PlanOptions &m_options;
    mutable std::array<std::pair<double, double>, 256> m_wholeMemo = [] {
        std::array<std::pair<double, double>, 256> memo;
        memo.fill({-1.0, -1.0}); // a wire time is never negative: -1 marks empty
        return memo;
    }();
    // brakeWireBytes and vectorWireBytes, memoised by value (direct-mapped): the pace asks for a
    // B's bytes at every vertex of every plan of a run and for each vector's once, and encoding
    // a command builds a string each time (a third of deriving a 1 M-move run).
    static constexpr std::size_t kVectorMemo = 1024;
    using Delta = std::array<std::int32_t, 4>;
    mutable std::array<std::pair<Delta, double>, kVectorMemo> m_vectorMemo = [] {
        std::array<std::pair<Delta, double>, kVectorMemo> memo;
        memo.fill({{0, 0, 0, 0}, -1.0}); // the zero vector is never asked for: -1 marks empty
        return memo;
    }();
    static constexpr std::size_t kBrakeMemo = 256;
    mutable std::array<std::pair<std::int64_t, double>, kBrakeMemo> m_brakeMemo = [] {
        std::array<std::pair<std::int64_t, double>, kBrakeMemo> memo;
        memo.fill({std::numeric_limits<std::int64_t>::min(), 0.0});
        return memo;
    }();
};

} // namespace frezka::machine::detail
