#pragma once
// The serial link between the PC and the unit, on a virtual clock: every byte takes 10 bit
// times (8N1) at the baud rate on its direction of the line, then arrives after that
// direction's latency (a USB-serial adapter adds 1-16 ms). A seeded fault injector can flip a
// bit of a byte, drop a byte, send a byte twice, or lose a whole message (everything up to and
// including the next CR). Same seed, same traffic -> same faults, on every platform.

#include <cstdint>
#include <deque>
#include <limits>
#include <string>
#include <string_view>

namespace frezka::emulator {

struct DirectionFaults
{
    double corruptByteRate = 0;   // probability per byte that one bit is flipped
    double dropByteRate = 0;      // probability per byte that it never arrives
    double duplicateByteRate = 0; // probability per byte that it arrives twice
    double loseMessageRate = 0;   // probability per message (up to CR) that all of it is lost
    bool operator==(const DirectionFaults &) const = default;
};

struct WireOptions
{
    int baud = 115200;
    double latencyPcToUnitS = 0;
    double latencyUnitToPcS = 0;
    std::uint64_t seed = 1;
    DirectionFaults pcToUnit{};
    DirectionFaults unitToPc{};
    bool operator==(const WireOptions &) const = default;
};

// Deterministic 64-bit generator (SplitMix64): the standard library's distributions are not
// guaranteed to give the same numbers on every implementation.
class SplitMix64
{
public:
    explicit SplitMix64(std::uint64_t seed)
        : m_state(seed)
    {}
    std::uint64_t next();
    double uniform(); // [0, 1)

private:
    std::uint64_t m_state;
};

struct WireStats
{
    std::int64_t bytesSent = 0;
    std::int64_t bytesCorrupted = 0;
    std::int64_t bytesDropped = 0;
    std::int64_t bytesDuplicated = 0;
    std::int64_t messagesLost = 0;
    bool operator==(const WireStats &) const = default;
};

// One direction of the line.
class ByteChannel
{
public:
    ByteChannel(int baud, double latencyS, DirectionFaults faults, SplitMix64 *rng);

    // Queue bytes for sending at time `nowS` (they follow whatever is still on the line).
    void send(double nowS, std::string_view bytes);
    // Time the next byte arrives, or infinity.
    double nextArrivalS() const;
    // Remove and return the bytes that have arrived by `timeS`.
    std::string takeArrived(double timeS);
    bool idle() const { return m_inFlight.empty(); }
    double byteTimeS() const { return m_byteTimeS; }
    const WireStats &stats() const { return m_stats; }

private:
    struct InFlight
    {
        double arrivalS;
        char byte;
    };
    void put(double nowS, char c);

    double m_byteTimeS;
    double m_latencyS;
    DirectionFaults m_faults;
    SplitMix64 *m_rng;
    double m_lineFreeAtS = 0;
    bool m_atMessageStart = true;
    bool m_losingMessage = false;
    std::deque<InFlight> m_inFlight;
    WireStats m_stats;
};

// Both directions with one fault generator.
class Wire
{
public:
    explicit Wire(WireOptions options = {});
    Wire(const Wire &) = delete; // the channels point at the shared generator
    Wire &operator=(const Wire &) = delete;

    ByteChannel &toUnit() { return m_toUnit; }
    ByteChannel &toPc() { return m_toPc; }
    const ByteChannel &toUnit() const { return m_toUnit; }
    const ByteChannel &toPc() const { return m_toPc; }
    const WireOptions &options() const { return m_options; }

private:
    WireOptions m_options;
    SplitMix64 m_rng;
    ByteChannel m_toUnit;
    ByteChannel m_toPc;
};

} // namespace frezka::emulator
