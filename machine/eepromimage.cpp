// The unit EEPROM settings a machine profile asks for (docs/gve-protocol.md §12).
//
// Adopted reading for the STEP/DIR byte 0x05 (the manuals give only the default FF): a set DIR
// bit is the normal direction, a cleared one reverses the axis. STEP bits by physical edge
// (docs/gve-protocol.md §12): GVE84/GVE64 bit4 set = falling edge, cleared = rising (the
// manuals' text); GVE114 bits 0-3 set = rising edge, cleared = falling (its worked example
// 0xAC: "X,Y falling edge, Z,A rising").
#include "machine/machineconfig.h"

#include <algorithm>
#include <cmath>

namespace frezka::machine {

namespace {

std::uint8_t functionCode(OutputFunction f)
{
    return static_cast<std::uint8_t>(f);
}

std::uint8_t stepDirByte(const MachineConfig &c)
{
    std::uint8_t b = 0xFF;
    const bool is114 = c.unit.variant == protocol::Variant::Gve114;
    // The edge a cleared STEP bit selects on this variant (see the reading above).
    const StepEdge clearedEdge = is114 ? StepEdge::Falling : StepEdge::Rising;
    const bool clearStep = c.eeprom.stepEdge == clearedEdge;
    const int axes = wireAxisCount(c);
    for (int i = 0; i < axes; ++i) {
        if (c.axes[static_cast<std::size_t>(i)].invertDirection)
            b = static_cast<std::uint8_t>(b & ~(1u << (is114 ? 4 + i : i)));
        if (is114 && clearStep)
            b = static_cast<std::uint8_t>(b & ~(1u << i));
    }
    if (!is114 && clearStep)
        b = static_cast<std::uint8_t>(b & ~0x10u);
    return b;
}

std::uint8_t mpgByte(MpgMode m)
{
    switch (m) {
    case MpgMode::On:
        return 0x01;
    case MpgMode::OnWithLimits:
        return 0x02;
    case MpgMode::OnRotaryA:
        return 0x81;
    case MpgMode::OnRotaryAWithLimits:
        return 0x82;
    case MpgMode::Off:
        break;
    }
    return 0xFF;
}

} // namespace

// One line per EEPROM address, in the order of §12: a table, kept whole like the manual's.
std::vector<EepromEntry> eepromEntries(const MachineConfig &c)
{
    using K = EepromKind;
    std::vector<EepromEntry> e;
    const EepromConfig &ee = c.eeprom;
    const auto byte = [&](int addr, int v, const char *what) {
        e.push_back({static_cast<std::uint8_t>(addr), K::Byte, static_cast<double>(v), what});
    };
    if (c.unit.variant == protocol::Variant::Gve84) {
        byte(0x01, functionCode(c.outputs.out[0]), "relay function");
        byte(0x05, stepDirByte(c), "STEP/DIR polarity");
        byte(0xFD, static_cast<int>(std::lround(ee.brakeReleaseDelayS * 10)),
             "brake release delay (0.1 s)");
        return e;
    }
    byte(0x01, functionCode(c.outputs.out[0]), "OUT1 function");
    byte(0x02, functionCode(c.outputs.out[1]), "OUT2 function");
    byte(0x03, functionCode(c.outputs.out[2]), "OUT3 function");
    byte(0x04, ee.pwmBreakout ? 0x01 : 0xFF, "PWM mode");
    byte(0x05, stepDirByte(c), "STEP/DIR polarity");
    byte(0x06, mpgByte(ee.mpg), "MPG mode");
    byte(0x07, ee.homingInput >= 3 ? ee.homingInput : 0xFF, "homing start input");
    byte(0x08, ee.interruptEnable, "interrupt enable IN0-7");
    byte(0x09, ee.interruptEnableHigh, "interrupt enable IN14-15");
    byte(0x0A, ee.polarity, "input polarity IN0-7");
    byte(0x0B, ee.polarityHigh, "input polarity IN14-15");
    byte(0x0C, ee.aSlavedTo ? ee.aSlavedTo : 0xFF, "A axis slaved to");
    static const char *lower[] = {"lower limit X", "lower limit Y", "lower limit Z",
                                  "lower limit A"};
    static const char *upper[] = {"upper limit X", "upper limit Y", "upper limit Z",
                                  "upper limit A"};
    static const char *steps[] = {"steps per mm X", "steps per mm Y", "steps per mm Z",
                                  "steps per mm A"};
    for (int i = 0; i < 4; ++i) {
        const AxisConfig &a = c.axes[static_cast<std::size_t>(i)];
        const auto addr = [&](int base) { return static_cast<std::uint8_t>(base + 4 * i); };
        e.push_back({addr(0x10), K::Float, std::clamp(a.softMinMm, 0.0, 10000.0), lower[i]});
        e.push_back({addr(0x20), K::Float, std::clamp(a.softMaxMm, 0.0, 10000.0), upper[i]});
        e.push_back({addr(0x30), K::Float, a.stepsPerMm, steps[i]});
    }
    e.push_back({0x40, K::Float, ee.mpgAccelMmPerS2, "MPG acceleration"});
    e.push_back({0x44, K::Float, ee.mpgMaxSpeedMmPerS, "MPG max speed"});
    e.push_back({0x48, K::Uint32, static_cast<double>(ee.mpgDelayMs), "MPG delay"});
    e.push_back(
        {0x4C, K::Uint32, static_cast<double>(ee.defaultSpindlePermille), "default spindle speed"});
    if (c.unit.variant == protocol::Variant::Gve114) {
        e.push_back({0x60, K::Float, ee.mpgStepMultiplier, "MPG step multiplier"});
        // The baud range: 230 400-921 600 Bd need 01, 19 200-57 600 need FF; 115 200 is in both.
        if (c.link.baud > 115200)
            byte(0x0D, 0x01, "baud range (01: 115 200-921 600 Bd)");
        else if (c.link.baud < 115200)
            byte(0x0D, 0xFF, "baud range (FF: 19 200-115 200 Bd)");
    } else {
        static const char *homing[] = {"homing speed X", "homing speed Y", "homing speed Z"};
        for (int i = 0; i < 3; ++i) {
            const AxisConfig &a = c.axes[static_cast<std::size_t>(i)];
            const double v = a.present && a.homing.order > 0 ? a.homing.towardMmPerS : 0.0;
            e.push_back({static_cast<std::uint8_t>(0x50 + 4 * i), K::Float, v, homing[i]});
        }
    }
    byte(0xFD, static_cast<int>(std::lround(ee.brakeReleaseDelayS * 10)),
         "brake release delay (0.1 s)");
    return e;
}

} // namespace frezka::machine
