#pragma once
// ProgressCheck: re-establishes how far a job got from the unit's position counters.
//
// Contract: when a packet's or a motion command's fate stays unknown (its reply and the
// recovery queries did not settle it) or the link was lost and came back, verify() blocks the
// job's stream, lets the unit run dry, reads the counters twice (the machine stands only when
// both reads agree) and finds the program command whose planned end position they equal: the
// unit ran exactly the prefix up to it. The job then continues from the next command after the
// modal settings (V, A, B, T, $, VK/VN) in force there have been sent again. Counters that match
// nothing while the link stayed up mean the unit ran something else: the path guard's fault.
// Counters that match several separated points, or nothing after a link loss (a reset unit),
// are an alarm: the operator must decide. pending() is true from the need to check (set on the
// link loss already) until the stream runs again.

#include <cstddef>
#include <functional>
#include <string>

namespace frezka::driver {

class CoreHost;
class Job;

class ProgressCheck
{
public:
    ProgressCheck(CoreHost &host, Job &job)
        : m_host(host)
        , m_job(job)
    {}

    void reset() { m_needVerify = m_linkWasLost = false; }
    bool pending() const { return m_needVerify; }
    void require() { m_needVerify = true; } // checked when the link is back
    void cancel() { m_needVerify = false; }
    void linkLost() { m_needVerify = m_linkWasLost = true; }
    // Blocks the stream and starts the check.
    void verify(const std::string &why);
    // The last value of each modal command before the cursor, sent again in program order;
    // then F, then `then`.
    void resendModals(std::function<void()> then);

private:
    void readStillPosition();
    void matchProgress();

    CoreHost &m_host;
    Job &m_job;
    bool m_needVerify = false;  // progress must be re-established from the counters
    bool m_linkWasLost = false; // counters matching nothing then mean a reset unit, not a fault
};

} // namespace frezka::driver
