// The .tbl reader and writer, and the tool table as the interpreter uses and changes it.
#include "gcode/interpreter.h"
#include "gcode/tooltable.h"

#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

using namespace frezka::gcode;

namespace {

ToolTable parsed(std::string_view text)
{
    ToolTable t;
    Error e;
    EXPECT_TRUE(parseToolTable(text, &t, &e)) << e.line << ":" << e.column << " " << e.detail;
    return t;
}

Error parseError(std::string_view text)
{
    ToolTable t;
    t.tools.push_back({});
    Error e;
    EXPECT_FALSE(parseToolTable(text, &t, &e));
    EXPECT_EQ(t.tools.size(), 1u) << "a failed read changed the table";
    return e;
}

} // namespace

TEST(ToolTable, ReadsLinuxCncLines)
{
    const ToolTable t = parsed("; header comment\n"
                               "T1 P1 Z+50.8 D6 ;6 mm end mill\r\n"
                               "\n"
                               "t2 p12 x1.5 z-3 a2 d3.175 i10 j20 q3 ;  ball nose  \n"
                               "  T10 P3 W4 ;\n");
    ASSERT_EQ(t.tools.size(), 3u);
    EXPECT_EQ(t.tools[0].tool, 1);
    EXPECT_EQ(t.tools[0].offsetMm[2], 50.8);
    EXPECT_EQ(t.tools[0].diameterMm, 6);
    EXPECT_EQ(t.tools[0].comment, "6 mm end mill");
    const ToolEntry &b = t.tools[1];
    EXPECT_EQ(b.pocket, 12);
    EXPECT_EQ(b.offsetMm[0], 1.5);
    EXPECT_EQ(b.offsetMm[2], -3);
    EXPECT_EQ(b.offsetMm[3], 2);
    EXPECT_EQ(b.frontAngle, 10);
    EXPECT_EQ(b.backAngle, 20);
    EXPECT_EQ(b.orientation, 3);
    EXPECT_EQ(b.comment, "ball nose");
    EXPECT_EQ(t.tools[2].offsetMm[8], 4);
    EXPECT_EQ(t.find(10), &t.tools[2]);
    EXPECT_EQ(t.find(3), nullptr);
}

TEST(ToolTable, BadLinesNameLineAndColumn)
{
    Error e = parseError("T1 P1 Z1\nT2 P2 Z1.2.3 D1\n");
    EXPECT_EQ(e.code, ErrorCode::ToolTableSyntax);
    EXPECT_EQ(e.line, 2u);
    EXPECT_EQ(e.column, 7u);
    EXPECT_EQ(e.detail, "Z1.2.3");
    e = parseError("T1 P1 K3\n");
    EXPECT_EQ(e.detail, "K3");
    e = parseError("P1 Z3 ;no tool number\n");
    EXPECT_EQ(e.line, 1u);
    EXPECT_EQ(e.detail, "T");
    e = parseError("T1 P1 Z3 Z4\n"); // a letter twice
    EXPECT_EQ(e.column, 10u);
    e = parseError("T1.5 P1\n");
    EXPECT_EQ(e.code, ErrorCode::ToolTableSyntax);
    e = parseError("T1 P1 Q12\n");
    EXPECT_EQ(e.detail, "Q12");
    e = parseError("T3 P1 Z1\n\nT3 P2 Z2\n");
    EXPECT_EQ(e.code, ErrorCode::ToolTableDuplicate);
    EXPECT_EQ(e.line, 3u);
    EXPECT_EQ(e.column, 1u);
    EXPECT_EQ(e.detail, "3");
    // "FILE:LINE:COL: message" for the user.
    const QString text = formatError(QStringLiteral("tools.tbl"), e);
    EXPECT_TRUE(text.startsWith(QStringLiteral("tools.tbl:3:1: "))) << text.toStdString();
}

TEST(ToolTable, WritesWhatItReads)
{
    const char *text = "T1 P1 Z50.8 D6 ;6 mm end mill\n"
                       "T2 P12 X1.5 Z-3 A2 D3.175 I10 J20 Q3 ;ball nose\n"
                       "T10 P3 W4 D0 ;\n";
    EXPECT_EQ(formatToolTable(parsed(text)), text);
    const ToolTable t = parsed(text);
    EXPECT_EQ(parsed(formatToolTable(t)), t);
}

