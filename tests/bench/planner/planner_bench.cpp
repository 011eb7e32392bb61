// Planner benchmark: every bundled program (tests/bench/planner/programs) is interpreted,
// planned four ways (the product's full plan; a grbl-style junction-deviation plan with a
// 16-block lookahead and grbl's per-block acceleration, as grbl plans; the same lookahead with
// every cap of the full plan, so that it keeps the limits our plan keeps; a naive exact-stop
// plan of L moves) and run on the
// in-process emulator core, fed as fast as its queue accepts with no link delay. Per program and
// plan it prints the emulator job time, the time-optimal bound, their ratio, brake violations,
// starvation stops, vertices over the velocity-jump limit (measured on the emulator's own vertex
// speeds) and whether the final counters equal the rounded end position; plus the planning time.
//
//   planner_bench [--machine PROFILE.json] [FILE.nc ...]     (default: the GVE64 profile)
#include "emulatorrun.h"

#include "gcode/interpreter.h"
#include "machine/machineconfig.h"
#include "machine/planner.h"

#include <QCoreApplication>
#include <QDir>
#include <QFileInfo>

#include <chrono>
#include <cstdio>
#include <string>
#include <vector>

using namespace frezka;
using namespace frezka::machine;

namespace {

struct Row
{
    const char *plan;
    PlanResult result;
    test::EmulatorRun run;
    double planMs = 0;
};

Row runOne(const char *name, const gcode::Toolpath &tp, const MachineConfig &c, PlanStrategy s,
           bool limits = false)
{
    PlanOptions o;
    o.strategy = s;
    o.grblKeepsAllLimits = limits;
    if (s == PlanStrategy::GrblJunction) { // grbl: each block's own acceleration limit
        o.accelWindowSteps = 0;
        o.accelTolerance = 0;
    }
    const auto t0 = std::chrono::steady_clock::now();
    Row row{name, plan(tp, c, o), {}, 0};
    row.planMs =
        std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - t0).count();
    if (row.result.ok())
        row.run = test::runOnEmulator(row.result.program, c);
    return row;
}

