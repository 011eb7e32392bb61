#pragma once
// CoreOptions and JobReport: the machine core's settings and the figures of a job (plain values).

#include "driver/link/linkengine.h"

#include <cstdint>

namespace frezka::driver {

struct CoreOptions
{
    LinkOptions link;
    bool checksums = true;             // switch checksums on when connecting
    bool packets = true;               // send runs of C/B as packets
    int maxPacketCommands = 0;         // 0 = up to the variant's queue capacity
    double pollIntervalS = 0.05;       // 20 Hz position + status while connected
    double inputsPollIntervalS = 0.25; // I1/I2
    double maxPollGapS = 4.0;          // while streaming wire-bound, poll at least this often
    double wireBoundPollShare = 0.005; // ... and otherwise spend at most this share on polls
    double streamPollShare = 0.5;      // while a job streams, polls take at most this share
    double slowPacketWireS = 0.1;      // where the motion is slow, packets at most this long
    bool compareEeprom = true;         // read the unit's EEPROM on connect and report differences
    bool optionalStops = true;         // M1 pauses
    // When the position leaves the planned path (see pathguard.h): false = stop
    // and hold the job for the operator (resume returns to the path); true = return to the
    // path and run on without asking (headless runs, soak tests).
    bool returnToPathAutomatically = false;
    // Hold the unit (H) at a chain's start until the wire can feed its lead-in (leadinhold.h).
    bool leadInHold = true;
    friend bool operator==(const CoreOptions &, const CoreOptions &) = default;
};

// Figures of a job for the CLI and the benchmarks.
struct JobReport
{
    std::int64_t vectors = 0;  // C and L commands accepted
    std::int64_t commands = 0; // program commands accepted
    double startS = 0;
    double endS = 0;
    std::int64_t linkBytes = 0; // both directions during the job
    std::int64_t resent = 0;
    std::int64_t recovered = 0;
    std::int64_t verified = 0;    // times progress was re-established from the counters
    std::int64_t packets = 0;     // packets sent (first attempts and resends)
    std::int64_t polls = 0;       // position polls during the job
    std::int64_t streamPolls = 0; // ... of them while vectors were still to send
    double maxStreamPollGapS = 0; // the longest time without one then (from the start)
    double firstStreamPollS = -1; // when the first and last of them started
    double lastStreamPollS = -1;
    std::int64_t leadInHolds = 0; // chains the unit was held at until their start was queued
    std::int64_t dryHolds = 0;    // chains halted where the unit would have run dry (held again)
    std::int64_t pathFaults = 0;  // times the position left the planned path (path guard)
    std::int64_t rerun = 0;       // vectors sent again after returning (queued ones too)
    std::int64_t returnMoves = 0; // L moves that took the machine back to the path
    double firstVectorAckS = -1;  // when the unit accepted the first / last motion command
    double lastVectorAckS = -1;
    int overrideLinkMinPercent =
        0;                 // the lowest XM the link held the operator's override to (0: never)
    bool finished = false; // reached ProgramEnd / the end of the program
    friend bool operator==(const JobReport &, const JobReport &) = default;
};

} // namespace frezka::driver
