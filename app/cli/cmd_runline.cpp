// frezka-cli run-line --unit ADDR:FILE[:PROFILE] [--unit ...]... [--machine PROFILE]
//                     [--offset G54:X,Y,Z[,A]]... [--work-zero X,Y,Z[,A]]
//                     [--port PATH|sim] [--baud N] [--latency-ms N] [--quiet-ms N]
//                     [--timeout S]
// frezka-cli run-line --machine PROFILE --rotary-a ADDR[:PROFILE] [options as above] FILE
//
// Several units on one serial line (GVE114 manual §9.5: further units on the EXT branch
// cable, each with its own address), each running its own program at the same time: every
// --unit names a unit's address (0..6), the program it runs and, optionally, the profile of
// what it drives (default --machine; the offsets are the same for every unit). Each unit gets its
// own MachineCore on the one line (driver/link/sharedline.h): one exchange on the wire at a time,
// polling and streaming of all units taking turns.
//
// --port sim (default) runs the in-process emulator with one unit per --unit on one emulated
// wire, on a virtual clock; --port PATH a real line (gve-emu --units 0:gve114,1:gve114) in real
// time. Ends with one JSON line on stdout: per unit its address, whether its job ran to its end,
// the vectors sent, its counters at the end (positions polled after the job), its exchanges and
// share of the line's time, the recoveries and the replies that met a foreign one; for the line
// its share in use, the lines nobody's (stray) and those that came before the addressed unit
// could have heard its command (early). Exit code 0 when every job ran to its end, 1 on an
// error (on stderr, "unit ADDR: ..."), 2 on bad usage.
//
// A profile whose line.units lists a rotary table (role rotaryA) runs FILE that way without
// --rotary-a (its address, its profile or else --machine's).
// With --rotary-a one program runs on two units: the machine's (--machine, at its unit.address)
// drives X Y Z, a rotary table on a GVE114 at ADDR (its own profile, else --machine; its A
// axis) drives A. The program is split at the blocks that move A into sync points
// (machine/rotarysplit.h, driver/link/synchold.h): such a block starts on both units together
// once both have finished what came before it. The JSON adds the sync points passed and, per
// unit, how often and how long it waited for the other there.

#include "cli.h"
#include "programoptions.h"
#include "rotaryline.h"

#include <QDir>
#include <QFileInfo>

#include "driver/link/drivererror.h"
#include "driver/link/emulatorport.h"
#include "driver/link/linerunner.h"
#include "driver/link/linesync.h"
#include "driver/link/serialtransport.h"
#include "driver/link/sharedline.h"
#include "driver/link/sharedlineworker.h"
#include "machine/planner.h"
#include "protocol/variant.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QJsonArray>
#include <QJsonDocument>
#include <QJsonObject>
#include <QTimer>

#include <memory>
#include <vector>

