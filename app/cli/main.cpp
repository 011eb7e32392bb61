// frezka-cli: the headless front end (check, toolpath, plan, run, grinder, ...).
#include "cli.h"

#include "app/common/datadir.h"
#include "app/common/translator.h"
#include "app/common/version.h"
#include "driver/link/tracerecorder.h"

#include <QCoreApplication>

using namespace frezka::cli;

namespace {

// A command's summary (marked with QT_TRANSLATE_NOOP where it registers) in the user's language.
QString translated(const char *text)
{
    return QCoreApplication::translate("frezka::cli", text);
}

// The exit codes, the same for every command.
QString exitCodes()
{
    return QCoreApplication::translate(
        "frezka::cli",
        "exit codes:\n"
        "  0  done: the program is good (check), planned (plan), ran to its end (run)\n"
        "  1  an error in the input or on the machine: a G-code error, a line beyond the "
        "machine's travel, a bad profile, a job that did not finish (on stderr, with the "
        "line)\n"
        "  2  bad usage: an unknown command or option, a malformed value\n");
}

// The overview (frezka-cli --help): every command with its options and the exit codes.
QString usageText()
{
    QString text = QCoreApplication::translate(
        "frezka::cli", "usage: frezka-cli COMMAND [ARGS...]\n\ncommands:\n");
    for (const auto &[name, command] : commands()) {
        text +=
            QStringLiteral("  %1\n      %2\n")
                .arg(QString::fromStdString(command.usage), translated(command.summary.c_str()));
    }
    text += QCoreApplication::translate(
        "frezka::cli",
        "\nwork offsets: --offset G54:X,Y,Z sets where the program's zero is on the "
        "machine (machine mm; G54 .. G59.3, repeatable); --work-zero X,Y,Z is --offset "
        "G54:X,Y,Z.\n"
        "operator stops: at M0, M1 and M6 frezka-cli run waits for Enter; "
        "--continue-at-stops runs on without an operator.\n"
        "run from a line: frezka-cli run --from-line N starts the job at line N with the "
        "program's state there (tool, spindle, coolant, feed, modes, offsets), after a safe "
        "approach (spindle on, Z up to the safe height, X/Y across, Z down at the feed).\n\n");
    text += QCoreApplication::translate("frezka::cli",
                                        "--version prints the version and the data folder "
                                        "(shipped machine profiles and sample programs).\n\n");
    return text + exitCodes();
}

// "frezka-cli COMMAND --help": its usage and what it does.
QString commandHelp(const std::string &name, const Command &command)
{
    return QStringLiteral("usage: frezka-cli %1\n%2\n\n")
               .arg(QString::fromStdString(command.usage), translated(command.summary.c_str())) +
           (name == "grinder" ? QString() : exitCodes());
}

bool isHelp(const QString &arg)
{
    return arg == QLatin1String("--help") || arg == QLatin1String("-h");
}

} // namespace

int main(int argc, char *argv[])
{
    QCoreApplication app(argc, argv);
    QCoreApplication::setApplicationName(QStringLiteral("frezka-cli"));
    QCoreApplication::setOrganizationName(QStringLiteral("Frezka"));
    frezka::app::installTranslator();
    frezka::driver::TraceRecorder::session().setProgramVersion(std::string("Frezka ") +
                                                               frezka::app::versionString());
    frezka::driver::TraceRecorder::session().setAlarmFolder(
        frezka::driver::TraceRecorder::defaultAlarmFolder());
    QStringList args = app.arguments().mid(1);
    if (args.isEmpty()) {
        err(usageText());
        return 2;
    }
    if (isHelp(args.first()) || args.first() == QLatin1String("help")) {
        out(usageText());
        return 0;
    }
    if (args.first() == QLatin1String("--version")) {
        out(frezka::app::versionText(QStringLiteral("frezka-cli")));
        return 0;
    }
    const std::string name = args.takeFirst().toStdString();
    const auto it = commands().find(name);
    if (it == commands().end()) {
        err(QCoreApplication::translate("frezka::cli", "frezka-cli: unknown command '%1'\n")
                .arg(QString::fromStdString(name)));
        err(usageText());
        return 2;
    }
    if (args.size() == 1 && isHelp(args.first())) {
        out(commandHelp(name, it->second));
        return 0;
    }
    return it->second.run(args);
}
