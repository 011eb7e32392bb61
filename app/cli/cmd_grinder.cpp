// frezka-cli grinder: program/table transfer and Z-position link with ANC/K51 grinding
// controls (issue 7). See docs/grinder.md.
#include "cli.h"

#include "driver/grinder/controllerheader.h"
#include "driver/grinder/grinderfile.h"
#include "driver/grinder/transfersession.h"
#include "driver/grinder/zlinksession.h"

#include <QCoreApplication>
#include <QEventLoop>
#include <QFile>
#include <QFileInfo>
#include <QSaveFile>

#include <cstdio>
#include <unistd.h>

using namespace frezka::grinder;
using frezka::cli::err;
using frezka::cli::out;

namespace {

struct GrinderCli
{
    Q_DECLARE_TR_FUNCTIONS(GrinderCli)
};

struct Args
{
    QString action; // ping, save, load, z
    QString file;
    SerialSettings serial;
    bool hasBaud = false; // without --baud: the family's rate (ANC 4800, K51/HEDIT 9600)
    Family family = Family::K51;
    QString header;
    bool hasHeader = false;
    int retries = 3;
    int replyTimeoutMs = 0; // 0: the session defaults
    int form = 1;
    bool hasGo = false;
    std::int64_t goUm = 0;
    bool sendAnyway = false;
    bool raw = false; // save: bare data as the old tools wrote
};

QString usage()
{
    return GrinderCli::tr(
        "usage: frezka-cli grinder ping|save|load --port PATH [--family k51|anc|hedit|table]\n"
        "                          [--baud N] [--header TEXT] [--retries N]\n"
        "                          [--reply-timeout-ms N] [--send-anyway] [--raw] FILE\n"
        "       frezka-cli grinder z --port PATH [--baud N] [--form 1|2] [--go MM]\n"
        "                          [--reply-timeout-ms N]\n"
        "  ping   link check (ENQ/ACK)\n"
        "  save   controller -> PC: write the controller's data to FILE, byte for byte, with\n"
        "         its header and system (a FILE ending in .bin, or --raw: the bare data, as\n"
        "         the old tools wrote)\n"
        "  load   PC -> controller: send FILE unchanged; the 16-character header is --header\n"
        "         or the one saved in FILE or, as K51LOAD 2.20 did, the file name (Czech\n"
        "         letters become their base letters); the file's length and inner blocks\n"
        "         are checked first and nothing is sent when they are wrong\n"
        "         --family table sends an APROXTAB table (LOA1) to a K51 set to table\n"
        "         transfer (KONFIG6 = 3); a table cannot be saved\n"
        "  z      Z-position link: print the table position (FORM=1 asks with Z?, FORM=2\n"
        "         waits for a binary frame); --go MM moves the table and waits until reached\n"
        "  --baud N               line rate (default: ANC 4800 Bd, as ANCLOAD/ANCSAVE; K51 and\n"
        "                         HEDIT 9600 Bd)\n"
        "  --retries N            repeats after a timeout, NAK or bad checksum (default 3)\n"
        "  --reply-timeout-ms N   silence allowed before a reply (default 3000; 10000 for\n"
        "                         the data after a request)\n"
        "  --send-anyway          load a file whose inner blocks have a wrong checksum (only\n"
        "                         if the controller itself gave it to you)\n"
        "  --go MM                -9999.999 to 9999.999 mm\n"
        "  --help                 this text\n"
        "Exit status: 0 done, 1 transfer failed (the reason is printed), 2 usage error.\n");
}

QString checkHeader(const QString &header)
{
    if (header.size() > int(kHeaderSize))
        return GrinderCli::tr("--header: '%1' is longer than 16 characters").arg(header);
    return ControllerHeader::fromText(header).error;
}

// One option with its value; returns the reason when it is unknown or the value is bad.
QString parseOption(const QString &option, const QString &value, Args &args)
{
    bool ok = true;
    if (option == "--port") {
        args.serial.portName = value;
    } else if (option == "--family") {
        const auto family = familyFromId(value.toStdString());
        if (!family)
            return GrinderCli::tr("--family: '%1' is not k51, anc, hedit or table").arg(value);
        args.family = *family;
    } else if (option == "--baud") {
        args.serial.baud = value.toInt(&ok);
        args.hasBaud = true;
        if (!ok || args.serial.baud <= 0)
            return GrinderCli::tr("--baud: '%1' is not a baud rate").arg(value);
    } else if (option == "--header") {
        args.header = value;
        args.hasHeader = true;
        return checkHeader(value);
    } else if (option == "--retries") {
        args.retries = value.toInt(&ok);
        if (!ok || args.retries < 0 || args.retries > 100)
            return GrinderCli::tr("--retries: '%1' is not 0 to 100").arg(value);
    } else if (option == "--reply-timeout-ms") {
        args.replyTimeoutMs = value.toInt(&ok);
        if (!ok || args.replyTimeoutMs < 100 || args.replyTimeoutMs > 600000)
            return GrinderCli::tr("--reply-timeout-ms: '%1' is not 100 to 600000").arg(value);
    } else if (option == "--form") {
        args.form = value.toInt(&ok);
        if (!ok || (args.form != 1 && args.form != 2))
            return GrinderCli::tr("--form: '%1' is not 1 or 2").arg(value);
    } else if (option == "--go") {
        const auto um = parseMillimetres(value.toStdString());
        if (!um || *um > kMaxGoUm || *um < -kMaxGoUm)
            return GrinderCli::tr("--go: '%1' is not a position from -9999.999 to 9999.999 mm "
                                  "(e.g. 12.5)")
                .arg(value);
        args.hasGo = true;
        args.goUm = *um;
    } else {
        return GrinderCli::tr("unknown option '%1'").arg(option);
    }
    return QString();
}

// Returns 0 when parsed, -1 after --help, else the exit code (2) after printing the reason.
int parseArgs(const QStringList &list, Args &args)
{
    auto fail = [](const QString &reason) {
        err(QStringLiteral("frezka-cli grinder: %1\n").arg(reason));
        return 2;
    };
    if (list.contains(QLatin1String("--help")) || list.contains(QLatin1String("-h"))) {
        out(usage());
        return -1; // done: exit 0
    }
    args.action = list.value(0);
    if (args.action != "ping" && args.action != "save" && args.action != "load" &&
        args.action != "z") {
        if (!args.action.isEmpty())
            err(GrinderCli::tr("frezka-cli grinder: unknown action '%1'\n").arg(args.action));
        err(usage());
        return 2;
    }
    for (int i = 1; i < list.size(); ++i) {
        const QString &arg = list[i];
        if (arg == QLatin1String("--send-anyway") || arg == QLatin1String("--raw")) {
            (arg == QLatin1String("--raw") ? args.raw : args.sendAnyway) = true;
            continue;
        }
        if (!arg.startsWith("--")) {
            if (!args.file.isEmpty())
                return fail(GrinderCli::tr("unexpected argument '%1'").arg(arg));
            args.file = arg;
            continue;
        }
        if (i + 1 >= list.size())
            return fail(GrinderCli::tr("%1 needs a value").arg(arg));
        const QString reason = parseOption(arg, list[++i], args);
        if (!reason.isEmpty())
            return fail(reason);
    }
    if (args.serial.portName.isEmpty())
        return fail(GrinderCli::tr("--port PATH is required"));
    if (!args.hasBaud)
        args.serial.baud = familyInfo(args.family).defaultBaud;
    if ((args.action == "save" || args.action == "load") && args.file.isEmpty())
        return fail(GrinderCli::tr("%1 needs a FILE").arg(args.action));
    if (args.hasHeader && args.family == Family::Anc)
        return fail(GrinderCli::tr("--header: ANC messages carry no header (ANCLOAD sent none); "
                                   "leave it out or choose --family k51 or hedit"));
    return 0;
}

QString formatSeconds(double seconds)
{
    const int s = int(seconds + 0.5);
    return s >= 60 ? QStringLiteral("%1:%2").arg(s / 60).arg(s % 60, 2, 10, QLatin1Char('0'))
                   : GrinderCli::tr("%1 s").arg(s);
}

// "[#########...........]  9876/21789 B  45%  12 s left" on a terminal; nothing otherwise.
class ProgressBar
{
public:
    ProgressBar(Clock &clock, int baud)
        : m_clock(clock)
        , m_baud(baud)
        , m_tty(::isatty(STDERR_FILENO) == 1)
        , m_startUs(clock.nowUs())
    {}
    void update(qint64 done, qint64 total)
    {
        if (!m_tty || total <= 0)
            return;
        const std::int64_t now = m_clock.nowUs();
        if (done < total && m_drawn && now - m_lastDrawUs < 100000)
            return; // ten redraws a second are plenty
        m_lastDrawUs = now;
        const int width = 30;
        const int filled = int(width * done / total);
        const double left = estimateSecondsLeft(done, total, m_clock.nowUs() - m_startUs, m_baud);
        err(QStringLiteral("\r[%1%2] %3/%4 B %5%  %6   ")
                .arg(QString(filled, QLatin1Char('#')), QString(width - filled, QLatin1Char('.')))
                .arg(done, 6)
                .arg(total)
                .arg(100 * done / total, 3)
                .arg(GrinderCli::tr("%1 left").arg(formatSeconds(left))));
        m_drawn = true;
    }
    void end()
    {
        if (m_drawn)
            err(QStringLiteral("\n"));
        m_drawn = false;
    }

private:
    Clock &m_clock;
    int m_baud;
    bool m_tty;
    std::int64_t m_startUs;
    bool m_drawn = false;
    std::int64_t m_lastDrawUs = 0;
};

int report(const TransferResult &result)
{
    if (!result.ok()) {
        err(GrinderCli::tr("frezka-cli grinder: %1 failed (%2): %3\n")
                .arg(result.operation == Operation::Ping   ? QStringLiteral("ping")
                     : result.operation == Operation::Save ? QStringLiteral("save")
                                                           : QStringLiteral("load"),
                     QString::fromLatin1(transferErrorId(result.error)), result.message));
        return 1;
    }
    out(result.message + QLatin1Char('\n'));
    if (result.retries > 0 || result.noiseBytes > 0)
        out(GrinderCli::tr("Repeats: %1 (NAK %2, bad checksum %3), noise bytes skipped: %4\n")
                .arg(result.retries)
                .arg(result.naks)
                .arg(result.checksumFailures)
                .arg(result.noiseBytes));
    if (result.operation != Operation::Ping && result.image.hasBlocks)
        out(GrinderCli::tr("Inner blocks: %1\n").arg(TransferSession::describeImage(result.image)));
    return 0;
}

// Writes atomically into the opened `file`: a failed write leaves no half file behind.
bool writeFile(QSaveFile &file, const QByteArray &data)
{
    if (file.write(data) == data.size() && file.commit())
        return true;
    err(GrinderCli::tr("frezka-cli grinder: cannot write %1: %2 (the data were received but not "
                       "saved)\n")
            .arg(file.fileName(), file.errorString()));
    return false;
}

// Reads FILE for a load (a Frezka grinder file or bare data) and picks the header: --header,
// else the one saved in the file, else the file name (K51LOAD 2.20). Returns an exit code.
int readLoadFile(const Args &args, QByteArray &data, Header &header)
{
    QFile file(args.file);
    if (!file.open(QIODevice::ReadOnly)) {
        err(GrinderCli::tr("frezka-cli grinder: cannot read %1: %2\n")
                .arg(args.file, file.errorString()));
        return 1;
    }
    const QByteArray bytes = file.readAll();
    std::string why;
    const auto decoded = decodeGrinderFile(Bytes(bytes.begin(), bytes.end()), why);
    if (!decoded) {
        err(GrinderCli::tr("frezka-cli grinder: %1 is damaged: %2; nothing was sent\n")
                .arg(args.file, QString::fromStdString(why)));
        return 1;
    }
    if (decoded->container && decoded->family != args.family) {
        err(GrinderCli::tr("frezka-cli grinder: %1 holds %2 data (saved from a %2 control), "
                           "not %3: is the wrong system selected? Use --family %4.\n")
                .arg(args.file, familyName(decoded->family), familyName(args.family),
                     QString::fromLatin1(familyInfo(decoded->family).id)));
        return 1;
    }
    data = QByteArray(reinterpret_cast<const char *>(decoded->data.data()),
                      qsizetype(decoded->data.size()));
    if (args.family == Family::Anc) {
        header = Header{};
        return 0;
    }
    if (decoded->container && !args.hasHeader) {
        header = decoded->header;
        return 0;
    }
    const QString typed =
        args.hasHeader ? args.header : QFileInfo(args.file).completeBaseName().left(16);
    const ControllerHeader mapped = ControllerHeader::fromText(typed);
    if (!mapped.ok()) {
        err(QStringLiteral("frezka-cli grinder: %1\n").arg(mapped.error));
        return args.hasHeader ? 2 : 1;
    }
    if (mapped.mapped)
        out(ControllerHeader::mappingNote(typed, mapped) + QLatin1Char('\n'));
    header = mapped.header();
    return 0;
}

// What a save writes: the Frezka grinder file, or the bare data for a .bin name or --raw.
QByteArray savedBytes(const Args &args, const TransferResult &result)
{
    if (args.raw || args.file.endsWith(QLatin1String(".bin"), Qt::CaseInsensitive))
        return result.data;
    GrinderFile file;
    file.family = args.family;
    file.header = result.header;
    file.data = Bytes(result.data.begin(), result.data.end());
    const Bytes bytes = encodeGrinderFile(file);
    return QByteArray(reinterpret_cast<const char *>(bytes.data()), qsizetype(bytes.size()));
}

int runTransfer(const Args &args)
{
    QByteArray data;
    Header header{};
    if (args.action == "load") {
        if (const int code = readLoadFile(args, data, header))
            return code;
    }
    // The target is opened before the transfer: an unwritable path fails at once, not after it.
    QSaveFile target(args.file);
    if (args.action == "save" && !target.open(QIODevice::WriteOnly)) {
        err(GrinderCli::tr("frezka-cli grinder: cannot write %1: %2; nothing was asked from the "
                           "controller\n")
                .arg(args.file, target.errorString()));
        return 1;
    }
    RealClock clock;
    SerialTransport transport(args.serial);
    QString error;
    if (!transport.open(&error)) {
        err(QStringLiteral("frezka-cli grinder: %1\n").arg(error));
        return 1;
    }
    TransferSession session(transport, clock, args.family);
    SessionTiming timing;
    timing.maxRetries = args.retries;
    if (args.replyTimeoutMs > 0) {
        timing.replyTimeoutMs = args.replyTimeoutMs;
        timing.firstByteTimeoutMs = args.replyTimeoutMs;
        timing.gapTimeoutMs = args.replyTimeoutMs;
    }
    session.setTiming(timing);
    ProgressBar bar(clock, args.serial.baud);
    QEventLoop loop;
    TransferResult result;
    QObject::connect(&session, &TransferSession::progressed, &loop,
                     [&](qint64 d, qint64 t) { bar.update(d, t); });
    QObject::connect(&session, &TransferSession::finished, &loop, [&](const TransferResult &r) {
        result = r;
        loop.quit();
    });
    if (args.action == "ping") {
        session.ping();
    } else if (args.action == "save") {
        session.save();
    } else {
        session.load(header, data, args.sendAnyway);
    }
    if (session.isBusy())
        loop.exec();
    bar.end();
    if (result.ok() && args.action == "save" && !writeFile(target, savedBytes(args, result)))
        return 1;
    const int code = report(result);
    if (code == 0 && args.action == "load" && args.family != Family::HardChrome &&
        args.family != Family::Table)
        out(GrinderCli::tr("Note: TCHIN programs show \"no prg set\" once until the X axis is set "
                           "up: select the program in AUT and hold RES.\n"));
    return code;
}

QString formatMm(qint64 um)
{
    return QString::fromStdString(formatMillimetres(um));
}

int runZ(const Args &args)
{
    RealClock clock;
    SerialTransport transport(args.serial);
    QString error;
    if (!transport.open(&error)) {
        err(QStringLiteral("frezka-cli grinder: %1\n").arg(error));
        return 1;
    }
    ZLinkSession session(transport, clock, args.form);
    if (args.replyTimeoutMs > 0)
        session.setReplyTimeoutMs(args.replyTimeoutMs);
    QEventLoop loop;
    int code = 1;
    QObject::connect(&session, &ZLinkSession::positionReceived, &loop, [&](qint64 um) {
        out(GrinderCli::tr("Z = %1 mm\n").arg(formatMm(um)));
        code = 0;
        loop.quit();
    });
    QObject::connect(&session, &ZLinkSession::replyFailed, &loop, [&](const QString &message) {
        err(QStringLiteral("frezka-cli grinder: %1\n").arg(message));
        code = 1;
        loop.quit();
    });
    if (args.form == 2) {
        if (args.hasGo) {
            err(GrinderCli::tr("frezka-cli grinder: --go needs FORM=1; FORM=2 only reports\n"));
            return 2;
        }
        const int waitMs = args.replyTimeoutMs > 0 ? args.replyTimeoutMs : 3000;
        const auto timer = clock.callAfter(std::int64_t(waitMs) * 1000, [&] {
            err(GrinderCli::tr("frezka-cli grinder: no FORM=2 position frame within %1 s\n")
                    .arg(waitMs / 1000.0));
            loop.quit();
        });
        loop.exec();
        clock.cancel(timer);
        return code;
    }
    if (args.hasGo)
        out(GrinderCli::tr("Moving to %1 mm...\n").arg(formatMm(args.goUm)));
    if (args.hasGo ? session.go(args.goUm) : session.query())
        loop.exec();
    return code;
}

int runGrinder(const QStringList &list)
{
    Args args;
    if (const int code = parseArgs(list, args))
        return code < 0 ? 0 : code;
    return args.action == "z" ? runZ(args) : runTransfer(args);
}

} // namespace

FREZKA_CLI_COMMAND(
    grinder, "grinder ping|save|load|z --port PATH [options] [FILE]",
    QT_TRANSLATE_NOOP("frezka::cli",
                      "Transfer programs to/from ANC/K51 grinding controls; Z-position link"),
    runGrinder);
