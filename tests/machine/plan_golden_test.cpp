// Plans kept byte-identical while the planner's internals change (issue 17: the link's pace made
// incremental, the plan's data made compact). Every program and profile below is planned and its
// whole result (each unit command's text, source line and end position, the estimate, the bound,
// the errors and warnings) is reduced to a 64-bit FNV-1a digest and compared with
// tests/machine/golden/plans.txt, made from the planner before those changes.
//
//   FREZKA_WRITE_GOLDEN=1  writes the golden file anew (only after a difference is explained)
//   FREZKA_PLAN_DUMP_DIR=D writes each plan's full text to D/<case>.txt, to diff two builds
#include "../bench/gcode/generate.h"
#include "randomjob.h"
#include "spiralprogram.h"

#include "gcode/interpreter.h"
#include "machine/planner.h"
#include "machine/unitwire.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <map>
#include <sstream>
#include <string>
#include <vector>

using namespace frezka;
using namespace frezka::machine;

namespace {

const std::string kGoldenPath = std::string(FREZKA_SOURCE_DIR) + "/tests/machine/golden/plans.txt";

struct Case
{
    std::string name;
    std::string program; // G-code text
    MachineConfig config;
    PlanOptions options;
};

std::string readFile(const std::string &path)
{
    std::ifstream in(path, std::ios::binary);
    std::ostringstream s;
    s << in.rdbuf();
    return s.str();
}

using test::spiral; // spiralprogram.h

// Profiles: the three units as shipped, and the link and mode settings that change the pace.
std::vector<std::pair<std::string, MachineConfig>> profiles()
{
    std::vector<std::pair<std::string, MachineConfig>> p;
    p.emplace_back("gve64", defaultMachineConfig(protocol::Variant::Gve64));
    p.emplace_back("gve84", defaultMachineConfig(protocol::Variant::Gve84));
    p.emplace_back("gve114", defaultMachineConfig(protocol::Variant::Gve114));
    MachineConfig slow = defaultMachineConfig(protocol::Variant::Gve64);
    slow.link.latencyMs = 16;
    slow.link.baud = 19200;
    p.emplace_back("gve64-19200-16ms", slow);
    MachineConfig vn = defaultMachineConfig(protocol::Variant::Gve114);
    vn.motion.speedMode = SpeedModeChoice::Vn;
    vn.link.packets = false;
    p.emplace_back("gve114-vn-nopackets", vn);
    return p;
}

std::vector<Case> cases()
{
    std::vector<std::pair<std::string, std::string>> programs;
    for (const char *name : {"engraving-star", "frezka-demo"})
        programs.emplace_back(
            name, readFile(std::string(FREZKA_SOURCE_DIR) + "/resources/programs/" + name + ".nc"));
    for (const char *name : {"pocket", "contour", "surface", "engrave", "adaptive"})
        programs.emplace_back(name, readFile(std::string(FREZKA_SOURCE_DIR) +
                                             "/tests/bench/planner/programs/" + name + ".nc"));
    programs.emplace_back("spiral30k", spiral(30000));
    programs.emplace_back("dense20k", gcode::bench::denseFinishing(20000));
    programs.emplace_back("arcs5k", gcode::bench::arcHeavy(5000));
    std::vector<Case> all;
    for (const auto &[name, text] : programs) {
        // The generated programs work around the origin: travel on both sides of it.
        const bool generated = name == "dense20k" || name == "arcs5k";
        auto travel = [generated](MachineConfig c) {
            for (AxisConfig &a : c.axes) {
                a.softMinMm = generated ? -5000 : a.softMinMm;
                a.softMaxMm = generated ? 5000 : a.softMaxMm;
            }
            return c;
        };
        for (const auto &[profile, config] : profiles())
            all.push_back({name + "." + profile, text, travel(config), {}});
        PlanOptions noPace;
        noPace.wireLimited = false;
        all.push_back({name + ".gve64-nopace", text, travel(profiles()[0].second), noPace});
        PlanOptions grbl;
        grbl.strategy = PlanStrategy::GrblJunction;
        all.push_back({name + ".gve64-grbl", text, travel(profiles()[0].second), grbl});
    }
    // Random jobs: every variant, axis scales, VK/VN, packets on and off, rates and latencies.
    for (std::uint64_t seed = 1; seed <= 60; ++seed) {
        const test::RandomJob job = test::drawJob(seed, 600);
        all.push_back({"random" + std::to_string(seed), job.program, job.config, {}});
    }
    return all;
}

std::uint64_t fnv1a(std::uint64_t h, const std::string &s)
{
    for (unsigned char c : s) {
        h ^= c;
        h *= 1099511628211ull;
    }
    return h;
}

std::string num(double v)
{
    char buf[40];
    std::snprintf(buf, sizeof buf, "%.17g", v);
    return buf;
}

// The plan as text: one line per command, then the figures, errors and warnings.
std::string planText(const PlanResult &r)
{
    std::string s;
    const UnitProgram &p = r.program;
    s += "axes " + std::to_string(p.axisCount) + "\n";
    for (const UnitCommand &c : p.commands) {
        s += commandText(c, p.axisCount) + " @" + std::to_string(c.sourceLine) + " ->";
        for (std::int64_t v : c.endSteps)
            s += " " + std::to_string(v);
        s += "\n";
    }
    const PlanStats &st = r.stats;
    s += "vectors " + std::to_string(st.vectors) + " chains " + std::to_string(st.chains) +
         " estimated " + num(st.estimatedS) + " bound " + num(st.boundS) + " wait " +
         num(st.waitS) + " link " + num(st.linkWaitS) + " jump " + num(st.maxVertexJumpMmPerS) +
         " ratio " + num(st.maxJumpRatio) + " over " + std::to_string(st.jumpOverLimit) +
         " curve " + num(st.maxCurveAccelRatio) + " over " +
         std::to_string(st.curveAccelOverLimit) + " brake " + std::to_string(st.brakeViolations) +
         " vk " + std::to_string(st.speedModeVk) + "\n";
    for (const PlanError &e : r.errors)
        s += "error " + std::to_string(int(e.code)) + " " + e.message + "\n";
    for (const PlanError &e : r.warnings)
        s += "warning " + std::to_string(int(e.code)) + " " + e.message + "\n";
    return s;
}

// One golden line: the case, the digest, and figures a reader can compare at a glance.
std::string goldenLine(const Case &c, const PlanResult &r, const std::string &text)
{
    char hash[20];
    std::snprintf(hash, sizeof hash, "%016llx",
                  static_cast<unsigned long long>(fnv1a(14695981039346656037ull, text)));
    return c.name + " " + hash + " commands " + std::to_string(r.program.commands.size()) +
           " estimated " + num(r.stats.estimatedS) + " bound " + num(r.stats.boundS);
}

std::map<std::string, std::string> readGolden()
{
    std::map<std::string, std::string> golden;
    std::ifstream in(kGoldenPath);
    for (std::string line; std::getline(in, line);) {
        if (!line.empty() && line[0] != '#')
            golden[line.substr(0, line.find(' '))] = line;
    }
    return golden;
}

} // namespace

