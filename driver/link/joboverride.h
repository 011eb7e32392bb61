#pragma once
// JobOverride: the feed override as the unit runs it (issue 14 item 5), a part of the job.
//
// Contract: the operator's percentage (MachineState::overridePercent) is what the window shows
// and what the rest of the job runs, as far as three things allow. With XM, while a job streams,
// follow() keeps the unit's XM at most at the highest override the link can feed over the
// motion from the executing command to a queue-full past the next to send (JobPace::
// overrideCeiling; XM scales speeds, so a stretch the plan paced to the wire at 100 % runs dry
// above it): lowered at once, raised again two steps of 5 % up. After damage on the link
// (noteDamage: a packet refused for a damaged line, a reply lost and recovered) the wire
// delivers less than the plan paced for; while the stretch ahead is wire-bound and the motion
// the unit holds would not outlast one more recovery (a damaged packet sent again, a lost
// reply's allowance, the '@' and '>'), the link holds the XM below 100 % too (linkPercent): to
// the XM at which what it holds outlasts that, sent only while the unit stands held by the job's
// H (unitHeld: a lower XM while it runs is a lower cruise for the vector it is in, which a short
// vector cannot brake to), and not raised again before the job ends (kRaiseDuringJob: no raise
// rule found yet that keeps the unit fed; docs/planner.md §7). The effective XM
// is the least of the operator's and the link's; the operator's again when the job ends (and
// while it is paused or held); what it holds shows in MachineState::overrideHeldPercent() and,
// for damage, MachineState::overrideHeldForFaults. Without XM (a GVE64 before v19) XU/XD change
// only the queued speeds, so the job streams every later V times speedScale(), and the link's
// hold does not apply. Estimates only decide how fast, never where: the path is the plan's.

namespace frezka::driver {

class CoreHost;
class JobPace;

class JobOverride
{
public:
    JobOverride(CoreHost &host, JobPace &pace)
        : m_host(host)
        , m_pace(pace)
    {}

    // The XM to send for the operator's `askedPercent` (streaming: a job is active).
    int toSend(int askedPercent, bool streaming) const;
    // Sends XM where the link's ceiling, its hold or the operator's word has changed it (with XM
    // only). mayRaise: a position was just read (the link's hold is raised at most once a poll).
    void follow(bool streaming, bool mayRaise = true);
    // A packet or command of the job came back damaged, or its reply was lost and recovered:
    // the link's hold is judged now (lowered at once where the unit holds too little).
    void noteDamage();
    // The unit stands, held by the job's H (LeadInHold): a lower hold judged while it ran goes
    // out now, before the G.
    void unitHeld();
    // Units without XM: the factor every V streamed from now on is scaled by (1 = the plan's).
    void setSpeedScale(double scale) { m_speedScale = scale; }
    double speedScale() const { return m_speedScale; }
    // The lowest XM the link held the operator's override to since reset (0: never).
    int linkMinPercent() const { return m_linkMin; }
    // The XM the link's hold after damage allows (100: none), and how often it was lowered.
    int linkPercent() const { return m_linkPercent; }
    int linkLowerings() const { return m_lowerings; }
    void resetLinkMin()
    {
        m_linkMin = 0;
        m_linkPercent = m_pendingPercent = 100;
        m_lowerings = 0;
        m_damageAt = -1;
        m_raisedAt = -1;
    }

    // The link is taken as clean again this long after its last damage, s.
    static constexpr double kQuietS = 2.0;
    // The link's hold applies where the clean wire carries the motion ahead less than this many
    // times over: where the plan paced the unit to the wire (the overfeed raster: 1.1-1.3), a
    // damaged wire leaves it no surplus to refill the queue after a recovery.
    static constexpr double kWireShare = 2.0;
    // The link's hold is raised by 10 % at most once in this time, s.
    static constexpr double kRaiseS = 0.5;
    static constexpr bool kRaiseDuringJob = false;
    // The lowest XM the link's hold sends (the unit crawls below it; the slider's least is 10).
    static constexpr int kLinkMinPercent = 20;

private:
    // The XM the link's hold allows now (100: none).
    int linkTarget(bool streaming) const;
    // What one more recovery costs the unit's queue: the reply allowance, the settle pause, the
    // '@' and '>' round trips, and a full packet sent again with its round trip, s.
    double recoveryS() const;

    CoreHost &m_host;
    JobPace &m_pace;
    double m_speedScale = 1.0;
    int m_linkMin = 0;
    int m_linkPercent = 100;
    int m_pendingPercent = 100;
    double m_raisedAt = -1; // when the link's hold last changed // a lower hold judged while the
                            // unit ran: sent once it stands
    int m_lowerings = 0;
    double m_damageAt = -1;
};

} // namespace frezka::driver
