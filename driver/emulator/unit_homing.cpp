// Homing: the progress of W (docs/gve-protocol.md §6) and homing started from an input
// (EEPROM 0x07; GVE64 manual 12.3).
//
// Homing from an input (0x07 = 3..7): armed while the MPG is on and silent (Y&; Y+ and Y-
// disable it), the wheel enabled, the machine idle and no interrupt pending; the input must be
// enabled in 0x08 and active by 0x0A for 1 s; once per press (emulator choice). The axis is the
// wheel's axis switch. It seeks the switch toward the lower limit (adopted reading: the manuals do
// not give the direction) over the axis' travel (upper - lower limit) at the homing speed (GVE64
// 0x50..0x58; the GVE114 has none: adopted reading, the MPG top speed 0x44), then backs off at 1
// mm/s for at most 10 mm, and sets the counter to the lower limit. No reply is sent: the PC sees it
// in its polls.

#include "driver/emulator/unit_impl.h"

#include <algorithm>
#include <cmath>

namespace frezka::emulator {

bool Unit::Impl::homeSwitchPressed() const
{
    return (inputLevels() >> homing->axis) & 1;
}

void Unit::Impl::checkHoming()
{
    if (!homing || (deferred != Deferred::Homing && !homing->fromInput))
        return;
    const bool pressed = homeSwitchPressed();
    if (!homing->backingOff) {
        if (pressed) {
            engine.abortHead();
            homing->backingOff = true;
            if (homing->backSteps == 0) {
                finishHoming(readings::kHomingNotFoundCode);
                return;
            }
            MotionVector v;
            v.isHoming = true;
            v.steps[homing->axis] = homing->backSteps;
            v.speedPulsesPerS = homing->backRate;
            engine.enqueue(v);
        } else if (engine.isIdle()) {
            finishHoming(readings::kHomingNotFoundCode);
        }
        return;
    }
    if (!pressed) {
        engine.abortHead();
        finishHoming(0);
    } else if (engine.isIdle()) {
        finishHoming(readings::kHomingNotFoundCode);
    }
}

void Unit::Impl::finishHoming(int code)
{
    if (homing && homing->fromInput) { // no reply; on success the counter is set (unit_mpg.cpp)
        const int axis = homing->axis;
        homing.reset();
        if (code == 0)
            engine.setPosition(axis,
                               std::llround(cfg.mpg.lowerMm[axis] * cfg.mpg.stepsPerMm[axis]));
        return;
    }
    homing.reset();
    if (deferred != Deferred::Homing)
        return;
    deferred = Deferred::None;
    const Reply r{code, {}};
    sendReply(r);
    lastReply = formatReply(r);
}

bool Unit::Impl::inputHomingArmed() const
{
    return cfg.homingInput >= 0 && mpg == Mpg::Silent && cfg.mpg.enabled && engine.isIdle() &&
           !homing && !inta && !kept && deferred == Deferred::None &&
           ((cfg.interruptEnable >> cfg.homingInput) & 1);
}

void Unit::Impl::checkInputHoming(std::uint16_t active)
{
    const bool pressed = cfg.homingInput >= 0 && ((active >> cfg.homingInput) & 1);
    if (!pressed)
        homingInputUsed = false; // one homing per press
    if (!inputHomingArmed() || !pressed || homingInputUsed) {
        homingInputSince = -1;
        return;
    }
    if (homingInputSince < 0)
        homingInputSince = engine.now();
    if (engine.now() >= homingInputSince + kHomingInputHoldS) {
        homingInputSince = -1;
        homingInputUsed = true;
        startInputHoming();
    }
}

void Unit::Impl::startInputHoming()
{
    const MpgSettings &m = cfg.mpg;
    const int axis = wheel.axis;
    if (axis >= info->axisCount || (axis == 3 && !m.fourthIsA))
        return; // the switch stands on the spindle: nothing to home
    const bool is114 = options.variant == protocol::Variant::Gve114;
    const double speedMm = is114 ? m.maxSpeedMmPerS : axis < 3 ? cfg.homingSpeedMmPerS[axis] : 0;
    const double spm = m.stepsPerMm[axis];
    const std::int64_t travel = std::llround((m.upperMm[axis] - m.lowerMm[axis]) * spm);
    if (!(speedMm > 0) || travel <= 0)
        return; // GVE64 manual 12.10: a zero homing speed disables it
    const auto rate = [&](double mmPerS) {
        return static_cast<int>(std::clamp<double>(std::llround(mmPerS * spm), 10, maxRate));
    };
    homing = Homing{axis,          -travel,   static_cast<std::int64_t>(std::llround(10 * spm)),
                    rate(speedMm), rate(1.0), false,
                    true};
    if (!homeSwitchPressed()) {
        MotionVector mv;
        mv.isHoming = true;
        mv.steps[axis] = -travel;
        mv.speedPulsesPerS = homing->seekRate;
        engine.enqueue(mv);
    }
    checkHoming();
}

} // namespace frezka::emulator
