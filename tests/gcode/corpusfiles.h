#pragma once
// The corpus tests' helpers (golden, LinuxCNC examples, LinuxCNC's interpreter suite, real CAM
// output): the programs of a folder, a file's text, the tool table beside a program, a
// parameterised test's name, and the two checks the corpora share: an edited copy against rs274,
// a program refused as listed.

#include "rs274.h"

#include "gcode/error.h"
#include "gcode/interpreter.h"
#include "gcode/tooltable.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <string>
#include <vector>

namespace frezka::gcode::test {

// The names (without .nc) of the programs in `dir`, sorted.
inline std::vector<std::string> programsIn(const std::filesystem::path &dir)
{
    std::vector<std::string> names;
    for (const auto &e : std::filesystem::directory_iterator(dir)) {
        if (e.path().extension() == ".nc")
            names.push_back(e.path().stem().string());
    }
    std::sort(names.begin(), names.end());
    return names;
}

inline std::string readText(const std::filesystem::path &path)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream ss;
    ss << in.rdbuf();
    return ss.str();
}

// The tool table `tbl` (mm) when the file exists, read for both Frezka and rs274; a bad one
// fails the test with its line.
inline std::optional<ToolTable> toolTableAt(const std::filesystem::path &tbl)
{
    if (!std::filesystem::exists(tbl))
        return std::nullopt;
    ToolTable table;
    Error error;
    EXPECT_TRUE(readToolTableFile(tbl.string(), &table, &error, false))
        << tbl << ":" << error.line << ": " << englishMessage(error);
    return table;
}

// A program's name as a test name (letters and digits, the rest '_').
inline std::string testName(const testing::TestParamInfo<std::string> &info)
{
    std::string s = info.param;
    std::replace_if(
        s.begin(), s.end(), [](char c) { return !std::isalnum(static_cast<unsigned char>(c)); },
        '_');
    return s;
}

// A program Frezka refuses, with the reason (a clear error, never a wrong path).
struct Refusal
{
    ErrorCode code; // Frezka's first error
    const char *why;
};

// The program `nc` against rs274 run on `text` (an edited copy of it, written to a temporary file):
// where rs274 needs a change that does not alter the path (`why`).
inline void expectEditedCopyMatchesRs274(const std::filesystem::path &nc, const std::string &text,
                                         const ToolTable *tools, const std::string &why)
{
    QTemporaryDir dir;
    const std::string copy = dir.filePath(QStringLiteral("edited.ngc")).toStdString();
    std::ofstream(copy, std::ios::binary) << text;
    EXPECT_TRUE(matchesRs274(nc.string(), copy, tools)) << why;
}

// `nc` is refused with the listed error first, in words that are translated.
inline void expectRefusedAsListed(const std::filesystem::path &nc,
                                  const std::optional<ToolTable> &tools, const Refusal &refusal)
{
    Options options;
    options.toolTable = tools;
    const Result r = interpretFile(nc.string(), options);
    ASSERT_FALSE(r.ok()) << "listed as refused (" << refusal.why << ") but accepted";
    EXPECT_EQ(errorName(r.errors[0].code), std::string(errorName(refusal.code)))
        << r.errors[0].line << ":" << r.errors[0].column << ": " << englishMessage(r.errors[0]);
    EXPECT_FALSE(translatedMessage(r.errors[0]).isEmpty());
}

} // namespace frezka::gcode::test