namespace {

using namespace frezka;

// The command's messages (lupdate files them under this name).
struct RunLineCli
{
    Q_DECLARE_TR_FUNCTIONS(RunLineCli)
};

struct UnitArg
{
    int address = 0;
    QString file;
    QString profile; // what the unit drives; empty: --machine
};

struct Args
{
    std::vector<UnitArg> units;
    std::optional<UnitArg> rotaryA; // --rotary-a ADDR[:PROFILE] (file: the one program)
    QString file;                   // the program with --rotary-a
    cli::ProgramOptions program;
    QString port = QStringLiteral("sim");
    int baud = 0;
    double latencyMs = 0;
    double quietMs = 2;
    double timeoutS = 3600;
};

int usage()
{
    cli::err(RunLineCli::tr(
                 "usage: frezka-cli run-line --unit ADDRESS:FILE[:PROFILE] [--unit ...]... %1 "
                 "[--port PATH|sim] [--baud N] [--latency-ms N] [--quiet-ms N] [--timeout S]\n"
                 "       frezka-cli run-line --machine PROFILE --rotary-a ADDRESS[:PROFILE] "
                 "[options as above] FILE\n")
                 .arg(cli::programOptionsUsage()));
    return 2;
}

bool takeUnit(const QString &value, Args &args)
{
    const auto colon = value.indexOf(QLatin1Char(':'));
    bool ok = colon > 0;
    const int address = ok ? value.left(colon).toInt(&ok) : -1;
    if (!ok || address < 0 || address > 6 || value.mid(colon + 1).isEmpty()) {
        cli::err(RunLineCli::tr(
                     "frezka-cli run-line: cannot read --unit '%1': write ADDRESS:FILE with an "
                     "address 0..6, e.g. --unit 1:part.nc\n")
                     .arg(value));
        return false;
    }
    for (const UnitArg &u : args.units) {
        if (u.address == address) {
            cli::err(RunLineCli::tr(
                         "frezka-cli run-line: address %1 is given twice: each unit on the line "
                         "has its own address\n")
                         .arg(address));
            return false;
        }
    }
    const QString rest = value.mid(colon + 1);
    const auto second = rest.indexOf(QLatin1Char(':'));
    args.units.push_back({address, second < 0 ? rest : rest.left(second),
                          second < 0 ? QString() : rest.mid(second + 1)});
    return true;
}

bool takeRotary(const QString &value, Args &args)
{
    const auto colon = value.indexOf(QLatin1Char(':'));
    bool ok = false;
    const int address = (colon < 0 ? value : value.left(colon)).toInt(&ok);
    if (!ok || address < 1 || address > 6 || args.rotaryA) {
        cli::err(RunLineCli::tr("frezka-cli run-line: cannot read --rotary-a '%1': write the "
                                "rotary unit's address 1..6, once, and optionally its profile, "
                                "e.g. --rotary-a 1:rotary.json\n")
                     .arg(value));
        return false;
    }
    args.rotaryA = UnitArg{address, {}, colon < 0 ? QString() : value.mid(colon + 1)};
    return true;
}

// 0 = parsed, else the exit code.
// A program FILE without --rotary-a: the rotary table the --machine profile lists on its line
// (line.units, role rotaryA, its address and profile relative to the machine's), if any.
bool takeProfileRotary(Args &args)
{
    if (args.program.machine.isEmpty())
        return false;
    const machine::ConfigResult r = machine::loadMachineConfig(args.program.machine.toStdString());
    if (!r.config)
        return false; // loaded again later, its errors named then
    for (const machine::LineUnitConfig &u : r.config->line.units) {
        if (u.role != machine::LineUnitRole::RotaryA)
            continue;
        QString profile = QString::fromStdString(u.profile);
        if (!profile.isEmpty() && QFileInfo(profile).isRelative())
            profile = QFileInfo(args.program.machine).absoluteDir().filePath(profile);
        args.rotaryA = UnitArg{u.address, {}, profile};
        return true;
    }
    return false;
}

int parseArgs(const QStringList &raw, Args &args)
{
    for (int i = 0; i < raw.size(); ++i) {
        const QString &a = raw[i];
        bool ok = true;
        if (cli::takeProgramOption(raw, i, &args.program, &ok)) {
            if (!ok)
                return 2;
            continue;
        }
        if (!a.startsWith(QLatin1String("--")) && args.file.isEmpty()) {
            args.file = a; // the program of --rotary-a
            continue;
        }
        if (i + 1 >= raw.size())
            return usage();
        const QString v = raw[++i];
        if (a == QLatin1String("--unit")) {
            if (!takeUnit(v, args))
                return 2;
        } else if (a == QLatin1String("--rotary-a")) {
            if (!takeRotary(v, args))
                return 2;
        } else if (a == QLatin1String("--port")) {
            args.port = v;
        } else if (a == QLatin1String("--baud")) {
            args.baud = v.toInt(&ok);
        } else if (a == QLatin1String("--latency-ms")) {
            args.latencyMs = v.toDouble(&ok);
        } else if (a == QLatin1String("--quiet-ms")) {
            args.quietMs = v.toDouble(&ok);
            ok = ok && args.quietMs >= 0 && args.quietMs <= 1000;
        } else if (a == QLatin1String("--timeout")) {
            args.timeoutS = v.toDouble(&ok);
            ok = ok && args.timeoutS > 0;
        } else {
            return usage();
        }
        if (!ok)
            return usage();
    }
    if (args.rotaryA && (!args.units.empty() || args.file.isEmpty())) {
        cli::err(RunLineCli::tr("frezka-cli run-line: --rotary-a runs one program on the "
                                "machine's unit and the rotary unit: give the program's FILE "
                                "and no --unit\n"));
        return 2;
    }
    if (!args.rotaryA && !args.file.isEmpty() && !takeProfileRotary(args))
        return usage();
    return args.units.empty() && !args.rotaryA ? usage() : 0;
}

std::optional<machine::UnitProgram> planFile(const QString &file, const Args &args,
                                             const machine::MachineConfig &config)
{
    const auto program = cli::interpretFile(file, args.program);
    if (!program)
        return std::nullopt;
    const machine::PlanResult plan = machine::plan(*program->toolpath, config, {});
    for (const machine::PlanError &e : plan.warnings)
        cli::err(cli::planMessage(file, e, RunLineCli::tr("warning: ")));
    if (!plan.ok()) {
        for (const machine::PlanError &e : plan.errors)
            cli::err(cli::planMessage(file, e, QString()));
        return std::nullopt;
    }
    return plan.program;
}

// The unit's profile (its own, else --machine) at the unit's address; only a GVE114 is ordered
// with another address than 0 (unit.address).
std::optional<machine::MachineConfig> unitProfile(const UnitArg &unit, const Args &args)
{
    auto config = cli::loadProfile(unit.profile.isEmpty() ? args.program.machine : unit.profile);
    if (!config)
        return std::nullopt;
    config->unit.address = unit.address;
    if (unit.address != 0 && config->unit.variant != protocol::Variant::Gve114) {
        const auto name = protocol::variantInfo(config->unit.variant).displayName;
        cli::err(RunLineCli::tr("frezka-cli run-line: unit %1: a %2 answers on address 0 only; "
                                "give it address 0, or use a GVE114 profile (--machine gve114)\n")
                     .arg(unit.address)
                     .arg(QString::fromUtf8(name.data(), static_cast<int>(name.size()))));
        return std::nullopt;
    }
    return config;
}

// The units on the line: their cores, the arbiter, what became of each job.
struct Line
{
    std::vector<std::unique_ptr<driver::MachineCore>> cores;
    std::unique_ptr<driver::SharedLine> line;
    std::unique_ptr<driver::LineSync> sync; // --rotary-a: the units' sync points
    std::vector<int> finished;              // -1 running, 0 failed, 1 ran to its end
    bool failed = false;
    bool started = false;