TEST(PlanGolden, EveryPlanIsByteIdenticalToTheGoldenFile)
{
    const bool write = std::getenv("FREZKA_WRITE_GOLDEN") != nullptr;
    const char *dumpDir = std::getenv("FREZKA_PLAN_DUMP_DIR");
    const std::map<std::string, std::string> golden = readGolden();
    std::string out = "# plan_golden_test: case, FNV-1a of the plan's text, commands, estimate, "
                      "bound\n";
    std::size_t compared = 0;
    for (const Case &c : cases()) {
        const gcode::Result g = gcode::interpretText(c.program);
        const PlanResult r = plan(g.toolpath, c.config, c.options);
        const std::string text = planText(r);
        if (dumpDir)
            std::ofstream(std::string(dumpDir) + "/" + c.name + ".txt") << text;
        const std::string line = goldenLine(c, r, text);
        out += line + "\n";
        if (write)
            continue;
        const auto it = golden.find(c.name);
        ASSERT_NE(it, golden.end()) << c.name << " is not in " << kGoldenPath;
        EXPECT_EQ(line, it->second) << "the plan of " << c.name << " changed";
        ++compared;
    }
    if (write) {
        std::ofstream(kGoldenPath) << out;
        GTEST_SKIP() << "wrote " << kGoldenPath;
    }
    EXPECT_EQ(compared, golden.size()) << "cases in the golden file that no longer run";
}
