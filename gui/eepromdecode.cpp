#include "eepromdecode.h"

#include <QCoreApplication>
#include <QStringList>

#include <cmath>

namespace frezka::gui {
namespace {

// lupdate files tr() calls here under the namespace, "frezka::gui".
QString tr(const char *s)
{
    return QCoreApplication::translate("frezka::gui", s);
}

QString axisList(unsigned bits, int first, int count)
{
    static const char kAxes[] = "XYZA";
    QStringList on;
    for (int i = 0; i < count; ++i) {
        if (bits & (1u << (first + i)))
            on << QString(QLatin1Char(kAxes[i]));
    }
    return on.isEmpty() ? tr("none") : on.join(QLatin1Char(' '));
}

QString inputList(unsigned bits, bool high)
{
    QStringList on;
    if (high) {
        if (bits & 0x40)
            on << QStringLiteral("IN14");
        if (bits & 0x80)
            on << QStringLiteral("IN15");
    } else {
        for (int i = 0; i < 8; ++i) {
            if (bits & (1u << i))
                on << QStringLiteral("IN%1").arg(i);
        }
    }
    return on.isEmpty() ? tr("none") : on.join(QLatin1Char(' '));
}

QString outputFunction(unsigned code, bool gve84)
{
    switch (code) {
    case 0x00:
        return gve84 ? tr("spindle") : tr("unused");
    case 0x01:
        return tr("laser");
    case 0x02:
        return tr("coolant");
    case 0x03:
        return tr("air blow");
    case 0x04:
        return tr("machine cover lock");
    case 0x05:
        return tr("tool release");
    case 0x06:
        return tr("tool cover open");
    case 0x08:
        return tr("brake");
    case 0x09:
        return tr("interrupt signal");
    default:
        return tr("unused");
    }
}

} // namespace

QString eepromLabel(protocol::Variant variant, std::uint8_t a)
{
    static const char kAxes[] = "XYZA";
    const bool gve84 = variant == protocol::Variant::Gve84;
    if (a >= 0x10 && a < 0x30) {
        const QString axis(QLatin1Char(kAxes[(a % 16) / 4]));
        return (a < 0x20 ? tr("Lower limit %1") : tr("Upper limit %1")).arg(axis);
    }
    if (a >= 0x30 && a < 0x40)
        return tr("Steps per mm %1").arg(QLatin1Char(kAxes[(a - 0x30) / 4]));
    if (a >= 0x50 && a < 0x5C)
        return tr("Homing speed %1").arg(QLatin1Char(kAxes[(a - 0x50) / 4]));
    switch (a) {
    case 0x01:
        return gve84 ? tr("Relay function") : tr("OUT1 function");
    case 0x02:
        return tr("OUT2 function");
    case 0x03:
        return tr("OUT3 function");
    case 0x04:
        return tr("PWM mode");
    case 0x05:
        return tr("STEP/DIR polarity");
    case 0x06:
        return tr("Handwheel (MPG)");
    case 0x07:
        return tr("Input that starts homing");
    case 0x08:
        return tr("Interrupt enable IN0-7");
    case 0x09:
        return tr("Interrupt enable IN14/IN15");
    case 0x0A:
        return tr("Input polarity IN0-7");
    case 0x0B:
        return tr("Input polarity IN14/IN15");
    case 0x0C:
        return tr("A axis coupling");
    case 0x0D:
        return tr("Baud range");
    case 0x40:
        return tr("Handwheel acceleration");
    case 0x44:
        return tr("Handwheel maximum speed");
    case 0x48:
        return tr("Handwheel brake delay");
    case 0x4C:
        return tr("Default spindle speed");
    case 0x60:
        return tr("Handwheel step multiplier");
    case 0xFD:
        return tr("Brake release delay");
    default:
        return tr("Address 0x%1").arg(a, 2, 16, QLatin1Char('0'));
    }
}

// One case per EEPROM address of §12: a table, kept whole so that it reads as the manual's.
QString eepromMeaning(protocol::Variant variant, std::uint8_t a, double value)
{
    const unsigned v = unsigned(std::lround(value)) & 0xFFFFFFFFu;
    const bool gve84 = variant == protocol::Variant::Gve84;
    const bool gve114 = variant == protocol::Variant::Gve114;
    if ((a >= 0x10 && a < 0x30) || a == 0x44)
        return QStringLiteral("%1 %2").arg(value, 0, 'g', 7).arg(a == 0x44 ? "mm/s" : "mm");
    if (a >= 0x30 && a < 0x40)
        return tr("%1 steps/mm").arg(value, 0, 'g', 7);
    if (a >= 0x50 && a < 0x5C)
        return value == 0 ? tr("homing off") : QStringLiteral("%1 mm/s").arg(value, 0, 'g', 7);
    switch (a) {
    case 0x01:
    case 0x02:
    case 0x03:
        return outputFunction(v, gve84);
    case 0x04:
        return v == 0xFF   ? tr("standard PWM")
               : v == 0x01 ? tr("breakout-board signal (jumper ANA/PWM)")
                           : tr("unknown (0x%1)").arg(v, 2, 16, QLatin1Char('0'));
    case 0x05:
        if (gve114)
            return tr("STEP inverted: %1; DIR inverted: %2")
                .arg(axisList(~v, 0, 4), axisList(~v, 4, 4));
        return tr("DIR inverted: %1; STEP on %2 edge")
            .arg(axisList(~v, 0, gve84 ? 3 : 4), (v & 0x10) ? tr("falling") : tr("rising"));
    case 0x06:
        switch (v) {
        case 0x01:
            return tr("on");
        case 0x02:
            return tr("on, within the limits");
        case 0x81:
            return gve114 ? tr("on, 4th position drives rotary A") : tr("off");
        case 0x82:
            return gve114 ? tr("on with limits, 4th position drives rotary A") : tr("off");
        default:
            return tr("off");
        }
    case 0x07:
        return v >= 3 && v <= 7 ? tr("IN%1 held > 1 s starts homing").arg(v) : tr("off");
    case 0x08:
        return tr("enabled: %1").arg(inputList(v, false));
    case 0x09:
        return tr("enabled: %1").arg(inputList(v, true));
    case 0x0A:
        return tr("active high: %1").arg(inputList(v, false));
    case 0x0B:
        return tr("active high: %1").arg(inputList(v, true));
    case 0x0C:
        return v == 1   ? tr("slaved to X")
               : v == 2 ? tr("slaved to Y")
               : v == 3 ? tr("slaved to Z")
                        : tr("independent");
    case 0x0D:
        return v == 0x01 ? tr("921 600 / 460 800 / 230 400 / 115 200 Bd")
                         : tr("19 200 / 38 400 / 57 600 / 115 200 Bd");
    case 0x40:
        return QStringLiteral("%1 mm/s²").arg(value, 0, 'g', 7);
    case 0x48:
        return QStringLiteral("%1 ms").arg(v);
    case 0x4C:
        return QStringLiteral("%1 ‰").arg(v);
    case 0x60:
        return tr("×%1 (x1 = %2 mm)").arg(value, 0, 'g', 7).arg(0.01 * value, 0, 'g', 7);
    case 0xFD:
        return QStringLiteral("%1 s").arg(double(v) / 10.0, 0, 'f', 1);
    default:
        return {};
    }
}

QString eepromValueText(machine::EepromKind kind, double value)
{
    if (kind == machine::EepromKind::Byte)
        return QStringLiteral("%1")
            .arg(unsigned(std::lround(value)) & 0xFF, 2, 16, QLatin1Char('0'))
            .toUpper();
    if (kind == machine::EepromKind::Uint32)
        return QString::number(qulonglong(std::llround(value)));
    return QString::number(value, 'g', 7);
}

QString eepromReadCommand(const machine::EepromEntry &e)
{
    static const char *kOp[] = {"ER", "EFR", "EUR"};
    return QStringLiteral("%1%2")
        .arg(QLatin1String(kOp[int(e.kind)]))
        .arg(e.address, 2, 16, QLatin1Char('0'))
        .toUpper();
}

QString eepromWriteCommand(const machine::EepromEntry &e)
{
    static const char *kOp[] = {"EW", "EFW", "EUW"};
    QString value = eepromValueText(e.kind, e.value);
    if (e.kind == machine::EepromKind::Float && !value.contains(QLatin1Char('.')) &&
        !value.contains(QLatin1Char('e')))
        value += QStringLiteral(".0");
    return QStringLiteral("%1%2,%3").arg(
        QLatin1String(kOp[int(e.kind)]),
        QStringLiteral("%1").arg(e.address, 2, 16, QLatin1Char('0')).toUpper(), value);
}

bool eepromSame(machine::EepromKind kind, double a, double b)
{
    if (kind == machine::EepromKind::Float)
        return std::abs(a - b) <= 1e-4 * std::max(1.0, std::abs(b));
    return std::llround(a) == std::llround(b);
}

} // namespace frezka::gui
