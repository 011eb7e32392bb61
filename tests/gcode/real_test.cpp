// Real CAM output (tests/gcode/data/real: programs written by CAM posts and users, taken from
// public repositories, see the README there) against `rs274 -g`, motion for motion with feeds,
// dwells and spindle speeds: every program gives rs274's motions, or is refused by Frezka with
// the error listed here. Where a program uses another controller's dialect that Frezka accepts
// on purpose (and rs274 refuses), rs274 is given an edited copy, with the reason listed.
#include "corpusfiles.h"
#include "rs274.h"

#include "gcode/interpreter.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>

#include <algorithm>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <set>
#include <sstream>
#include <vector>

using namespace frezka::gcode;
using namespace frezka::gcode::test;
namespace fs = std::filesystem;

namespace {

const fs::path kDir = fs::path(FREZKA_GCODE_DATA_DIR) / "real";

// The programs Frezka refuses, with the reason (each a clear error, never a wrong path).
const std::map<std::string, Refusal> &refused()
{
    using E = ErrorCode;
    static const std::map<std::string, Refusal> kRefused = {
        // rs274 refuses each of these at the same line.
        {"hand_cncjs_full_circle",
         {E::ArcMissingCentre, "an arc (modal G2) with only X: no R, I or J (rs274 too)"}},
        {"hand_shapeoko_calibration",
         {E::ArcRadiusMismatch, "an arc whose end is 1.4 mm off its circle (rs274 too)"}},
        {"hand_ugs_line_skip", {E::ZeroFeedRate, "G1 before any F (rs274 too)"}},
        {"hand_tinyg_coordinate_offsets",
         {E::GrblCommand, "TinyG's $sr status request in the program (rs274 too)"}},
        {"hand_tinyg_inverse_time",
         {E::InverseTimeFeedMissing,
          "G93 with F once for many moves, as TinyG reads it (rs274 too)"}},
    };
    return kRefused;
}

// A text replacement in the copy rs274 is given (every occurrence), and why.
struct Edit
{
    std::string from, to;
    const char *why;
};

const std::map<std::string, std::vector<Edit>> &edits()
{
    static const std::map<std::string, std::vector<Edit>> kEdits = {
        // The file ends under G42 without a program end: Frezka ends it as M2 would (with a
        // warning), which sends the move compensation held back for its lookahead; rs274 stops
        // with an error and never sends it. With M2 it sends it too.
        {"hand_cncjs_helical_thread",
         {{"Z0.0179 R0.0975\n", "Z0.0179 R0.0975\nM2\n", "program end under compensation"}}},
        // FreeCAD's grbl post writes K0 on G17 arcs: Frezka ignores it with a note, rs274
        // refuses it ("K word given for arc in xy plane").
        {"freecad_grbl_k0", {{" K0.000", "", "K0 on XY arcs"}}},
    };
    return kEdits;
}

// NAME.tbl beside the program (mm) when it needs tool sizes (cutter compensation, G43), for both
// Frezka and rs274; none otherwise.
std::optional<ToolTable> toolsFor(const std::string &name)
{
    return toolTableAt(kDir / (name + ".tbl"));
}

// The generator is the part of the name before the first '_' (README.md lists them); "other"
// is a program whose generator is not known.
std::string generatorOf(const std::string &name)
{
    return name.substr(0, name.find('_'));
}

class RealProgram : public testing::TestWithParam<std::string>
{
};

} // namespace

TEST_P(RealProgram, MatchesRs274OrIsRefusedAsListed)
{
    const fs::path nc = kDir / (GetParam() + ".nc");
    const std::optional<ToolTable> table = toolsFor(GetParam());
    const ToolTable *tools = table ? &*table : nullptr;
    const auto it = refused().find(GetParam());
    if (it == refused().end()) {
        if (test::rs274Path().empty())
            GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
        const auto edit = edits().find(GetParam());
        if (edit == edits().end()) {
            EXPECT_TRUE(test::matchesRs274(nc.string(), {}, tools));
            return;
        }
        std::string text = readText(nc);
        for (const Edit &e : edit->second) {
            std::size_t at = text.find(e.from);
            ASSERT_NE(at, std::string::npos) << e.why;
            for (; at != std::string::npos; at = text.find(e.from, at + e.to.size()))
                text.replace(at, e.from.size(), e.to);
        }
        expectEditedCopyMatchesRs274(nc, text, tools, {});
        return;
    }
    expectRefusedAsListed(nc, table, it->second);
}

INSTANTIATE_TEST_SUITE_P(Corpus, RealProgram, testing::ValuesIn(programsIn(kDir)), testName);

// The corpus's size and variety: at least 30 programs from 8 generators (issue 15), among them
// programs without a program end, FreeCAD's Fanuc post with its safety line (G17 G54 G40 G49
// G80 G90 G94), TinyG's tests with G00 and G80 on one line (G00 G17 G21 G40 G49 G80 G90) and
// FreeCAD's grbl post with its K0 arcs.
TEST(RealCorpus, IsLargeAndVaried)
{
    const std::vector<std::string> all = programsIn(kDir);
    std::set<std::string> generators;
    for (const std::string &name : all) {
        if (generatorOf(name) != "other")
            generators.insert(generatorOf(name));
    }
    for (const auto &[name, refusal] : refused())
        EXPECT_NE(std::find(all.begin(), all.end(), name), all.end()) << name;
    for (const auto &[name, list] : edits())
        EXPECT_NE(std::find(all.begin(), all.end(), name), all.end()) << name;
    EXPECT_GE(all.size(), 30u);
    EXPECT_NE(readText(kDir / "freecad_grbl_k0.nc").find(" K0.000"), std::string::npos);
    EXPECT_GE(generators.size(), 8u);
    EXPECT_TRUE(fs::exists(kDir / "README.md"));
}
