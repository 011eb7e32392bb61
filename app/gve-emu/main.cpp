// gve-emu: an emulated GVE interpolator on a pseudo-terminal. See --help and docs/emulator.md.

#include "emuoptions.h"
#include "ptyserver.h"

#include "app/common/datadir.h"
#include "app/common/translator.h"

#include <QCoreApplication>
#include <QFile>
#include <QSocketNotifier>

#include <csignal>
#include <cstdio>
#include <unistd.h>

namespace {

int g_signalPipe[2] = {-1, -1};

void onSignal(int)
{
    const char c = 1;
    [[maybe_unused]] const auto n = ::write(g_signalPipe[1], &c, 1);
}

void printErr(const QString &text)
{
    std::fprintf(stderr, "gve-emu: %s\n", text.toLocal8Bit().constData());
}

} // namespace

int main(int argc, char **argv)
{
    QCoreApplication app(argc, argv);
    frezka::app::installTranslator();
    using namespace frezka::gveemu;
    if (app.arguments().contains(QStringLiteral("--version"))) {
        std::fputs(frezka::app::versionText(QStringLiteral("gve-emu")).toLocal8Bit().constData(),
                   stdout);
        return 0;
    }
    EmuOptions options;
    QString error;
    if (!parseEmuOptions(app.arguments().mid(1), options, error)) {
        printErr(error);
        return 2;
    }
    if (options.help) {
        std::fputs(emuHelpText().toLocal8Bit().constData(), stdout);
        return 0;
    }
    if (::pipe(g_signalPipe) != 0) {
        printErr(QCoreApplication::translate("gve-emu", "cannot create a pipe"));
        return 1;
    }
    struct sigaction sa
    {
    };
    sa.sa_handler = onSignal;
    sigemptyset(&sa.sa_mask);
    ::sigaction(SIGINT, &sa, nullptr);
    ::sigaction(SIGTERM, &sa, nullptr);
    QSocketNotifier signalNotifier(g_signalPipe[0], QSocketNotifier::Read);
    QObject::connect(&signalNotifier, &QSocketNotifier::activated, &app, &QCoreApplication::quit);

    PtyServer server(options);
    if (!options.replayFile.isEmpty()) {
        QFile file(options.replayFile);
        if (!file.open(QIODevice::ReadOnly)) {
            printErr(QCoreApplication::translate("gve-emu", "cannot read the trace %1: %2")
                         .arg(options.replayFile, file.errorString()));
            return 2;
        }
        const QByteArray text = file.readAll();
        frezka::emulator::SerialTrace trace;
        frezka::emulator::TraceMessage bad;
        if (!frezka::emulator::parseTrace(
                std::string_view(text.constData(), static_cast<std::size_t>(text.size())), trace,
                bad)) {
            QString why = QCoreApplication::translate("SerialTrace", bad.text);
            for (const std::string &arg : bad.args)
                why = why.arg(QString::fromStdString(arg));
            printErr(QStringLiteral("%1: %2").arg(options.replayFile, why));
            return 2;
        }
        server.setReplay(std::move(trace));
    }
    if (!server.open(error)) {
        printErr(error);
        return 1;
    }
    const auto eepromError = options.simulation.unit.eepromFile.empty()
                                 ? std::string()
                                 : frezka::emulator::Unit(options.simulation.unit).eepromError();
    if (!eepromError.empty()) {
        printErr(QString::fromStdString(eepromError));
        return 1;
    }
    if (!options.linkPath.isEmpty()) {
        QFile::remove(options.linkPath);
        if (!QFile::link(server.slavePath(), options.linkPath)) {
            printErr(QCoreApplication::translate("gve-emu", "cannot create the link %1")
                         .arg(options.linkPath));
            return 1;
        }
    }
    std::printf("%s\n", server.slavePath().toLocal8Bit().constData());
    std::fflush(stdout);
    // --wheel: the MPG handwheel from stdin, a line per turn; the end of stdin ends nothing.
    QSocketNotifier wheelNotifier(STDIN_FILENO, QSocketNotifier::Read);
    wheelNotifier.setEnabled(options.wheel);
    QByteArray wheelText;
    QObject::connect(&wheelNotifier, &QSocketNotifier::activated, &app, [&] {
        char buf[256];
        const ssize_t n = ::read(STDIN_FILENO, buf, sizeof buf);
        if (n <= 0) {
            wheelNotifier.setEnabled(false);
            return;
        }
        wheelText.append(buf, n);
        for (qsizetype nl; (nl = wheelText.indexOf('\n')) >= 0;) {
            const QString line = QString::fromLocal8Bit(wheelText.left(nl));
            wheelText.remove(0, nl + 1);
            WheelTurn turn;
            QString why;
            if (line.trimmed().isEmpty())
                continue;
            if (!parseWheelLine(line, turn, why))
                printErr(why);
            else if (!server.turnWheel(turn))
                printErr(QCoreApplication::translate(
                    "gve-emu", "the wheel does nothing: the MPG is off (Y-), not enabled in the "
                               "EEPROM (0x06 and its parameters) or an interrupt waits for G"));
        }
    });
    const int rc = app.exec();
    if (!options.linkPath.isEmpty())
        QFile::remove(options.linkPath);
    return rc;
}
