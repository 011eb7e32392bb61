#pragma once
// The tool table in LinuxCNC's .tbl format: one tool a line,
//   T<tool> P<pocket> [X Y Z A B C U V W <offset>] [D<diameter>] [I<front angle>]
//   [J<back angle>] [Q<orientation>] [; comment]
// (letters in any case, words in any order, blank lines and lines starting with ';' ignored).
// Lengths are in mm (Frezka's machines are metric; LinuxCNC reads them in the machine's units),
// angles in degrees. A line that cannot be read is an error naming the file and the line, never
// skipped: a tool measured wrong cuts at the wrong height.

#include "gcode/error.h"

#include <array>
#include <string>
#include <string_view>
#include <vector>

namespace frezka::gcode {

struct ToolEntry
{
    int tool = 0;   // T, 1 or more
    int pocket = 0; // P (Frezka has no changer: kept as written)
    // X Y Z A B C U V W offsets: mm (A B C degrees). Z is the tool length G43 applies.
    std::array<double, 9> offsetMm{};
    double diameterMm = 0; // D: G41/G42 use half of it
    double frontAngle = 0; // I, degrees (lathe tools)
    double backAngle = 0;  // J, degrees (lathe tools)
    int orientation = 0;   // Q, 0..9 (lathe tools)
    std::string comment;   // after ';', without the leading blanks
    friend bool operator==(const ToolEntry &, const ToolEntry &) = default;
};

struct ToolTable
{
    std::vector<ToolEntry> tools; // file order
    const ToolEntry *find(int tool) const;
    ToolEntry *find(int tool);
    friend bool operator==(const ToolTable &, const ToolTable &) = default;
};

// Reads .tbl text. On a bad line returns false with error ToolTableSyntax or ToolTableDuplicate
// (line and column of the offending word set); *table is then left unchanged.
bool parseToolTable(std::string_view text, ToolTable *table, Error *error);
// The .tbl text of a table, one line a tool in table order ("T1 P1 Z12.5 D6 ;comment").
std::string formatToolTable(const ToolTable &table);

// A file that does not exist reads as an empty table when missingIsEmpty (a profile's default
// table that was never written), else FileOpenFailed. Errors carry the line of the bad entry.
bool readToolTableFile(const std::string &path, ToolTable *table, Error *error,
                       bool missingIsEmpty = true);
// Writes atomically (a temporary file renamed over the old one): a crash leaves the old table
// or the new one, never half of it. False with FileWriteFailed and the reason.
bool writeToolTableFile(const std::string &path, const ToolTable &table, Error *error);

} // namespace frezka::gcode
