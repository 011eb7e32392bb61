// Subroutine files (o<name> call of name.ngc on the search path, as LinuxCNC's SUBROUTINE_PATH)
// and what the interpreter reads from a LinuxCNC INI file: where files are found, that their
// motions are rs274's, that errors in them name the file, line and column, and LinuxCNC's
// errors for definitions a subroutine file may not hold.
#include "rs274.h"

#include "gcode/interpreter.h"
#include "gcode/linuxcncini.h"

#include <gtest/gtest.h>

#include <QTemporaryDir>

#include <filesystem>
#include <fstream>

using namespace frezka::gcode;
namespace fs = std::filesystem;

namespace {

class SubFiles : public testing::Test
{
protected:
    // Writes `text` to `name` under the temporary folder; returns its path.
    std::string write(const std::string &name, const std::string &text)
    {
        const fs::path p = fs::path(m_dir.path().toStdString()) / name;
        fs::create_directories(p.parent_path());
        std::ofstream(p, std::ios::binary) << text;
        return p.string();
    }
    std::string dir(const std::string &sub = {}) const
    {
        return (fs::path(m_dir.path().toStdString()) / sub).lexically_normal().string();
    }
    QTemporaryDir m_dir;
};

const std::string kSquare = "(a square of side #1 at feed #2)\n"
                            "o<square> sub\n"
                            "G91 G1 X#1 F#2\nY#1\nX-#1\nY-#1\nG90\n"
                            "o<square> endsub\n"
                            "M2\n";

} // namespace

// A file on the subroutine path runs as its o<name> sub: the motions are those of the same body
// written in the program, the call's arguments arrive, and the moves count as the call's line.
TEST_F(SubFiles, SubroutineFileOnThePathRunsAsTheCall)
{
    write("lib/square.ngc", kSquare);
    const std::string nc = write("prog/part.ngc", "G0 X10 Y10\no<square> call [5] [300]\n"
                                                  "G0 X20\no<square> call [2] [100]\nM2\n");
    Options options;
    options.subroutinePath = {dir("lib")};
    const Result r = interpretFile(nc, options);
    ASSERT_TRUE(r.ok()) << r.errors[0].file << ":" << r.errors[0].line << ": "
                        << englishMessage(r.errors[0]);
    const Result inline_ = interpretText("G0 X10 Y10\nG91 G1 X5 F300\nY5\nX-5\nY-5\nG90\n"
                                         "G0 X20\nG91 G1 X2 F100\nY2\nX-2\nY-2\nG90\nM2\n");
    ASSERT_EQ(r.toolpath.size(), inline_.toolpath.size());
    for (std::size_t i = 0; i < r.toolpath.size(); ++i) {
        EXPECT_EQ(r.toolpath.end(i), inline_.toolpath.end(i)) << i;
        EXPECT_EQ(r.toolpath.feedMmPerMin(i), inline_.toolpath.feedMmPerMin(i)) << i;
    }
    EXPECT_EQ(r.toolpath.line(1), 2u); // the first call's line, not the file's
    EXPECT_EQ(r.toolpath.line(6), 4u);
    // Without the path the call is refused, naming where to put the file.
    const Result none = interpretFile(nc);
    ASSERT_FALSE(none.ok());
    EXPECT_EQ(none.errors[0].code, ErrorCode::SubroutineUndefined);
    EXPECT_EQ(none.errors[0].line, 2u);
    EXPECT_NE(englishMessage(none.errors[0]).find("program.subroutinePath"), std::string::npos);
}

// The program's own folder comes first (LinuxCNC's working folder and PROGRAM_PREFIX), then the
// path's folders in order.
TEST_F(SubFiles, ProgramFolderFirstThenThePathInOrder)
{
    write("a/move.ngc", "o<move> sub\nG0 X1\no<move> endsub\n");
    write("b/move.ngc", "o<move> sub\nG0 X2\no<move> endsub\n");
    write("b/other.ngc", "o<other> sub\nG0 Y7\no<other> endsub\n");
    const std::string nc = write("p/part.ngc", "o<move> call\no<other> call\nM2\n");
    Options options;
    options.subroutinePath = {dir("a"), dir("b")};
    Result r = interpretFile(nc, options);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(r.toolpath.end(0).x, 1);
    EXPECT_EQ(r.toolpath.end(1), (Point4{1, 7, 0, 0}));
    write("p/move.ngc", "o<move> sub\nG0 X3\no<move> endsub\n");
    r = interpretFile(nc, options);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(r.toolpath.end(0).x, 3);
}

