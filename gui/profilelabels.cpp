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

const Label kKeys[] = {
    {"name", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Profile name")},
    {"unit", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Unit")},
    {"variant", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Unit type")},
    {"maxPulseRate", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Maximum pulse rate")},
    {"firmwareVersion", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Firmware version")},
    {"startInput", QT_TRANSLATE_NOOP("frezka::gui::Profile", "START button input (0 = none)")},
    {"address", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Unit address on the line (0..6)")},
    {"link", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Connection")},
    {"port", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Port")},
    {"baud", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Baud rate")},
    {"checksums", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Checksums")},
    {"packets", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Packets")},
    {"latencyMs", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Adapter latency (each way)")},
    {"axes", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Axes")},
    {"x", QT_TRANSLATE_NOOP("frezka::gui::Profile", "X axis")},
    {"y", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Y axis")},
    {"z", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Z axis")},
    {"a", QT_TRANSLATE_NOOP("frezka::gui::Profile", "A axis")},
    {"present", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Present")},
    {"stepsPerMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Steps per mm")},
    {"invertDirection", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Invert direction")},
    {"softMinMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Soft limit min")},
    {"softMaxMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Soft limit max")},
    {"maxSpeedMmPerMin", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Maximum speed")},
    {"rapidMmPerMin", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Rapid speed")},
    {"accelMmPerS2", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Acceleration")},
    {"maxJumpMmPerS", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Maximum speed jump at a corner")},
    {"homing", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Homing")},
    {"order", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Order (0 = not homed)")},
    {"direction", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Direction to the switch (-1/+1)")},
    {"travelMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Maximum search travel")},
    {"towardMmPerS", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Speed toward the switch")},
    {"offMmPerS", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Speed off the switch")},
    {"backOffMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Maximum back-off travel")},
    {"homePositionMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Position after homing")},
    {"motion", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Motion")},
    {"junctionDeviationMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Corner deviation")},
    {"chordToleranceMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Arc chord tolerance")},
    {"pauseMs", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Pause between stand-alone moves")},
    {"speedMode", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Speed mode")},
    {"toolLiftMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Tool lift")},
    {"runBeforeHoming",
     QT_TRANSLATE_NOOP("frezka::gui::Profile", "Allow a run before homing (with a warning)")},
    {"spindle", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Spindle")},
    {"maxRpm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Maximum spindle speed")},
    {"spinUpMs", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Spin-up wait")},
    {"stopAtProgramStop",
     QT_TRANSLATE_NOOP("frezka::gui::Profile", "Spindle and coolant off at M0 / M1")},
    {"stopAtToolChange",
     QT_TRANSLATE_NOOP("frezka::gui::Profile", "Spindle and coolant off at M6")},
    {"outputs", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Outputs")},
    {"tools", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Tools")},
    {"tableFile", QT_TRANSLATE_NOOP("frezka::gui::Profile",
                                    "Tool table file (LinuxCNC .tbl, beside the profile)")},
    {"sensor", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Tool length sensor")},
    {"enabled", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Present")},
    {"xMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "X (machine)")},
    {"yMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Y (machine)")},
    {"clearanceZMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Clearance Z (machine)")},
    {"feedMmPerMin", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Probing feed")},
    {"slowFeedMmPerMin", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Slow probing feed")},
    {"retractMm", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Back-off before the slow probe")},
    {"referenceZMm",
     QT_TRANSLATE_NOOP("frezka::gui::Profile", "Trip Z of the reference tool (length 0)")},
    {"program", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Program")},
    {"maxLinesExecuted", QT_TRANSLATE_NOOP("frezka::gui::Profile",
                                           "Lines executed at most (a program that never ends)")},
    {"maxMoves",
     QT_TRANSLATE_NOOP("frezka::gui::Profile", "Moves at most (a program that never ends)")},
    {"subroutinePath",
     QT_TRANSLATE_NOOP("frezka::gui::Profile",
                       "Subroutine folders (o<name> call of name.ngc; separated by :)")},
    {"out1", QT_TRANSLATE_NOOP("frezka::gui::Profile", "OUT1 function")},
    {"out2", QT_TRANSLATE_NOOP("frezka::gui::Profile", "OUT2 function")},
    {"out3", QT_TRANSLATE_NOOP("frezka::gui::Profile", "OUT3 function")},
    {"mist", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Output switched by M7")},
    {"eeprom", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Unit EEPROM")},
    {"sync", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Compare with the unit on connect")},
    {"mpg", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Handwheel (MPG)")},
    {"mpgAccelMmPerS2", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Handwheel acceleration")},
    {"mpgMaxSpeedMmPerS", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Handwheel maximum speed")},
    {"mpgDelayMs", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Handwheel brake delay")},
    {"mpgStepMultiplier", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Handwheel step multiplier")},
    {"homingInput",
     QT_TRANSLATE_NOOP("frezka::gui::Profile", "Input that starts homing (0 = off)")},
    {"interruptEnable", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Interrupt enable IN0-7")},
    {"interruptEnableHigh",
     QT_TRANSLATE_NOOP("frezka::gui::Profile", "Interrupt enable IN14/IN15")},
    {"polarity", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Polarity IN0-7")},
    {"polarityHigh", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Polarity IN14/IN15")},
    {"aSlavedTo",
     QT_TRANSLATE_NOOP("frezka::gui::Profile", "A axis slaved to (0 none, 1 X, 2 Y, 3 Z)")},
    {"pwmBreakout", QT_TRANSLATE_NOOP("frezka::gui::Profile", "PWM for breakout boards")},
    {"stepActiveEdge", QT_TRANSLATE_NOOP("frezka::gui::Profile", "STEP active edge")},
    {"defaultSpindlePermille", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Default spindle speed")},
    {"brakeReleaseDelayS", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Brake release delay")},
};

const Label kChoices[] = {
    {"auto", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Automatic")},
    {"vk", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Path speed (VK)")},
    {"vn", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Major axis speed (VN)")},
    {"unused", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Unused")},
    {"spindle", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Spindle")},
    {"laser", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Laser")},
    {"coolant", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Coolant")},
    {"airBlow", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Air blow")},
    {"coverLock", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Machine cover lock")},
    {"toolRelease", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Tool release")},
    {"toolCoverOpen", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Tool cover open")},
    {"brake", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Brake")},
    {"interrupt", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Interrupt signal")},
    {"off", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Off")},
    {"on", QT_TRANSLATE_NOOP("frezka::gui::Profile", "On")},
    {"onWithLimits", QT_TRANSLATE_NOOP("frezka::gui::Profile", "On, within the limits")},
    {"onRotaryA", QT_TRANSLATE_NOOP("frezka::gui::Profile", "On, 4th position drives rotary A")},
    {"onRotaryAWithLimits",
     QT_TRANSLATE_NOOP("frezka::gui::Profile", "On with limits, 4th position drives rotary A")},
    {"default", QT_TRANSLATE_NOOP("frezka::gui::Profile", "As the unit left the factory")},
    {"falling", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Falling edge")},
    {"rising", QT_TRANSLATE_NOOP("frezka::gui::Profile", "Rising edge")},
    {"gve84", QT_TRANSLATE_NOOP("frezka::gui::Profile", "GVE84")},
    {"gve64", QT_TRANSLATE_NOOP("frezka::gui::Profile", "GVE64")},
    {"gve64-phantom", QT_TRANSLATE_NOOP("frezka::gui::Profile", "GVE64 PHANTOM")},
    {"gve114", QT_TRANSLATE_NOOP("frezka::gui::Profile", "GVE114")},
};

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
    case C::Retired:
        what = QT_TRANSLATE_NOOP("frezka::gui::Profile",
                                 "a key of an older profile, read into its successor or ignored");
        break;
    }
    return QCoreApplication::translate("frezka::gui::Profile", "%1: %2 (%3)")
        .arg(where, QCoreApplication::translate("frezka::gui::Profile", what),
             QString::fromStdString(error.message));
}

} // namespace frezka::gui
