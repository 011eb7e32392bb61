#pragma once
// What the interpreter takes from a LinuxCNC INI file (a machine configuration of LinuxCNC, e.g.
// the interpreter tests' test.ini): [RS274NGC]SUBROUTINE_PATH (folders separated by ':',
// relative ones from the INI's folder, as LinuxCNC runs from there) and, unless
// [RS274NGC]INI_VARS = 0, every numeric value as #<_ini[section]name>. Other keys are left alone.

#include "gcode/error.h"
#include "gcode/interpreter.h"

#include <string>
#include <string_view>

namespace frezka::gcode {

// Reads the INI text (its path names the folder for relative paths) into options; a line that
// is neither a [section], a NAME = VALUE, a comment (# or ;) nor blank is an IniSyntax error
// naming the line (Error::file the INI).
bool readLinuxCncIni(std::string_view text, const std::string &path, Options *options,
                     Error *error);
// The same for a file; FileOpenFailed when it cannot be read.
bool readLinuxCncIniFile(const std::string &path, Options *options, Error *error);

} // namespace frezka::gcode
