#pragma once
// JobPace: how much motion the unit holds and how fast the wire must feed it, for one job.
//
// Built once per job from the unit program: the estimated motion time before each program
// command (machine/unitmodel.h, the planner's own model, exact for the unit while its queue does
// not run dry), the wire bytes and the motion commands before each. From those and the job's
// cursor (what was sent, what the last poll saw executing, when) it answers the streamer's and
// the poller's questions: how many seconds of motion are queued, whether the motion ahead runs
// faster than the wire can carry it, how many vectors will still be queued a little later, where
// a packet should end so that polls keep their rate. Estimates only: they size packets and pace
// polls, never the motion itself, and a wrong one costs time, not position.

#include "machine/leadin.h"
#include "machine/unitprogram.h"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace frezka::driver {

class CoreHost;

// Where a job stands: shared by the job's parts (the streamer, its pace, progress, path guard).
struct JobCursor
{
    std::size_t next = 0;        // next program command to send (all before it were accepted)
    std::size_t exec = 0;        // program command executing (from the polled position)
    std::size_t inflightEnd = 0; // end of the commands in flight
    double execAt = 0;           // when exec was read from the unit, s
    std::int64_t vectorsAcked = 0;
    // Where a polled position lies on several passes of the path, the pace's own reading of the
    // executing command (JobTracker::positionRead): the pass nearest to the model, which may lie
    // after exec. Valid while exec and execAt are the ones it was read with (paceKey, paceKeyAt).
    std::size_t paceExec = 0;
    double paceExecAt = 0;
    std::size_t paceKey = static_cast<std::size_t>(-1);
    double paceKeyAt = -1;
};

class JobPace
{
public:
    JobPace(CoreHost &host, const machine::UnitProgram &program, const JobCursor &cursor)
        : m_host(host)
        , m_program(program)
        , m_cursor(cursor)
    {}

    // Derives the prefixes from the program (call when a job starts).
    void build();

    // Motion commands (C, L) before program index i.
    std::int64_t vectorsBefore(std::size_t i) const { return m_vectorPrefix[i]; }
    std::size_t size() const { return m_vectorPrefix.size(); }
    // Estimated seconds of motion before program index i, at 100 %.
    double timeBefore(std::size_t i) const { return m_timePrefix[i]; }
    // Estimated seconds the unit takes from program index `from` to `to` at the feed override.
    double runS(std::size_t from, std::size_t to) const;

