// InputHoming: the unit parked in Y& while idle, Y- before motion. See inputhoming.h.

#include "inputhoming.h"

#include "driver/link/corehost.h"

namespace frezka::driver {

using namespace frezka::protocol;

bool InputHoming::wanted(const machine::MachineConfig &config, const Features &unit)
{
    const int input = config.eeprom.homingInput;
    return input >= 3 && input <= 7 && config.eeprom.mpg != machine::MpgMode::Off && unit.mpg;
}

bool InputHoming::wanted() const
{
    return wanted(m_host.config(), m_host.liveState().features);
}

void InputHoming::park()
{
    if (m_parked || !wanted())
        return;
    m_parked = true;
    m_host.send(cmd::mpgSilent(), [this](const Outcome &o) {
        if (m_host.unitError(o, "switching the MPG on for homing from the input (Y&)",
                             MachineMode::Alarm)) {
            m_parked = false;
            return;
        }
        m_host.liveState().mpgOn = true;
        m_host.markDirty();
    });
}

bool InputHoming::unpark()
{
    if (!m_parked)
        return false;
    m_parked = false;
    m_host.send(cmd::mpgOff(), [this](const Outcome &o) {
        if (m_host.unitError(o, "switching the MPG off before moving (Y-)", MachineMode::Alarm)) {
            m_host.clearSteps();
            return;
        }
        m_host.liveState().mpgOn = false;
        m_host.markDirty();
    });
    return true;
}

} // namespace frezka::driver
