// bench_gui_load: generates an N-line program (default 5 000 000), opens it in the main window
// and measures how long the GUI event loop is blocked at most while the program loads
// (a 5 ms timer records the largest gap between its ticks), and how long one frame of the
// toolpath view takes afterwards. Prints the figures; not run by ctest.
//   bench_gui_load [lines] [--gl]   (offscreen by default: QT_QPA_PLATFORM=offscreen)
#include "gui/mainwindow.h"
#include "gui/programview.h"
#include "gui/toolpathview.h"

#include <QApplication>
#include <QElapsedTimer>
#include <QFile>
#include <QTemporaryDir>
#include <QTimer>

#include <cmath>
#include <cstdio>

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
    {
        QFile f(path);
        if (!f.open(QIODevice::WriteOnly))
            return 1;
        QByteArray buf;
        buf.reserve(1 << 20);
        buf += "G21 G90 G94\nG0 X0 Y0 Z0\nG1 Z-1 F1500\n";
        // A spiral of short segments, like CAM output for a 3D surface.
        for (long i = 3; i < lines - 1; ++i) {
            const double t = double(i) * 0.002;
            const double r = 10 + double(i) * 120.0 / double(lines);
            buf += "G1 X" + QByteArray::number(200 + r * std::cos(t), 'f', 3) + " Y" +
                   QByteArray::number(150 + r * std::sin(t), 'f', 3) + "\n";
            if (buf.size() > (1 << 20) - 64) {
                f.write(buf);
                buf.clear();
            }
        }
        buf += "M30\n";
        f.write(buf);
    }
    std::printf("program: %ld lines, %.1f MB\n", lines, double(QFile(path).size()) / 1e6);

    frezka::gui::MainWindowOptions options;
    options.restoreLayout = false;
    frezka::gui::MainWindow window(options);
    window.show();

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
            QCoreApplication::quit();
        });
    });
    // Start once the window is up and idle, so start-up (GL initialisation) is not counted.
    QTimer::singleShot(1000, [&] {
        clock.start();
        sinceTick.start();
        ticker.start();
        window.openProgram(path);
    });
    return app.exec();
}
