#include "displayunits.h"

#include <QSettings>

namespace frezka::gui {

LengthUnit displayUnit()
{
    return QSettings().value(QStringLiteral("display/units")).toString() == QLatin1String("inch")
               ? LengthUnit::Inch
               : LengthUnit::Mm;
}

void setDisplayUnit(LengthUnit unit)
{
    QSettings().setValue(QStringLiteral("display/units"),
                         unit == LengthUnit::Inch ? QStringLiteral("inch") : QStringLiteral("mm"));
}

double fromMm(double mm, LengthUnit unit)
{
    return unit == LengthUnit::Inch ? mm / kMmPerInch : mm;
}

double toMm(double value, LengthUnit unit)
{
    return unit == LengthUnit::Inch ? value * kMmPerInch : value;
}

QString formatLength(double mm, LengthUnit unit)
{
    return QString::number(fromMm(mm, unit), 'f', unit == LengthUnit::Inch ? 4 : 3);
}

QString formatFeed(double mmPerMin, LengthUnit unit)
{
    return QString::number(fromMm(mmPerMin, unit), 'f', unit == LengthUnit::Inch ? 1 : 0);
}

QString lengthSuffix(LengthUnit unit)
{
    return unit == LengthUnit::Inch ? QStringLiteral("in") : QStringLiteral("mm");
}

QString feedSuffix(LengthUnit unit)
{
    return unit == LengthUnit::Inch ? QStringLiteral("in/min") : QStringLiteral("mm/min");
}

} // namespace frezka::gui
