#include "linuxcncini.h"

#include <algorithm>
#include <cctype>
#include <charconv>
#include <filesystem>
#include <fstream>
#include <sstream>

namespace frezka::gcode {

namespace {

std::string_view trimmed(std::string_view s)
{
    const auto space = [](char c) { return c == ' ' || c == '\t' || c == '\r'; };
    while (!s.empty() && space(s.front()))
        s.remove_prefix(1);
    while (!s.empty() && space(s.back()))
        s.remove_suffix(1);
    return s;
}

std::string lower(std::string_view s)
{
    std::string out(s);
    std::transform(out.begin(), out.end(), out.begin(),
                   [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
    return out;
}

// SUBROUTINE_PATH: folders separated by ':', relative ones from the INI's folder.
void addSubroutinePath(std::string_view value, const std::filesystem::path &base, Options *options)
{
    while (!value.empty()) {
        const std::size_t colon = value.find(':');
        const std::string_view dir = trimmed(value.substr(0, colon));
        if (!dir.empty()) {
            std::filesystem::path p(dir);
            options->subroutinePath.push_back(
                (p.is_absolute() ? p : base / p).lexically_normal().string());
        }
        if (colon == std::string_view::npos)
            break;
        value.remove_prefix(colon + 1);
    }
}

} // namespace

bool readLinuxCncIni(std::string_view text, const std::string &path, Options *options, Error *error)
{
    const std::filesystem::path base = std::filesystem::absolute(path).parent_path();
    std::string section;
    std::map<std::string, double> values;
    bool iniVars = true; // LinuxCNC's default
    std::uint32_t line = 0;
    while (!text.empty()) {
        const std::size_t nl = text.find('\n');
        const std::string_view raw = text.substr(0, nl);
        text.remove_prefix(nl == std::string_view::npos ? text.size() : nl + 1);
        ++line;
        const std::string_view s = trimmed(raw);
        if (s.empty() || s.front() == '#' || s.front() == ';')
            continue;
        if (s.front() == '[' && s.back() == ']') {
            section = lower(trimmed(s.substr(1, s.size() - 2)));
            continue;
        }
        const std::size_t eq = s.find('=');
        if (eq == std::string_view::npos || section.empty() || trimmed(s.substr(0, eq)).empty()) {
            *error = {ErrorCode::IniSyntax, line, 1, std::string(s), path};
            return false;
        }
        const std::string name = lower(trimmed(s.substr(0, eq)));
        const std::string_view value = trimmed(s.substr(eq + 1));
        if (section == "rs274ngc" && name == "subroutine_path")
            addSubroutinePath(value, base, options);
        if (section == "rs274ngc" && name == "ini_vars")
            iniVars = value != "0";
        double number = 0;
        const auto [end, ec] = std::from_chars(value.data(), value.data() + value.size(), number);
        if (ec == std::errc() && end == value.data() + value.size())
            values[section + "]" + name] = number;
    }
    if (iniVars)
        options->iniValues.insert(values.begin(), values.end());
    return true;
}

bool readLinuxCncIniFile(const std::string &path, Options *options, Error *error)
{
    std::ifstream in(path, std::ios::binary);
    std::stringstream text;
    if (!in || !(text << in.rdbuf())) {
        *error = {ErrorCode::FileOpenFailed, 0, 0, path, path};
        return false;
    }
    return readLinuxCncIni(text.str(), path, options, error);
}

} // namespace frezka::gcode
