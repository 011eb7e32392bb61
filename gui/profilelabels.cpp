#include "profilelabels.h"

#include <QCoreApplication>
#include <QHash>

namespace frezka::gui {
namespace {

struct Label
{
    const char *key;
    const char *text;
};

// Context "frezka::gui::Profile" for lupdate.
#define P(k, t)                                                                                    \
    {                                                                                              \
        k, QT_TRANSLATE_NOOP("frezka::gui::Profile", t)                                            \
    }
const Label kKeys[] = {
    P("name", "Profile name"),
    P("unit", "Unit"),
    P("variant", "Unit type"),
    P("maxPulseRate", "Maximum pulse rate"),
    P("firmwareVersion", "Firmware version"),
    P("link", "Connection"),
    P("port", "Port"),
    P("baud", "Baud rate"),
    P("checksums", "Checksums"),
    P("packets", "Packets"),
    P("packetCommands", "Commands per packet"),
    P("axes", "Axes"),
    P("x", "X axis"),
    P("y", "Y axis"),
    P("z", "Z axis"),
    P("a", "A axis"),
    P("present", "Present"),
    P("stepsPerMm", "Steps per mm"),
    P("invertDirection", "Invert direction"),
    P("softMinMm", "Soft limit min"),
    P("softMaxMm", "Soft limit max"),
    P("maxSpeedMmPerMin", "Maximum speed"),
    P("rapidMmPerMin", "Rapid speed"),
    P("accelMmPerS2", "Acceleration"),
    P("maxJumpMmPerS", "Maximum speed jump at a corner"),
    P("homing", "Homing"),
    P("order", "Order (0 = not homed)"),
    P("direction", "Direction to the switch (-1/+1)"),
    P("travelMm", "Maximum search travel"),
    P("towardMmPerS", "Speed toward the switch"),
    P("offMmPerS", "Speed off the switch"),
    P("backOffMm", "Maximum back-off travel"),
    P("homePositionMm", "Position after homing"),
    P("motion", "Motion"),
    P("junctionDeviationMm", "Corner deviation"),
    P("chordToleranceMm", "Arc chord tolerance"),
    P("pauseMs", "Pause between stand-alone moves"),
    P("speedMode", "Speed mode"),
    P("toolLiftMm", "Tool lift"),
    P("spindle", "Spindle"),
    P("maxRpm", "Maximum speed"),
    P("spinUpMs", "Spin-up wait"),
    P("outputs", "Outputs"),
    P("out1", "OUT1 function"),
    P("out2", "OUT2 function"),
    P("out3", "OUT3 function"),
    P("mist", "Output switched by M7"),
    P("eeprom", "Unit EEPROM"),
    P("sync", "Compare with the unit on connect"),
    P("mpg", "Handwheel (MPG)"),
    P("mpgAccelMmPerS2", "Handwheel acceleration"),
    P("mpgMaxSpeedMmPerS", "Handwheel maximum speed"),
    P("mpgDelayMs", "Handwheel brake delay"),
    P("mpgStepMultiplier", "Handwheel step multiplier"),
    P("homingInput", "Input that starts homing (0 = off)"),
    P("interruptEnable", "Interrupt enable IN0-7"),
    P("interruptEnableHigh", "Interrupt enable IN14/IN15"),
    P("polarity", "Polarity IN0-7"),
    P("polarityHigh", "Polarity IN14/IN15"),
    P("aSlavedTo", "A axis slaved to (0 none, 1 X, 2 Y, 3 Z)"),
    P("pwmBreakout", "PWM for breakout boards"),
    P("stepPolarityInvert", "Invert STEP polarity"),
    P("defaultSpindlePermille", "Default spindle speed"),
    P("brakeReleaseDelayS", "Brake release delay"),
};

const Label kChoices[] = {
    P("auto", "Automatic"),
    P("vk", "Path speed (VK)"),
    P("vn", "Major axis speed (VN)"),
    P("unused", "Unused"),
    P("spindle", "Spindle"),
    P("laser", "Laser"),
    P("coolant", "Coolant"),
    P("airBlow", "Air blow"),
    P("coverLock", "Machine cover lock"),
    P("toolRelease", "Tool release"),
    P("toolCoverOpen", "Tool cover open"),
    P("brake", "Brake"),
    P("interrupt", "Interrupt signal"),
    P("off", "Off"),
    P("on", "On"),
    P("onWithLimits", "On, within the limits"),
    P("onRotaryA", "On, 4th position drives rotary A"),
    P("onRotaryAWithLimits", "On with limits, 4th position drives rotary A"),
    P("gve84", "GVE84"),
    P("gve64", "GVE64"),
    P("gve64-phantom", "GVE64 PHANTOM"),
    P("gve114", "GVE114"),
};
#undef P

QString lookup(const Label *table, std::size_t n, const QString &key)
{
    for (std::size_t i = 0; i < n; ++i) {
        if (key == QLatin1String(table[i].key))
            return QCoreApplication::translate("frezka::gui::Profile", table[i].text);
    }
    return key;
}

} // namespace

QString profileKeyLabel(const QString &key)
{
    return lookup(kKeys, std::size(kKeys), key);
}

QString profileChoiceLabel(const QString &name)
{
    return lookup(kChoices, std::size(kChoices), name);
}

QString configErrorText(const machine::ConfigError &error)
{
    const QString key = QString::fromStdString(error.key);
    QStringList parts = key.split(QLatin1Char('.'));
    for (QString &p : parts)
        p = profileKeyLabel(p);
    const QString where = key.isEmpty()
                              ? QCoreApplication::translate("frezka::gui::Profile", "Profile")
                              : parts.join(QStringLiteral(" › "));
    const char *what = nullptr;
    using C = machine::ConfigErrorCode;
    switch (error.code) {
    case C::FileUnreadable:
        what = QT_TRANSLATE_NOOP("frezka::gui::Profile", "the file cannot be read or written");
        break;
    case C::Syntax:
        what = QT_TRANSLATE_NOOP("frezka::gui::Profile", "the file is not valid JSON");
        break;
    case C::WrongType:
        what = QT_TRANSLATE_NOOP("frezka::gui::Profile", "the value has the wrong type");
        break;
    case C::UnknownKey:
        what = QT_TRANSLATE_NOOP("frezka::gui::Profile", "unknown key (a typo?)");
        break;
    case C::OutOfRange:
        what = QT_TRANSLATE_NOOP("frezka::gui::Profile", "the value is outside its range");
        break;
    case C::BadChoice:
        what = QT_TRANSLATE_NOOP("frezka::gui::Profile", "the value is none of the allowed ones");
        break;
    case C::Inconsistent:
        what = QT_TRANSLATE_NOOP("frezka::gui::Profile",
                                 "the value contradicts another setting or the unit type");
        break;
    }
    return QCoreApplication::translate("frezka::gui::Profile", "%1: %2 (%3)")
        .arg(where, QCoreApplication::translate("frezka::gui::Profile", what),
             QString::fromStdString(error.message));
}

} // namespace frezka::gui
