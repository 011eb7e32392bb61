#pragma once
// JobOverride: the feed override as the unit runs it (issue 14 item 5), a part of the job.
//
// Contract: the operator's percentage (MachineState::overridePercent) is what the window shows
// and what the rest of the job runs, as far as two things allow. With XM, while a job streams,
// follow() keeps the unit's XM at most at the highest override the link can feed over the
// motion from the executing command to a queue-full past the next to send (JobPace::
// overrideCeiling; XM scales speeds, so a stretch the plan paced to the wire at 100 % runs dry
// above it): lowered at once, raised again two steps of 5 % up, the operator's XM again when
// the job ends; what it holds shows in MachineState::overrideHeldPercent(). Without XM (a GVE64
// before v19) XU/XD change only the queued speeds, so the job streams every later V times
// speedScale(). Estimates only decide how fast, never where: the path is the plan's.

namespace frezka::driver {

class CoreHost;
class JobPace;

class JobOverride
{
public:
    JobOverride(CoreHost &host, const JobPace &pace)
        : m_host(host)
        , m_pace(pace)
    {}

    // The XM to send for the operator's `askedPercent` (streaming: a job is active).
    int toSend(int askedPercent, bool streaming) const;
    // Sends XM where the link's ceiling or the operator's word has changed it (with XM only).
    void follow(bool streaming);
    // Units without XM: the factor every V streamed from now on is scaled by (1 = the plan's).
    void setSpeedScale(double scale) { m_speedScale = scale; }
    double speedScale() const { return m_speedScale; }
    // The lowest XM the link held the operator's override to since reset (0: never).
    int linkMinPercent() const { return m_linkMin; }
    void resetLinkMin() { m_linkMin = 0; }

private:
    CoreHost &m_host;
    const JobPace &m_pace;
    double m_speedScale = 1.0;
    int m_linkMin = 0;
};

} // namespace frezka::driver
