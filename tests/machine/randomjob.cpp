#include "randomjob.h"

#include "emulatorrun.h"

#include "machine/unitmodel.h"

#include "driver/link/machinecore.h"
#include "driver/link/simrunner.h"
#include "gcode/error.h"
#include "gcode/interpreter.h"
#include "protocol/variant.h"

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <random>
#include <set>

namespace frezka::machine::test {

namespace {

using Rng = std::mt19937_64;

double uniform(Rng &rng, double lo, double hi)
{
    return std::uniform_real_distribution<double>(lo, hi)(rng);
}
double logUniform(Rng &rng, double lo, double hi)
{
    return std::exp(uniform(rng, std::log(lo), std::log(hi)));
}
bool chance(Rng &rng, double p)
{
    return uniform(rng, 0, 1) < p;
}
template<class T>
T pick(Rng &rng, std::span<const T> values)
{
    return values[std::uniform_int_distribution<std::size_t>(0, values.size() - 1)(rng)];
}

// Axis keys across their schema ranges (machine/configschema.h), made consistent the way a
// user's profile must be (machine/configrules.cpp): speeds within the pulse rate, rapid at most
// the maximum speed, acceleration x steps/mm at least the unit's A1.
void drawAxis(Rng &rng, AxisConfig &a, int pulseRate)
{
    // Mostly what machines have (5..2000 steps/mm), sometimes the schema's extremes.
    a.stepsPerMm = chance(rng, 0.85) ? logUniform(rng, 5, 2000) : logUniform(rng, 1, 10000);
    a.stepsPerMm = std::round(a.stepsPerMm * 1000) / 1000;
    const double limit = std::floor(pulseRate / a.stepsPerMm * 60.0);
    a.maxSpeedMmPerMin = std::max(1.0, std::floor(std::min(limit, 1e6) * uniform(rng, 0.05, 1)));
    a.maxSpeedMmPerMin = std::min(a.maxSpeedMmPerMin, std::min(limit, 20000.0));
    a.rapidMmPerMin = std::max(1.0, std::floor(a.maxSpeedMmPerMin * uniform(rng, 0.5, 1)));
    const double minAccel = 1000.0 / a.stepsPerMm;
    a.accelMmPerS2 = std::max(minAccel * 1.001, logUniform(rng, 5, chance(rng, 0.9) ? 3000 : 1e5));
    a.maxJumpMmPerS = chance(rng, 0.05) ? 0 : logUniform(rng, 0.05, chance(rng, 0.9) ? 20 : 1000);
}

MachineConfig drawConfig(Rng &rng, driver::WireOptions &wire)
{
    static constexpr protocol::Variant kVariants[] = {
        protocol::Variant::Gve84, protocol::Variant::Gve64, protocol::Variant::Gve64Phantom,
        protocol::Variant::Gve114};
    const protocol::Variant variant = pick<protocol::Variant>(rng, kVariants);
    MachineConfig c = defaultMachineConfig(variant);
    const auto &info = protocol::variantInfo(variant);
    c.unit.maxPulseRate = pick<int>(rng, info.maxPulseRates);
    for (int i = 0; i < info.axisCount; ++i)
        drawAxis(rng, c.axes[static_cast<std::size_t>(i)], c.unit.maxPulseRate);
    if (info.axisCount == 4)
        c.axes[3].present = chance(rng, 0.4);
    // The MPG's top speed must stay within half the pulse rate on every axis (configrules.cpp);
    // it plays no part in a job, and a dumped profile must load.
    for (const AxisConfig &a : c.axes) {
        if (a.present)
            c.eeprom.mpgMaxSpeedMmPerS = std::min(
                c.eeprom.mpgMaxSpeedMmPerS, c.unit.maxPulseRate / 2.0 / a.stepsPerMm * (1 - 1e-9));
    }
    c.motion.junctionDeviationMm = chance(rng, 0.1) ? 0 : logUniform(rng, 0.001, 10);
    c.motion.chordToleranceMm = logUniform(rng, 0.0001, 1);
    c.motion.pauseMs = std::uniform_int_distribution<int>(1, 24)(rng);
    static constexpr SpeedModeChoice kModes[] = {SpeedModeChoice::Auto, SpeedModeChoice::Vk,
                                                 SpeedModeChoice::Vn};
    c.motion.speedMode = pick<SpeedModeChoice>(rng, kModes);
    if (c.motion.speedMode == SpeedModeChoice::Vk && c.axes[3].present)
        c.motion.speedMode = SpeedModeChoice::Vn;
    c.spindle.spinUpMs = chance(rng, 0.5) ? 0 : std::uniform_int_distribution<int>(0, 3000)(rng);
    c.link.baud = pick<int>(rng, info.bauds);
    c.link.packets = chance(rng, 0.85);
    c.link.latencyMs = chance(rng, 0.2) ? 0 : std::round(uniform(rng, 0, 16) * 10) / 10;
    c.link.checksums = true;
    wire.baud = c.link.baud;
    wire.latencyS = c.link.latencyMs / 1000.0;
    if (chance(rng, 0.25)) {
        wire.byteErrorRate = 1e-3;
        wire.replyLossRate = 1e-3;
    }
    wire.seed = static_cast<std::uint32_t>(rng());
    return c;
}

// Writes G-code for moves inside a box of the machine's travel, in mm or inches.
class ProgramWriter
{
public:
    ProgramWriter(Rng &rng, const MachineConfig &c)
        : m_rng(rng)
        , m_c(c)
    {
        for (int i = 0; i < 3; ++i) {
            const AxisConfig &a = c.axes[static_cast<std::size_t>(i)];
            const double span = a.softMaxMm - a.softMinMm;
            m_lo[i] = a.softMinMm + 0.1 * span;
            m_hi[i] = a.softMaxMm - 0.1 * span;
        }
        m_maxFeed = 1e9;
        for (int i = 0; i < 4; ++i) {
            if (c.axes[static_cast<std::size_t>(i)].present)
                m_maxFeed =
                    std::min(m_maxFeed, c.axes[static_cast<std::size_t>(i)].maxSpeedMmPerMin);
        }
        m_text = "(random job)\nG21 G90 G17 G94 G64\n";
        m_pos = {0, 0, 0, std::clamp(0.0, c.axes[3].softMinMm + 1, c.axes[3].softMaxMm - 1)};
    }

