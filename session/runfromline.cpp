#include "runfromline.h"

#include "session/workoffsets.h"

#include "machine/lineapproach.h"

#include <QStringList>

namespace frezka::session {
namespace {

QString mm(double v)
{
    return QString::number(v, 'f', 3);
}

QString gCode(int tenTimes)
{
    return tenTimes % 10 == 0 ? QStringLiteral("G%1").arg(tenTimes / 10)
                              : QStringLiteral("G%1.%2").arg(tenTimes / 10).arg(tenTimes % 10);
}

// Why the mark has no state, in words, with the line to choose instead.
QString refusalText(const gcode::LineMark &mark)
{
    const QString label = QString::fromStdString(mark.label);
    switch (mark.refusal) {
    case gcode::LineMarkRefusal::NotReached:
        return RunFromLine::tr("line %1 is never reached: the program ends on line %2. Choose a "
                               "line up to %2.")
            .arg(mark.askedLine)
            .arg(mark.refLine);
    case gcode::LineMarkRefusal::InSubroutine:
        return RunFromLine::tr("line %1 is inside the subroutine o%2 (defined on line %3), which "
                               "runs only when it is called. Choose the line that calls it, or a "
                               "line outside the subroutine.")
            .arg(mark.askedLine)
            .arg(label)
            .arg(mark.refLine);
    case gcode::LineMarkRefusal::InCall:
        return RunFromLine::tr("line %1 runs only inside the subroutine o%2, called on line %3. "
                               "Choose line %3, or a line outside the subroutine.")
            .arg(mark.askedLine)
            .arg(label)
            .arg(mark.refLine);
    case gcode::LineMarkRefusal::InLoop:
        return RunFromLine::tr("line %1 is inside the loop o%2 that opens on line %3, so the "
                               "program runs it more than once. Choose line %3, or a line after "
                               "the loop.")
            .arg(mark.askedLine)
            .arg(label)
            .arg(mark.refLine);
    case gcode::LineMarkRefusal::NotTaken:
        return RunFromLine::tr("line %1 is never run: the program skips it at o%2 on line %3 (a "
                               "branch or a loop it does not take). Choose a line the program "
                               "runs.")
            .arg(mark.askedLine)
            .arg(label)
            .arg(mark.refLine);
    case gcode::LineMarkRefusal::InCutterComp:
        return RunFromLine::tr("line %1 is in a path with cutter radius compensation, turned on "
                               "on line %2: where the tool runs there depends on the moves "
                               "before. Choose line %2 or a line before it, or a line after G40.")
            .arg(mark.askedLine)
            .arg(mark.refLine);
    case gcode::LineMarkRefusal::None:
        break;
    }
    return {};
}

// The events that put the machine in the line's state: path mode, spindle, coolant.
void appendStateEvents(gcode::Toolpath &job, const gcode::LineState &s, std::uint32_t line)
{
    const double feed = s.feedMmPerMin;
    job.appendEvent({gcode::EventKind::PathMode, double(s.pathMode), s.pathToleranceMm, s.pathQMm},
                    feed, line);
    if (s.spindle != 0) {
        job.appendEvent({s.spindle > 0 ? gcode::EventKind::SpindleCw : gcode::EventKind::SpindleCcw,
                         s.speedRpm, 0, 0},
                        feed, line);
    }
    if (s.mist)
        job.appendEvent({gcode::EventKind::CoolantMist, 0, 0, 0}, feed, line);
    if (s.flood)
        job.appendEvent({gcode::EventKind::CoolantFlood, 0, 0, 0}, feed, line);
}

} // namespace

FromLineOutcome runFromLine(const gcode::Toolpath &whole, const gcode::LineMark &mark,
                            const machine::MachineConfig &config, const gcode::Point4 &fromMm,
                            const QString &fileName)
{
    FromLineOutcome out;
    const auto refuse = [&](const QString &why) {
        out.refusal = RunFromLine::tr("%1:%2: cannot run from this line: %3")
                          .arg(fileName)
                          .arg(mark.askedLine)
                          .arg(why);
        return out;
    };
    if (!mark.ok())
        return refuse(refusalText(mark));
    const gcode::LineState &s = mark.state;
    if (s.feedMmPerMin <= 0) {
        return refuse(RunFromLine::tr("no feed is in force at line %1 (no F word yet, or G93 "
                                      "inverse time). Choose a line after an F word in G94.")
                          .arg(mark.line));
    }
    out.from.askedLine = mark.askedLine;
    out.from.line = mark.line;
    out.from.state = s;
    out.from.safeZMm = machine::approachSafeZ(config, whole, fromMm, s.machineMm);
    auto job = std::make_shared<gcode::Toolpath>();
    job->setOrigin(fromMm);
    appendStateEvents(*job, s, mark.line);
    for (const machine::ApproachMove &m :
         machine::lineApproach(fromMm, s.machineMm, out.from.safeZMm)) {
        if (m.feed)
            job->appendFeed(m.endMm, s.feedMmPerMin, mark.line);
        else
            job->appendRapid(m.endMm, s.feedMmPerMin, mark.line);
    }
    out.from.approachEntries = job->size();
    job->appendEntries(whole, mark.entry);
    out.toolpath = std::move(job);
    return out;
}

QString fromLineSummary(const FromLine &from)
{
    const gcode::LineState &s = from.state;
    QStringList parts;
    if (s.tool != 0)
        parts << RunFromLine::tr("tool %1 (length %2 mm)").arg(s.tool).arg(mm(s.toolLengthMm));
    else
        parts << RunFromLine::tr("no tool loaded by the program");
    const QString spindle = s.spindle > 0   ? QStringLiteral("M3")
                            : s.spindle < 0 ? QStringLiteral("M4")
                                            : QStringLiteral("M5");
    parts << QStringLiteral("S%1 %2").arg(s.speedRpm).arg(spindle);
    QStringList coolant;
    if (s.mist)
        coolant << QStringLiteral("M7");
    if (s.flood)
        coolant << QStringLiteral("M8");
    parts << (coolant.isEmpty() ? QStringLiteral("M9") : coolant.join(QLatin1Char(' ')));
    parts << QStringLiteral("F%1").arg(s.feedMmPerMin / (s.metric ? 1.0 : 25.4));
    parts << QStringList{workSystemName(s.coordinateSystem), gCode(s.absolute ? 900 : 910),
                         gCode(s.metric ? 210 : 200), gCode(s.plane)}
                 .join(QLatin1Char(' '));
    return RunFromLine::tr("Line %1: %2; the approach crosses at Z %3 (machine) and comes down "
                           "at the feed to X %4 Y %5 Z %6 (machine).")
        .arg(from.line)
        .arg(parts.join(QStringLiteral(", ")))
        .arg(mm(from.safeZMm), mm(s.machineMm.x), mm(s.machineMm.y), mm(s.machineMm.z));
}

} // namespace frezka::session
