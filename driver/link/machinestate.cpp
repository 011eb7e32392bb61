// The English names of the modes and activities (machinestate.h).

#include "machinestate.h"

namespace frezka::driver {

const char *machineModeName(MachineMode mode)
{
    switch (mode) {
    case MachineMode::Disconnected:
        return "Disconnected";
    case MachineMode::Connecting:
        return "Connecting";
    case MachineMode::Idle:
        return "Idle";
    case MachineMode::Homing:
        return "Homing";
    case MachineMode::Jogging:
        return "Jogging";
    case MachineMode::Running:
        return "Running";
    case MachineMode::Stopping:
        return "Stopping";
    case MachineMode::Paused:
        return "Paused";
    case MachineMode::ToolLifted:
        return "Tool lifted";
    case MachineMode::Alarm:
        return "Alarm";
    case MachineMode::LinkLost:
        return "Link lost";
    }
    return "?";
}

const char *machineActivityName(MachineActivity activity)
{
    switch (activity) {
    case MachineActivity::None:
        return "None";
    case MachineActivity::Connecting:
        return "Connecting";
    case MachineActivity::Homing:
        return "Homing";
    case MachineActivity::Jogging:
        return "Jogging";
    case MachineActivity::Job:
        return "Job";
    case MachineActivity::CheckingProgress:
        return "Checking progress";
    case MachineActivity::Probing:
        return "Probing";
    case MachineActivity::PathFault:
        return "Path fault";
    case MachineActivity::ReturnToPath:
        return "Return to path";
    case MachineActivity::ToolLift:
        return "Tool lift";
    }
    return "?";
}

} // namespace frezka::driver
