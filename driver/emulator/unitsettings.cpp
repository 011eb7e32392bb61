// The unit's EEPROM decoded into its behaviour. See unitsettings.h; the readings are listed in
// docs/emulator.md ("EEPROM-driven behaviour").

#include "driver/emulator/unitsettings.h"

#include <algorithm>
#include <cmath>

namespace frezka::emulator {

namespace {

bool inRange(double v, double lo, double hi)
{
    return std::isfinite(v) && v >= lo && v <= hi;
}

// 0x05 (manuals 11.5). GVE84/GVE64: bits 0-3 DIR of X..A, bit 4 STEP of all axes (set =
// falling edge). GVE114: bits 0-3 STEP of X..A (its example 0xAC: "X,Y falling, Z,A rising",
// so set = rising), bits 4-7 DIR. A cleared DIR bit reverses the axis (the example's "X
// reversed" has bit 4 cleared), the reading machine/eepromimage.cpp writes by.
void decodeStepDir(std::uint8_t b, protocol::Variant variant, UnitSettings &s)
{
    const bool is114 = variant == protocol::Variant::Gve114;
    for (int i = 0; i < 4; ++i) {
        const int dirBit = is114 ? 4 + i : i;
        s.dirReversed[i] = !((b >> dirBit) & 1);
        s.stepRisingEdge[i] = is114 ? ((b >> i) & 1) != 0 : !((b >> 4) & 1);
    }
}

// 0x06 and the MPG parameters (manuals 12.2, 12.4-12.9): out of range disables the MPG.
MpgSettings decodeMpg(const Eeprom &e, protocol::Variant variant, int maxPulseRate)
{
    MpgSettings m;
    const std::uint8_t mode = e.byte(0x06);
    const bool is114 = variant == protocol::Variant::Gve114;
    const bool known = mode == 0x01 || mode == 0x02 || (is114 && (mode == 0x81 || mode == 0x82));
    m.withLimits = (mode & 0x7F) == 0x02;
    m.fourthIsA = is114 && (mode & 0x80);
    const int axes = m.fourthIsA ? 4 : 3; // GVE64 has no A limits nor A steps in its table
    bool ok = known;
    double fastest = 0;
    for (int i = 0; i < 4; ++i) {
        m.lowerMm[i] = e.readFloat(0x10 + 4 * i);
        m.upperMm[i] = e.readFloat(0x20 + 4 * i);
        m.stepsPerMm[i] = e.readFloat(0x30 + 4 * i);
        if (i < axes) {
            ok = ok && inRange(m.lowerMm[i], 0, 10000) && inRange(m.upperMm[i], 0, 10000) &&
                 inRange(m.stepsPerMm[i], 1, 10000);
            fastest = std::max(fastest, m.stepsPerMm[i]);
        }
    }
    m.accelMmPerS2 = e.readFloat(0x40);
    m.maxSpeedMmPerS = e.readFloat(0x44);
    const std::uint32_t delayMs = e.readUint32(0x48);
    m.delayS = delayMs / 1000.0;
    ok = ok && inRange(m.accelMmPerS2, 1, 10000) && m.maxSpeedMmPerS > 0 &&
         inRange(m.maxSpeedMmPerS * fastest, 0, maxPulseRate / 2.0) && delayMs >= 1 &&
         delayMs <= 2000;
    if (is114) {
        const double multiplier = e.readFloat(0x60);
        ok = ok && inRange(multiplier, 1e-4, 1e4);
        m.stepMm = 0.01 * multiplier;
    }
    m.enabled = ok;
    return m;
}

} // namespace

UnitSettings decodeSettings(const Eeprom &e, protocol::Variant variant, int maxPulseRate)
{
    UnitSettings s;
    const bool is84 = variant == protocol::Variant::Gve84;
    for (int i = 0; i < 3; ++i)
        s.outputFunction[i] = static_cast<OutputFunction>(e.byte(0x01 + i));
    decodeStepDir(e.byte(0x05), variant, s);
    const double delay = std::min(e.byte(0xFD), std::uint8_t{50}) * 0.1; // max 5 s
    s.brakeReleaseDelayS = delay;
    if (is84)
        return s; // the GVE84 has the relay, STEP/DIR and the brake delay only
    s.pwmBreakout = e.byte(0x04) == 0x01;
    s.mpg = decodeMpg(e, variant, maxPulseRate);
    const std::uint8_t homing = e.byte(0x07);
    s.homingInput = homing >= 3 && homing <= 7 ? homing : -1;
    s.interruptEnable = e.byte(0x08);
    s.interruptEnableHigh = e.byte(0x09);
    s.polarity = e.byte(0x0A);
    s.polarityHigh = e.byte(0x0B);
    const std::uint8_t slave = e.byte(0x0C);
    s.aSlavedTo = slave >= 1 && slave <= 3 ? slave - 1 : -1;
    s.highBaudRange = variant == protocol::Variant::Gve114 && e.byte(0x0D) == 0x01;
    if (variant != protocol::Variant::Gve114) {
        for (int i = 0; i < 3; ++i)
            s.homingSpeedMmPerS[i] = e.readFloat(0x50 + 4 * i);
    }
    return s;
}

int switchBaud(int switchPosition, bool highRange)
{
    static constexpr int kLow[] = {19200, 38400, 57600, 115200};
    static constexpr int kHigh[] = {921600, 460800, 230400, 115200};
    const int p = std::clamp(switchPosition, 0, 3);
    return highRange ? kHigh[p] : kLow[p];
}

int switchPositionFor(int baud)
{
    for (bool high : {false, true}) {
        for (int p = 0; p < 4; ++p) {
            if (switchBaud(p, high) == baud)
                return p;
        }
    }
    return -1;
}

double analogOutput(int permille, AnalogJumper jumper, bool breakout)
{
    const double fraction = std::clamp(permille, 0, 1000) / 1000.0;
    const double level = breakout ? 1.0 - fraction : fraction;
    return jumper == AnalogJumper::Analog ? 10.0 * level : 100.0 * level;
}

} // namespace frezka::emulator
