#pragma once
// EepromSync: the unit's EEPROM settings (§12) against the machine profile.
//
// Contract: compare() queues a read of every entry the profile sets (machine::eepromEntries;
// floats and 32-bit values only where the firmware has them) and lists each difference in
// MachineState::eepromDifferences (and the log), changing nothing on the unit. write() (Idle
// only, and only when the operator asks) queues the writes of the same entries, then compares
// again. A refusal of the unit is an alarm. No fields: the results live in the state.

#include "driver/link/machinestate.h"

#include <optional>

namespace frezka::driver {

class CoreHost;

class EepromSync
{
public:
    explicit EepromSync(CoreHost &host)
        : m_host(host)
    {}

    void compare();
    // nullopt when accepted, else why not.
    std::optional<MachineError> write();

private:
    MachineState &state();

    CoreHost &m_host;
};

} // namespace frezka::driver
