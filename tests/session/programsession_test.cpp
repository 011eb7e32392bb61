// The program session headless (issue 13 Deliver 2: load, check, plan and re-plan in the
// session layer, Qt Core only): a file loaded in its worker thread is checked, indexed and
// planned for the profile, with the front end's view built meanwhile; a file with errors and
// one beyond the soft limits are not runnable and say where; a reload after the work offsets
// changed plans the moved program; a profile never set means a check without a plan.
#include "session/programsession.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QFile>
#include <QTemporaryDir>
#include <QTimer>

#include <gtest/gtest.h>

namespace frezka::session {
namespace {

void ensureApplication()
{
    static int argc = 1;
    static char name[] = "programsession_test";
    static char *argv[] = {name, nullptr};
    static QCoreApplication *app =
        QCoreApplication::instance() ? nullptr : new QCoreApplication(argc, argv);
    (void)app;
}

struct CountedView : ProgramView
{
    std::size_t entries = 0;
};

struct Loader
{
    Loader()
    {
        ensureApplication();
        QObject::connect(&session, &ProgramSession::loaded, [this] { ++loads; });
        QObject::connect(&session, &ProgramSession::loadFailed,
                         [this](const QString &why) { failure = why; });
    }
    QString write(const char *name, const char *text)
    {
        const QString path = dir.filePath(QString::fromLatin1(name));
        QFile f(path);
        EXPECT_TRUE(f.open(QIODevice::WriteOnly));
        f.write(text);
        return path;
    }
    // Loads (or reloads) and waits for the result; false on a time-out or a failure.
    bool wait(const std::function<void()> &start)
    {
        const int before = loads;
        failure.clear();
        start();
        QEventLoop loop;
        QTimer guard;
        guard.setSingleShot(true);
        QObject::connect(&guard, &QTimer::timeout, &loop, &QEventLoop::quit);
        QObject::connect(&session, &ProgramSession::loaded, &loop, &QEventLoop::quit);
        QObject::connect(&session, &ProgramSession::loadFailed, &loop, &QEventLoop::quit);
        guard.start(20000);
        if (loads == before && failure.isEmpty())
            loop.exec();
        return loads > before;
    }
    QTemporaryDir dir;
    ProgramSession session;
    int loads = 0;
    QString failure;
};

const machine::MachineConfig kGve64 = machine::defaultMachineConfig(protocol::Variant::Gve64);

TEST(ProgramSession, LoadsChecksAndPlansInItsThread)
{
    Loader l;
    l.session.setProfile(kGve64);
    int viewsBuilt = 0;
    l.session.setViewBuilder([&viewsBuilt](const gcode::Toolpath &path,
                                           const std::function<void(double)> &progress,
                                           const std::atomic_bool *) {
        ++viewsBuilt;
        progress(1.0);
        auto view = std::make_shared<CountedView>();
        view->entries = path.size();
        return view;
    });
    const QString path =
        l.write("square.nc", "G21 G90\nG0 X10 Y10\nG1 X30 F600\nG1 Y30\nG1 X10\nG1 Y10\nM2\n");
    ASSERT_TRUE(l.wait([&] { l.session.load(path); })) << l.failure.toStdString();
    const LoadedProgram &p = l.session.program();
    EXPECT_EQ(p.path, path);
    ASSERT_TRUE(p.text);
    EXPECT_EQ(p.text->lineCount(), 7);
    EXPECT_TRUE(p.errors.empty());
    ASSERT_TRUE(p.runnable());
    EXPECT_GT(p.estimatedS, 0);
    EXPECT_NEAR(p.lengthMm, 80 + std::hypot(10.0, 10.0), 1e-6);
    EXPECT_NE(p.entryOfLine(4), gcode::Toolpath::kNone);
    EXPECT_FALSE(p.speed.empty());
    ASSERT_EQ(p.lineEndS.size(), 8u);
    EXPECT_NEAR(p.remainingS(7), 0, 1e-6);
    EXPECT_NEAR(p.remainingS(0), p.estimatedS, 1e-6);
    EXPECT_EQ(viewsBuilt, 1);
    const auto view = std::dynamic_pointer_cast<const CountedView>(p.view);
    ASSERT_TRUE(view);
    EXPECT_EQ(view->entries, p.toolpath->size());
}

TEST(ProgramSession, ErrorsAndLimitsMakeItNotRunnable)
{
    Loader l;
    l.session.setProfile(kGve64);
    ASSERT_TRUE(l.wait([&] { l.session.load(l.write("bad.nc", "G21\nG1 X10 Q\nM2\n")); }));
    ASSERT_EQ(l.session.program().errors.size(), 1u);
    EXPECT_EQ(l.session.program().errors[0].line, 2);
    EXPECT_TRUE(l.session.program().errors[0].text.startsWith(QStringLiteral("bad.nc:2:")));
    EXPECT_FALSE(l.session.program().runnable());
    ASSERT_TRUE(
        l.wait([&] { l.session.load(l.write("far.nc", "G21 G90\nG0 X10\nG1 X450 F1000\nM2\n")); }));
    EXPECT_TRUE(l.session.program().ok() == false);
    EXPECT_FALSE(l.session.program().runnable());
    ASSERT_FALSE(l.session.program().errors.empty());
    EXPECT_EQ(l.session.program().errors[0].line, 3);
    EXPECT_FALSE(l.wait([&] { l.session.load(l.dir.filePath(QStringLiteral("none.nc"))); }));
    EXPECT_TRUE(l.failure.contains(QStringLiteral("none.nc"))) << l.failure.toStdString();
}

TEST(ProgramSession, ReloadPlansWithTheOffsetsAndPositionOfNow)
{
    Loader l;
    l.session.setProfile(kGve64);
    const QString path = l.write("move.nc", "G21 G90\nG0 X10 Y0\nM2\n");
    ASSERT_TRUE(l.wait([&] { l.session.load(path); }));
    ASSERT_TRUE(l.session.program().runnable());
    EXPECT_EQ(l.session.program().toolpath->end(0).x, 10.0);
    OffsetState offsets;
    offsets.systems[0] = {100, 20, 0, 0}; // G54
    l.session.setWorkOffsets(offsets);
    l.session.setStartPosition({5, 5, 0, 0});
    ASSERT_TRUE(l.wait([&] { l.session.reload(); }));
    const LoadedProgram &p = l.session.program();
    ASSERT_TRUE(p.runnable());
    EXPECT_EQ(p.toolpath->origin(), (gcode::Point4{5, 5, 0, 0}));
    EXPECT_EQ(p.toolpath->end(0).x, 110.0);
    EXPECT_EQ(p.toolpath->end(0).y, 20.0);
    EXPECT_EQ(p.unitProgram->startSteps[0],
              std::llround(5 * kGve64.axes[0].stepsPerMm)); // planned from where it stands
}

// A height map (issue 19) bends the loaded program before its plan: the cut split to the grid
// and raised by the surface, every piece on the program's line; a cut outside the map is the
// load's error at its line; without the map the program is as written again.
TEST(ProgramSession, AHeightMapBendsTheProgramBeforeItsPlan)
{
    Loader l;
    l.session.setProfile(kGve64);
    gcode::HeightMap map(10, 10, 10, 10, 3, 2); // X 10..30, Y 10..20
    for (int i = 0; i < 3; ++i)
        for (int j = 0; j < 2; ++j)
            map.setZ(i, j, 0.1 * i); // rising 0.01 mm per mm in X
    l.session.setHeightMap(map);
    const QString path = l.write("cut.nc", "G21 G90\nG0 X10 Y15 Z-5\nG1 X30 F600\nM2\n");
    ASSERT_TRUE(l.wait([&] { l.session.load(path); }));
    const LoadedProgram &p = l.session.program();
    ASSERT_TRUE(p.runnable()) << (p.errors.empty() ? "" : p.errors[0].text.toStdString());
    EXPECT_EQ(p.toolpath->last(), (gcode::Point4{30, 15, -4.8, 0}));
    std::size_t cutPieces = 0;
    for (std::size_t i = 0; i < p.toolpath->size(); ++i) {
        if (p.toolpath->kind(i) != gcode::MotionKind::Feed)
            continue;
        ++cutPieces;
        EXPECT_EQ(p.toolpath->line(i), 3u);
        EXPECT_NEAR(p.toolpath->end(i).z, -5 + 0.01 * (p.toolpath->end(i).x - 10), 1e-9);
    }
    EXPECT_EQ(cutPieces, 2u); // split at the grid's 10 mm spacing
    EXPECT_EQ(p.unitProgram->commands.back().endSteps[2],
              std::llround(-4.8 * kGve64.axes[2].stepsPerMm));

    ASSERT_TRUE(l.wait([&] {
        l.session.load(l.write("wide.nc", "G21 G90\nG0 X10 Y15 Z-5\n"
                                          "G1 X40 F600\nM2\n"));
    }));
    ASSERT_FALSE(l.session.program().errors.empty());
    EXPECT_EQ(l.session.program().errors[0].line, 3);
    EXPECT_FALSE(l.session.program().runnable());

    l.session.setHeightMap(std::nullopt);
    ASSERT_TRUE(l.wait([&] { l.session.load(path); }));
    EXPECT_EQ(l.session.program().toolpath->last(), (gcode::Point4{30, 15, -5, 0}));
}

TEST(ProgramSession, WithoutAProfileItIsCheckedNotPlanned)
{
    Loader l;
    ASSERT_TRUE(l.wait([&] { l.session.load(l.write("p.nc", "G21\nG0 X1\nM2\n")); }));
    EXPECT_TRUE(l.session.program().ok());
    EXPECT_FALSE(l.session.program().runnable());
    EXPECT_LT(l.session.program().estimatedS, 0);
    EXPECT_FALSE(l.session.program().view); // no view builder, no view
}

// Issue 17 item 4: the profile's bound stops a program that never ends, with its loop's line.
TEST(ProgramSession, AnEndlessProgramStopsAtTheProfilesBoundWithItsLoopsLine)
{
    Loader l;
    machine::MachineConfig profile = kGve64;
    profile.program.maxMoves = 5000;
    l.session.setProfile(profile);
    ASSERT_TRUE(l.wait([&] {
        l.session.load(l.write("endless.nc", "G21 F100\no7 while [1]\nG1 X1\nG1 X0\n"
                                             "o7 endwhile\nM2\n"));
    }));
    const LoadedProgram &p = l.session.program();
    ASSERT_EQ(p.errors.size(), 1u);
    EXPECT_EQ(p.errors[0].line, 2);
    EXPECT_TRUE(p.errors[0].text.startsWith(
        QStringLiteral("endless.nc:2:1: o7 while has not ended after 5000 moves")))
        << p.errors[0].text.toStdString();
    EXPECT_FALSE(p.runnable());
}

// Cancel at any moment: the load stops at once (its thread is not waited for), the program
// loaded before stays, and the next load runs as usual.
TEST(ProgramSession, CancelKeepsTheProgramBeforeAndTheNextLoadRuns)
{
    Loader l;
    l.session.setProfile(kGve64);
    const QString before = l.write("before.nc", "G21 G90\nG0 X10\nM2\n");
    ASSERT_TRUE(l.wait([&] { l.session.load(before); }));
    QStringList cancelled;
    QObject::connect(&l.session, &ProgramSession::loadCancelled,
                     [&cancelled](const QString &path) { cancelled << path; });
    // Endless at the default bounds (ten million moves): still interpreting when cancelled.
    const QString endless =
        l.write("endless.nc", "G21 F100\no1 while [1]\nG1 X1\nG1 X0\no1 endwhile\nM2\n");
    const int loads = l.loads;
    l.session.load(endless);
    ASSERT_TRUE(l.session.isLoading());
    l.session.cancel();
    EXPECT_FALSE(l.session.isLoading());
    EXPECT_EQ(cancelled, QStringList{endless});
    l.session.cancel(); // nothing to cancel: no second signal
    EXPECT_EQ(cancelled.size(), 1);
    QCoreApplication::processEvents();
    EXPECT_EQ(l.loads, loads); // the cancelled load reports nothing
    EXPECT_EQ(l.session.program().path, before);
    EXPECT_TRUE(l.session.program().runnable());
    const QString next = l.write("next.nc", "G21 G90\nG0 X20\nM2\n");
    ASSERT_TRUE(l.wait([&] { l.session.load(next); }));
    EXPECT_EQ(l.session.program().path, next);
    EXPECT_EQ(cancelled.size(), 1); // a load replaced by another is not "cancelled"
}

} // namespace
} // namespace frezka::session
