// The MPG handwheel (EEPROM 0x06 and the MPG parameters; GVE64 manual 12.2-12.10, GVE114
// manual 12.2-12.9, docs/gve-protocol.md §13). Homing from an input is in unit_homing.cpp.
//
// The wheel: each detent moves the axis chosen on the axis switch by the step of the step
// switch (x1 = 0.01 mm; GVE114: times the 0x60 multiplier), as a stand-alone move with the MPG
// acceleration (0x40) and top speed (0x44) converted with the axis' steps per mm (0x30..).
// With limits (0x06 = 02/82) the target stays within the lower and upper limits (counter /
// steps per mm is the position in mm). When the wheel has not turned for the MPG delay (0x48)
// and steps remain, the unit brakes along the ramp and drops them. The 4th switch position
// drives A (0x06 = 81/82) or the spindle: adopted reading, each detent changes the spindle by
// 1 permille times the step switch. Out-of-range parameters disable the wheel.

#include "driver/emulator/unit_impl.h"

#include <algorithm>
#include <cmath>

namespace frezka::emulator {

bool Unit::Impl::turnWheel(int detents)
{
    const MpgSettings &m = cfg.mpg;
    if (!info->hasMpg || !mpgOn() || !m.enabled || inta || homing || kept || detents == 0 ||
        deafUntil > engine.now())
        return false;
    wheel.lastTurnAt = engine.now();
    const int axis = wheel.axis;
    if (axis == 3 && !m.fourthIsA) { // the spindle
        spindle = std::clamp(spindle + detents * wheel.multiplier, 0, 1000);
        outputs = spindle == 0 ? (outputs | 0x01) : (outputs & ~0x01);
        noteSpindle();
        return true;
    }
    if (axis >= info->axisCount)
        return false;
    if (!wheel.moving)
        wheel.target = engine.position();
    const double spm = m.stepsPerMm[axis];
    std::int64_t target =
        wheel.target[axis] + std::llround(detents * m.stepMm * wheel.multiplier * spm);
    if (m.withLimits)
        target = std::clamp<std::int64_t>(target, std::llround(m.lowerMm[axis] * spm),
                                          std::llround(m.upperMm[axis] * spm));
    const std::int64_t delta = target - wheel.target[axis];
    if (delta == 0)
        return true;
    MotionVector v;
    v.steps[axis] = delta;
    v.isLine = true;
    v.speedPulsesPerS = m.maxSpeedMmPerS * spm;
    v.brakePulsesPerS = v.speedPulsesPerS;
    v.accelPulsesPerS2 = m.accelMmPerS2 * spm;
    v.serial = ++serial;
    engine.enqueue(v);
    wheel.target[axis] = target;
    wheel.moving = true;
    return true;
}

double Unit::Impl::wheelEventAt() const
{
    double at = kNever;
    if (wheel.moving && !engine.isStopping() && !engine.isHeld())
        at = wheel.lastTurnAt + cfg.mpg.delayS;
    if (homingInputSince >= 0)
        at = std::min(at, homingInputSince + kHomingInputHoldS);
    return at;
}

void Unit::Impl::checkWheel()
{
    if (wheel.moving && engine.isIdle())
        wheel.moving = false;
    if (wheel.moving && !engine.isStopping() && !engine.isHeld() &&
        engine.now() >= wheel.lastTurnAt + cfg.mpg.delayS)
        engine.requestStop(); // the delay is over: brake, drop what is left (onStopped)
}

} // namespace frezka::emulator
