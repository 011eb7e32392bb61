#pragma once
// The corpus tests' file helpers (golden, LinuxCNC examples, LinuxCNC's interpreter suite, real
// CAM output): the programs of a folder, a file's text, the tool table beside a program, and a
// parameterised test's name.

#include "gcode/error.h"
#include "gcode/tooltable.h"

#include <gtest/gtest.h>

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

} // namespace frezka::gcode::test