    int count() const { return m_lines; }
    std::string take() { return m_text + "M5 M9\nM2\n"; }

    void block()
    {
        const double r = uniform(m_rng, 0, 1);
        if (chance(m_rng, 0.15))
            units(!m_inch);
        if (r < 0.3)
            raster();
        else if (r < 0.45)
            arcs();
        else if (r < 0.6)
            zigzag();
        else if (r < 0.75)
            lines();
        else if (r < 0.85)
            rapids();
        else
            io();
    }

private:
    void units(bool inch)
    {
        m_inch = inch;
        put(inch ? "G20" : "G21");
    }
    std::string num(double mm) const
    {
        char buf[32];
        std::snprintf(buf, sizeof buf, "%.4f", m_inch ? mm / 25.4 : mm);
        return buf;
    }
    void put(const std::string &line)
    {
        m_text += line + '\n';
        ++m_lines;
    }
    // A feed from 1 % to 300 % of the slowest present axis's maximum speed (mm/min).
    void feed()
    {
        const double f = m_maxFeed * logUniform(m_rng, 0.01, 3.0);
        put("F" + num(std::max(f, 0.01)));
    }
    double inBox(int i, double v) const { return std::clamp(v, m_lo[i], m_hi[i]); }
    std::string xyz(double x, double y, double z)
    {
        m_pos[0] = inBox(0, x), m_pos[1] = inBox(1, y), m_pos[2] = inBox(2, z);
        return "X" + num(m_pos[0]) + " Y" + num(m_pos[1]) + " Z" + num(m_pos[2]);
    }
    std::string aWord(double step)
    {
        if (!m_c.axes[3].present)
            return {};
        const AxisConfig &a = m_c.axes[3];
        m_pos[3] = std::clamp(m_pos[3] + step, a.softMinMm + 1, a.softMaxMm - 1);
        char buf[32];
        std::snprintf(buf, sizeof buf, " A%.3f", m_pos[3]);
        return buf;
    }

