#pragma once
// UnitControls: the unit's settings an operator changes by hand: MPG, spindle, outputs, feed
// override, and raw console commands.
//
// Contract: each is checked against the unit's variant and firmware (an MPG needs v10, XM v19;
// a GVE84 switches its spindle relay on output 0 instead of !7V) and the machine's mode, then
// queued as one command whose accepted reply updates MachineState; a refusal of the unit is an
// alarm. A raw command is parsed and validated like any other, refused when it would disturb a
// running job (motion, queue and counter commands), and its reply is logged. No fields: what
// they set lives in the state.

#include "driver/link/machinestate.h"

#include <cstdint>
#include <optional>
#include <string>

namespace frezka::driver {

class CoreHost;
class Job;

class UnitControls
{
public:
    UnitControls(CoreHost &host, Job &job)
        : m_host(host)
        , m_job(job)
    {}

    // Each: nullopt when accepted, else why not.
    std::optional<MachineError> setMpg(bool on);
    std::optional<MachineError> setSpindleRpm(double rpm);
    // Output OUTn on or off (O0 with its port bit changed, the other outputs as they are).
    std::optional<MachineError> setOutput(int output, bool on);
    std::optional<MachineError> setOverride(int percent);
    std::optional<MachineError> overrideStep(bool up);
    std::optional<MachineError> sendRaw(const std::string &text);

private:
    MachineState &state();

    CoreHost &m_host;
    Job &m_job;
};

} // namespace frezka::driver
