// EepromSync: the unit's EEPROM against the profile. See eepromsync.h.

#include "eepromsync.h"

#include "driver/link/corehost.h"
#include "driver/link/machinecore_internal.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;

MachineState &EepromSync::state()
{
    return m_host.liveState();
}

void EepromSync::compare()
{
    state().eepromDifferences.clear();
    const bool wide = state().features.eepromFloat;
    for (const machine::EepromEntry &e : machine::eepromEntries(m_host.config())) {
        Command c;
        switch (e.kind) {
        case machine::EepromKind::Byte:
            c = cmd::eepromReadByte(e.address);
            break;
        case machine::EepromKind::Float:
            c = cmd::eepromReadFloat(e.address);
            break;
        case machine::EepromKind::Uint32:
            c = cmd::eepromReadUint(e.address);
            break;
        }
        if (!wide && e.kind != machine::EepromKind::Byte)
            continue;
        m_host.send(c, [this, e](const Outcome &o) {
            if (m_host.unitError(o, "reading the EEPROM", MachineMode::Alarm))
                return;
            double have = 0;
            if (e.kind == machine::EepromKind::Byte)
                have = o.reply.hexValue().value_or(0);
            else
                have = o.reply.real().value_or(0);
            const double tolerance = e.kind == machine::EepromKind::Float
                                         ? 1e-4 * std::max(1.0, std::abs(e.value))
                                         : 0.0;
            if (std::abs(have - e.value) > tolerance) {
                const EepromDifference &d = state().eepromDifferences.emplace_back(e, have);
                m_host.markDirty();
                m_host.log("EEPROM differs: " + d.text());
            }
        });
    }
}

std::optional<MachineError> EepromSync::write()
{
    if (state().mode != MachineMode::Idle)
        return detail::notNow("Writing the EEPROM", state().mode);
    const bool wide = state().features.eepromFloat;
    for (const machine::EepromEntry &e : machine::eepromEntries(m_host.config())) {
        Command c;
        switch (e.kind) {
        case machine::EepromKind::Byte:
            c = cmd::eepromWriteByte(e.address, static_cast<int>(std::lround(e.value)));
            break;
        case machine::EepromKind::Float:
            c = cmd::eepromWriteFloat(e.address, e.value);
            break;
        case machine::EepromKind::Uint32:
            c = cmd::eepromWriteUint(e.address, std::llround(e.value));
            break;
        }
        if (!wide && e.kind != machine::EepromKind::Byte)
            continue;
        m_host.send(c, [this, what = e.what](const Outcome &o) {
            m_host.unitError(o, "writing the EEPROM (" + what + ")", MachineMode::Alarm);
        });
    }
    compare();
    return std::nullopt;
}

} // namespace frezka::driver