    // The largest packet: the unit's queue less one (or CoreOptions::maxPacketCommands).
    int maxPacket() const;
    // The estimated executing command, from the time since the last poll.
    std::size_t execEstimate() const;
    // Estimated motion still queued in the unit, s.
    double bufferedS() const;
    // The time left before the unit must have its next vector: what it holds less the braking
    // of its last vector, which brakes to rest when nothing follows it (a long rapid brakes for
    // a sixth of a second: the plunge after it must be queued before that begins), s.
    double leadS() const;
    // Vectors still queued in the unit `aheadS` seconds from now.
    std::int64_t queuedAfter(double aheadS) const;
    // The motion of the next queue-full runs faster than the wire can carry it.
    bool wireBoundAhead() const;
    // The highest feed override (percent, at least 100) at which the wire still carries every
    // queue-full of motion from the executing command to a queue-full past the next to send:
    // XM scales speeds, so a stretch paced to the wire at 100 % runs dry above it.
    int overrideCeiling() const;
    // A chain's lead-in on this link at the override (machine/leadin.h).
    machine::LeadInLink leadInLink() const;
    machine::LeadInPrefixes leadInPrefixes() const;
    bool chainStartsAt(std::size_t i) const;
    std::size_t firstPacketEnd(std::size_t start) const;
    double leadInSlackS(std::size_t start, std::size_t queuedEnd) const;
    // Whether packets sized as the job sizes them (packetBudgetS) keep the unit fed when it
    // starts the chain at `start` with [start, queuedEnd) queued: each packet costs its framing
    // and a round trip, so packets cut to half of a little held motion on a stretch the wire
    // barely feeds shrink cycle after cycle until the unit runs dry (property seed 132, and seed
    // 235 with its spindle on). leadInSlackS counts the wire's bytes as a stream; this plays the
    // packets, up to a second of motion held or the chain's end.
    bool leadInFeeds(std::size_t start, std::size_t queuedEnd, double delayS = 0) const;
    // The wire time a packet may take while the unit holds `heldS` of motion (its last vector's
    // braking excluded): the rest is kept for the reply's and the next packet's round trips and
    // the drift of the estimate, or half of what it holds when it holds little.
    static double packetBudgetS(double heldS, double rttS);
    // The same play from where the unit is now, in the middle of a chain (the model's place, the
    // commands from the cursor on sent as the job sends them, the first one `delayS` from now:
    // one recovery of a lost reply on the way): kFeeds, or 1 + the last vector the unit holds
    // when it runs dry (brakes to rest at the end of its queue).
    static constexpr std::size_t kFeeds = static_cast<std::size_t>(-1);
    std::size_t dryAhead(double delayS = 0) const;
    // The vector before `vectorEnd` brakes from its V to rest within its own length (running
    // dry there is a stop on the ramp, not a brake violation).
    bool brakesWithin(std::size_t vectorEnd) const;
    // Where a unit halted `aheadS` seconds from now stands: the command the model has it
    // execute then plus its braking from the V in effect (at most the last vector queued).
    std::size_t stopEstimate(double aheadS) const;
    // The planned V (pulses/s) in effect at the command the unit executes (0: none yet).
    std::int64_t plannedSpeedNow() const;
    // Where a packet ends to keep polls at their rate where the motion is slow (next = no cap).
    std::size_t slowMotionPacketEnd() const;
    // Seconds since the last poll that the unit spent moving by the model (less its waits).
    double elapsedS() const;
    // Motion commands up to `next` were accepted at `arrivalS`: where the model had the unit run
    // dry before then, it waited for them, and the model's clock is held back by the wait.
    void noteArrival(std::size_t oldNext, double arrivalS);
    // The unit reported a full queue: the executing command is at most a queue-full back.
    // Returns the new estimate of the executing command.
    std::size_t executingAtFull() const;

private:
    void estimateDurations();
    // Plays the job's packets from `queuedEnd` on, the first leaving at t0 (s from now), with
    // the unit's motion counted from program time originS: kFeeds, or 1 + the last vector
    // queued when a packet's vectors come after the unit began braking to rest. `floor`: no
    // vector at or after it queued yet means the unit has not started (it waits, it feeds).
    std::size_t playPackets(double originS, std::size_t floor, std::size_t queuedEnd,
                            double t0) const;
    double rate() const; // program seconds per second of the unit's time
    // The executing command and when it was read, as the pace takes them (JobCursor::paceExec).
    std::size_t exec() const;
    double execAt() const;

    CoreHost &m_host;
    const machine::UnitProgram &m_program;
    const JobCursor &m_cursor;
    std::vector<double> m_timePrefix;         // estimated motion seconds before each index
    std::vector<std::int64_t> m_bytePrefix;   // wire bytes of the program commands before each
    std::vector<std::int64_t> m_vectorPrefix; // motion commands before each program index
    // Round trips before each index: each command that cannot travel in a packet (A, V, $, ...)
    // is one, and so is each run of C/B commands between them (one packet, when packets are on).
    std::vector<std::int64_t> m_tripPrefix;
    std::vector<std::size_t> m_lastMotion; // 1 + the last motion command before each index
    std::vector<double> m_brakeS;          // braking time from V to rest before each index
    // A change inside a chain: commands that cannot travel in a packet (A, V, ...) after motion
    // that has not rested since. What the unit holds when it goes out is at least the motion of
    // the stretch before it (since the last change or rest); the change's round trips and the
    // next packet's first B and C must arrive within that (the planner's pace, at 100 %).
    struct ModalChange
    {
        std::size_t at = 0;         // program index of its first command
        double stretchS = 0;        // motion of the stretch before it at 100 %, less its braking
        int commands = 0;           // its commands, each a round trip
        std::int64_t nextBytes = 0; // the B and C that follow it, up to the first C, on the wire
    };
    void findModalChanges();
    std::vector<ModalChange> m_changes; // in program order
    // The unit's waits for motion since the poll that set (m_waitExec, m_waitExecAt), s.
    double m_waitS = 0;
    std::size_t m_waitExec = 0;
    double m_waitExecAt = -1;
};

} // namespace frezka::driver
