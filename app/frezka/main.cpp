// frezka: the desktop application. Opens the operating window on the built-in emulator
// (or the port of the last profile); a program path on the command line is loaded at once.

#include "gui/language.h"
#include "gui/mainwindow.h"
#include "gui/programsession.h"

#include <QApplication>
#include <QCommandLineParser>
#include <QSettings>
#include <QTimer>

int main(int argc, char **argv)
{
    QApplication app(argc, argv);
    QApplication::setOrganizationName(QStringLiteral("Frezka"));
    QApplication::setApplicationName(QStringLiteral("frezka"));
    QApplication::setApplicationVersion(QStringLiteral(FREZKA_VERSION));
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
    parser.addPositionalArgument(QStringLiteral("program"),
                                 QApplication::translate("main", "G-code program to open."));
    parser.process(app);
    frezka::gui::applyLanguage(frezka::gui::effectiveLanguage(
        parser.isSet(language) ? parser.value(language)
                               : QSettings().value(QStringLiteral("language")).toString()));

    frezka::gui::MainWindowOptions options;
    if (parser.isSet(software))
        options.view = frezka::gui::MainWindowOptions::View::Software;
    frezka::gui::MainWindow window(options);
    window.show();
    if (parser.isSet(screenshot)) {
        const QString png = parser.value(screenshot);
        auto shoot = [&window, png] {
            // Let the docks settle and the view paint once more before grabbing.
            QTimer::singleShot(700, &window, [&window, png] {
                const bool ok = window.grab().save(png);
                QCoreApplication::exit(ok ? 0 : 1);
            });
        };
        if (parser.positionalArguments().isEmpty())
            shoot();
        else
            QObject::connect(window.program(), &frezka::gui::ProgramSession::loaded, &window,
                             shoot);
    }
    if (!parser.positionalArguments().isEmpty())
        window.openProgram(parser.positionalArguments().constFirst());
    return app.exec();
}