// An error inside a subroutine file stands at its line and column in that file, and the
// formatted message names the file, not the program.
TEST_F(SubFiles, ErrorInTheFileNamesTheFileLineAndColumn)
{
    const std::string sub = write("lib/bad.ngc", "(header)\no<bad> sub\n  G1 X1 F100\n"
                                                 "  #1 = [2/#2]\no<bad> endsub\n");
    const std::string nc = write("prog/part.ngc", "G0 X0\no<bad> call [1] [0]\nM2\n");
    Options options;
    options.subroutinePath = {dir("lib")};
    const Result r = interpretFile(nc, options);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].code, ErrorCode::DivisionByZero);
    EXPECT_EQ(r.errors[0].file, fs::path(sub).lexically_normal().string());
    EXPECT_EQ(r.errors[0].line, 4u);
    EXPECT_EQ(r.errors[0].column, 10u);
    EXPECT_EQ(formatError(QStringLiteral("part.ngc"), r.errors[0])
                  .startsWith(QString::fromStdString(r.errors[0].file) + QStringLiteral(":4:10: ")),
              true);
    // A file that does not define its subroutine, and one whose sub never ends.
    write("lib/empty.ngc", "G0 X1\nM2\n");
    write("lib/open.ngc", "o<open> sub\nG0 X1\n");
    const Result e = interpretText("o<empty> call\nM2\n", options);
    ASSERT_FALSE(e.ok());
    EXPECT_EQ(e.errors[0].code, ErrorCode::SubroutineFileWithoutSub);
    EXPECT_EQ(e.errors[0].line, 1u);
    EXPECT_TRUE(e.errors[0].file.empty());
    const Result o = interpretText("o<open> call\nM2\n", options);
    ASSERT_FALSE(o.ok());
    EXPECT_EQ(o.errors[0].code, ErrorCode::OwordNotClosed);
    EXPECT_EQ(o.errors[0].file, dir("lib/open.ngc"));
    EXPECT_EQ(o.errors[0].line, 1u);
}

// LinuxCNC (#3880): a sub line inside a called subroutine is an error, and a file holds only
// its own subroutine (a numbered one after its endsub is not found); a subroutine file may call
// another file's subroutine.
TEST_F(SubFiles, NestedDefinitionsAndSecondSubroutinesAreRefused)
{
    Options options;
    options.subroutinePath = {dir("lib")};
    write("lib/outer.ngc", "o<outer> sub\no100 sub\no100 endsub\no<outer> endsub\n");
    Result r = interpretText("o<outer> call\nM2\n", options);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].code, ErrorCode::NestedSubDefinition);
    EXPECT_EQ(r.errors[0].line, 2u);
    EXPECT_EQ(r.errors[0].file, dir("lib/outer.ngc"));
    r = interpretText("o1 sub\n  o2 sub\n  o2 endsub\no1 endsub\no1 call\nM2\n");
    ASSERT_FALSE(r.ok()) << "the same in the program itself";
    EXPECT_EQ(r.errors[0].code, ErrorCode::NestedSubDefinition);
    EXPECT_EQ(r.errors[0].line, 2u);
    write("lib/first.ngc", "o<first> sub\no200 call\no<first> endsub\no200 sub\no200 endsub\n");
    r = interpretText("o<first> call\nM2\n", options);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].code, ErrorCode::SubroutineNotFound);
    EXPECT_EQ(r.errors[0].line, 2u);
    write("lib/caller.ngc", "o<caller> sub\no<helper> call [#1 * 2]\no<caller> endsub\n");
    write("lib/helper.ngc", "o<helper> sub\nG0 X#1\no<helper> endsub\n");
    r = interpretText("o<caller> call [3]\no<caller> call [4]\nM2\n", options);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    ASSERT_EQ(r.toolpath.size(), 3u);
    EXPECT_EQ(r.toolpath.end(0).x, 6);
    EXPECT_EQ(r.toolpath.end(1).x, 8);
}

