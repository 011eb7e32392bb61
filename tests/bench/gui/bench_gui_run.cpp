// bench_gui_run: a job of N lines (default 5 000 000: the spiral of bench_gui_load) run from the
// main window on the built-in emulator on a virtual clock (frezka --clock virtual, issue 17
// item 3): homes, opens the program, runs it, and prints the job's time (virtual) against the
// planner's estimate, the wall time of the load and of the run, the peak resident memory
// (getrusage), the largest stall of the event loop while the job ran (a 5 ms timer records the
// largest gap between its ticks) and the longest slice of the clock, and the emulator's
// account (counters at the program's end, vectors, brake violations, starvation stops). Not run
// by ctest.
//   bench_gui_run [lines]   (offscreen by default: QT_QPA_PLATFORM=offscreen)
#include "../../gui/spiralprogram.h"

#include "gui/jogpanel.h"
#include "gui/mainwindow.h"
#include "gui/programview.h"

#include "session/virtualclocklink.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QPushButton>
#include <QTemporaryDir>
#include <QTimer>

#include <sys/resource.h>

#include <cstdio>

namespace {

double peakRssMb()
{
    rusage u{};
    getrusage(RUSAGE_SELF, &u);
    return double(u.ru_maxrss) / 1024.0;
}

std::int64_t motionCommands(const frezka::machine::UnitProgram &p)
{
    std::int64_t n = 0;
    for (const frezka::machine::UnitCommand &c : p.commands)
        n += c.op == frezka::machine::UnitOp::Vector || c.op == frezka::machine::UnitOp::Line ||
             c.op == frezka::machine::UnitOp::Probe;
    return n;
}

} // namespace

int main(int argc, char **argv)
{
    using frezka::driver::MachineMode;
    if (qEnvironmentVariableIsEmpty("QT_QPA_PLATFORM"))
        qputenv("QT_QPA_PLATFORM", "offscreen");
    QApplication app(argc, argv);
    QCoreApplication::setOrganizationName(QStringLiteral("FrezkaBenchRun"));
    const long lines = argc > 1 ? std::atol(argv[1]) : 5'000'000;

    QTemporaryDir dir;
    const QString path = dir.filePath(QStringLiteral("spiral.nc"));
    if (!frezka::gui::test::writeSpiral(path, lines))
        return 1;
    std::printf("program: %ld lines, %.1f MB\n", lines, double(QFile(path).size()) / 1e6);

    frezka::gui::MainWindowOptions options;
    options.restoreLayout = false;
    options.view = frezka::gui::MainWindowOptions::View::Software;
    options.clock = frezka::gui::MainWindowOptions::Clock::Virtual;
    frezka::gui::MainWindow window(options);
    window.show();
    frezka::session::VirtualClockLink *clock = window.virtualClock();

    QElapsedTimer wall, sinceTick;
    qint64 maxGapMs = 0;
    double maxGapEndS = 0; // when the largest stall ended: wall seconds into the run
    QTimer ticker;
    ticker.setInterval(5);
    QObject::connect(&ticker, &QTimer::timeout, [&] {
        const qint64 gap = sinceTick.restart();
        if (gap > maxGapMs) {
            maxGapMs = gap;
            maxGapEndS = wall.elapsed() / 1000.0;
        }
    });
    frezka::emulator::Stats before;
    std::shared_ptr<const frezka::machine::UnitProgram> plan;
    double estimateS = -1, loadS = 0;
    int step = 0;
    QTimer driver; // the operator: home, open, run, once each step is done
    driver.setInterval(50);
    QObject::connect(&driver, &QTimer::timeout, [&] {
        const auto &st = window.machineState();
        if (step == 0 && st.mode == MachineMode::Idle) {
            window.jogPanel()->findChild<QPushButton *>(QStringLiteral("homeAll"))->click();
            step = 1;
        } else if (step == 1 && st.homed && st.mode == MachineMode::Idle) {
            step = 2;
            wall.start();
            window.openProgram(path);
        }
    });
    QObject::connect(window.program(), &frezka::gui::ProgramSession::loaded, [&] {
        if (step != 2 || !window.program()->program().runnable())
            return;
        step = 3;
        loadS = wall.elapsed() / 1000.0;
        before = clock->sim()->port().unit().stats();
        wall.start();
        sinceTick.start();
        ticker.start();
        window.runProgram();
    });
    QObject::connect(window.workflow(), &frezka::session::RunWorkflow::jobStarted, [&] {
        plan = window.program()->program().unitProgram;
        estimateS = window.program()->program().estimatedS;
    });
    QObject::connect(window.workflow(), &frezka::session::RunWorkflow::jobFinished, [&](bool ok) {
        const double runS = wall.elapsed() / 1000.0;
        ticker.stop();
        const double jobS = window.workflow()->jobElapsedS();
        const auto &unit = clock->sim()->port().unit();
        const frezka::emulator::Stats after = unit.stats();
        std::printf("job %s: %.3f s (virtual), estimate %.3f s (%+.4f %%)\n",
                    ok ? "ended" : "FAILED", jobS, estimateS,
                    estimateS > 0 ? 100.0 * (jobS - estimateS) / estimateS : 0.0);
        std::printf("wall: load+plan %.1f s, run %.1f s\n", loadS, runS);
        std::printf("peak RSS %.0f MB\n", peakRssMb());
        std::printf("largest event-loop stall while running: %lld ms, ending %.1f s into the "
                    "run (longest clock slice %lld ms)\n",
                    static_cast<long long>(maxGapMs), maxGapEndS,
                    static_cast<long long>(clock->longestSliceMs()));
        if (plan) {
            std::printf("vectors run %lld of %lld; counters %s the program's end\n",
                        static_cast<long long>(after.motion.vectorsExecuted -
                                               before.motion.vectorsExecuted),
                        static_cast<long long>(motionCommands(*plan)),
                        unit.position() == plan->commands.back().endSteps ? "at" : "NOT at");
            std::printf("brake violations %lld, starvation stops %lld (planned restarts %lld)\n",
                        static_cast<long long>(after.motion.brakeViolations -
                                               before.motion.brakeViolations),
                        static_cast<long long>(after.motion.starvationStops -
                                               before.motion.starvationStops),
                        static_cast<long long>(frezka::machine::plannedRestarts(*plan)));
        }
        QCoreApplication::exit(ok ? 0 : 1);
    });
    driver.start();
    return app.exec();
}
