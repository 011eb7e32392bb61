#pragma once
// The length unit the operator reads (issue 16 item 6): mm or inch for the DRO, the jog steps
// and feed, the status panel's feeds and the speed plot. Display only: the machine, the planner
// and every value passed between modules stay in mm (and mm/min). Stored in QSettings under
// "display/units" ("mm", "inch"); mm by default.

#include <QString>

namespace frezka::gui {

enum class LengthUnit { Mm, Inch };

constexpr double kMmPerInch = 25.4;

LengthUnit displayUnit();
void setDisplayUnit(LengthUnit unit);

// A length in the unit: mm with 3 decimals, inch with 4 (as LinuxCNC's DROs), no suffix.
QString formatLength(double mm, LengthUnit unit);
// A feed in the unit's per minute, no suffix: mm/min whole, in/min with 1 decimal.
QString formatFeed(double mmPerMin, LengthUnit unit);
double fromMm(double mm, LengthUnit unit);
double toMm(double value, LengthUnit unit);
QString lengthSuffix(LengthUnit unit); // "mm", "in"
QString feedSuffix(LengthUnit unit);   // "mm/min", "in/min"

} // namespace frezka::gui
