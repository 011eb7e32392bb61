// frezka-cli plan, run as a process: wire lines, the JSON summary, errors before any output.
#include <gtest/gtest.h>

#include <QJsonDocument>
#include <QJsonObject>
#include <QProcess>
#include <QTemporaryDir>

namespace {

struct CliRun
{
    int code = -1;
    QString out, err;
};

CliRun cli(const QStringList &args, const QString &command = QStringLiteral("plan"))
{
    QProcess p;
    p.start(QStringLiteral(FREZKA_CLI), QStringList{command} + args);
    p.waitForFinished(60000);
    return {p.exitCode(), QString::fromUtf8(p.readAllStandardOutput()),
            QString::fromUtf8(p.readAllStandardError())};
}

QString writeProgram(const QTemporaryDir &dir, const char *name, const char *text)
{
    const QString path = dir.filePath(QString::fromLatin1(name));
    QFile f(path);
    f.open(QIODevice::WriteOnly);
    f.write(text);
    return path;
}

} // namespace

TEST(PlanCli, WritesWireLinesAndASummary)
{
    QTemporaryDir dir;
    const QString file = writeProgram(dir, "square.nc",
                                      "G21 G90 G94\nG0 X10 Y10 Z-1\nF1200\nG1 X20\nG1 Y20\n"
                                      "G1 X10\nG1 Y10\nM2\n");
    const CliRun r = cli({file});
    ASSERT_EQ(r.code, 0) << r.err.toStdString();
    const QStringList lines = r.out.split(QLatin1Char('\n'), Qt::SkipEmptyParts);
    ASSERT_GE(lines.size(), 8);
    EXPECT_EQ(lines[0], QStringLiteral("!0VK"));
    EXPECT_EQ(lines[1], QStringLiteral("!0$1"));
    EXPECT_EQ(lines[2], QStringLiteral("!0T10"));
    EXPECT_TRUE(lines.contains(QStringLiteral("!0C2000,0,0"))); // G1 X20 at 200 steps/mm
    for (const QString &l : lines.mid(0, lines.size() - 1))
        EXPECT_TRUE(l.startsWith(QLatin1String("!0")) || l.startsWith(QLatin1String("!7")) ||
                    l.startsWith(QLatin1String("# ")))
            << l.toStdString();
    const QJsonObject summary = QJsonDocument::fromJson(lines.last().toUtf8()).object();
    EXPECT_EQ(summary.keys(),
              (QStringList{"bound_s", "chains", "estimated_s", "max_vertex_jump_mm_s", "vectors"}));
    EXPECT_EQ(summary.value(QLatin1String("vectors")).toInt(), 5); // the rapid, 4 sides
    EXPECT_GT(summary.value(QLatin1String("estimated_s")).toDouble(),
              summary.value(QLatin1String("bound_s")).toDouble() * 0.999);
}

TEST(PlanCli, SoftLimitErrorNamesTheLineAndWritesNothing)
{
    QTemporaryDir dir;
    const QString file = writeProgram(dir, "far.nc", "G21 G90\nG1 X500 Y10 F100\nM2\n");
    const CliRun r = cli({file});
    EXPECT_EQ(r.code, 1);
    EXPECT_TRUE(r.out.isEmpty());
    EXPECT_EQ(r.err, file + QStringLiteral(":2: X 500.000 is outside the soft limits 0.000 .. "
                                           "400.000 mm; check the work offset and the program\n"));
}

TEST(PlanCli, TakesAMachineProfileAndRejectsABadOne)
{
    QTemporaryDir dir;
    const QString file = writeProgram(dir, "a.nc", "G21 G90\nG1 X10 Y10 Z-1 F600\nM2\n");
    const QString good = dir.filePath(QStringLiteral("g.json"));
    QFile g(good);
    g.open(QIODevice::WriteOnly);
    g.write(R"({"unit": {"variant": "gve84"}, "axes": {"x": {"stepsPerMm": 100}}})");
    g.close();
    const CliRun ok = cli({file, QStringLiteral("--machine"), good});
    ASSERT_EQ(ok.code, 0) << ok.err.toStdString();
    EXPECT_TRUE(ok.out.contains(QStringLiteral("!0C1000,2000,-200"))) << ok.out.toStdString();
    const QString bad = dir.filePath(QStringLiteral("b.json"));
    QFile b(bad);
    b.open(QIODevice::WriteOnly);
    b.write(R"({"axes": {"x": {"stepsPerMm": 0}}})");
    b.close();
    const CliRun no = cli({file, QStringLiteral("--machine"), bad});
    EXPECT_EQ(no.code, 1);
    EXPECT_TRUE(no.out.isEmpty());
    EXPECT_TRUE(no.err.contains(QStringLiteral("axes.x.stepsPerMm: is 0, must be 1 .. 10000")));
    EXPECT_EQ(cli({}).code, 2);
}

// A feed above what the axes allow (the GVE64's X and Y run at most 4000 mm/min) is told once, in
// words, with the line of the first such feed, the feed asked for and the feed the machine runs,
// by check (with the machine) and by plan; the plan is written.
TEST(PlanCli, FeedAboveTheAxesIsToldOnceWithTheFiguresByCheckAndPlan)
{
    QTemporaryDir dir;
    const QString file =
        writeProgram(dir, "fast.nc", "G21 G90\nG0 X10 Y10 Z-1\nG1 X20 F12000\nG1 Y20\nM2\n");
    const QString warning =
        file + QStringLiteral(":3: warning: F12000 mm/min is above what the axes allow along "
                              "this move; the machine runs it at 4000 mm/min (X's maximum "
                              "speed of 4000 mm/min); 1 more line is capped the same way. "
                              "Lower the F word, or raise the axis maxima in the machine profile "
                              "if the machine can go faster\n");
    const CliRun plan = cli({file});
    EXPECT_EQ(plan.code, 0);
    EXPECT_EQ(plan.err, warning);
    EXPECT_TRUE(plan.out.contains(QStringLiteral("!0C2000,0,0")));
    const QString profile = QStringLiteral(FREZKA_SOURCE_DIR) + "/resources/machines/gve64.json";
    const CliRun check = cli({file, QStringLiteral("--machine"), profile}, QStringLiteral("check"));
    EXPECT_EQ(check.code, 0);
    EXPECT_EQ(check.err, warning);
    EXPECT_TRUE(check.out.contains(QStringLiteral(": OK, 5 lines")));
}
