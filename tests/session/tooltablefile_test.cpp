// The profile's tool table reaches the program check: its file beside the profile, its lengths
// in the toolpath, its errors (file:line) as the load's first error.
#include "session/programplanner.h"
#include "session/tooltablefile.h"

#include <QDir>
#include <QFile>
#include <QTemporaryDir>

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

void write(const QString &path, const char *text)
{
    QFile f(path);
    ASSERT_TRUE(f.open(QIODevice::WriteOnly));
    f.write(text);
}

TEST(ToolTableFile, BesideTheProfileByDefault)
{
    QTemporaryDir dir;
    const QString profile = dir.filePath(QStringLiteral("mill.json"));
    machine::MachineConfig c;
    EXPECT_EQ(QString::fromStdString(machine::toolTablePath(c, profile.toStdString())),
              dir.filePath(QStringLiteral("tool.tbl")));
    c.tools.tableFile = "tables/../t2.tbl";
    EXPECT_EQ(QString::fromStdString(machine::toolTablePath(c, profile.toStdString())),
              dir.filePath(QStringLiteral("t2.tbl")));
    c.tools.tableFile = "/abs/t.tbl";
    EXPECT_EQ(machine::toolTablePath(c, profile.toStdString()), "/abs/t.tbl");
    c.tools.tableFile.clear();
    EXPECT_EQ(machine::toolTablePath(c, profile.toStdString()), "");
    // The key is part of the profile's JSON.
    c.tools.tableFile = "my tools.tbl";
    const machine::ConfigResult back = machine::parseMachineConfig(machine::toJson(c));
    ASSERT_TRUE(back.config);
    EXPECT_EQ(back.config->tools.tableFile, "my tools.tbl");
}

TEST(ToolTableFile, LengthsReachTheToolpathAndErrorsStopIt)
{
    QTemporaryDir dir;
    const QString profile = dir.filePath(QStringLiteral("mill.json"));
    const machine::MachineConfig c;
    ToolTableFile t = readProfileToolTable(c, profile);
    EXPECT_FALSE(t.table); // no file yet: no table
    EXPECT_TRUE(t.error.isEmpty());

    write(dir.filePath(QStringLiteral("tool.tbl")), "T1 P1 Z42 D6 ;end mill\n");
    t = readProfileToolTable(c, profile);
    ASSERT_TRUE(t.table);
    InterpretRequest r;
    r.text = "G21 G90\nT1 M6 G43\nG0 Z0\nM2\n";
    r.fileName = QStringLiteral("job.nc");
    r.toolTable = t.table;
    InterpretOutcome out = interpretProgram(r);
    ASSERT_TRUE(out.errors.empty()) << out.errors[0].text.toStdString();
    EXPECT_EQ(out.toolpath->end(1).z, 42.0);
    // A tool not in the table is the program's error.
    r.text = "G21\nT2 M6\nM2\n";
    out = interpretProgram(r);
    ASSERT_EQ(out.errors.size(), 1u);
    EXPECT_EQ(out.errors[0].line, 2);

    write(dir.filePath(QStringLiteral("tool.tbl")), "T1 P1 Z42 D6\nT2 P2 Z4x\n");
    t = readProfileToolTable(c, profile);
    EXPECT_FALSE(t.table);
    EXPECT_TRUE(t.error.startsWith(dir.filePath(QStringLiteral("tool.tbl:2:7: "))))
        << t.error.toStdString();
    r.text = "G21\nG0 X1\nM2\n";
    r.toolTable = t.table;
    r.toolTableError = t.error;
    out = interpretProgram(r);
    ASSERT_EQ(out.errors.size(), 1u);
    EXPECT_EQ(out.errors[0].text, t.error);
}

} // namespace
} // namespace frezka::session
