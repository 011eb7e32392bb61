#pragma once
// The commissioning's steps that move nothing (issue 21 item 1), over a UnitChannel: identify
// the unit, check the adopted readings, measure the link, read the EEPROM. Each fills its step
// of the CommissionResult (result and details) and its own part (readings, link, eeprom).
// Nothing here moves an axis or switches an output; the only state they change on the unit is
// what the driver sets again on connecting (checksums, MPG off, B).

#include "protocol/variant.h"
#include "session/commission.h"
#include "session/unitchannel.h"

namespace frezka::session {

struct ProbeContext
{
    UnitChannel &channel;
    const machine::MachineConfig &profile;
    int baud = 115200;
    // Set by identifyUnit (the variant's full set until then).
    protocol::Features features;
    int axisCount = 3;
    bool identified = false;
};

// ? and Q; the variant and firmware against the profile's; MPG off where the unit has one.
void identifyUnit(ProbeContext &context, CommissionResult &result);
// Switches checksums on (%+) and checks each reading (readingchecks.cpp); the rest of the
// steps then talk with checksums.
void checkReadings(ProbeContext &context, CommissionResult &result);
// Round trips per command class, bytes/s, the adapter's latency; proposes link.latencyMs
// (result.profileAfter).
void measureLink(ProbeContext &context, CommissionResult &result);
// Reads every EEPROM setting the profile keeps (machine::eepromEntries) and compares.
void readEeprom(ProbeContext &context, CommissionResult &result);
// Leaves the unit as after a reset as far as the checks touched it: checksums off.
void finishProbe(ProbeContext &context);

} // namespace frezka::session

namespace frezka::driver {
class Transport;
}

namespace frezka::session {

// The four steps above in order over `transport` (opened here, closed at the end); the unit
// answers at `baud`. False (and *error) when the port cannot be opened; a unit that does not
// answer is a step that did not hold, not an error.
bool runUnitProbe(driver::Transport &transport, const machine::MachineConfig &profile, int baud,
                  CommissionResult &result, QString *error);

} // namespace frezka::session
