// JobOverride: the feed override as the unit runs it during a job. See joboverride.h.

#include "joboverride.h"

#include "driver/link/corehost.h"
#include "driver/link/jobpace.h"
#include "driver/link/machinecore_internal.h"

#include <algorithm>

namespace frezka::driver {

using namespace frezka::protocol;

int JobOverride::toSend(int asked, bool streaming) const
{
    if (!streaming || asked <= 100)
        return asked;
    // In steps of 5 %, raised again only two steps up: each XM is a round trip outside the
    // packets, and the ceiling wavers by a step as the window moves (160/165 % in turn).
    const int ceiling = m_pace.overrideCeiling() / 5 * 5;
    const int sent = m_host.liveState().overrideSentPercent;
    return std::min(asked, ceiling < sent || ceiling >= sent + 10 ? ceiling : sent);
}

void JobOverride::follow(bool streaming)
{
    MachineState &state = m_host.liveState();
    if (!state.features.vlVkXmNa)
        return;
    const int want = toSend(state.overridePercent, streaming);
    if (want < state.overridePercent && streaming)
        m_linkMin = m_linkMin ? std::min(m_linkMin, want) : want;
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
