// Machine profile: rules that tie keys to each other and to the unit variant, the built-in
// defaults per variant, output bits and the EEPROM image (docs/gve-protocol.md §1, §10, §12).
#include "machine/machineconfig.h"

#include <QDir>
#include <QFileInfo>

#include <algorithm>
#include <charconv>
#include <cmath>

namespace frezka::machine {

namespace {

std::string fmt(double v)
{
    char buf[32];
    auto [end, ec] = std::to_chars(buf, buf + sizeof buf, v);
    return ec == std::errc() ? std::string(buf, end) : std::string("?");
}

std::string axisKey(int i)
{
    static const char *keys[] = {"axes.x", "axes.y", "axes.z", "axes.a"};
    return keys[i];
}

struct Rules
{
    const MachineConfig &c;
    const protocol::VariantInfo &info;
    std::vector<ConfigError> errors;

    void fail(const std::string &key, const std::string &what)
    {
        errors.push_back({ConfigErrorCode::Inconsistent, key, key + ": " + what});
    }

    void unit()
    {
        const auto &rates = info.maxPulseRates;
        if (std::find(rates.begin(), rates.end(), c.unit.maxPulseRate) == rates.end()) {
            std::string list;
            for (int r : rates)
                list += (list.empty() ? "" : ", ") + std::to_string(r);
            fail("unit.maxPulseRate", "is " + std::to_string(c.unit.maxPulseRate) + ", a " +
                                          std::string(info.displayName) + " is made for " + list +
                                          " pulses/s; use the rate of your unit");
        }
        const auto &bauds = info.bauds;
        if (std::find(bauds.begin(), bauds.end(), c.link.baud) == bauds.end()) {
            std::string list;
            for (int b : bauds)
                list += (list.empty() ? "" : ", ") + std::to_string(b);
            fail("link.baud", "is " + std::to_string(c.link.baud) + ", a " +
                                  std::string(info.displayName) + " talks at " + list +
                                  " Bd; set the rate its switches select");
        }
        if (c.link.port.empty())
            fail("link.port", "is empty; give a serial port such as /dev/ttyUSB0, or \"emulator\"");
    }

    void axes()
    {
        bool any = false;
        for (int i = 0; i < kAxisCount; ++i) {
            const AxisConfig &a = c.axes[static_cast<std::size_t>(i)];
            if (!a.present)
                continue;
            any = true;
            const std::string k = axisKey(i);
            if (i >= info.axisCount)
                fail(k + ".present", "a " + std::string(info.displayName) + " has no " +
                                         kAxisLetters[static_cast<std::size_t>(i)] +
                                         " axis; set it to false");
            if (a.softMinMm >= a.softMaxMm)
                fail(k + ".softMaxMm", "must be greater than softMinMm (" + fmt(a.softMinMm) + ")");
            if (a.rapidMmPerMin > a.maxSpeedMmPerMin)
                fail(k + ".rapidMmPerMin", "is " + fmt(a.rapidMmPerMin) +
                                               ", must not exceed maxSpeedMmPerMin (" +
                                               fmt(a.maxSpeedMmPerMin) + ")");
            const double limit = c.unit.maxPulseRate / a.stepsPerMm * 60.0;
            if (a.maxSpeedMmPerMin > limit)
                fail(k + ".maxSpeedMmPerMin",
                     "is " + fmt(a.maxSpeedMmPerMin) + " mm/min, but at " + fmt(a.stepsPerMm) +
                         " steps/mm the unit's " + std::to_string(c.unit.maxPulseRate) +
                         " pulses/s allow at most " + fmt(std::floor(limit)) +
                         " mm/min; lower it or raise unit.maxPulseRate");
            if (a.accelMmPerS2 * a.stepsPerMm < 1000)
                fail(k + ".accelMmPerS2", "times stepsPerMm must be at least 1000 pulses/s² "
                                          "(the unit's smallest acceleration, A1); raise it");
            const HomingConfig &h = a.homing;
            if (h.direction == 0)
                fail(k + ".homing.direction", "must be -1 or +1");
            if (h.order > 0 && (h.homePositionMm < a.softMinMm || h.homePositionMm > a.softMaxMm))
                fail(k + ".homing.homePositionMm",
                     "is " + fmt(h.homePositionMm) + ", must lie within the soft limits " +
                         fmt(a.softMinMm) + " .. " + fmt(a.softMaxMm));
        }
        if (!any)
            fail("axes", "no axis is present; set present to true for the machine's axes");
    }

