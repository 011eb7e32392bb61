#pragma once
// LeadInHold: the unit held at a chain's start until the wire can feed the chain.
//
// Contract: at a chain's first command (the unit stands with an empty queue: the job's start or
// after a rest), when the chain's lead-in outruns the wire from an empty queue (JobPace::
// leadInSlackS for the first packet a free unit would start with: an A or a V a vector in, a
// slow link with packets of a few vectors while the unit accelerates), the job sends H first:
// the standing unit sets INTA and queues what follows without running it. The job streams on
// in full packets; once the queued motion covers the wire's part of the lead-in and the job's own
// packets, sized to what the unit holds, keep it fed (JobPace::leadInFeeds; a free start is held
// on the same test), or the chain is all queued, or the queue is full, the interrupt causes are
// read (ST4/ST5: an input that fired meanwhile holds the job for the operator, as any interrupt
// does) and G starts the chain. Without it the unit ran dry a few vectors into such a chain and
// stopped dead where its last vector was too short to brake in (property seed 235: 19 200 Bd, two
// brake violations). The hold costs the H, the reads and the G (round trips) and the time the queue
// takes to fill, only at the chains that need it. An abort meanwhile takes the hold over (its D
// clears it); an operator's pause is resumed without G (Hold::goOn): the unit stays held until this
// G.
//
// The same hold in the middle of a chain, after a damaged packet or a recovered reply there
// (Job::chainDamaged): where the job's own packets from here (JobPace::dryAhead) would come after
// the unit's last queued vector began braking to rest and that vector cannot brake within itself
// (a brake violation), the job sends H while the unit still holds the ramp; the unit brakes
// through its queue and stands, and the chain goes on as above from where it stands
// (JobPace::stopEstimate: never taken to stand before it does). Property seeds 90 and 132.

#include <cstddef>

namespace frezka::driver {

class CoreHost;
class Job;

class LeadInHold
{
public:
    LeadInHold(CoreHost &host, Job &job)
        : m_host(host)
        , m_job(job)
    {}

    void reset();
    // Before the job sends the command at its cursor: true when the hold took the step (H, the
    // reads or G are on the wire, and the job sends nothing else now).
    bool step(double now);
    bool held() const { return m_state == State::Held; }
    // A progress check (ProgressCheck) waits for the unit to run dry to read how far it got; a
    // unit this hold keeps standing never would (the job stood polling for ever on a faulty
    // link): the held chain is started now, from rest, as fed() would have started it; while
    // the operator holds the job, once the operator resumes it (Hold::goOn).
    void releaseForCheck();
    // Where the held chain began (valid while held).
    std::size_t start() const { return m_start; }

private:
    enum class State { Off, Halting, Held, Releasing };
    bool haltBeforeDry();
    // What one recovery of a lost reply costs the stream after damage: the reply allowance,
    // the settle pause and the '@' and '>' (or the resend's) round trips, s.
    double recoveryS() const;
    void halt(std::size_t start);
    bool fed();
    void readCause(int n);
    void go();

    CoreHost &m_host;
    Job &m_job;
    State m_state = State::Off;
    std::size_t m_start = 0;
    std::size_t m_decided = static_cast<std::size_t>(-1); // the chain start already judged
    bool m_afterDamage = false; // held by haltBeforeDry: released with room for a recovery
};

} // namespace frezka::driver
