#include "toollength.h"

#include <QCoreApplication>

namespace frezka::session {

namespace {

QString tr(const char *text)
{
    return QCoreApplication::translate("frezka::session::ToolLength", text);
}

} // namespace

QString toolSensorProblem(const machine::MachineConfig &config)
{
    if (!config.tools.sensor.enabled)
        return tr("The machine profile has no tool length sensor: set its position and "
                  "probing in Machine › Settings (Tools › Tool length sensor), then measure "
                  "again.");
    return {};
}

HeightProbeSettings toolSensorSettings(const machine::ToolSensorConfig &sensor)
{
    HeightProbeSettings s;
    s.clearanceZMm = sensor.clearanceZMm;
    s.bottomZMm = sensor.clearanceZMm - sensor.travelMm;
    s.feedMmPerMin = sensor.feedMmPerMin;
    s.slowFeedMmPerMin = sensor.slowFeedMmPerMin;
    s.retractMm = sensor.retractMm;
    s.pointEndsAtClearance = true;
    return s;
}

double toolLengthFromTrip(const machine::ToolSensorConfig &sensor, double tripZMm)
{
    return tripZMm - sensor.referenceZMm;
}

void setToolLength(gcode::ToolTable *table, int tool, double lengthMm)
{
    if (gcode::ToolEntry *e = table->find(tool)) {
        e->offsetMm[2] = lengthMm;
        return;
    }
    gcode::ToolEntry e;
    e.tool = tool;
    e.pocket = tool;
    e.offsetMm[2] = lengthMm;
    e.comment = "measured on the tool length sensor";
    table->tools.push_back(e);
}

} // namespace frezka::session
