// JobOverride: the feed override as the unit runs it during a job. See joboverride.h.

#include "joboverride.h"

#include "driver/link/corehost.h"
#include "driver/link/jobpace.h"
#include "driver/link/linkengine.h"
#include "driver/link/machinecore_internal.h"
#include "protocol/variant.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;

int JobOverride::toSend(int asked, bool streaming) const
{
    if (!streaming)
        return asked;
    int want = asked;
    if (asked > 100) {
        // In steps of 5 %, raised again only two steps up: each XM is a round trip outside the
        // packets, and the ceiling wavers by a step as the window moves (160/165 % in turn).
        const int ceiling = m_pace.overrideCeiling() / 5 * 5;
        const int sent = m_host.liveState().overrideSentPercent;
        want = std::min(asked, ceiling < sent || ceiling >= sent + 10 ? ceiling : sent);
    }
    return m_linkPercent < 100 ? std::min(want, m_linkPercent) : want;
}

double JobOverride::recoveryS() const
{
    LinkEngine &link = m_host.link();
    return link.replyAllowanceS() + link.options().settleS + 3 * m_host.rttS() +
           m_pace.packetWireS();
}

int JobOverride::linkTarget(bool streaming) const
{
    const MachineState &state = m_host.liveState();
    if (!streaming || state.mode != MachineMode::Running || m_damageAt < 0 ||
        m_host.now() - m_damageAt >= kQuietS || m_pace.wireShareAhead(true) >= kWireShare)
        return 100;
    // What the unit holds in the program's seconds (at 100 %) lasts 100 / p as long at XM p on
    // a wire-bound stretch (short vectors at their cruise, which XM scales): the highest p at
    // which it outlasts one more recovery, in steps of 5 %.
    const double held = m_pace.leadS() * m_pace.rate();
    const double need = recoveryS();
    const int p = static_cast<int>(std::floor(100.0 * held / need / 5.0)) * 5;
    return std::clamp(p, kLinkMinPercent, 100);
}

void JobOverride::noteDamage()
{
    m_damageAt = m_host.now();
    follow(true, false);
}

void JobOverride::unitHeld()
{
    if (m_pendingPercent < m_linkPercent)
        follow(true, false);
}

void JobOverride::follow(bool streaming, bool mayRaise)
{
    MachineState &state = m_host.liveState();
    if (!state.features.vlVkXmNa)
        return;
    if (!streaming || state.mode != MachineMode::Running) {
        m_linkPercent = m_pendingPercent = 100; // the job ended or stands: the operator's XM
    } else if (!state.inta) {
        // The unit runs: a lower XM would lower the cruise of the vector it is in, which a short
        // vector cannot brake to within what is left of it (the emulator's brake violation: 33
        // on the test's raster where it went out at once). It waits for the unit to stand.
        const int target = linkTarget(streaming);
        if (target < m_linkPercent) {
            m_pendingPercent = std::min(m_pendingPercent, target);
        } else {
            m_pendingPercent = 100;
            // Not raised during the job (kRaiseDuringJob): raised again in steps of 10 %, one each
            // kRaiseS while the unit's queue was three quarters full, the unit ran dry 22 times
            // on the test's raster once the damage had passed (its packets shrank to a few
            // vectors, each with its frame and round trip: docs/benchmarks.md, twelfth session);
            // raised at once to 100 %, 16 times. Kept for the raise rule still to be found.
            const std::int64_t capacity = variantInfo(m_host.config().unit.variant).queueCapacity;
            if (kRaiseDuringJob && mayRaise && m_linkPercent < 100 &&
                (target == 100 || target >= m_linkPercent + 10) &&
                m_host.now() >= m_raisedAt + kRaiseS && m_pace.queuedAfter(0) * 4 >= capacity * 3) {
                m_linkPercent = std::min(target, m_linkPercent + 10);
                m_raisedAt = m_host.now();
            }
        }
    } else if (m_pendingPercent < m_linkPercent) {
        // Held by the job's H (the dry halt after damage): it stands, the lower XM goes out now,
        // before the G, so that the chain runs on at what the damaged wire can feed.
        m_linkPercent = m_pendingPercent;
        m_pendingPercent = 100;
        m_raisedAt = m_host.now();
        ++m_lowerings;
    }
    const int want = toSend(state.overridePercent, streaming);
    if (want < state.overridePercent && streaming)
        m_linkMin = m_linkMin ? std::min(m_linkMin, want) : want;
    // The link's hold below what the operator's override runs at (100 at most: above, the model
    // runs at XM / 100 already): the factor the pace counts the unit's motion at.
    const int base = std::min(100, state.overridePercent);
    m_pace.setLinkRate(want < base ? static_cast<double>(want) / base : 1.0);
    const bool forFaults = want < state.overridePercent && m_linkPercent == want;
    if (forFaults != state.overrideHeldForFaults) {
        state.overrideHeldForFaults = forFaults;
        m_host.markDirty();
    }
    if (want != state.overrideSentPercent) {
        m_host.send(cmd::multiplier(want), [this](const Outcome &o) {
            m_host.unitError(o, "keeping the feed override within the link (XM)",
                             MachineMode::Alarm);
        });
        m_host.markDirty(); // the override held (MachineState::overrideHeldPercent) changes
        state.overrideSentPercent = want; // the reply confirms it (noteOutputsAccepted)
    }
}

} // namespace frezka::driver