    void features()
    {
        const bool is64 = info.variant == protocol::Variant::Gve64 ||
                          info.variant == protocol::Variant::Gve64Phantom;
        const bool fwMpg = info.hasMpg && (!is64 || c.unit.firmwareVersion >= 10);
        const bool fwVk = info.hasVlVkXmNa && (!is64 || c.unit.firmwareVersion >= 19);
        if (c.eeprom.mpg != MpgMode::Off && !fwMpg)
            fail("eeprom.mpg", "this unit (firmware " + std::to_string(c.unit.firmwareVersion) +
                                   ") has no MPG handwheel; set \"off\"");
        if ((c.eeprom.mpg == MpgMode::OnRotaryA || c.eeprom.mpg == MpgMode::OnRotaryAWithLimits) &&
            info.variant != protocol::Variant::Gve114)
            fail("eeprom.mpg", "only a GVE114 drives the rotary axis from the MPG; use \"on\"");
        if (c.motion.speedMode == SpeedModeChoice::Vk && !fwVk)
            fail("motion.speedMode", "this unit's firmware has no VK; use \"vn\" or \"auto\"");
        if (c.motion.speedMode == SpeedModeChoice::Vk && c.axes[3].present)
            fail("motion.speedMode", "VK ignores the rotary axis A; use \"vn\" or \"auto\"");
        const protocol::Features fw = protocol::featuresOf(info.variant, c.unit.firmwareVersion);
        for (int i = 0; i < kAxisCount && !fw.switchHoming; ++i) {
            const AxisConfig &a = c.axes[static_cast<std::size_t>(i)];
            if (a.present && a.homing.order > 0)
                fail(axisKey(i) + ".homing.order",
                     "this unit's firmware (v" + std::to_string(c.unit.firmwareVersion) +
                         ") has no W (homing to a switch comes with IP64MPG v10); set 0 and "
                         "set the position by hand, or update the unit");
        }
        if (info.variant == protocol::Variant::Gve64Phantom &&
            c.eeprom.stepEdge == StepEdge::Rising)
            fail("eeprom.stepActiveEdge", "a GVE64 PHANTOM steps on the falling edge only (its "
                                          "STEP polarity cannot be changed); set \"default\" or "
                                          "\"falling\" and use drivers that take that edge");
        if (c.unit.startInput != 0 &&
            (c.unit.startInput < 3 || info.variant == protocol::Variant::Gve84))
            fail("unit.startInput", "must be 0 (no START button) or an input 3..7 (GVE64/GVE114 "
                                    "only; the GVE84's inputs are its home switches)");
        if (c.unit.address != 0 && info.variant != protocol::Variant::Gve114)
            fail("unit.address", "must be 0: only a GVE114 is ordered with another address (to "
                                 "share its line with other units)");
        if (c.eeprom.homingInput != 0 && (c.eeprom.homingInput < 3 || !info.hasMpg))
            fail("eeprom.homingInput", "must be 0 (off) or an input 3..7 (GVE64/GVE114 only)");
        if (c.eeprom.aSlavedTo != 0 && info.axisCount < 4)
            fail("eeprom.aSlavedTo",
                 "a " + std::string(info.displayName) + " has no A axis; set 0");
        const bool withLimits =
            c.eeprom.mpg == MpgMode::OnWithLimits || c.eeprom.mpg == MpgMode::OnRotaryAWithLimits;
        for (int i = 0; i < info.axisCount && withLimits; ++i) {
            const AxisConfig &a = c.axes[static_cast<std::size_t>(i)];
            if (a.present && (a.softMinMm < 0 || a.softMaxMm > 10000))
                fail(axisKey(i) + ".softMinMm", "the MPG with limits stores the soft limits in "
                                                "the unit, which takes 0 .. 10000 mm; move the "
                                                "limits into that range or use mpg \"on\"");
        }
        for (int i = 0; i < kAxisCount && c.eeprom.mpg != MpgMode::Off; ++i) {
            const AxisConfig &a = c.axes[static_cast<std::size_t>(i)];
            if (a.present && c.eeprom.mpgMaxSpeedMmPerS * a.stepsPerMm > c.unit.maxPulseRate / 2.0)
                fail("eeprom.mpgMaxSpeedMmPerS",
                     "is " + fmt(c.eeprom.mpgMaxSpeedMmPerS) +
                         " mm/s, more than half the "
                         "unit's pulse rate on axis " +
                         kAxisLetters[static_cast<std::size_t>(i)] + " (at most " +
                         fmt(c.unit.maxPulseRate / 2.0 / a.stepsPerMm) + " mm/s); lower it");
        }
    }

