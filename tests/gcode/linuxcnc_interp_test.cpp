// LinuxCNC's own interpreter test suite (tests/gcode/data/linuxcnc-interp: copies of
// tests/interp/*/ in LinuxCNC's source tree, one directory deep, and of tests/interp/bad/, see
// the README there) against `rs274 -g` as the suite runs it: every program that is not lathe,
// spindle-synchronised, B-axis or Python plug-in gives rs274's motions, feeds, dwells and spindle
// speeds, or is refused by Frezka with the error listed here; every bad program is refused.
#include "corpusfiles.h"
#include "rs274.h"

#include "gcode/interpreter.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>

#include <algorithm>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <map>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

using namespace frezka::gcode;
using namespace frezka::gcode::test;
namespace fs = std::filesystem;

namespace {

const fs::path kDir = fs::path(FREZKA_GCODE_DATA_DIR) / "linuxcnc-interp";

// The suite's programs Frezka refuses, with the reason (each a clear error, never a wrong path).
const std::map<std::string, Refusal> &refused()
{
    using E = ErrorCode;
    static const std::map<std::string, Refusal> kRefused = {
        // Lathe, spindle-synchronised and B-axis programs (the GVE units drive X Y Z and A and
        // have no spindle encoder).
        {"g33.1", {E::UnsupportedGCode, "rigid tapping G33.1"}},
        {"g71-endless-loop", {E::UnsupportedGCode, "lathe diameter mode G8"}},
        {"g71-endless-loop2", {E::UnsupportedGCode, "feed per revolution G95 (lathe)"}},
        {"g71-endless-loop_2", {E::UnsupportedGCode, "lathe diameter mode G7"}},
        {"g71-with-g70", {E::UnsupportedGCode, "lathe cycle G71.1"}},
        {"g72-facing", {E::UnsupportedGCode, "lathe cycle G72"}},
        {"g72-missing-iteration", {E::UnsupportedGCode, "lathe cycle G72"}},
        {"g76", {E::UnsupportedGCode, "lathe threading G76"}},
        {"m19", {E::UnsupportedMCode, "spindle orientation M19"}},
        {"unit-conversion", {E::UnsupportedAxis, "axis B"}},
        // Python plug-ins and subroutine files the suite's INI names (rs274 run standalone, as
        // here, refuses them too: "EOF ... seeking o-word").
        {"pymove", {E::SubroutineUndefined, "Python plug-in o<canonmove>"}},
        {"python-self", {E::SubroutineUndefined, "Python plug-in o<retainparam1>"}},
        {"value-returned", {E::SubroutineUndefined, "Python plug-in o<returns4711>"}},
        {"nested-sub-error", {E::SubroutineUndefined, "o<nested> from the INI's subroutine path"}},
        {"nested-sub-in-file-error",
         {E::SubroutineUndefined, "o<sequential> from the INI's subroutine path"}},
        {"oword-unwind", {E::SubroutineUndefined, "o<fail> from the INI's subroutine path"}},
        {"sequence-number", {E::SubroutineUndefined, "o<rm400> from the INI's subroutine path"}},
        {"sub-call-from-sub", {E::SubroutineUndefined, "o<caller> from the INI's subroutine path"}},
        {"iniparam", {E::NamedParameterUndefined, "#<_ini[vars]toolchange_x> from the INI"}},
        // Meant to fail, or refused by rs274 as well.
        {"g64-r-planner", {E::WordNotUsed, "G64 P1 R0.5: rs274 refuses the R word too"}},
        // Meant to fail: the (abort, ...) comment at the loop's 20th pass ends the program.
        {"abort-hot-comment", {E::ProgramAborted, "(abort, ...) in a loop, as LinuxCNC"}},
        // LinuxCNC dialect Frezka does not read yet.
    };
    return kRefused;
}

// Programs rs274 is given in an edited copy (one text replacement), and why.
struct Edit
{
    const char *from, *to, *why;
};

const std::map<std::string, Edit> &edits()
{
    static const std::map<std::string, Edit> kEdits = {
        // rs274 prints a PRINT comment's text on a line of its own, which cannot be told from
        // its error message; the copy has a plain comment (no motion either way).
        {"subs-follow-main", {"(PRINT,X IN O1)", "(X IN O1)", "rs274 prints the PRINT text"}},
    };
    return kEdits;
}

// Where Frezka and LinuxCNC still differ: Frezka accepts the program and rs274 refuses it. The
// test fails when either changes, so that the entry is moved to where it belongs.
const std::map<std::string, const char *> &differences()
{
    static const std::map<std::string, const char *> kDifferences = {};
    return kDifferences;
}

// NAME.tbl (mm) when the suite runs the program with a tool table (its test.tbl, converted
// from inches; the original is NAME.inch-tbl).
std::optional<ToolTable> toolsFor(const std::string &name)
{
    return toolTableAt(kDir / (name + ".tbl"));
}

class LinuxCncInterpTest : public testing::TestWithParam<std::string>
{
};

class LinuxCncInterpBad : public testing::TestWithParam<std::string>
{
};

} // namespace

