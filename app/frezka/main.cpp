// frezka: the desktop application. Opens the operating window on the built-in emulator
// (or the port of the last profile); a program path on the command line is loaded at once.

#include "app/common/version.h"
#include "gui/language.h"
#include "gui/mainwindow.h"
#include "gui/programview.h"
#include "gui/settingsdialog.h"

#include "driver/link/machinecontroller.h"
#include "driver/link/tracerecorder.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QDockWidget>
#include <QSettings>
#include <QTimer>

#include <cstdio>
#include <functional>
#include <memory>

namespace {

// Screenshot of a running job: home once the unit is ready, run, shoot after ms of running.
void runForScreenshot(frezka::gui::MainWindow &window, int ms, const std::function<void()> &shoot)
{
    using frezka::driver::MachineMode;
    auto *timer = new QTimer(&window);
    auto step = std::make_shared<int>(0);
    QObject::connect(timer, &QTimer::timeout, &window, [&window, timer, step, ms, shoot] {
        const auto &st = window.machineState();
        if (*step == 0 && st.mode == MachineMode::Idle) {
            window.link()->home(0xF);
            *step = 1;
        } else if (*step == 1 && st.mode == MachineMode::Idle && st.homed) {
            window.runProgram();
            *step = 2;
        } else if (*step == 2 && st.mode == MachineMode::Running) {
            *step = 3;
            timer->stop();
            QTimer::singleShot(ms, &window, shoot);
        }
    });
    timer->start(100);
}

// --help and --version only print: they get a QCoreApplication, which needs no display (the
// package's smoke test and a terminal without X run them).
bool printsOnly(int argc, char **argv)
{
    for (int i = 1; i < argc; ++i) {
        const QByteArray arg(argv[i]);
        if (arg == "--help" || arg == "-h" || arg == "--help-all" || arg == "--version" ||
            arg == "-v")
            return true;
    }
    return false;
}

} // namespace

// The start-up sequence read top to bottom: language, options, window, emulator or port. Long
// as a script is; each step is a call, and splitting it would scatter the order that matters.
int main(int argc, char **argv)
{
    const std::unique_ptr<QCoreApplication> app(
        printsOnly(argc, argv) ? new QCoreApplication(argc, argv) : new QApplication(argc, argv));
    QApplication::setOrganizationName(QStringLiteral("Frezka"));
    QApplication::setApplicationName(QStringLiteral("frezka"));
    QApplication::setApplicationVersion(QString::fromUtf8(frezka::app::versionString()));
    frezka::driver::TraceRecorder::session().setProgramVersion(std::string("Frezka ") +
                                                               frezka::app::versionString());
    frezka::driver::TraceRecorder::session().setAlarmFolder(
        frezka::driver::TraceRecorder::defaultAlarmFolder());
    frezka::gui::applyLanguage(
        frezka::gui::effectiveLanguage(QSettings().value(QStringLiteral("language")).toString()));

    QCommandLineParser parser;
    parser.setApplicationDescription(
        QApplication::translate("main", "Frezka: runs CNC mills through GVE interpolators."));
    parser.addHelpOption();
    parser.addVersionOption();
    QCommandLineOption software(
        QStringLiteral("software-view"),
        QApplication::translate("main", "Draw the toolpath without OpenGL."));
    parser.addOption(software);
    QCommandLineOption language(QStringLiteral("language"),
                                QApplication::translate("main", "User interface language: cs or en "
                                                                "(default: the settings, else the "
                                                                "system language)."),
                                QStringLiteral("code"));
    parser.addOption(language);
    QCommandLineOption screenshot(
        QStringLiteral("screenshot"),
        QApplication::translate("main", "Save the window as PNG once the program has loaded, "
                                        "then quit (README screenshots)."),
        QStringLiteral("png"));
    parser.addOption(screenshot);
    QCommandLineOption screenshotRun(
        QStringLiteral("screenshot-running"),
        QApplication::translate("main", "With --screenshot: home, run the program and take the "
                                        "screenshot after this many seconds of running."),
        QStringLiteral("seconds"));
    parser.addOption(screenshotRun);
    QCommandLineOption screenshotDock(
        QStringLiteral("screenshot-dock"),
        QApplication::translate("main", "With --screenshot: show this dock in front of the others "
                                        "(its object name, such as unitsDock)."),
        QStringLiteral("name"));
    parser.addOption(screenshotDock);
    QCommandLineOption heightMap(
        QStringLiteral("height-map"),
        QApplication::translate("main", "Apply this height map file to the program (as Machine › "
                                        "Height map › Apply, the work zero left as it is)."),
        QStringLiteral("file"));
    parser.addOption(heightMap);
    QCommandLineOption clock(
        QStringLiteral("clock"),
        QApplication::translate("main", "real (default): the machine in real time; virtual: the "
                                        "built-in emulator on a virtual clock, as fast as the "
                                        "computer allows (a port is refused)."),
        QStringLiteral("real|virtual"));
    parser.addOption(clock);
    parser.addPositionalArgument(QStringLiteral("program"),
                                 QApplication::translate("main", "G-code program to open."));
    parser.process(*app);
    frezka::gui::applyLanguage(frezka::gui::effectiveLanguage(
        parser.isSet(language) ? parser.value(language)
                               : QSettings().value(QStringLiteral("language")).toString()));

    frezka::gui::MainWindowOptions options;
    if (parser.isSet(software))
        options.view = frezka::gui::MainWindowOptions::View::Software;
    if (parser.isSet(clock)) {
        const QString value = parser.value(clock);
        if (value == QLatin1String("virtual")) {
            options.clock = frezka::gui::MainWindowOptions::Clock::Virtual;
        } else if (value != QLatin1String("real")) {
            std::fprintf(stderr, "%s\n",
                         qPrintable(QApplication::translate(
                                        "main", "--clock takes real or virtual, not \"%1\".")
                                        .arg(value)));
            return 2;
        }
    }
    frezka::gui::MainWindow window(options);
    window.show();
    if (parser.isSet(heightMap)) {
        QString error;
        if (!window.applyHeightMapFile(parser.value(heightMap), &error)) {
            std::fprintf(stderr, "%s\n", qPrintable(error));
            return 2;
        }
    }
    if (parser.isSet(screenshot)) {
        const QString png = parser.value(screenshot);
        auto *dock = parser.isSet(screenshotDock)
                         ? window.findChild<QDockWidget *>(parser.value(screenshotDock))
                         : nullptr;
        if (dock) {
            dock->show();
            dock->raise();
        }
        auto shoot = [&window, png] {
            // Let the docks settle and the view paint once more before grabbing.
            QTimer::singleShot(700, &window, [&window, png] {
                const bool ok = window.grab().save(png);
                QCoreApplication::exit(ok ? 0 : 1);
            });
        };
        if (parser.positionalArguments().isEmpty()) {
            shoot();
        } else if (parser.isSet(screenshotRun)) {
            const int ms = int(parser.value(screenshotRun).toDouble() * 1000);
            QObject::connect(
                window.program(), &frezka::gui::ProgramSession::loaded, &window,
                [&window, ms, shoot] { runForScreenshot(window, ms, shoot); },
                Qt::SingleShotConnection);
        } else {
            QObject::connect(window.program(), &frezka::gui::ProgramSession::loaded, &window,
                             shoot);
        }
    }
    if (!parser.positionalArguments().isEmpty())
        window.openProgram(parser.positionalArguments().constFirst());
    return QCoreApplication::exec();
}
