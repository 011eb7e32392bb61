// frezka-cli commission --port PATH [--machine P.json] [--baud N] --report FILE
//                       [--profile-out FILE]
//
// The commissioning assistant on the command line (issue 21): first the steps that move
// nothing (identify, the protocol's readings, the link, the EEPROM) on the port; then, with a
// terminal on standard input, each step that moves or switches something after the operator
// confirmed it (session/commissionmoves.h). Without a terminal only the first ones run; the
// others are listed as skipped. The report is written in every case; the updated profile
// (link.latencyMs, corrected steps per mm) only to --profile-out, never over --machine.
// Exit code 0 when every step that ran held (EEPROM differences aside: reported, written only
// when asked), 1 when one did not hold or the port failed.

#include "cli.h"
#include "programoptions.h"

#include "app/common/version.h"
#include "driver/link/serialtransport.h"
#include "driver/link/tracerecorder.h"
#include "driver/link/tracingtransport.h"
#include "session/commissionmoves.h"
#include "session/commissionreport.h"
#include "session/unitprobe.h"

#include <QCoreApplication>

#include <cstdio>
#include <unistd.h>

using namespace frezka;

namespace {

struct CommissionCli
{
    Q_DECLARE_TR_FUNCTIONS(CommissionCli)
};

struct Args
{
    QString port;
    QString machine;
    QString report;
    QString profileOut;
    int baud = 0;
};

int usage()
{
    cli::err(CommissionCli::tr("usage: frezka-cli commission --port PATH [--machine PROFILE] "
                               "[--baud N] --report FILE [--profile-out FILE]\n"));
    return 2;
}

std::optional<Args> parse(const QStringList &args)
{
    Args a;
    for (int i = 0; i < args.size(); ++i) {
        const QString &k = args[i];
        const bool hasValue = i + 1 < args.size();
        bool ok = true;
        if (k == QLatin1String("--port") && hasValue)
            a.port = args[++i];
        else if (k == QLatin1String("--machine") && hasValue)
            a.machine = args[++i];
        else if (k == QLatin1String("--report") && hasValue)
            a.report = args[++i];
        else if (k == QLatin1String("--profile-out") && hasValue)
            a.profileOut = args[++i];
        else if (k == QLatin1String("--baud") && hasValue)
            a.baud = args[++i].toInt(&ok);
        else
            ok = false;
        if (!ok) {
            cli::err(CommissionCli::tr("frezka-cli commission: bad option '%1'\n").arg(k));
            return std::nullopt;
        }
    }
    if (a.port.isEmpty() || a.report.isEmpty()) {
        cli::err(CommissionCli::tr("frezka-cli commission: --port and --report are needed\n"));
        return std::nullopt;
    }
    return a;
}

// The steps that move nothing, over the port, recorded into `recorder`.
bool probe(const Args &a, int baud, session::CommissionResult &result,
           driver::TraceRecorder &recorder)
{
    auto *serial = new driver::SerialTransport(a.port, baud);
    driver::TracingTransport traced(
        serial, recorder,
        {{"variant", std::string(protocol::variantInfo(result.profileBefore.unit.variant).id)},
         {"baud", std::to_string(baud)},
         {"operation", "commission"}});
    QString error;
    if (!session::runUnitProbe(traced, result.profileBefore, baud, result, &error)) {
        cli::err(
            CommissionCli::tr("frezka-cli commission: cannot open %1: %2\n").arg(a.port, error));
        return false;
    }
    return true;
}

// The operator on the terminal: each question on stdout, the answer a line of standard input.
class TerminalOperator : public session::CommissionOperator
{
public:
    bool confirm(const session::CommissionStep &step) override
    {
        cli::out(QStringLiteral("\n%1\n  %2\n").arg(step.title, step.does));
        return ask(CommissionCli::tr("Run this step? (y = run, n = skip)"));
    }
    bool ask(const QString &question) override
    {
        const QString answer = line(question + QStringLiteral(" [y/n] ")).trimmed().toLower();
        return answer.startsWith(QLatin1Char('y')) || answer.startsWith(QLatin1Char('a'));
    }
    std::optional<double> askNumber(const QString &question) override
    {
        bool ok = false;
        const double v = line(question + QLatin1Char(' ')).trimmed().toDouble(&ok);
        return ok ? std::optional<double>(v) : std::nullopt;
    }
    void instruct(const QString &text) override { cli::out(text + QLatin1Char('\n')); }

private:
    static QString line(const QString &prompt)
    {
        cli::out(prompt);
        char buffer[256];
        if (!std::fgets(buffer, sizeof buffer, stdin))
            return {};
        return QString::fromLocal8Bit(buffer);
    }
};

void printSteps(const session::CommissionResult &result)
{
    for (const auto &s : result.steps)
        cli::out(QStringLiteral("[%1] %2\n").arg(session::stepResultText(s.result), s.title));
}

} // namespace