    bool allConnected() const
    {
        for (const auto &c : cores)
            if (c->state().mode != driver::MachineMode::Idle)
                return false;
        return true;
    }
    bool allDone() const
    {
        return failed ||
               std::all_of(finished.begin(), finished.end(), [](int f) { return f >= 0; });
    }
};

void build(Line &l, const Args &args, const std::vector<machine::MachineConfig> &configs)
{
    std::vector<driver::MachineCore *> raw;
    for (std::size_t i = 0; i < args.units.size(); ++i) {
        driver::CoreOptions options;
        options.link.sharedLine = true;
        options.link.unitAddress = args.units[i].address;
        if (args.baud > 0)
            options.link.baud = args.baud;
        auto core = std::make_unique<driver::MachineCore>(configs[i], options);
        const int address = args.units[i].address;
        core->onError = [address](const driver::MachineError &e) {
            cli::err(RunLineCli::tr("unit %1: %2\n")
                         .arg(address)
                         .arg(driver::translatedText(e.reason, true)));
        };
        core->onStateChanged = [&l](const driver::MachineState &s) {
            l.failed = l.failed || s.mode == driver::MachineMode::Alarm ||
                       s.mode == driver::MachineMode::LinkLost;
        };
        core->onJobFinished = [&l, i](bool ok) { l.finished[i] = ok ? 1 : 0; };
        raw.push_back(core.get());
        l.cores.push_back(std::move(core));
    }
    l.finished.assign(args.units.size(), -1);
    driver::SharedLineOptions lineOptions;
    lineOptions.baud = args.baud > 0 ? args.baud : configs.front().link.baud;
    lineOptions.quietS = args.quietMs / 1000.0;
    l.line = std::make_unique<driver::SharedLine>(raw, lineOptions);
    if (args.rotaryA)
        l.sync = std::make_unique<driver::LineSync>(raw);
}

// Starts every job once every unit is connected; false (on stderr) when a core refuses.
bool startJobs(Line &l, const std::vector<machine::SyncedProgram> &programs, const Args &args,
               double now)
{
    l.started = true;
    for (std::size_t i = 0; i < l.cores.size(); ++i) {
        if (const auto refused = l.cores[i]->runSynced(programs[i], now)) {
            cli::err(RunLineCli::tr("unit %1: %2\n")
                         .arg(args.units[i].address)
                         .arg(driver::translatedText(refused->reason, true)));
            return false;
        }
    }
    return true;
}

bool runSim(Line &l, const std::vector<machine::SyncedProgram> &programs, const Args &args,
            const std::vector<machine::MachineConfig> &configs, double &now)
{
    std::vector<emulator::UnitOptions> units;
    for (std::size_t i = 0; i < args.units.size(); ++i) {
        emulator::UnitOptions u = driver::unitOptionsFor(configs[i]);
        u.address = args.units[i].address;
        u.spindleAddress = i == 0;
        units.push_back(std::move(u));
    }
    driver::WireOptions wire;
    wire.baud = args.baud > 0 ? args.baud : configs.front().link.baud;
    wire.latencyS = args.latencyMs / 1000.0;
    driver::EmulatorPort port(std::move(units), wire);
    driver::LineRunner runner(*l.line, port);
    runner.open();
    const bool connected =
        runner.runUntil([&] { return l.allConnected() || l.failed; }, 60) && !l.failed;
    now = runner.now();
    if (!connected || !startJobs(l, programs, args, runner.now()))
        return false;
    runner.runUntil([&] { return l.allDone(); }, args.timeoutS);
    runner.runFor(0.3); // a last poll of every unit's counters
    now = runner.now();
    return l.allDone() && !l.failed;
}

bool runPort(Line &l, const std::vector<machine::SyncedProgram> &programs, const Args &args,
             const std::vector<machine::MachineConfig> &configs, double &now)
{
    const int baud = args.baud > 0 ? args.baud : configs.front().link.baud;
    driver::SharedLineWorker worker(*l.line, new driver::SerialTransport(args.port, baud));
    QEventLoop loop;
    bool ok = true;
    QObject::connect(&worker, &driver::SharedLineWorker::closed, &loop, [&](const QString &why) {
        if (!why.isEmpty())
            cli::err(RunLineCli::tr("frezka-cli run-line: %1\n").arg(why));
        ok = false;
        loop.quit();
    });
    QTimer tick; // the jobs start when all are connected; the loop ends when all are done
    QObject::connect(&tick, &QTimer::timeout, &loop, [&] {
        if (l.failed || (l.started && l.allDone())) {
            loop.quit();
        } else if (!l.started && l.allConnected()) {
            ok = startJobs(l, programs, args, worker.now());
            worker.service();
            if (!ok)
                loop.quit();
        }
    });
    tick.start(20);
    QTimer::singleShot(static_cast<int>(args.timeoutS * 1000), &loop, &QEventLoop::quit);
    worker.open();
    loop.exec();
    if (ok && l.allDone() && !l.failed) {
        QTimer::singleShot(300, &loop, &QEventLoop::quit); // a last poll of every unit
        loop.exec();
    }
    QObject::disconnect(&worker, nullptr, &loop, nullptr);
    now = worker.now();
    worker.close();
    return ok && l.allDone() && !l.failed;
}

QJsonObject report(const Line &l, const Args &args, double now)
{
    QJsonArray units;
    const driver::SharedLineStats &s = l.line->stats();
    for (std::size_t i = 0; i < l.cores.size(); ++i) {
        const driver::MachineCore &c = *l.cores[i];
        QJsonArray pos;
        for (std::int64_t p : c.state().positionSteps)
            pos.append(static_cast<double>(p));
        units.append(QJsonObject{
            {QStringLiteral("address"), args.units[i].address},
            {QStringLiteral("ok"), l.finished[i] == 1},
            {QStringLiteral("vectors"), static_cast<double>(c.jobReport().vectors)},
            {QStringLiteral("position_steps"), pos},
            {QStringLiteral("exchanges"), static_cast<double>(s.units[i].exchanges)},
            {QStringLiteral("line_share"), l.line->unitShare(i, now)},
            {QStringLiteral("collisions"), static_cast<double>(s.units[i].collisions)},
            {QStringLiteral("recovered"), static_cast<double>(c.engine().stats().recovered)},
            {QStringLiteral("resent"), static_cast<double>(c.engine().stats().resent)}});
        if (l.sync) {
            QJsonObject u = units.last().toObject();
            u.insert(QStringLiteral("role"),
                     i == 0 ? QStringLiteral("machine") : QStringLiteral("rotaryA"));
            u.insert(QStringLiteral("sync_waits"),
                     static_cast<double>(l.sync->stats().units[i].waits));
            u.insert(QStringLiteral("sync_wait_s"), l.sync->stats().units[i].waitS);
            units[static_cast<int>(i)] = u;
        }
    }
    QJsonObject out{{QStringLiteral("units"), units},
                    {QStringLiteral("line_share"), l.line->lineShare(now)},
                    {QStringLiteral("stray_lines"), static_cast<double>(s.strayLines)},
                    {QStringLiteral("early_lines"), static_cast<double>(s.earlyLines)},
                    {QStringLiteral("elapsed_s"), now - s.startS}};
    if (l.sync)
        out.insert(QStringLiteral("sync_points"), static_cast<double>(l.sync->stats().released));
    return out;
}

// --rotary-a: the machine's unit first, the rotary unit second, one program split for both.
bool planRotary(Args &args, std::vector<machine::MachineConfig> &configs,
                std::vector<machine::SyncedProgram> &programs)
{
    auto plan =
        cli::planRotaryLine(args.file, args.program, args.rotaryA->address, args.rotaryA->profile);
    if (!plan)
        return false;
    args.units = {{plan->machine.unit.address, args.file, {}}, *args.rotaryA};
    configs = {plan->machine, plan->rotary};
    programs = {std::move(plan->split.machine), std::move(plan->split.rotary)};
    return true;
}

int runLine(const QStringList &raw)
{
    Args args;
    if (const int code = parseArgs(raw, args))
        return code;
    std::vector<machine::MachineConfig> configs;
    std::vector<machine::SyncedProgram> programs;
    if (args.rotaryA && !planRotary(args, configs, programs))
        return 1;
    for (const UnitArg &u : args.rotaryA ? std::vector<UnitArg>{} : args.units) {
        auto config = unitProfile(u, args);
        auto program = config ? planFile(u.file, args, *config) : std::nullopt;
        if (!program)
            return 1;
        configs.push_back(std::move(*config));
        programs.push_back({std::move(*program), {}});
    }
    Line l;
    build(l, args, configs);
    double now = 0;
    const bool ok = args.port == QLatin1String("sim") ? runSim(l, programs, args, configs, now)
                                                      : runPort(l, programs, args, configs, now);
    cli::out(QString::fromUtf8(QJsonDocument(report(l, args, now)).toJson(QJsonDocument::Compact)) +
             QLatin1Char('\n'));
    return ok ? 0 : 1;
}

} // namespace

// Registered by hand: the command's name is not an identifier (FREZKA_CLI_COMMAND).
static const bool frezkaCliRegisteredRunLine = frezka::cli::registerCommand(
    "run-line",
    {"run-line --unit ADDRESS:FILE[:PROFILE] [--unit ...]... [--machine PROFILE] "
     "[--port PATH|sim] [--baud N] [--latency-ms N] [--quiet-ms N] [--timeout S]; "
     "run-line --machine PROFILE --rotary-a ADDRESS[:PROFILE] [...] FILE",
     QT_TRANSLATE_NOOP("frezka::cli",
                       "Run a program on each of several units sharing one serial line"),
     runLine});
