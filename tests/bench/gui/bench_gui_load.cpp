// bench_gui_load: generates an N-line program (default 5 000 000), opens it in the main window
// and measures how long the GUI event loop is blocked at most while the program loads
// (a 5 ms timer records the largest gap between its ticks), and how long one frame of the
// toolpath view takes afterwards. Prints the figures, and the loader's stages (issue 17 item 1:
// seconds, resident memory at the end and peak memory of each, from the program session's own
// account); not run by ctest.
//   bench_gui_load [lines] [--gl]   (offscreen by default: QT_QPA_PLATFORM=offscreen)
//   BENCH_PLAN_ONCE=1: also plans the toolpath once without the link's pace, for the re-plans'
//   share of the plan stage.
#include "../../gui/spiralprogram.h"

#include "gui/mainwindow.h"
#include "gui/programview.h"
#include "gui/toolpathview.h"

#include "machine/planner.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTimer>

#include <cmath>
#include <cstdio>

namespace {

// The loader's stages, then the window's part (from the last stage to the loaded signal's
// handlers, on the GUI thread) and the whole load's peak.
void printStages(const frezka::gui::LoadedProgram &p, double loadS, double windowPeakMb,
                 double startMb)
{
    std::printf("%-28s %9s %12s %9s\n", "stage", "seconds", "RSS end MB", "peak MB");
    double threadS = 0, peakMb = windowPeakMb;
    for (const frezka::session::LoadStage &s : p.stages) {
        std::printf("%-28s %9.3f %12.0f %9.0f\n", s.name.c_str(), s.seconds, s.residentMb,
                    s.peakMb);
        threadS += s.seconds;
        peakMb = std::max(peakMb, s.peakMb);
    }
    std::printf("%-28s %9.3f %12.0f %9.0f\n", "window takes it (GUI)", loadS - threadS,
                frezka::session::residentMb(), windowPeakMb);
    std::printf("resident before the load: %.0f MB, peak during it: %.0f MB\n", startMb, peakMb);
}

// The plan's share of the link's pace: the same toolpath planned once without it (no re-plans
// with the B, V, A commands' wire time; docs/planner.md §4).
void printPlanOnce(const frezka::gui::LoadedProgram &p, const frezka::machine::MachineConfig &c)
{
    if (!p.toolpath)
        return;
    frezka::machine::PlanOptions once;
    once.wireLimited = false;
    QElapsedTimer t;
    t.start();
    const frezka::machine::PlanResult r = frezka::machine::plan(*p.toolpath, c, once);
    std::printf("plan without the link's pace (one pass): %.3f s, %zu vectors\n",
                double(t.nsecsElapsed()) / 1e9, r.stats.vectors);
}

} // namespace

// Reports every event whose handling takes longer than 50 ms (BENCH_VERBOSE=1).
class TimingApplication : public QApplication
{
public:
    using QApplication::QApplication;
    bool notify(QObject *receiver, QEvent *event) override
    {
        if (!m_verbose)
            return QApplication::notify(receiver, event);
        QElapsedTimer t;
        t.start();
        const int type = event->type();
        const char *cls = receiver->metaObject()->className(); // receiver may die in notify
        const QString name = receiver->objectName();
        const bool r = QApplication::notify(receiver, event);
        const qint64 ms = t.elapsed();
        if (ms > 50)
            std::printf("  event %d to %s (%s) took %lld ms\n", type, cls, qPrintable(name),
                        static_cast<long long>(ms));
        return r;
    }

private:
    bool m_verbose = qEnvironmentVariableIsSet("BENCH_VERBOSE");
};

int main(int argc, char **argv)
{
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    TimingApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("FrezkaBench"));
    const long lines = argc > 1 ? std::atol(argv[1]) : 5'000'000;

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("big.nc"));
    if (!frezka::gui::test::writeSpiral(path, lines)) // a spiral of short segments, like CAM output
        return 1;
    std::printf("program: %ld lines, %.1f MB\n", lines, double(QFile(path).size()) / 1e6);

    frezka::gui::MainWindowOptions options;
    options.restoreLayout = false;
    frezka::gui::MainWindow window(options);
    window.program()->setMeasurePeaks(true);
    window.show();
    double startMb = 0;

    QElapsedTimer clock, sinceTick;
    qint64 maxGapMs = 0;
    QTimer ticker;
    ticker.setInterval(5);
    QObject::connect(&ticker, &QTimer::timeout, [&] {
        const qint64 gap = sinceTick.restart();
        if (gap > 100 && qEnvironmentVariableIsSet("BENCH_VERBOSE"))
            std::printf("  stall of %lld ms ending at %.2f s\n", static_cast<long long>(gap),
                        clock.elapsed() / 1000.0);
        maxGapMs = std::max(maxGapMs, gap);
    });
    QObject::connect(window.program(), &frezka::gui::ProgramSession::loaded, [&] {
        const double loadS = clock.elapsed() / 1000.0;
        const double windowPeakMb = frezka::session::peakResidentMb(); // since the last stage
        printStages(window.program()->program(), loadS, windowPeakMb, startMb);
        // Let the view paint the new scene once while the ticker still runs.
        QTimer::singleShot(300, [&, loadS] {
            ticker.stop();
            QElapsedTimer frame;
            frame.start();
            const QImage img = window.toolpathView()->grabFrame();
            const double frameMs = double(frame.nsecsElapsed()) / 1e6;
            const auto &p = window.program()->program();
            std::printf("load+interpret+plan: %.2f s (errors: %zu)\n", loadS, p.errors.size());
            const auto scene = frezka::gui::sceneOf(p);
            std::printf("scene segments drawn: %zu of %zu toolpath entries (%s view)\n",
                        scene ? scene->segments.size() : 0, scene ? scene->sourceEntries : 0,
                        window.toolpathView()->usesOpenGl() ? "OpenGL" : "software");
            std::printf("largest event-loop stall while loading: %lld ms\n",
                        static_cast<long long>(maxGapMs));
            std::printf("one full frame of the toolpath view: %.1f ms (%dx%d)\n", frameMs,
                        img.width(), img.height());
            if (qEnvironmentVariableIsSet("BENCH_PLAN_ONCE")) // after the stall was measured
                printPlanOnce(window.program()->program(), window.profile());
            QCoreApplication::quit();
        });
    });
    // Start once the window is up and idle, so start-up (GL initialisation) is not counted.
    QTimer::singleShot(1000, [&] {
        startMb = frezka::session::residentMb();
        clock.start();
        sinceTick.start();
        ticker.start();
        window.openProgram(path);
    });
    return app.exec();
}