TEST(ToolTable, FilesAreWrittenAtomicallyAndReadBack)
{
    QTemporaryDir dir;
    const std::string path = dir.filePath(QStringLiteral("tool.tbl")).toStdString();
    ToolTable t;
    Error e;
    ASSERT_TRUE(readToolTableFile(path, &t, &e)); // a missing default table is empty
    EXPECT_TRUE(t.tools.empty());
    EXPECT_FALSE(readToolTableFile(path, &t, &e, false));
    EXPECT_EQ(e.code, ErrorCode::FileOpenFailed);
    t = parsed("T4 P4 Z12.5 D8 ;drill\n");
    ASSERT_TRUE(writeToolTableFile(path, t, &e));
    ToolTable back;
    ASSERT_TRUE(readToolTableFile(path, &back, &e, false));
    EXPECT_EQ(back, t);
    // A folder that does not exist: an error, no partial file.
    const std::string bad = dir.filePath(QStringLiteral("no/such/tool.tbl")).toStdString();
    EXPECT_FALSE(writeToolTableFile(bad, t, &e));
    EXPECT_EQ(e.code, ErrorCode::FileWriteFailed);
    EXPECT_FALSE(QFile::exists(QString::fromStdString(bad)));
    // A bad file names its line.
    QFile f(QString::fromStdString(path));
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write("T1 P1 Z1\nT2 P2 Zfoo\n");
    f.close();
    EXPECT_FALSE(readToolTableFile(path, &back, &e));
    EXPECT_EQ(e.line, 2u);
    EXPECT_EQ(back, t); // unchanged
}

TEST(ToolTable, InterpreterUsesAndChangesTheTable)
{
    Options o;
    o.toolTable = parsed("T1 P1 Z10 D6 ;a\nT2 P2 X1 Z20 D4 ;b\n");
    // G43 with the tool in the spindle, then G10 L1 (no effect until the next G43), then G43.
    Result r = interpretText("G21 G90\nT2 M6 G43\nG0 X0 Y0 Z0\nG10 L1 P2 Z30 R1.5\nG0 Z1\n"
                             "G43\nG0 Z2\nG10 L10 P1 Z5\nM2\n",
                             o);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    ASSERT_GE(r.toolpath.size(), 4u);
    std::vector<Point4> ends;
    for (std::size_t i = 0; i < r.toolpath.size(); ++i) {
        if (r.toolpath.kind(i) == MotionKind::Rapid)
            ends.push_back(r.toolpath.end(i));
    }
    ASSERT_EQ(ends.size(), 3u);
    EXPECT_EQ(ends[0].x, 1);  // X offset of tool 2
    EXPECT_EQ(ends[0].z, 20); // its length
    EXPECT_EQ(ends[1].z, 21); // G10 L1 does not change the offset in force
    EXPECT_EQ(ends[2].z, 32);
    EXPECT_TRUE(r.toolTableChanged);
    ASSERT_NE(r.toolTable.find(2), nullptr);
    EXPECT_EQ(r.toolTable.find(2)->offsetMm[2], 30);
    EXPECT_EQ(r.toolTable.find(2)->diameterMm, 3);
    EXPECT_EQ(r.toolTable.find(2)->comment, "b");
    // L10: the machine Z is 32 and Z should read 5 without tool offsets: length 27.
    EXPECT_EQ(r.toolTable.find(1)->offsetMm[2], 27);
    // Without G10 the table is not changed.
    r = interpretText("T1 M6 G43\nG0 Z1\nM2\n", o);
    EXPECT_FALSE(r.toolTableChanged);
    EXPECT_EQ(r.toolTable, *o.toolTable);
}

TEST(ToolTable, ParametersGiveTheSpindleTool)
{
    Options o;
    o.toolTable = parsed("T3 P1 Z25.4 D12.7 ;\n");
    // In G20 too the values are the table's (machine units, mm), as in LinuxCNC.
    const Result r = interpretText("G20\nT3 M6\nG0 X[#5400] Y[#5403] Z[#5410]\nM2\n", o);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    const Point4 end = r.toolpath.end(r.toolpath.size() - 2);
    EXPECT_NEAR(end.x, 3 * 25.4, 1e-9);
    EXPECT_NEAR(end.y, 25.4 * 25.4, 1e-9);
    EXPECT_NEAR(end.z, 12.7 * 25.4, 1e-9);
}

TEST(ToolTable, WithoutATableEveryToolIsAccepted)
{
    Options o;
    o.toolLengthMm[5] = 7;
    const Result r = interpretText("T5 M6\nG43\nG0 Z0\nT99 M6\nG43 H5\nG0 Z1\nM2\n", o);
    ASSERT_TRUE(r.ok()) << englishMessage(r.errors[0]);
    EXPECT_EQ(r.toolpath.end(r.toolpath.size() - 2).z, 8);
}
