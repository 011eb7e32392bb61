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

// !7V for a speed asked (per mille; the program's S): scaled by the spindle override, and
// noted in the state as the speed asked (a later override scales it).
protocol::Command spindleSpeedCommand(CoreHost &host, int askedPermille);

class UnitControls
{
public:
    UnitControls(CoreHost &host, Job &job)
        : m_host(host)
        , m_job(job)
    {}

    // Each: nullopt when accepted, else why not.
    std::optional<MachineError> setMpg(bool on);
    // The speed asked, sent scaled by the spindle override.
    std::optional<MachineError> setSpindleRpm(double rpm);
    // The spindle override (kSpindleOverrideMinPercent .. Max): a turning spindle takes it at
    // once (!7V), every later spindle speed (the job's, the buttons', a hold's restart) with it.
    std::optional<MachineError> setSpindleOverride(int percent);
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
