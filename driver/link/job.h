#pragma once
// Job: the job activity of MachineCore: streams a unit program to the unit and follows it to
// its end.
//
// Contract: start() checks the program against the unit and the machine's position and, when
// it accepts, owns the job until finish() (or abandon() on abort). Whenever the core's link is
// free and nothing else is due (operation steps and polls go first), the core calls streamStep(),
// which puts the next packet of C/B commands (sized by JobPace to what the unit's queue holds)
// or the next single command on the wire, or waits: for an empty queue (L), for the machine to
// stand (WaitIdle, Dwell, M0/M1/M6, ProgramEnd, probe), for the operator, for a check. Progress
// is the index of the next command to send (the cursor): everything before it was accepted.
// JobTracker reads where the unit is from its counters, JobFigures counts for the report.
// An unknown outcome hands over to ProgressCheck (the counters tell how far the unit got), a
// position off the planned path to PathGuard, a G38 move to ProbeMove; each of those owns its
// own fields and gives the job back by unblocking the stream. The job never blocks and never
// waits on time itself: it tells the core the earliest time it may send again (waitUntil).

#include "driver/link/coretypes.h"
#include "driver/link/jobfigures.h"
#include "driver/link/joboverride.h"
#include "driver/link/jobpace.h"
#include "driver/link/jobtracker.h"
#include "driver/link/leadinhold.h"
#include "driver/link/lineerrors.h"
#include "driver/link/machinestate.h"
#include "driver/link/pathguard.h"
#include "driver/link/probemove.h"
#include "driver/link/progresscheck.h"
#include "driver/link/synchold.h"
#include "machine/unitprogram.h"

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace frezka::driver {

class CoreHost;

class Job
{
public:
    explicit Job(CoreHost &host);
    Job(const Job &) = delete;
    Job &operator=(const Job &) = delete;

    // ---- the core's side
    // Accepts the program (nullopt) or says why not, changing nothing.
    std::optional<MachineError> start(machine::UnitProgram program, double now);
    bool active() const { return m_active; }
    // Counts the jobs started: an operation of one job tells it from the next.
    std::uint64_t serial() const { return m_serial; }
    // Running, not waiting for the machine, the operator or a check, and not before waitUntil.
    bool mayStream(double now) const;
    // ... and commands are left to send.
    bool streaming(double now) const;
    // Commands are left to send and only the unit's full queue holds them back (if at all).
    bool feeding() const;
    // The feed override as the unit runs it (the link's ceiling, XU/XD without XM).
    JobOverride &feedOverride() { return m_override; }
    void streamStep(double now);
    double waitUntil() const { return m_waitUntil; }
    bool queueFullSeen() const { return m_queueFullSeen; }
    const JobPace &pace() const { return m_pace; }
    const JobReport &report() const { return m_figures.report(); }
    JobReport &report() { return m_figures.report(); }
    const machine::UnitProgram &program() const { return m_program; }
    void pollStarted(double now); // counts the job's polls
    // The executing command from the new counters (JobTracker), then the override's ceiling there.
    void positionRead()
    {
        if (m_tracker.positionRead(m_figures.report().startS))
            m_override.follow(m_active);
    }
    void unitStands() { m_tracker.unitStands(); } // F read RUN = 0: everything accepted has run
    void checkPolledPosition(bool kept);          // the path guard's check of a poll
    void linkOpened();                            // a wait in progress is taken up again
    void linkLost();                              // progress must be re-established afterwards
    bool resumeAfterReconnect();                  // connected again: true when a check starts
    bool verifying() const { return m_check.pending(); }
    // The unit is held at a chain's start until its lead-in is queued (leadinhold.h): a resume
    // must leave it held, the hold's own G starts the chain.
    bool leadInHeld() const { return m_active && m_lead.held(); }
    void releaseLeadIn() { m_lead.releaseForCheck(); } // for ProgressCheck (leadinhold.h)
    bool offPath() const { return m_guard.faulted(); }
    bool probing() const;
    void returnToPath() { m_guard.returnToPath(); }
    void abandon(); // abort: the job ends now, whatever is still on the wire is dropped
    void finish(bool ok);

    // ---- the job's parts (ProgressCheck, PathGuard, ReturnToPath, ProbeMove)
    JobCursor &cursor() { return m_cursor; }
    // arrivedJustNow: the reply came at once (no recovery), so the unit took them a
    // moment ago, which tells the pace how long the unit may have waited for them.
    void acceptUpTo(std::size_t end, bool arrivedJustNow = false);
    void setStreamBlocked(bool on) { m_streamBlocked = on; }
    void setQueueFullSeen(bool on) { m_queueFullSeen = on; }
    void setWaitUntil(double t) { m_waitUntil = t; }
    // A packet or command of the chain being streamed was damaged, or its reply lost and
    // recovered: the unit may hold less than the job's packets were sized for (LeadInHold halts
    // it where it would run dry). Cleared where a chain starts from rest.
    bool chainDamaged() const { return m_chainDamaged; }
    void setChainDamaged(bool on) { m_chainDamaged = on; }
    void resetPacketLimit() { m_packetLimit = m_pace.maxPacket(); }
    protocol::Command toCommand(const machine::UnitCommand &c) const;
    ProgressCheck &progress() { return m_check; }
    PathGuard &guard() { return m_guard; }
    SyncHold &sync() { return m_sync; }

private:
    void sendPacket(double now);
    void onPacketOutcome(const Outcome &o, std::size_t first, std::size_t n, double now);
    void onCommandOutcome(const Outcome &o, std::size_t index, double now);
    void handlePcOp(const machine::UnitCommand &c);
    void operatorStop(const machine::UnitCommand &c, std::size_t index);
    void atRest(std::size_t index, std::function<void()> then);
    void finishWithPosition();

    CoreHost &m_host;
    bool m_active = false;
    std::uint64_t m_serial = 0;
    machine::UnitProgram m_program;
    JobCursor m_cursor;
    bool m_streamBlocked = false; // waiting for idle / operator / verification
    bool m_queueFullSeen = false; // last C/packet hit a full queue
    bool m_afterRest = false;     // a PC-side wait (dwell) ended: the unit holds nothing
    bool m_chainDamaged = false;  // see chainDamaged()
    // The last command the job waited at and found the unit standing where the plan has it.
    static constexpr std::size_t kNoRest = static_cast<std::size_t>(-1);
    std::size_t m_restVerified = kNoRest;
    double m_waitUntil = -1; // a dwell or back-off: nothing from the job before this time
    int m_packetLimit = 1;   // adaptive packet size (commands)
    LineErrors m_lineErrors; // damaged packet lines lately: caps m_packetLimit's growth
    JobFigures m_figures;
    JobPace m_pace;
    JobOverride m_override{m_host, m_pace};
    JobTracker m_tracker{m_host, m_program, m_cursor, m_pace};
    ProgressCheck m_check;
    PathGuard m_guard;
    ProbeMove m_probe;
    LeadInHold m_lead{m_host, *this};
    SyncHold m_sync{m_host, *this};
    // Where the chain held by H (lead-in or sync point) began; nullopt when none is held.
    std::optional<std::size_t> heldFrom() const;
};

} // namespace frezka::driver
