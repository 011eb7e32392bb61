#include "rs274.h"

#include "gcode/interpreter.h"
#include "gcode/linuxcncini.h"
#include "gcode/trace.h"

#include <QDir>
#include <QFile>
#include <QFileInfo>
#include <QLockFile>
#include <QProcess>
#include <QStandardPaths>
#include <QString>
#include <QTemporaryDir>
#include <QTemporaryFile>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>
#include <cstdlib>
#include <numbers>
#include <sstream>

namespace frezka::gcode::test {

namespace {

std::vector<double> numbersIn(const std::string &args)
{
    std::vector<double> out;
    const char *p = args.c_str();
    while (*p) {
        char *end = nullptr;
        const double v = std::strtod(p, &end);
        if (end != p) {
            out.push_back(v);
            p = end;
        } else {
            ++p;
        }
    }
    return out;
}

} // namespace

std::string rs274Path()
{
    return QStandardPaths::findExecutable(QStringLiteral("rs274")).toStdString();
}

namespace {

// A copy of the INI in dir with SUBROUTINE_PATH's folders absolute (from the INI's folder).
QString iniCopy(const std::string &ini, const QTemporaryDir &dir)
{
    QFile in(QString::fromStdString(ini));
    if (!in.open(QIODevice::ReadOnly))
        return {};
    const QDir base = QFileInfo(in).absoluteDir();
    QString text;
    for (QString line : QString::fromUtf8(in.readAll()).split(QLatin1Char('\n'))) {
        const qsizetype eq = line.indexOf(QLatin1Char('='));
        if (eq > 0 && line.left(eq).trimmed().compare(QLatin1String("SUBROUTINE_PATH"),
                                                      Qt::CaseInsensitive) == 0) {
            QStringList dirs;
            for (const QString &d : line.mid(eq + 1).split(QLatin1Char(':')))
                dirs << QDir::cleanPath(base.absoluteFilePath(d.trimmed()));
            line = QStringLiteral("SUBROUTINE_PATH = ") + dirs.join(QLatin1Char(':'));
        }
        text += line + QLatin1Char('\n');
    }
    QFile out(dir.filePath(QStringLiteral("test.ini")));
    if (!out.open(QIODevice::WriteOnly) || out.write(text.toUtf8()) < 0)
        return {};
    return out.fileName();
}

} // namespace

Rs274Run runRs274(const std::string &file, const ToolTable *toolTable, const std::string &ini)
{
    Rs274Run run;
    const std::string exe = rs274Path();
    if (exe.empty())
        return run;
    run.available = true;
    QProcess process;
    process.setProcessChannelMode(QProcess::MergedChannels);
    // rs274's built-in tool table has non-zero lengths; Frezka's default is length 0 for
    // every tool, so give rs274 a table of zero-length tools.
    QTemporaryFile tools;
    if (!tools.open()) {
        run.error = "cannot write the tool table";
        return run;
    }
    if (toolTable) {
        ToolTable inches = *toolTable;
        for (ToolEntry &e : inches.tools) {
            for (std::size_t i : {0, 1, 2, 6, 7, 8})
                e.offsetMm[i] /= 25.4;
            e.diameterMm /= 25.4;
        }
        const std::string text = formatToolTable(inches);
        tools.write(text.data(), static_cast<qint64>(text.size()));
    } else {
        for (int t = 1; t <= 99; ++t)
            tools.write(QStringLiteral("T%1 P%1 Z0 D1 ;\n").arg(t).toLatin1());
    }
    tools.flush();
    // Concurrent rs274 runs (ctest -j) interfere with each other (they end with exit code 7 and
    // lose their output): one at a time across processes, each in a directory of its own, since
    // rs274 also rewrites its parameter file (rs274ngc.var) in its working directory.
    QLockFile lock(QDir::temp().filePath(QStringLiteral("frezka-rs274.lock")));
    lock.setStaleLockTime(0);
    if (!lock.lock()) {
        run.error = "cannot take the rs274 lock";
        return run;
    }
    QTemporaryDir workDir;
    process.setWorkingDirectory(workDir.path());
    QStringList args{QStringLiteral("-t"), tools.fileName(), QStringLiteral("-g")};
    if (!ini.empty()) {
        const QString copy = iniCopy(ini, workDir);
        if (copy.isEmpty()) {
            run.error = "cannot copy the INI file";
            return run;
        }
        args << QStringLiteral("-i") << copy;
    }
    process.start(QString::fromStdString(exe), args << QString::fromStdString(file));
    process.closeWriteChannel();
    if (!process.waitForFinished(60000)) {
        run.error = "rs274 did not finish";
        return run;
    }
    const bool succeeded = process.exitStatus() == QProcess::NormalExit && process.exitCode() == 0;
    std::istringstream in(process.readAll().toStdString());
    double unit = 1;
    std::array<double, 6> g5x{}, g92{};
    std::array<double, 4> tool{}; // USE_TOOL_LENGTH_OFFSET, mm (A degrees)
    double feedMm = 0, rpm = 0, rotationDeg = 0;
    int spindleDir = 0;
    Plane plane = Plane::XY;
    std::string line;
    bool expectErrorLine = false;
    while (std::getline(in, line)) {
        // "   12 N..... CALL(...)" or "   12 N10    CALL(...)" when the block has an N word.
        std::size_t n = line.find_first_not_of(' ');
        const bool canon = n != std::string::npos &&
                           std::isdigit(static_cast<unsigned char>(line[n])) &&
                           line.find(" N", n) != std::string::npos;
        if (canon) {
            n = line.find(" N", n) + 2;
            n = line.find(' ', n);
            n = line.find_first_not_of(' ', n);
        }
        if (!canon || n == std::string::npos) {
            if (line == "executing" || line.empty())
                continue;
            if (expectErrorLine) {
                run.errorLine = line;
                expectErrorLine = false;
            } else if (run.error.empty()) {
                run.error = line;
                expectErrorLine = true;
            }
            continue;
        }
        const std::string call = line.substr(n);
        const auto open = call.find('(');
        const std::string name = call.substr(0, open);
        const std::vector<double> v = numbersIn(open == std::string::npos ? "" : call.substr(open));
        // Offsets are kept in mm as printed (rs274 does not print them again when the units
        // change); positions are in the units in force when printed. A is in degrees.
        // LinuxCNC's canon (emccanon.cc from_prog): the XY rotation turns the point with its
        // G92 offset, before the work and tool offsets.
        auto machine = [&](double x, double y, double z, double a) {
            const double t = rotationDeg * std::numbers::pi / 180.0;
            const double px = x * unit + g92[0], py = y * unit + g92[1];
            const double rx = px * std::cos(t) - py * std::sin(t);
            const double ry = px * std::sin(t) + py * std::cos(t);
            return Point4{rx + g5x[0] + tool[0], ry + g5x[1] + tool[1],
                          z * unit + g5x[2] + g92[2] + tool[2], a + g5x[3] + g92[3] + tool[3]};
        };
        auto toMm = [&](std::array<double, 6> &o) {
            for (int i = 0; i < 3; ++i)
                o[i] *= unit;
        };
        auto push = [&](CanonMove m) {
            m.unitMm = unit;
            m.call = call;
            m.feedMmPerMin = feedMm;
            m.spindleRpm = spindleDir * rpm;
            run.moves.push_back(m);
        };
        if (name == "USE_LENGTH_UNITS") {
            unit = call.find("INCHES") != std::string::npos ? 25.4 : 1.0;
        } else if (name == "SET_G5X_OFFSET" && v.size() >= 7) {
            std::copy(v.begin() + 1, v.begin() + 7, g5x.begin());
            toMm(g5x);
        } else if (name == "SET_XY_ROTATION" && !v.empty()) {
            rotationDeg = v[0];
        } else if (name == "SET_G92_OFFSET" && v.size() >= 6) {
            std::copy(v.begin(), v.begin() + 6, g92.begin());
            toMm(g92);
        } else if (name == "USE_TOOL_LENGTH_OFFSET" && v.size() >= 4) {
            tool = {v[0] * unit, v[1] * unit, v[2] * unit, v[3]};
        } else if (name == "SELECT_PLANE") {
            plane = call.find("XZ") != std::string::npos   ? Plane::XZ
                    : call.find("YZ") != std::string::npos ? Plane::YZ
                                                           : Plane::XY;
        } else if ((name == "STRAIGHT_TRAVERSE" || name == "STRAIGHT_FEED" ||
                    name == "STRAIGHT_PROBE") &&
                   v.size() >= 4) {
            CanonMove m;
            m.kind = name == "STRAIGHT_TRAVERSE" ? MotionKind::Rapid
                     : name == "STRAIGHT_FEED"   ? MotionKind::Feed
                                                 : MotionKind::Probe;
            m.end = machine(v[0], v[1], v[2], v[3]);
            push(m);
        } else if (name == "ARC_FEED" && v.size() >= 7) {
            // ARC_FEED(first_end, second_end, first_axis, second_axis, rotation, axis_end, a..)
            CanonMove m;
            m.kind = MotionKind::Arc;
            m.plane = plane;
            m.turns = static_cast<int>(v[4]);
            double e[3] = {0, 0, 0}, c[3] = {0, 0, 0};
            const int u = plane == Plane::XY ? 0 : plane == Plane::XZ ? 2 : 1;
            const int w = plane == Plane::XY ? 2 : plane == Plane::XZ ? 1 : 0;
            const int vv = 3 - u - w;
            e[u] = v[0];
            e[vv] = v[1];
            e[w] = v[5];
            c[u] = v[2];
            c[vv] = v[3];
            m.end = machine(e[0], e[1], e[2], v[6]);
            m.centre = machine(c[0], c[1], c[2], 0);
            push(m);
        } else if (name == "NURBS_FEED") {
            CanonMove m;
            m.kind = MotionKind::Feed;
            m.spline = true;
            push(m);
        } else if (name == "DWELL" && !v.empty()) {
            CanonMove m;
            m.kind = MotionKind::Dwell;
            m.dwellSeconds = v[0];
            push(m);
        } else if (name == "SET_FEED_RATE" && !v.empty()) {
            feedMm = v[0] * unit;
        } else if (name == "SET_SPINDLE_SPEED" && v.size() >= 2) {
            rpm = v[1];
        } else if (name == "START_SPINDLE_CLOCKWISE") {
            spindleDir = 1;
        } else if (name == "START_SPINDLE_COUNTERCLOCKWISE") {
            spindleDir = -1;
        } else if (name == "STOP_SPINDLE_TURNING") {
            spindleDir = 0;
        }
    }
    if (succeeded) { // what was taken for an error was printed by (PRINT, ...)
        run.error.clear();
        run.errorLine.clear();
    }
    return run;
}

bool Rs274Run::endedWithoutEnd() const
{
    return error == "File ended with no percent sign or program end";
}

namespace {

bool near(const Point4 &p, const Point4 &q, double tol)
{
    return std::fabs(p.x - q.x) <= tol && std::fabs(p.y - q.y) <= tol &&
           std::fabs(p.z - q.z) <= tol && std::fabs(p.a - q.a) <= 1e-4;
}

// The spindle speed in force after each entry of the toolpath (rpm; + M3, - M4, 0 stopped).
std::vector<double> spindleInForce(const Toolpath &tp)
{
    std::vector<double> out(tp.size());
    double rpm = 0;
    for (std::size_t i = 0; i < tp.size(); ++i) {
        if (tp.kind(i) == MotionKind::Event) {
            const Event &e = tp.event(i);
            if (e.kind == EventKind::SpindleCw)
                rpm = e.value;
            else if (e.kind == EventKind::SpindleCcw)
                rpm = -e.value;
            else if (e.kind == EventKind::SpindleOff)
                rpm = 0;
            else if (e.kind == EventKind::SpindleSpeed)
                rpm = rpm < 0 ? -e.value : e.value;
        }
        out[i] = rpm;
    }
    return out;
}

} // namespace

testing::AssertionResult matchesRs274(const std::string &file, const std::string &rs274File,
                                      const ToolTable *tools, const std::string &ini)
{
    const Rs274Run ref = runRs274(rs274File.empty() ? file : rs274File, tools, ini);
    if (!ref.error.empty() && !ref.endedWithoutEnd())
        return testing::AssertionFailure() << "rs274: " << ref.error << " at: " << ref.errorLine;
    Options options;
    Error iniError;
    if (!ini.empty() && !readLinuxCncIniFile(ini, &options, &iniError))
        return testing::AssertionFailure()
               << ini << ":" << iniError.line << ": " << englishMessage(iniError);
    if (tools)
        options.toolTable = *tools;
    const Result r = interpretFile(file, options);
    if (!r.ok())
        return testing::AssertionFailure()
               << "frezka: " << r.errors[0].line << ":" << r.errors[0].column << ": "
               << englishMessage(r.errors[0]);
    const Toolpath &tp = r.toolpath;
    const std::vector<double> spindle = spindleInForce(tp);
    std::vector<std::size_t> ours;
    for (std::size_t i = 0; i < tp.size(); ++i) {
        if (tp.kind(i) != MotionKind::Event)
            ours.push_back(i);
    }
    // A spline's chords (Frezka) stand for one NURBS_FEED (rs274): o walks Frezka's motions.
    std::size_t o = 0, k = 0;
    for (; k < ref.moves.size() && o < ours.size(); ++k, ++o) {
        const std::size_t i = ours[o];
        const CanonMove &m = ref.moves[k];
        std::string entry;
        appendJsonLine(entry, tp, i, true);
        auto failure = [&](const char *what) {
            return testing::AssertionFailure() << what << " differs at motion " << k
                                               << "\n  frezka " << entry << "\n  rs274  " << m.call;
        };
        if (tp.kind(i) != m.kind)
            return failure("kind");
        if (m.spline) { // every chord at the feed in force; the end is checked by what follows
            for (; o < ours.size() && tp.kind(ours[o]) == MotionKind::Feed &&
                   tp.line(ours[o]) == tp.line(i);
                 ++o) {
                if (std::fabs(tp.feedMmPerMin(ours[o]) - m.feedMmPerMin) >
                    1e-4 * 25.4 + 1e-9 * m.feedMmPerMin)
                    return failure("spline feed");
            }
            --o;
            continue;
        }
        if (std::fabs(spindle[i] - m.spindleRpm) > 1e-4 + 1e-9 * std::fabs(m.spindleRpm))
            return failure("spindle speed");
        if (m.kind == MotionKind::Dwell) {
            if (std::fabs(tp.event(i).value - m.dwellSeconds) > 1e-4)
                return failure("dwell time");
            continue;
        }
        const double tol = 1e-4 * m.unitMm + 1e-9; // 4 decimals in program units
        if (!near(tp.end(i), m.end, tol))
            return failure("end point");
        // rs274 prints the rate with 4 decimals in the units of the SET_FEED_RATE call.
        if (m.kind != MotionKind::Rapid &&
            std::fabs(tp.feedMmPerMin(i) - m.feedMmPerMin) > 1e-4 * 25.4 + 1e-9 * m.feedMmPerMin)
            return failure("feed");
        if (m.kind != MotionKind::Arc)
            continue;
        const ArcInfo arc = tp.arc(i);
        if (arc.plane != m.plane || arc.turns != m.turns)
            return failure("plane or turns");
        Point4 c = arc.centre, mc = m.centre; // only the in-plane coordinates are defined
        if (arc.plane == Plane::XY)
            c.z = mc.z = 0;
        else if (arc.plane == Plane::XZ)
            c.y = mc.y = 0;
        else
            c.x = mc.x = 0;
        c.a = mc.a = 0;
        if (!near(c, mc, tol))
            return failure("arc centre");
    }
    if (o != ours.size() || k != ref.moves.size())
        return testing::AssertionFailure()
               << "frezka has " << ours.size() - o << " more motions and dwells, rs274 "
               << ref.moves.size() - k << " more";
    return testing::AssertionSuccess();
}

} // namespace frezka::gcode::test