    // A 3D finishing raster: rows of short segments over a wavy surface.
    void raster()
    {
        feed();
        const double seg = logUniform(m_rng, 0.01, 0.5);
        const int n = std::uniform_int_distribution<int>(20, 300)(m_rng);
        const int rows = std::uniform_int_distribution<int>(1, 4)(m_rng);
        const double amp = logUniform(m_rng, 0.01, 5), wave = logUniform(m_rng, 0.05, 3);
        const double x0 = m_pos[0], y0 = m_pos[1], z0 = inBox(2, m_pos[2] - 2 * amp);
        for (int row = 0; row < rows; ++row) {
            for (int k = 0; k < n; ++k) {
                const double t = row % 2 ? n - k : k;
                const double x = x0 + t * seg, y = y0 + row * seg * 3;
                put("G1 " + xyz(x, y, z0 + amp * std::sin(x * wave) * std::cos(y * wave)) +
                    aWord(chance(m_rng, 0.3) ? seg : 0));
            }
        }
    }
    // Arcs and helices of many radii.
    void arcs()
    {
        feed();
        const int n = std::uniform_int_distribution<int>(1, 6)(m_rng);
        for (int k = 0; k < n; ++k) {
            const double r = logUniform(m_rng, 0.05, 30);
            const double cx = inBox(0, m_pos[0] + r), cy = m_pos[1];
            if (cx - r < m_lo[0] || cx + r > m_hi[0] || cy - r < m_lo[1] || cy + r > m_hi[1])
                return;
            const double dz = chance(m_rng, 0.4) ? uniform(m_rng, -2, 0) : 0;
            const double angle = uniform(m_rng, 0.2, 6.2);
            const double ex = cx - r * std::cos(angle), ey = cy + r * std::sin(angle);
            const std::string i = " I" + num(cx - m_pos[0]) + " J" + num(cy - m_pos[1]);
            put(std::string(chance(m_rng, 0.5) ? "G2 " : "G3 ") + xyz(ex, ey, m_pos[2] + dz) + i);
            // The endpoint the interpreter computes may differ from ours by rounding only.
        }
    }
    // Short back-and-forth moves at random angles (engraving, adaptive clearing).
    void zigzag()
    {
        feed();
        const int n = std::uniform_int_distribution<int>(10, 200)(m_rng);
        const double len = logUniform(m_rng, 0.005, 2);
        double az = uniform(m_rng, 0, 6.283);
        for (int k = 0; k < n; ++k) {
            az += uniform(m_rng, 1.5, 4.7);
            const double dz = chance(m_rng, 0.3) ? uniform(m_rng, -0.2, 0.2) * len : 0;
            put("G1 " +
                xyz(m_pos[0] + len * std::cos(az), m_pos[1] + len * std::sin(az), m_pos[2] + dz) +
                aWord(chance(m_rng, 0.2) ? len : 0));
        }
    }
    void lines()
    {
        feed();
        const int n = std::uniform_int_distribution<int>(1, 10)(m_rng);
        for (int k = 0; k < n; ++k)
            put("G1 " +
                xyz(uniform(m_rng, m_lo[0], m_hi[0]), uniform(m_rng, m_lo[1], m_hi[1]),
                    uniform(m_rng, m_lo[2], m_hi[2])) +
                aWord(chance(m_rng, 0.3) ? uniform(m_rng, -90, 90) : 0));
    }
    void rapids()
    {
        const int n = std::uniform_int_distribution<int>(1, 4)(m_rng);
        for (int k = 0; k < n; ++k)
            put("G0 " + xyz(uniform(m_rng, m_lo[0], m_hi[0]), uniform(m_rng, m_lo[1], m_hi[1]),
                            uniform(m_rng, m_lo[2], m_hi[2])));
    }
    // Synchronisation points: spindle speed changes, coolant, a dwell.
    void io()
    {
        const double r = uniform(m_rng, 0, 1);
        if (r < 0.4)
            put("M3 S" + std::to_string(std::uniform_int_distribution<int>(100, 20000)(m_rng)));
        else if (r < 0.6)
            put(chance(m_rng, 0.5) ? "M8" : "M9");
        else if (r < 0.8)
            put("G4 P" + std::to_string(uniform(m_rng, 0.01, 0.5)).substr(0, 5));
        else
            put("M5");
    }