    // The tool sensor's position and its probe's range inside the soft limits, the slow probe
    // no faster than the fast one.
    void toolSensor()
    {
        const ToolSensorConfig &k = c.tools.sensor;
        if (!k.enabled)
            return;
        const double at[3] = {k.xMm, k.yMm, k.clearanceZMm};
        const char *keys[3] = {"tools.sensor.xMm", "tools.sensor.yMm", "tools.sensor.clearanceZMm"};
        for (int i = 0; i < 3; ++i) {
            const AxisConfig &a = c.axes[static_cast<std::size_t>(i)];
            if (a.present && (at[i] < a.softMinMm || at[i] > a.softMaxMm))
                fail(keys[i], "is " + fmt(at[i]) + " mm, outside axis " + kAxisLetters[i] +
                                  "'s soft limits " + fmt(a.softMinMm) + " .. " + fmt(a.softMaxMm) +
                                  " mm; measure the sensor's position in "
                                  "machine coordinates again");
        }
        const AxisConfig &z = c.axes[2];
        if (z.present && k.clearanceZMm - k.travelMm < z.softMinMm)
            fail("tools.sensor.travelMm",
                 "is " + fmt(k.travelMm) + " mm: the probe would go below Z's soft limit " +
                     fmt(z.softMinMm) + " mm; at most " + fmt(k.clearanceZMm - z.softMinMm) +
                     " mm from this clearance");
        if (k.slowFeedMmPerMin > k.feedMmPerMin)
            fail("tools.sensor.slowFeedMmPerMin",
                 "is " + fmt(k.slowFeedMmPerMin) + " mm/min, faster than the first probe (" +
                     fmt(k.feedMmPerMin) + " mm/min); the second probe is the slow one");
    }