void print(const std::string &program, const Row &r, double bound)
{
    if (!r.result.ok()) {
        std::printf("%-10s %-11s plan error: %s\n", program.c_str(), r.plan,
                    r.result.errors.front().message.c_str());
        return;
    }
    if (!r.run.error.empty()) {
        std::printf("%-10s %-11s emulator error: %s\n", program.c_str(), r.plan,
                    r.run.error.c_str());
        return;
    }
    std::size_t av = 0; // A and V commands: they cannot travel in packets (§2.2)
    for (const UnitCommand &c : r.result.program.commands)
        av += c.op == UnitOp::Accel || c.op == UnitOp::Speed ? 1 : 0;
    std::printf("%-10s %-11s %8zu %10.3f %10.3f %7.4f %6lld %6lld/%-4lld %6zu %7.3f %6zu %7.3f %5s "
                "%6zu %8.1f\n",
                program.c_str(), r.plan, r.result.stats.vectors, r.run.jobS, bound,
                r.run.jobS / bound, static_cast<long long>(r.run.brakeViolations),
                static_cast<long long>(r.run.starvationStops),
                static_cast<long long>(r.run.plannedStops), r.run.jumpOverLimit, r.run.maxJumpRatio,
                r.result.stats.curveAccelOverLimit, r.result.stats.maxCurveAccelRatio,
                r.run.countersMatch ? "yes" : "NO", av, r.planMs);
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    MachineConfig config = defaultMachineConfig(protocol::Variant::Gve64);
    std::vector<std::string> files;
    const QStringList args = app.arguments().mid(1);
    for (int i = 0; i < args.size(); ++i) {
        if (args[i] == QLatin1String("--machine") && i + 1 < args.size()) {
            const ConfigResult loaded = loadMachineConfig(args[++i].toStdString());
            if (!loaded.config) {
                for (const ConfigError &e : loaded.errors)
                    std::fprintf(stderr, "%s\n", e.message.c_str());
                return 1;
            }
            config = *loaded.config;
        } else {
            files.push_back(args[i].toStdString());
        }
    }
    if (files.empty()) {
        const QDir dir(QStringLiteral(FREZKA_PLANNER_PROGRAMS));
        for (const QString &f : dir.entryList({QStringLiteral("*.nc")}, QDir::Files, QDir::Name))
            files.push_back(dir.filePath(f).toStdString());
    }
    std::printf("machine: %s (%s), jump limit X %.1f mm/s\n", config.name.c_str(),
                protocol::variantInfo(config.unit.variant).displayName.data(),
                config.axes[0].maxJumpMmPerS);
    std::printf("%-10s %-11s %8s %10s %10s %7s %6s %11s %6s %7s %6s %7s %5s %6s %8s\n", "program",
                "plan", "vectors", "emulator_s", "bound_s", "ratio", "brakeV", "starv/plan",
                "jump>", "jumpMax", "acc>", "accMax", "cnt", "A+V", "plan_ms");
    int failures = 0;
    // Dense CAM programs (at least kDense vectors): the full plan against the grbl-style baseline.
    constexpr std::size_t kDense = 10000;
    int dense = 0, denseWins = 0;
    std::string vsBaseline, vsPlain;
    for (const std::string &file : files) {
        const gcode::Result g = gcode::interpretFile(file);
        const std::string name =
            QFileInfo(QString::fromStdString(file)).completeBaseName().toStdString();
        if (!g.ok()) {
            std::printf("%-14s G-code error: %s\n", name.c_str(),
                        gcode::formatError(QString::fromStdString(file), g.errors.front())
                            .toStdString()
                            .c_str());
            ++failures;
            continue;
        }
        const Row full = runOne("full", g.toolpath, config, PlanStrategy::Full);
        const Row grbl = runOne("grbl-jd", g.toolpath, config, PlanStrategy::GrblJunction);
        const Row grblJ =
            runOne("grbl+limits", g.toolpath, config, PlanStrategy::GrblJunction, true);
        const Row stop = runOne("exact-stop", g.toolpath, config, PlanStrategy::ExactStop);
        const double bound = full.result.stats.boundS;
        for (const Row *r : {&full, &grbl, &grblJ, &stop})
            print(name, *r, bound);
        const bool ok = full.result.ok() && full.run.error.empty() &&
                        full.run.jobS <= 1.02 * bound && full.run.brakeViolations == 0 &&
                        full.run.jumpOverLimit == 0 && full.run.countersMatch;
        failures += ok ? 0 : 1;
        if (ok && full.result.stats.vectors >= kDense && grblJ.run.error.empty() &&
            grbl.run.error.empty()) {
            ++dense;
            const bool wins = full.run.jobS < grblJ.run.jobS;
            denseWins += wins ? 1 : 0;
            char buf[128];
            std::snprintf(buf, sizeof buf, "%s%s %+.1f %%", vsBaseline.empty() ? "" : ", ",
                          name.c_str(), 100.0 * (full.run.jobS / grblJ.run.jobS - 1));
            vsBaseline += buf;
            std::snprintf(buf, sizeof buf, "%s%s %+.1f %%", vsPlain.empty() ? "" : ", ",
                          name.c_str(), 100.0 * (full.run.jobS / grbl.run.jobS - 1));
            vsPlain += buf;
        }
    }
    std::printf("full plans meeting every target (<= 1.02 x bound, no brake violation, no vertex "
                "over the jump limit, exact counters): %zu of %zu\n",
                files.size() - failures, files.size());
    std::printf("dense CAM programs (>= %zu vectors) where the full plan beats the grbl-style "
                "baseline held to the machine's limits (grbl+limits): %d of %d (%s)\n",
                kDense, denseWins, dense, vsBaseline.c_str());
    std::printf("for reference, against plain grbl junction deviation, which goes over the axis "
                "acceleration and jump limits (acc>, jump> above): %s\n",
                vsPlain.c_str());
    return failures || denseWins < dense ? 1 : 0;
}
