// frezka-cli plan FILE [--machine PROFILE.json] [--offset G54:X,Y,Z[,A]]...
//                      [--work-zero X,Y,Z[,A]] [--strategy full|exact-stop|grbl]
//
// Interprets FILE from its work offsets (programoptions.h), plans it for the machine (default:
// the shipped GVE64 profile) and writes the unit commands one per line as they would go on the
// wire without checksums ("!0B1200", "!0C697,30,0"); the driver's own steps (waiting for the
// queue to drain, dwells, operator stops, probing, the end) are comment lines starting with '#'.
// The last line is a JSON summary:
// {"vectors":…,"chains":…,"estimated_s":…,"bound_s":…,"max_vertex_jump_mm_s":…}.
// G-code, profile and plan errors (soft limits first) go to stderr before anything is written
// to stdout; exit code 1. Plan warnings go to stderr and the plan is written.
#include "cli.h"
#include "programoptions.h"

#include "machine/machineconfig.h"
#include "machine/planner.h"
#include "machine/unitwire.h"

#include <QCoreApplication>

#include <cstdio>

namespace {

using namespace frezka;

QString usageText()
{
    return QStringLiteral("usage: frezka-cli plan FILE %1 [--strategy full|exact-stop|grbl]\n")
        .arg(cli::programOptionsUsage());
}

struct Args
{
    QString file;
    cli::ProgramOptions program;
    machine::PlanStrategy strategy = machine::PlanStrategy::Full;
};

bool parseArgs(const QStringList &args, Args *out)
{
    for (int i = 0; i < args.size(); ++i) {
        const QString &a = args[i];
        bool ok = true;
        if (cli::takeProgramOption(args, i, &out->program, &ok)) {
            if (!ok)
                return false;
        } else if (a == QLatin1String("--strategy") && i + 1 < args.size()) {
            const QString s = args[++i];
            if (s == QLatin1String("full"))
                out->strategy = machine::PlanStrategy::Full;
            else if (s == QLatin1String("exact-stop"))
                out->strategy = machine::PlanStrategy::ExactStop;
            else if (s == QLatin1String("grbl"))
                out->strategy = machine::PlanStrategy::GrblJunction;
            else
                return false;
        } else if (out->file.isEmpty() && !a.startsWith(QLatin1String("--"))) {
            out->file = a;
        } else {
            return false;
        }
    }
    return !out->file.isEmpty();
}

// "FILE:LINE: what" (the message without its own "line N: " prefix).
QString tr(const char *text)
{
    return QCoreApplication::translate("frezka::cli", text);
}

int runPlan(const QStringList &rawArgs)
{
    Args args;
    if (!parseArgs(rawArgs, &args)) {
        cli::err(usageText());
        return 2;
    }
    const std::optional<machine::MachineConfig> config = cli::loadProfile(args.program.machine);
    if (!config)
        return 1;
    const auto program = cli::interpretFile(args.file, args.program);
    if (!program)
        return 1;
    machine::PlanOptions options;
    options.strategy = args.strategy;
    const machine::PlanResult plan = machine::plan(*program->toolpath, *config, options);
    for (const machine::PlanError &e : plan.warnings)
        cli::err(cli::planMessage(args.file, e, tr("warning: ")));
    if (!plan.ok()) {
        for (const machine::PlanError &e : plan.errors)
            cli::err(cli::planMessage(args.file, e, QString()));
        return 1;
    }
    std::string out;
    out.reserve(1 << 20);
    for (const machine::UnitCommand &c : plan.program.commands) {
        out += machine::commandText(c, plan.program.axisCount);
        out += '\n';
        if (out.size() > (1 << 20) - 64) {
            std::fwrite(out.data(), 1, out.size(), stdout);
            out.clear();
        }
    }
    char summary[256];
    const machine::PlanStats &s = plan.stats;
    std::snprintf(summary, sizeof summary,
                  "{\"vectors\":%zu,\"chains\":%zu,\"estimated_s\":%.4f,\"bound_s\":%.4f,"
                  "\"max_vertex_jump_mm_s\":%.4f}\n",
                  s.vectors, s.chains, s.estimatedS, s.boundS, s.maxVertexJumpMmPerS);
    out += summary;
    if (std::fwrite(out.data(), 1, out.size(), stdout) != out.size() || std::fflush(stdout) != 0) {
        cli::err(tr("frezka-cli: cannot write the plan\n"));
        return 1;
    }
    return 0;
}

} // namespace

FREZKA_CLI_COMMAND(
    plan,
    "plan FILE [--machine PROFILE] [--offset G54:X,Y,Z[,A]]... "
    "[--work-zero X,Y,Z[,A]] [--strategy full|exact-stop|grbl]",
    QT_TRANSLATE_NOOP("frezka::cli",
                      "Plan a G-code program for a machine and print the unit commands"),
    runPlan);