// The INI's SUBROUTINE_PATH (relative to the INI's folder) and numeric values as
// #<_ini[section]name>; a malformed line is an error at its line.
TEST_F(SubFiles, LinuxCncIniGivesThePathAndValues)
{
    const std::string ini =
        write("cfg/machine.ini", "# a comment\n[RS274NGC]\nSUBROUTINE_PATH = subs:../lib\n"
                                 "INI_VARS = 1\n\n[VARS]\nTOOLCHANGE_X = 10.5\nNAME = text\n");
    Options options;
    Error error;
    ASSERT_TRUE(readLinuxCncIniFile(ini, &options, &error)) << englishMessage(error);
    EXPECT_EQ(options.subroutinePath, (std::vector<std::string>{dir("cfg/subs"), dir("lib")}));
    EXPECT_EQ(options.iniValues.at("vars]toolchange_x"), 10.5);
    EXPECT_EQ(options.iniValues.count("vars]name"), 0u);
    Result r = interpretText("G0 X#<_INI[vars]toolchange_x>\nM2\n", options);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(r.toolpath.end(0).x, 10.5);
    r = interpretText("#<_ini[vars]toolchange_x> = 1\nM2\n", options);
    ASSERT_FALSE(r.ok());
    EXPECT_EQ(r.errors[0].code, ErrorCode::ReadOnlyParameter);
    Options off;
    ASSERT_TRUE(readLinuxCncIni("[RS274NGC]\nINI_VARS=0\n[V]\nA=1\n", ini, &off, &error));
    EXPECT_TRUE(off.iniValues.empty());
    Options bad;
    EXPECT_FALSE(readLinuxCncIni("[RS274NGC]\nINI_VARS=0\nthis is no pair\n", ini, &bad, &error));
    EXPECT_EQ(error.code, ErrorCode::IniSyntax);
    EXPECT_EQ(error.line, 3u);
    EXPECT_EQ(error.file, ini);
}

// rs274 -i with the same INI gives the same motions, feeds and dwells for a program whose
// subroutines are files on the INI's path, one calling another.
TEST_F(SubFiles, MatchesRs274WithTheSameIni)
{
    if (test::rs274Path().empty())
        GTEST_SKIP() << "rs274 (Debian package linuxcnc-uspace) is not installed";
    write("cfg/subs/square.ngc", kSquare);
    write("cfg/subs/pocket.ngc", "o<pocket> sub\n#<i> = 1\no1 while [#<i> LE #1]\n"
                                 "  o<square> call [#<i> * 2] [200]\n  G4 P0.5\n"
                                 "  #<i> = [#<i> + 1]\no1 endwhile\no<pocket> endsub\nM2\n");
    const std::string ini =
        write("cfg/test.ini", "[RS274NGC]\nSUBROUTINE_PATH = subs\n[VARS]\nDEPTH = -1.5\n");
    const std::string nc = write("prog/part.ngc", "G21 G0 X5 Y5\nG1 Z#<_ini[vars]depth> F50\n"
                                                  "o<pocket> call [3]\nG0 Z5\nM2\n");
    EXPECT_TRUE(test::matchesRs274(nc, {}, nullptr, ini));
}

// Run from a line: the lines of a subroutine file are not the program's, so a skipped block in
// the file does not refuse a start line of the same number in the program.
TEST_F(SubFiles, RunFromLineCountsOnlyTheProgramsLines)
{
    write("lib/s.ngc", "o<s> sub\no1 if [0]\nG0 Y1\no1 endif\no<s> endsub\n");
    const std::string nc = write("prog/part.ngc", "o<s> call\nG0 X1\nG0 X2\nM2\n");
    Options options;
    options.subroutinePath = {dir("lib")};
    options.startLine = 3;
    const Result r = interpretFile(nc, options);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(r.mark.refusal, LineMarkRefusal::None);
    EXPECT_EQ(r.mark.line, 3u);
    EXPECT_EQ(r.mark.entry, 1u); // after G0 X1
}
