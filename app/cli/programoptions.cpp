#include "programoptions.h"

#include "cli.h"

#include "app/common/datadir.h"

#include "gcode/error.h"
#include "gcode/heightmap.h"
#include "session/tooltablefile.h"

#include <QFile>
#include <QFileInfo>

namespace frezka::cli {
namespace {

// "X,Y,Z" or "X,Y,Z,A" in mm.
bool parseAxes(const QString &text, session::Axes4 *out)
{
    const QStringList parts = text.split(QLatin1Char(','));
    if (parts.size() < 3 || parts.size() > 4)
        return false;
    session::Axes4 axes{};
    for (int i = 0; i < parts.size(); ++i) {
        bool ok = false;
        axes[std::size_t(i)] = parts[i].trimmed().toDouble(&ok);
        if (!ok)
            return false;
    }
    *out = axes;
    return true;
}

// "G54:X,Y,Z[,A]": the system's index and offset.
bool parseOffset(const QString &text, int *system, session::Axes4 *axes)
{
    const int colon = text.indexOf(QLatin1Char(':'));
    if (colon < 0)
        return false;
    const QString name = text.left(colon).trimmed().toUpper();
    for (int s = 0; s < session::kWorkSystems; ++s) {
        if (session::workSystemName(s) == name) {
            *system = s;
            return parseAxes(text.mid(colon + 1), axes);
        }
    }
    return false;
}

} // namespace

// The map of `path` applied to the outcome's toolpath, said on stdout with the map's range;
// false (the reason on stderr) when the file is bad or the program cuts outside the map.
static bool applyHeightMapFile(const QString &path, session::InterpretOutcome *outcome)
{
    QString error;
    const std::optional<gcode::HeightMap> map = gcode::HeightMap::load(path, &error);
    if (!map) {
        err(error + QLatin1Char('\n'));
        return false;
    }
    gcode::HeightMapApplied applied = gcode::applyHeightMap(*outcome->toolpath, *map);
    if (!applied.path) {
        err(applied.error + QLatin1Char('\n'));
        return false;
    }
    out(ProgramCli::tr("Height map %1 applied: X %2 to %3, Y %4 to %5 mm, heights %6 to %7 mm "
                       "(%8 x %9 points)\n")
            .arg(path)
            .arg(map->originX(), 0, 'f', 3)
            .arg(map->endX(), 0, 'f', 3)
            .arg(map->originY(), 0, 'f', 3)
            .arg(map->endY(), 0, 'f', 3)
            .arg(map->minZ(), 0, 'f', 3)
            .arg(map->maxZ(), 0, 'f', 3)
            .arg(map->countX())
            .arg(map->countY()));
    outcome->toolpath = std::make_shared<gcode::Toolpath>(std::move(*applied.path));
    return true;
}

QString programOptionsUsage()
{
    return QStringLiteral("[--machine PROFILE] [--offset G54:X,Y,Z[,A]]... [--work-zero X,Y,Z[,A]] "
                          "[--height-map FILE]");
}

bool takeProgramOption(const QStringList &args, int &i, ProgramOptions *options, bool *ok)
{
    const QString &key = args[i];
    const bool known = key == QLatin1String("--machine") || key == QLatin1String("--offset") ||
                       key == QLatin1String("--work-zero") || key == QLatin1String("--height-map");
    if (!known)
        return false;
    if (i + 1 >= args.size()) {
        err(ProgramCli::tr("frezka-cli: %1 needs a value\n").arg(key));
        *ok = false;
        return true;
    }
    const QString value = args[++i];
    int system = 0;
    session::Axes4 axes{};
    if (key == QLatin1String("--machine")) {
        options->machine = value;
    } else if (key == QLatin1String("--height-map")) {
        options->heightMap = value;
    } else if (key == QLatin1String("--offset") ? parseOffset(value, &system, &axes)
                                                : parseAxes(value, &axes)) {
        options->offsets.systems[std::size_t(system)] = axes;
        options->offsetsGiven = true;
    } else {
        err(ProgramCli::tr("frezka-cli: %1 %2: expected %3 (machine mm of the program's zero)\n")
                .arg(key, value,
                     key == QLatin1String("--offset") ? QStringLiteral("G54:X,Y,Z[,A] .. G59.3:...")
                                                      : QStringLiteral("X,Y,Z[,A]")));
        *ok = false;
    }
    return true;
}

std::optional<machine::MachineConfig> loadProfile(const QString &path)
{
    if (path.isEmpty())
        return machine::defaultMachineConfig(protocol::Variant::Gve64);
    // A file, or a shipped profile by name (--machine gve84): app/common/datadir.h.
    const machine::ConfigResult loaded =
        machine::loadMachineConfig(app::resolveProfile(path).toStdString());
    printConfigNotes(loaded);
    if (!loaded.config) {
        for (const machine::ConfigError &e : loaded.errors)
            err(QString::fromStdString(e.message) + QLatin1Char('\n'));
        return std::nullopt;
    }
    return *loaded.config;
}

std::optional<session::InterpretOutcome> interpretFile(const QString &file,
                                                       const ProgramOptions &options,
                                                       int *errorCount, std::uint32_t startLine,
                                                       session::InterpretRequest *requestOut)
{
    QFile f(file);
    if (!f.open(QIODevice::ReadOnly)) {
        err(gcode::formatError(file,
                               {gcode::ErrorCode::FileOpenFailed, 0, 0, file.toStdString(), {}}) +
            QLatin1Char('\n'));
        if (errorCount)
            *errorCount = 1;
        return std::nullopt;
    }
    session::InterpretRequest request;
    request.text = f.readAll();
    request.fileName = file;
    request.programDirectory = QFileInfo(file).absolutePath().toStdString();
    request.offsets = options.offsets;
    request.startLine = startLine;
    if (!options.machine.isEmpty()) { // the profile's tool table (its errors come as the first)
        const machine::ConfigResult named =
            machine::loadMachineConfig(app::resolveProfile(options.machine).toStdString());
        if (named.config) { // its bounds on a program that never ends, its subroutine folders
            request.limits = named.config->program;
            request.splineToleranceMm = named.config->motion.chordToleranceMm;
            request.subroutinePath = machine::subroutineFolders(
                *named.config, app::resolveProfile(options.machine).toStdString());
        }
        const machine::ConfigResult profile =
            machine::loadMachineConfig(options.machine.toStdString());
        if (profile.config) {
            session::ToolTableFile tools =
                session::readProfileToolTable(*profile.config, options.machine);
            request.toolTable = std::move(tools.table);
            request.toolTableError = tools.error;
        }
    }
    request.maxErrors =
        gcode::Options{}.maxErrors; // a terminal lists as many as the interpreter keeps
    session::InterpretOutcome outcome = session::interpretProgram(request);
    if (requestOut)
        *requestOut = request;
    for (const session::ProgramMessage &w : outcome.warnings)
        err(w.text + QLatin1Char('\n'));
    if (errorCount) // the errors shown (the last line may say how many more) and those not
        *errorCount = int(outcome.errors.size() - (outcome.errorsNotShown > 0 ? 1 : 0) +
                          outcome.errorsNotShown);
    if (outcome.errors.empty() && !options.heightMap.isEmpty() && outcome.toolpath &&
        !applyHeightMapFile(options.heightMap, &outcome)) {
        if (errorCount)
            *errorCount = 1;
        return std::nullopt;
    }
    if (outcome.errors.empty())
        return outcome;
    for (const session::ProgramMessage &e : outcome.errors)
        err(e.text + QLatin1Char('\n'));
    return std::nullopt;
}

} // namespace frezka::cli
