// LinuxCNC's own interpreter test suite (tests/gcode/data/linuxcnc-interp: copies of
// tests/interp/*/ in LinuxCNC's source tree, one directory deep, and of tests/interp/bad/, see
// the README there) against `rs274 -g` as the suite runs it: every program that is not lathe,
// spindle-synchronised, B-axis or Python plug-in gives rs274's motions, feeds, dwells and spindle
// speeds, or is refused by Frezka with the error listed here; every bad program is refused.
#include "corpusfiles.h"
#include "rs274.h"

#include "gcode/interpreter.h"
#include "gcode/linuxcncini.h"

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
        // Python plug-ins (rs274 without LinuxCNC's Python refuses them too).
        {"pymove", {E::SubroutineUndefined, "Python plug-in o<canonmove>"}},
        {"python-self", {E::SubroutineUndefined, "Python plug-in o<retainparam1>"}},
        {"value-returned", {E::SubroutineUndefined, "Python plug-in o<returns4711>"}},
        // Meant to fail (the suite's test.sh expects an error), with the INI's values and
        // subroutine files read: a sub defined inside the called subroutine file, a numbered
        // subroutine after the named one's endsub in the same file (both errors since LinuxCNC
        // #3880, 2026; the installed rs274 2.9 still runs them), a division by zero inside the
        // file fail.ngc, an INI value that does not exist, an assignment to an INI value.
        {"nested-sub-error", {E::NestedSubDefinition, "o100 sub inside o<nested>"}},
        {"nested-sub-in-file-error",
         {E::SubroutineNotFound, "o200 after o<sequential> endsub in its file"}},
        {"oword-unwind", {E::DivisionByZero, "1/0 in fail.ngc, as rs274 -i test.ini"}},
        {"iniparam", {E::NamedParameterUndefined, "#<_ini[nosuchsection]nosuchname>, as rs274"}},
        {"iniparam-failassign", {E::ReadOnlyParameter, "an INI value assigned, as rs274"}},
        // Meant to fail, or refused by rs274 as well.
        {"g64-r-planner", {E::WordNotUsed, "G64 P1 R0.5: rs274 refuses the R word too"}},
        // Meant to fail: the (abort, ...) comment at the loop's 20th pass ends the program.
        {"abort-hot-comment", {E::ProgramAborted, "(abort, ...) in a loop, as LinuxCNC"}},
        // LinuxCNC dialect Frezka does not read yet.
    };
    return kRefused;
}

// Where the listed refusals stand (file:line; the file is a subroutine file when named), so that
// they are the errors the suite means and not an earlier one.
const std::map<std::string, std::string> &refusedAt()
{
    static const std::map<std::string, std::string> kAt = {
        {"nested-sub-error", "subs/nested.ngc:2"},
        {"nested-sub-in-file-error", "subs/sequential.ngc:3"},
        {"oword-unwind", "fail.ngc:4"},
        {"iniparam", ":7"},
        {"iniparam-failassign", ":1"},
    };
    return kAt;
}

// The INI file the suite runs a program with (NAME.ini, its test.ini), empty when none.
std::string iniFor(const std::string &name)
{
    const fs::path ini = kDir / (name + ".ini");
    return fs::exists(ini) ? ini.string() : std::string();
}

// Programs rs274 is given in an edited copy (one text replacement), and why.
struct Edit
{
    const char *from, *to, *why;
};

const std::map<std::string, Edit> &edits()
{
    // None now: rs274's PRINT output (subs-follow-main, sub-call-from-sub) is told from its
    // errors by its exit status.
    static const std::map<std::string, Edit> kEdits = {};
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
            EXPECT_TRUE(
                test::matchesRs274(nc.string(), {}, table ? &*table : nullptr, iniFor(GetParam())));
            return;
        }
        std::string text = readText(nc);
        const auto at = text.find(edit->second.from);
        ASSERT_NE(at, std::string::npos) << edit->second.why;
        text.replace(at, std::strlen(edit->second.from), edit->second.to);
        expectEditedCopyMatchesRs274(nc, text, table ? &*table : nullptr, edit->second.why);
        return;
    }
    Options options;
    options.toolTable = table;
    Error iniError;
    if (!iniFor(GetParam()).empty())
        ASSERT_TRUE(readLinuxCncIniFile(iniFor(GetParam()), &options, &iniError))
            << englishMessage(iniError);
    const Result r = interpretFile(nc.string(), options);
    ASSERT_FALSE(r.ok()) << "listed as refused (" << it->second.why << ") but accepted";
    const Error &e = r.errors[0];
    EXPECT_EQ(errorName(e.code), std::string(errorName(it->second.code)))
        << e.file << ":" << e.line << ":" << e.column << ": " << englishMessage(e);
    EXPECT_FALSE(translatedMessage(e).isEmpty());
    if (const auto at = refusedAt().find(GetParam()); at != refusedAt().end()) {
        const std::string file =
            e.file.empty() ? std::string() : fs::relative(e.file, kDir).generic_string();
        EXPECT_EQ(file + ":" + std::to_string(e.line), at->second) << englishMessage(e);
        // iniparam moves to its INI's [VARS] before its error, as rs274's trace shows.
        if (GetParam() == "iniparam") {
            ASSERT_GE(r.toolpath.size(), 1u);
            EXPECT_EQ(r.toolpath.end(0), (Point4{10, 20, 30, 0}));
        }
        // rs274 with the same INI refuses them too (but for the nested definitions, which the
        // installed LinuxCNC 2.9 does not check yet).
        if (!test::rs274Path().empty() && GetParam().rfind("nested-sub", 0) != 0)
            EXPECT_FALSE(test::runRs274(nc.string(), nullptr, iniFor(GetParam())).error.empty())
                << "rs274 accepts it";
    }
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
    // Every program that is not lathe, spindle-synchronised, B-axis, Python plug-in or meant to
    // fail (LinuxCNC's own standalone run of the suite matches 17).
    EXPECT_GE(matched, 23u);
    EXPECT_EQ(programsIn(kDir / "bad").size(), 23u);
}