static int runCommission(const QStringList &args)
{
    const auto a = parse(args);
    if (!a)
        return usage();
    const auto profile = cli::loadProfile(a->machine);
    if (!profile)
        return 1;
    const int baud = a->baud > 0 ? a->baud : profile->link.baud;
    session::CommissionResult result = session::startCommission(*profile, a->port.toStdString());
    driver::TraceRecorder recorder;
    recorder.setProgramVersion(std::string("Frezka ") + app::versionString());
    const bool opened = probe(*a, baud, result, recorder);
    result.trace = emulator::formatTrace(recorder.snapshot());
    if (opened && isatty(STDIN_FILENO)) {
        TerminalOperator op;
        session::runOperatorSteps(a->port, baud, result, op);
        // The driver's part of the session, recorded by its own transport.
        result.trace += emulator::formatTrace(driver::TraceRecorder::session().snapshot());
    } else {
        session::skipOperatorSteps(
            result, opened ? CommissionCli::tr("no terminal on standard input: nobody to confirm "
                                               "it; run frezka-cli commission in a terminal")
                           : CommissionCli::tr("the port could not be opened"));
        cli::out(CommissionCli::tr("Skipped (they move or need the operator):\n"));
        for (const auto &s : result.steps)
            if (s.result == session::StepResult::Skipped)
                cli::out(QStringLiteral("  %1\n").arg(s.title));
    }
    printSteps(result);
    QString error;
    if (!session::saveCommissionText(a->report, session::commissionReportText(result), &error)) {
        cli::err(QStringLiteral("frezka-cli commission: %1\n").arg(error));
        return 1;
    }
    cli::out(CommissionCli::tr("Report written to %1\n").arg(a->report));
    if (!a->profileOut.isEmpty()) {
        if (!session::saveCommissionedProfile(result.profileAfter, a->profileOut, a->machine,
                                              &error)) {
            cli::err(QStringLiteral("frezka-cli commission: %1\n").arg(error));
            return 1;
        }
        cli::out(CommissionCli::tr("Updated profile written to %1\n").arg(a->profileOut));
    }
    // The EEPROM's differences are reported, not a failure: they are written when the operator
    // asks (Machine › Unit configuration), as on connecting.
    bool failed = !opened;
    for (const auto &s : result.steps)
        failed = failed || (s.result == session::StepResult::DidNotHold && s.id != "eeprom");
    return failed ? 1 : 0;
}

FREZKA_CLI_COMMAND(commission,
                   "commission --port PATH [--machine PROFILE] [--baud N] --report FILE "
                   "[--profile-out FILE]",
                   QT_TRANSLATE_NOOP("frezka::cli",
                                     "Commission a unit: identify it, check the protocol's "
                                     "readings, measure the link, read the EEPROM, then (in a "
                                     "terminal) test each axis, switch, the spindle, the outputs "
                                     "and homing after asking; write a report and an updated "
                                     "profile"),
                   runCommission);