TEST_P(LinuxCncInterpTest, MatchesRs274OrIsRefusedAsListed)
{
    const fs::path nc = kDir / (GetParam() + ".nc");
    const std::optional<ToolTable> table = toolsFor(GetParam());
    const auto it = refused().find(GetParam());
    if (it == refused().end()) {
        if (test::rs274Path().empty())
            GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
        if (const auto d = differences().find(GetParam()); d != differences().end()) {
            EXPECT_TRUE(interpretFile(nc.string(), Options{}).ok()) << d->second;
            EXPECT_FALSE(test::runRs274(nc.string()).error.empty()) << d->second;
            return;
        }
        const auto edit = edits().find(GetParam());
        if (edit == edits().end()) {
            EXPECT_TRUE(test::matchesRs274(nc.string(), {}, table ? &*table : nullptr));
            return;
        }
        std::string text = readText(nc);
        const auto at = text.find(edit->second.from);
        ASSERT_NE(at, std::string::npos) << edit->second.why;
        text.replace(at, std::strlen(edit->second.from), edit->second.to);
        expectEditedCopyMatchesRs274(nc, text, table ? &*table : nullptr, edit->second.why);
        return;
    }
    expectRefusedAsListed(nc, table, it->second);
}

INSTANTIATE_TEST_SUITE_P(Suite, LinuxCncInterpTest, testing::ValuesIn(programsIn(kDir)), testName);

// Every program of tests/interp/bad is refused by Frezka with a message, as by rs274.
TEST_P(LinuxCncInterpBad, IsRefused)
{
    const fs::path nc = kDir / "bad" / (GetParam() + ".nc");
    const Result r = interpretFile(nc.string(), Options{});
    ASSERT_FALSE(r.ok()) << "accepted a program LinuxCNC's suite expects to fail";
    EXPECT_GT(r.errors[0].line, 0u);
    EXPECT_FALSE(translatedMessage(r.errors[0]).isEmpty());
    RecordProperty("error", errorName(r.errors[0].code));
    if (!test::rs274Path().empty()) {
        EXPECT_FALSE(test::runRs274(nc.string()).error.empty()) << "rs274 accepts it";
    }
}

INSTANTIATE_TEST_SUITE_P(Bad, LinuxCncInterpBad, testing::ValuesIn(programsIn(kDir / "bad")),
                         testName);

// The counts: the suite's mill programs that match rs274 (not refused here) and the bad ones.
TEST(LinuxCncInterpSuite, Counts)
{
    const std::vector<std::string> all = programsIn(kDir);
    for (const auto &[name, refusal] : refused())
        EXPECT_NE(std::find(all.begin(), all.end(), name), all.end()) << name;
    const std::size_t matched = all.size() - refused().size() - differences().size();
    RecordProperty("matched", static_cast<int>(matched));
    RecordProperty("refused", static_cast<int>(refused().size()));
    EXPECT_GE(matched, 17u); // as many as LinuxCNC's own run of the suite matches
    EXPECT_EQ(programsIn(kDir / "bad").size(), 23u);
}