    Rng &m_rng;
    const MachineConfig &m_c;
    std::array<double, 3> m_lo{}, m_hi{};
    std::array<double, 4> m_pos{};
    double m_maxFeed = 0;
    bool m_inch = false;
    int m_lines = 0;
    std::string m_text;
};

std::string describe(const MachineConfig &c, const driver::WireOptions &w)
{
    char buf[512];
    std::snprintf(buf, sizeof buf,
                  "%s %d p/s, steps/mm %.3g/%.3g/%.3g%s, speed %.0f/%.0f/%.0f mm/min, accel "
                  "%.3g/%.3g/%.3g, jump %.3g/%.3g/%.3g, mode %d, %d Bd, %.1f ms, packets %s, "
                  "faults %g",
                  protocol::variantInfo(c.unit.variant).displayName.data(), c.unit.maxPulseRate,
                  c.axes[0].stepsPerMm, c.axes[1].stepsPerMm, c.axes[2].stepsPerMm,
                  c.axes[3].present ? " +A" : "", c.axes[0].maxSpeedMmPerMin,
                  c.axes[1].maxSpeedMmPerMin, c.axes[2].maxSpeedMmPerMin, c.axes[0].accelMmPerS2,
                  c.axes[1].accelMmPerS2, c.axes[2].accelMmPerS2, c.axes[0].maxJumpMmPerS,
                  c.axes[1].maxJumpMmPerS, c.axes[2].maxJumpMmPerS,
                  static_cast<int>(c.motion.speedMode), w.baud, w.latencyS * 1000,
                  c.link.packets ? "on" : "off", w.byteErrorRate);
    return buf;
}

} // namespace

RandomJob drawJob(std::uint64_t seed, int maxLines)
{
    Rng rng(seed * 0x9E3779B97F4A7C15ull + 1);
    RandomJob job;
    job.seed = seed;
    job.config = drawConfig(rng, job.wire);
    ProgramWriter w(rng, job.config);
    const int target = std::uniform_int_distribution<int>(20, std::max(20, maxLines))(rng);
    while (w.count() < target)
        w.block();
    job.program = w.take();
    // One job in four runs at a feed override (XM, set before the run) from 50 to 200 %: the
    // driver must hold it to what the link can feed, and VL keeps each axis under its maximum.
    // Drawn last, so that the program, the profile and the link of a seed stay as they were.
    if (std::uniform_int_distribution<int>(0, 3)(rng) == 0)
        job.overridePercent = std::uniform_int_distribution<int>(10, 40)(rng) * 5;
    job.summary =
        describe(job.config, job.wire) + ", " + std::to_string(w.count()) + " lines" +
        (job.overridePercent != 100 ? ", override " + std::to_string(job.overridePercent) + " %"
                                    : std::string());
    return job;
}

namespace {

void fail(JobOutcome &o, const std::string &what)
{
    o.wrong.push_back(what);
}
void slow(JobOutcome &o, const std::string &what)
{
    o.pace.push_back(what);
}

void judgePlan(const PlanResult &p, JobOutcome &o)
{
    const PlanStats &s = p.stats;
    if (s.jumpOverLimit > 0)
        fail(o, std::to_string(s.jumpOverLimit) + " planned vertices over the jump limit (worst " +
                    std::to_string(s.maxJumpRatio) + " x)");
    if (s.brakeViolations > 0)
        fail(o, std::to_string(s.brakeViolations) + " brake violations in the plan's model");
    // The bound is a lower bound of any plan this unit can run (docs/planner.md §7): an estimate
    // below it is a plan faster than the machine's limits allow, or a wrong bound.
    if (s.estimatedS < s.boundS * (1 - 1e-9))
        fail(o, "estimate " + std::to_string(s.estimatedS) + " s below the bound " +
                    std::to_string(s.boundS) + " s");
    else if (s.estimatedS > 1.02 * s.boundS)
        slow(o, "estimate " + std::to_string(s.estimatedS) + " s more than 1.02 x the bound " +
                    std::to_string(s.boundS) + " s");
}

} // namespace

JobOutcome runJob(const RandomJob &job)
{
    JobOutcome o;
    const gcode::Result g = gcode::interpretText(job.program);
    if (!g.ok()) {
        const gcode::Error &e = g.errors.front();
        fail(o, std::string("the generated program does not interpret: ") +
                    gcode::errorName(e.code) + " at line " + std::to_string(e.line) + " (" +
                    e.detail + ")");
        return o;
    }
    const PlanResult p = plan(g.toolpath, job.config);
    if (!p.ok()) {
        fail(o, "the generated program does not plan: " + p.errors.front().message);
        return o;
    }
    o.planned = true;
    o.stats = p.stats;
    judgePlan(p, o);
    // The emulator counts every C that starts after a C which ended with the queue empty; the
    // plan asks for that at its synchronisation points (machine::plannedRestarts), so those are
    // not starvation.
    const std::int64_t plannedStops = machine::plannedRestarts(p.program);
    for (const UnitCommand &c : p.program.commands) {
        o.vectorsPlanned += c.op == UnitOp::Vector || c.op == UnitOp::Line ? 1 : 0;
        o.rests += c.op > UnitOp::Spindle ? 1 : 0; // PC-side: the queue drains first
    }

    emulator::UnitOptions unit = driver::unitOptionsFor(job.config);
    unit.trace = true;
    driver::EmulatorPort port(unit, job.wire);
    driver::CoreOptions options;
    options.packets = job.config.link.packets;
    options.checksums = job.config.link.checksums;
    options.returnToPathAutomatically = true;                              // no operator here
    options.leadInHold = std::getenv("FREZKA_NO_LEAD_IN_HOLD") == nullptr; // A/B in the soak
    driver::MachineCore core(job.config, options);
    driver::SimRunner runner(core, port);
    std::vector<bool> finished;
    std::string firstError;
    core.onJobFinished = [&](bool ok) { finished.push_back(ok); };
    if (std::getenv("FREZKA_PROPERTY_TRACE")) // the link log with virtual times, to stderr
        core.onLog = [&port](const std::string &text) {
            std::fprintf(stderr, "%.6f %s\n", port.now(), text.c_str());
        };
    core.onError = [&](const driver::MachineError &e) {
        if (firstError.empty())
            firstError = e.message + " [" + e.command + "] -> '" + e.reply + "'";
    };
    runner.open();
    runner.runUntil([&] { return core.state().mode != driver::MachineMode::Connecting; }, 300);
    if (core.state().mode != driver::MachineMode::Idle) {
        fail(o, "did not connect: " + firstError);
        return o;
    }
    if (job.overridePercent != 100) {
        if (const auto refused = core.setOverride(job.overridePercent, runner.now())) {
            fail(o, "override refused: " + refused->message);
            return o;
        }
        runner.runUntil([&] { return core.state().overridePercent == job.overridePercent; }, 10);
    }
    if (const auto refused = core.run(p.program, runner.now())) {
        fail(o, "run refused: " + refused->message);
        return o;
    }
    const double limit = 3 * p.stats.estimatedS + 600;
    runner.runUntil([&] { return !finished.empty(); }, limit);
    const driver::JobReport &rep = core.jobReport();
    o.jobS = rep.endS - rep.startS;
    const emulator::Stats stats = port.unit().stats();
    o.vectorsExecuted = stats.motion.vectorsExecuted;
    o.movingS = stats.motion.movingTimeS;
    o.modelMotionS = runUnitModel(p.program, p.stats.speedModeVk).motionS;
    o.brakeViolations = stats.motion.brakeViolations;
    o.starvationStops = stats.motion.starvationStops - plannedStops;
    o.pathFaults = rep.pathFaults;
    o.leadInHolds = rep.leadInHolds;
    o.dryHolds = rep.dryHolds;
    o.resendShare = rep.commands > 0 ? static_cast<double>(rep.resent) /
                                           static_cast<double>(rep.commands + rep.resent)
                                     : 0;
    const bool clean = job.wire.byteErrorRate == 0 && job.wire.replyLossRate == 0;
    if (finished.empty() || !finished.front()) {
        // A stop with a named error is safe (the job can be resumed), not a wrong end; on a
        // clean link it is still a defect of the link's handling, reported with the others.
        slow(o, std::string(clean ? "clean link: " : "") + "the job did not finish: " +
                    (firstError.empty() ? "(no error; time limit)" : firstError));
        return o;
    }
    const auto pos = port.unit().position();
    const Steps4 end = p.program.commands.back().endSteps;
    o.exact = true;
    for (int i = 0; i < 4; ++i)
        o.exact = o.exact && pos[i] == end[i];
    if (std::getenv("FREZKA_PROPERTY_TRACE")) {
        // Restarts after a planned rest begin where the plan drains the queue; the others are
        // the starvation stops.
        std::set<Steps4> restPoints;
        Steps4 at{};
        for (const UnitCommand &c : p.program.commands) {
            if (c.op == UnitOp::Vector || c.op == UnitOp::Line)
                at = c.endSteps;
            else if (c.op > UnitOp::Spindle)
                restPoints.insert(at);
        }
        const auto &trace = port.unit().trace();
        for (double t : port.unit().stats().motion.starvationAtS) {
            auto it = std::upper_bound(
                trace.begin(), trace.end(), t,
                [](double v, const emulator::TracePoint &p) { return v < p.timeS; });
            Steps4 stood{};
            if (it != trace.begin())
                for (int i = 0; i < 4; ++i)
                    stood[i] = std::prev(it)->position[static_cast<std::size_t>(i)];
            std::fprintf(
                stderr,
                restPoints.contains(stood)
                    ? "%.6f restart at %lld,%lld,%lld\n"
                    : "%.6f STARVATION: the unit restarts after running dry at %lld,%lld,%lld\n",
                t, static_cast<long long>(stood[0]), static_cast<long long>(stood[1]),
                static_cast<long long>(stood[2]));
        }
        for (double t : port.unit().stats().motion.brakeViolationAtS)
            std::fprintf(stderr, "%.6f BRAKE VIOLATION: a vector arrived faster than its exit\n",
                         t);
        for (const emulator::TracePoint &t : port.unit().trace()) // where the machine stood
            if (t.pathSpeedPulsesPerS == 0)
                std::fprintf(stderr, "%.6f unit at rest at %lld,%lld,%lld\n", t.timeS,
                             static_cast<long long>(t.position[0]),
                             static_cast<long long>(t.position[1]),
                             static_cast<long long>(t.position[2]));
    }
    const JumpFigures jumps = measureJumps(port.unit().trace(), p.program, job.config);
    o.jumpOverLimit = jumps.overLimit;
    o.maxJumpRatio = jumps.maxRatio;

    if (!o.exact)
        fail(o, "final counters differ from the plan's end");
    const std::int64_t extra = o.vectorsExecuted - o.vectorsPlanned - rep.returnMoves;
    if (rep.pathFaults == 0 ? extra != 0 : extra < 0 || extra > rep.rerun)
        fail(o, std::to_string(o.vectorsExecuted) + " vectors executed for " +
                    std::to_string(o.vectorsPlanned) + " planned (path faults " +
                    std::to_string(rep.pathFaults) + ", re-run " + std::to_string(rep.rerun) +
                    ", return moves " + std::to_string(rep.returnMoves) + ")");
    if (o.brakeViolations > 0)
        slow(o, std::to_string(o.brakeViolations) + " brake violations on the unit");
    if (o.starvationStops > 0)
        slow(o, std::to_string(o.starvationStops) + " starvation stops");
    if (o.jumpOverLimit > 0)
        fail(o, std::to_string(o.jumpOverLimit) + " vertices over the jump limit on the unit");
    // The estimate is the plan's at 100 %; a job at another override is judged on its stops.
    if (clean && job.overridePercent == 100 &&
        std::abs(o.jobS - p.stats.estimatedS) > 0.02 * p.stats.estimatedS)
        slow(o, "job " + std::to_string(o.jobS) + " s against an estimate of " +
                    std::to_string(p.stats.estimatedS) + " s");
    return o;
}

} // namespace frezka::machine::test
