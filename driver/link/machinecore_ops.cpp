// MachineCore: machine operations (issue 5 item 4): pause/resume/abort, tool lift with
// KEEP/RESTORE, homing, jog, MPG, spindle, outputs, feed override, raw commands, interrupts.

#include "machinecore.h"

#include "driver/link/machinecore_internal.h"
#include "machine/homing.h"

#include "protocol/commandparser.h"

#include <algorithm>
#include <cmath>

namespace frezka::driver {

using namespace frezka::protocol;
using detail::notNow;
using detail::refusal;

std::int64_t MachineCore::stepsFromMm(int axis, double mm) const
{
    return std::llround(mm * m_config.axes[static_cast<std::size_t>(axis)].stepsPerMm);
}

double MachineCore::mmFromSteps(int axis, std::int64_t steps) const
{
    return static_cast<double>(steps) / m_config.axes[static_cast<std::size_t>(axis)].stepsPerMm;
}

// ---- run / pause / resume / abort ----

MachineCore::Result MachineCore::run(machine::UnitProgram program, double now)
{
    if (auto refused = m_job.start(std::move(program), now))
        return refused;
    m_toolLift.reset();
    pump(now);
    return std::nullopt;
}

// ---- pause, resume, abort (hold.h) --------------------------------------------------------

MachineCore::Result MachineCore::pause(double now)
{
    return accepted(m_hold.pause(), now);
}

MachineCore::Result MachineCore::resume(double now)
{
    return accepted(m_hold.resume(), now);
}

MachineCore::Result MachineCore::abort(double now)
{
    return accepted(m_hold.abort(), now);
}

// ---- tool lift (toollift.h) ----------------------------------------------------------------

MachineCore::Result MachineCore::toolLift(bool stopSpindle, double now)
{
    return accepted(m_toolLift.lift(stopSpindle), now);
}

MachineCore::Result MachineCore::toolLower(int speedPulsesPerS, double now)
{
    return accepted(m_toolLift.lower(speedPulsesPerS), now);
}

// ---- homing (homingcycle.h), jog (jog.h) ----------------------------------------------------

MachineCore::Result MachineCore::home(double now, unsigned axisMask)
{
    bool queued = false;
    if (auto refused = m_homing.start(axisMask, &queued))
        return refused;
    if (queued)
        pump(now);
    return std::nullopt;
}

MachineCore::Result MachineCore::accepted(Result refused, double now)
{
    if (!refused)
        pump(now);
    return refused;
}

MachineCore::Result MachineCore::jogStep(int axis, double distanceMm, double speedMmPerMin,
                                         double now)
{
    return accepted(m_jog.step(axis, distanceMm, speedMmPerMin), now);
}

MachineCore::Result MachineCore::jogContinuous(int axis, int direction, double speedMmPerMin,
                                               double now)
{
    return accepted(m_jog.continuous(axis, direction, speedMmPerMin), now);
}

MachineCore::Result MachineCore::writeEeprom(double now)
{
    return accepted(m_eeprom.write(), now);
}

MachineCore::Result MachineCore::jogStop(double now)
{
    return accepted(m_jog.stop(), now);
}

// ---- MPG, spindle, outputs, override, raw (unitcontrols.h) ---------------------------------

MachineCore::Result MachineCore::setMpg(bool on, double now)
{
    return accepted(m_controls.setMpg(on), now);
}

MachineCore::Result MachineCore::setSpindleRpm(double rpm, double now)
{
    return accepted(m_controls.setSpindleRpm(rpm), now);
}

MachineCore::Result MachineCore::setOutputs(std::uint8_t mask, std::uint8_t activeHigh, double now)
{
    return accepted(m_controls.setOutputs(mask, activeHigh), now);
}

MachineCore::Result MachineCore::setOverride(int percent, double now)
{
    return accepted(m_controls.setOverride(percent), now);
}

MachineCore::Result MachineCore::overrideStep(bool up, double now)
{
    return accepted(m_controls.overrideStep(up), now);
}

MachineCore::Result MachineCore::sendRaw(const std::string &text, double now)
{
    return accepted(m_controls.sendRaw(text), now);
}

} // namespace frezka::driver