    void outputs()
    {
        const int count = info.variant == protocol::Variant::Gve84 ? 1 : 3;
        for (int i = 0; i < 3; ++i) {
            const OutputFunction f = c.outputs.out[static_cast<std::size_t>(i)];
            const std::string key = "outputs.out" + std::to_string(i + 1);
            if (i >= count && f != OutputFunction::Unused)
                fail(key, "a GVE84 has one relay (out1); set \"unused\"");
            if (f == OutputFunction::Spindle && info.variant != protocol::Variant::Gve84)
                fail(key, "the spindle is OUT0 with the analog output on this unit; choose "
                          "another function");
        }
        if (c.outputs.mist != OutputFunction::Unused && outputBit(c, c.outputs.mist) == 0)
            fail("outputs.mist", "no output (out1..out3) has this function; map one or set "
                                 "\"unused\"");
    }
};

} // namespace

std::vector<ConfigError> lineUnitsProblems(const MachineConfig &config); // lineunits.cpp

std::vector<ConfigError> checkConsistency(const MachineConfig &config)
{
    Rules rules{config, protocol::variantInfo(config.unit.variant), {}};
    rules.unit();
    rules.axes();
    rules.features();
    rules.outputs();
    rules.toolSensor();
    for (ConfigError &e : lineUnitsProblems(config))
        rules.errors.push_back(std::move(e));
    return rules.errors;
}

MachineConfig defaultMachineConfig(protocol::Variant variant)
{
    const protocol::VariantInfo &info = protocol::variantInfo(variant);
    MachineConfig c;
    c.name = std::string(info.displayName) + " mill";
    c.unit.variant = variant;
    c.unit.maxPulseRate = info.defaultMaxPulseRate;
    c.unit.firmwareVersion = variant == protocol::Variant::Gve84    ? 3
                             : variant == protocol::Variant::Gve114 ? 16
                                                                    : 19;
    c.link.baud = info.defaultBaud;
    const double travel[4] = {400, 300, 120, 360};
    for (int i = 0; i < kAxisCount; ++i) {
        AxisConfig &a = c.axes[static_cast<std::size_t>(i)];
        a.present = i < 3;
        a.stepsPerMm = i == 3 ? 100 : 200; // 1.8° motor, 1/8 step... A: per degree
        a.softMinMm = i == 2 ? -travel[i] : 0;
        a.softMaxMm = i == 2 ? 0 : travel[i];
        a.maxSpeedMmPerMin = i == 2 ? 2000 : 4000;
        a.rapidMmPerMin = a.maxSpeedMmPerMin;
        a.accelMmPerS2 = i == 2 ? 200 : 400;
        a.maxJumpMmPerS = 4;
        a.homing.order = i == 2 ? 1 : (i < 2 ? 2 : 0);
        a.homing.direction = i == 2 ? 1 : -1;
        a.homing.travelMm = travel[i] + 20;
        a.homing.towardMmPerS = 10;
        a.homing.offMmPerS = 1;
        a.homing.backOffMm = 10;
        a.homing.homePositionMm = 0;
    }
    if (variant == protocol::Variant::Gve84) {
        c.outputs.out = {OutputFunction::Spindle, OutputFunction::Unused, OutputFunction::Unused};
        c.outputs.mist = OutputFunction::Unused;
        c.eeprom.mpg = MpgMode::Off;
    }
    if (variant == protocol::Variant::Gve114 || variant == protocol::Variant::Gve64Phantom) {
        // A faster unit: finer steps at the same speeds.
        for (int i = 0; i < 3; ++i) {
            c.axes[static_cast<std::size_t>(i)].stepsPerMm = 400;
            c.axes[static_cast<std::size_t>(i)].maxSpeedMmPerMin = i == 2 ? 3000 : 6000;
            c.axes[static_cast<std::size_t>(i)].rapidMmPerMin =
                c.axes[static_cast<std::size_t>(i)].maxSpeedMmPerMin;
            c.axes[static_cast<std::size_t>(i)].accelMmPerS2 = i == 2 ? 300 : 600;
        }
    }
    return c;
}

std::string toolTablePath(const MachineConfig &config, const std::string &profilePath)
{
    const std::string &file = config.tools.tableFile;
    if (file.empty())
        return {};
    const QFileInfo table(QString::fromStdString(file));
    if (table.isAbsolute() || profilePath.empty())
        return table.filePath().toStdString();
    const QDir dir = QFileInfo(QString::fromStdString(profilePath)).absoluteDir();
    return QDir::cleanPath(dir.filePath(table.filePath())).toStdString();
}

std::vector<std::string> subroutineFolders(const MachineConfig &config,
                                           const std::string &profilePath)
{
    std::vector<std::string> out;
    const QDir base = QFileInfo(QString::fromStdString(profilePath)).absoluteDir();
    for (const QString &folder :
         QString::fromStdString(config.program.subroutinePath).split(QLatin1Char(':'))) {
        const QString f = folder.trimmed();
        if (f.isEmpty())
            continue;
        out.push_back(QDir::isAbsolutePath(f) || profilePath.empty()
                          ? QDir::cleanPath(f).toStdString()
                          : QDir::cleanPath(base.filePath(f)).toStdString());
    }
    return out;
}

int wireAxisCount(const MachineConfig &config)
{
    return protocol::variantInfo(config.unit.variant).axisCount;
}

std::uint8_t outputBit(const MachineConfig &config, OutputFunction function)
{
    return outputPortBit(config.unit.variant, outputNumber(config, function));
}

int outputNumber(const MachineConfig &config, OutputFunction function)
{
    if (function == OutputFunction::Unused)
        return -1;
    if (config.unit.variant == protocol::Variant::Gve84)
        return config.outputs.out[0] == function ? 0 : -1;
    for (std::size_t i = 0; i < 3; ++i) {
        if (config.outputs.out[i] == function)
            return static_cast<int>(i) + 1;
    }
    return -1;
}

std::uint8_t outputPortBit(protocol::Variant variant, int output)
{
    // Port 0 bits: bit0 OUT0, bit1 OUT3, bit2 OUT1, bit3 OUT2 (§10). GVE84: its relay is bit0.
    static constexpr std::uint8_t bits[4] = {0x01, 0x04, 0x08, 0x02};
    if (output < 0 || output > (variant == protocol::Variant::Gve84 ? 0 : 3))
        return 0;
    return bits[output];
}

} // namespace frezka::machine
