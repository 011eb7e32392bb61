// Corpus tests: golden traces of the good programs, the differential test against LinuxCNC's
// rs274 on the same programs, and the bad programs with the error and line:col they expect.
//
// Golden traces (good/NAME.trace) are the JSON Lines of gcode/trace.h with events. They are
// regenerated with FREZKA_UPDATE_GOLDEN=1 (then reviewed and checked against rs274 by
// Rs274Diff, which is independent of them).
#include "corpusfiles.h"
#include "rs274.h"

#include "gcode/interpreter.h"
#include "gcode/trace.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>

using namespace frezka::gcode;
using namespace frezka::gcode::test;
namespace fs = std::filesystem;

namespace {

const fs::path kData = FREZKA_GCODE_DATA_DIR;

std::string sourceLine(const std::string &text, std::uint32_t line)
{
    std::istringstream in(text);
    std::string s;
    for (std::uint32_t i = 0; i < line && std::getline(in, s); ++i) {
    }
    while (!s.empty() && (s.back() == '\r' || s.back() == ' '))
        s.pop_back();
    return s;
}

// The tool table beside a program (NAME.tbl, mm), read for both Frezka and rs274.
std::optional<ToolTable> toolTableFor(fs::path nc)
{
    return toolTableAt(nc.replace_extension(".tbl"));
}

Options optionsFor(const fs::path &nc)
{
    Options options;
    options.toolTable = toolTableFor(nc);
    return options;
}

class GoodProgram : public testing::TestWithParam<std::string>
{
};

class BadProgram : public testing::TestWithParam<std::string>
{
};

} // namespace

TEST_P(GoodProgram, MatchesGoldenTrace)
{
    const fs::path nc = kData / "good" / (GetParam() + ".nc");
    const fs::path golden = kData / "good" / (GetParam() + ".trace");
    const Result r = interpretFile(nc.string(), optionsFor(nc));
    ASSERT_TRUE(r.ok()) << r.errors[0].line << ":" << r.errors[0].column << ": "
                        << englishMessage(r.errors[0]);
    // Ended by M2/M30/%, or at the end of the file with the warning that says so.
    const bool implied = std::any_of(r.warnings.begin(), r.warnings.end(), [](const Error &w) {
        return w.code == ErrorCode::ImpliedProgramEnd;
    });
    EXPECT_TRUE(r.ended || implied);
    const std::string trace = jsonLines(r.toolpath, true);
    if (std::getenv("FREZKA_UPDATE_GOLDEN")) {
        std::ofstream(golden, std::ios::binary) << trace;
        GTEST_SKIP() << "golden trace written: " << golden;
    }
    ASSERT_TRUE(fs::exists(golden)) << "missing " << golden << " (FREZKA_UPDATE_GOLDEN=1)";
    const std::string expected = readText(golden);
    if (trace == expected)
        return;
    std::istringstream a(trace), b(expected);
    std::string la, lb;
    for (int n = 1;; ++n) {
        const bool ga = static_cast<bool>(std::getline(a, la));
        const bool gb = static_cast<bool>(std::getline(b, lb));
        if (!ga && !gb)
            break;
        ASSERT_EQ(la, lb) << "first difference at trace line " << n;
    }
}

TEST_P(GoodProgram, MatchesRs274)
{
    const fs::path nc = kData / "good" / (GetParam() + ".nc");
    if (test::rs274Path().empty())
        GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
    const auto tools = toolTableFor(nc);
    EXPECT_TRUE(test::matchesRs274(nc.string(), {}, tools ? &*tools : nullptr));
}

INSTANTIATE_TEST_SUITE_P(Corpus, GoodProgram, testing::ValuesIn(programsIn(kData / "good")),
                         testName);

TEST_P(BadProgram, ReportsExpectedErrorAt)
{
    const fs::path nc = kData / "bad" / (GetParam() + ".nc");
    const std::string text = readText(nc);
    // A line "; expect: ErrorName LINE:COL" (the first line, or the second after a %), and
    // "; rs274: error" when LinuxCNC's rs274 must reject the same line.
    const auto pos = text.find("; expect: ");
    ASSERT_NE(pos, std::string::npos) << "bad program without '; expect: NAME LINE:COL'";
    std::istringstream header(text.substr(pos + 10, text.find('\n', pos) - pos - 10));
    std::string name, where;
    header >> name >> where;
    ErrorCode code{};
    ASSERT_TRUE(errorCodeFromName(name, &code)) << "unknown error name " << name;
    const auto colon = where.find(':');
    const auto line = static_cast<std::uint32_t>(std::stoul(where.substr(0, colon)));
    const auto column = static_cast<std::uint32_t>(std::stoul(where.substr(colon + 1)));

    const Result r = interpretFile(nc.string(), optionsFor(nc));
    ASSERT_FALSE(r.ok());
    const Error &e = r.errors.front();
    EXPECT_EQ(errorName(e.code), name) << englishMessage(e);
    EXPECT_EQ(e.line, line) << englishMessage(e);
    EXPECT_EQ(e.column, column) << englishMessage(e);
    EXPECT_FALSE(translatedMessage(e).isEmpty());

    if (text.find("\n; rs274: error") != std::string::npos) {
        const auto tools = toolTableFor(nc);
        const test::Rs274Run ref = test::runRs274(nc.string(), tools ? &*tools : nullptr);
        if (!ref.available)
            GTEST_SKIP() << "rs274 is not installed";
        EXPECT_FALSE(ref.error.empty()) << "rs274 accepted the program";
        EXPECT_EQ(ref.errorLine, sourceLine(text, line)) << "rs274: " << ref.error;
    }
}

INSTANTIATE_TEST_SUITE_P(Corpus, BadProgram, testing::ValuesIn(programsIn(kData / "bad")),
                         testName);
