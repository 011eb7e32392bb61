// The driver's code table (driver/link/drivererror.h): every code has a name, an English text
// and a "what to do", both translated into Czech in the shipped catalogue (and present in the
// English one); arguments are filled in; fixed phrases inside arguments are translated too.
#include "simfixture.h"

#include "driver/link/commandrefusal.h"
#include "driver/link/drivererror.h"
#include "driver/link/machinestate.h"
#include "protocol/command.h"
#include "protocol/commandparser.h"

#include <QCoreApplication>
#include <QTranslator>
#include <QtTest>

#include <cmath>
#include <cstring>
#include <limits>
#include <set>

using namespace frezka::driver;
namespace protocol = frezka::protocol;
namespace machine = frezka::machine;

namespace {

// English words of the protocol's reasons and the refusals around them: none may be left in
// their Czech wording.
constexpr const char *kEnglish[] = {
    "address",    "has no",   "not a",   "components", "takes",      "outside", "value",
    "finite",     "travel",   "switch",  "belong",     "packet",     "needs",   "missing",
    "number",     "wrong",    "unknown", "parameters", "unexpected", "speed",   "spindle",
    "multiplier", "cannot",   "command", "feed",       "override",   "Choose",  "Enter",
    "See the",    "checksum", "unit",    "Line",       "threshold",  "brake",   "status",
};

// Why the protocol refuses `check`, in Czech (the shipped catalogue installed meanwhile).
QString czech(const DriverMessage &message, bool withHint = false)
{
    QTranslator cs;
    if (!cs.load(QStringLiteral(":/i18n/frezka_cs.qm")))
        return QStringLiteral("(no Czech catalogue)");
    QCoreApplication::installTranslator(&cs);
    const QString text = translatedText(message, withHint);
    QCoreApplication::removeTranslator(&cs);
    return text;
}

bool hasEnglish(const QString &text)
{
    for (const char *word : kEnglish) {
        if (text.contains(QLatin1String(word)))
            return true;
    }
    return false;
}

// One failing check of every protocol::CommandProblem.
std::vector<protocol::CommandCheck> failedChecks()
{
    namespace cmd = protocol::cmd;
    using protocol::Variant;
    protocol::Command address8 = cmd::flag();
    address8.address = 8;
    protocol::Command vectorOn7 = cmd::vector(1, 2, 3);
    vectorOn7.address = 7;
    protocol::Command spindleOn0 = cmd::spindle(300);
    spindleOn0.address = 0;
    protocol::Command flagOn2 = cmd::flag();
    flagOn2.address = 2;
    protocol::Command twoComponents = cmd::vector(1, 2, 3);
    twoComponents.argCount = 2;
    const protocol::Command noCommands[1] = {cmd::line(1, 2, 3)};
    return {
        protocol::validate(address8, Variant::Gve64),
        protocol::validate(cmd::spindle(300), Variant::Gve84),
        protocol::validate(vectorOn7, Variant::Gve64),
        protocol::validate(spindleOn0, Variant::Gve64),
        protocol::validate(flagOn2, Variant::Gve64),
        protocol::validate(cmd::vector(1, 2, 3, 4), Variant::Gve84),
        protocol::validate(twoComponents, Variant::Gve64),
        protocol::validate(cmd::speed(9), Variant::Gve64),
        protocol::validate(cmd::pause(25), Variant::Gve64),
        protocol::validate(cmd::eepromWriteFloat(0x10, std::numeric_limits<double>::quiet_NaN()),
                           Variant::Gve64),
        protocol::validate(cmd::home(protocol::Axis::X, 0, 1000, 10, 1000), Variant::Gve64),
        protocol::validate(cmd::home(protocol::Axis::A, 100, 1000, 10, 1000), Variant::Gve84),
        protocol::validate(cmd::mpgOff(), Variant::Gve84),
        protocol::validatePacket(noCommands, Variant::Gve64),
        protocol::validatePacket({}, Variant::Gve64),
    };
}

// One line of every protocol::ParseProblem.
std::vector<protocol::ParsedCommand> failedLines()
{
    std::vector<protocol::ParsedCommand> out;
    for (const char *line : {"!8F", "!0ZZ", "!0V", "!0V99999999999999999999", "!0V1x", "!0O0,ZZ",
                             "!0EFW10,x", "!0C1,2", "!0W", "!0O0", "!0H5"})
        out.push_back(protocol::parseCommand(line, false));
    out.push_back(protocol::parseCommand("!0A100,4E", true));
    return out;
}

} // namespace

class DriverErrorTest : public QObject
{
    Q_OBJECT

private slots:
    void everyCodeHasANameATextAndAHint()
    {
        const auto codes = allDriverCodes();
        QVERIFY(codes.size() >= 50);
        std::set<std::string> names;
        for (DriverCode c : codes) {
            const std::string name = driverCodeName(c);
            QVERIFY2(names.insert(name).second, name.c_str()); // stable and unique
            QVERIFY2(std::strlen(driverTemplate(c)) > 0, name.c_str());
            QVERIFY2(std::strlen(driverHint(c)) > 0, name.c_str());
        }
    }

    // Each template and hint has a Czech translation different from the English, and the English
    // catalogue has them too (the translations test checks that none is unfinished).
    void everyCodeIsTranslated_data()
    {
        QTest::addColumn<QString>("language");
        QTest::newRow("cs") << QStringLiteral("cs");
        QTest::newRow("en") << QStringLiteral("en");
    }
    void everyCodeIsTranslated()
    {
        QFETCH(QString, language);
        QTranslator tr;
        QVERIFY(tr.load(QStringLiteral(":/i18n/frezka_%1.qm").arg(language)));
        for (DriverCode c : allDriverCodes()) {
            for (const char *source : {driverTemplate(c), driverHint(c)}) {
                const QString t = tr.translate("frezka::driver", source);
                QVERIFY2(!t.isEmpty(), qPrintable(language + QLatin1Char(' ') + source));
                if (language == QLatin1String("cs"))
                    QVERIFY2(t != QLatin1String(source), source);
                // The same arguments in both languages.
                for (char n = '1'; n <= '9'; ++n) {
                    const QString arg = QStringLiteral("%") + QLatin1Char(n);
                    QVERIFY2(QString::fromUtf8(source).contains(arg) == t.contains(arg),
                             qPrintable(t));
                }
            }
        }
    }

    void argumentsAreFilledInAndPhrasesTranslated()
    {
        const DriverMessage m6{DriverCode::HoldToolChange, {"3", "1"}};
        QCOMPARE(englishText(m6), std::string("Tool change (M6) at line 3: change to tool 1"));
        const DriverMessage refused{DriverCode::UnitAnswered, {"pausing (H)", "queue full"}};
        QCOMPARE(englishText(refused, true),
                 std::string("pausing (H): the unit answered: queue full. Check the machine and "
                             "the connection, then try again."));
        QTranslator cs;
        QVERIFY(cs.load(QStringLiteral(":/i18n/frezka_cs.qm")));
        QCoreApplication::installTranslator(&cs);
        const QString czech = translatedText(refused);
        QCoreApplication::removeTranslator(&cs);
        QVERIFY2(!czech.contains(QLatin1String("pausing")), qPrintable(czech));
        QVERIFY2(!czech.contains(QLatin1String("queue full")), qPrintable(czech));
        QVERIFY2(czech.contains(QLatin1String("(H)")), qPrintable(czech));
        // The mode names the driver puts into "not possible now" are phrases of the catalogue.
        for (int m = 0; m <= int(MachineMode::LinkLost); ++m) {
            const char *name = machineModeName(MachineMode(m));
            QVERIFY2(cs.translate("frezka::driver", name) != QString(), name);
        }
    }

    // A link that gives up (the cable cut in the middle of a job): the error names what the
    // driver was doing, the command, what went wrong and the attempts, and in Czech nothing of
    // it is English (it was "čtení polohy: linka selhala: '!0P4': no reply; gave up after 10
    // attempts").
    void aLinkThatGivesUpIsWordedInTheUsersLanguage()
    {
        test::Sim sim;
        QVERIFY(sim.connect());
        QVERIFY(!sim.core.run(test::slowProgram(200), sim.runner.now()));
        sim.runner.runFor(2.0);
        sim.port.tamper = [](std::string_view) { return std::string(); }; // the cable is cut
        QVERIFY(sim.runner.runUntil([&] { return !sim.errors.empty(); }, 120));
        const MachineError &e = sim.errors.front();
        QCOMPARE(e.reason.code, DriverCode::LinkGaveUp);
        QVERIFY2(e.message.find("no reply") != std::string::npos, e.message.c_str());
        QVERIFY2(e.message.find("gave up after 10 attempts") != std::string::npos,
                 e.message.c_str());
        QTranslator cs;
        QVERIFY(cs.load(QStringLiteral(":/i18n/frezka_cs.qm")));
        QCoreApplication::installTranslator(&cs);
        const QString czech = translatedText(e.reason, true);
        QCoreApplication::removeTranslator(&cs);
        for (const char *english : {"no reply", "gave up", "line", "attempts", "Check", "got no"})
            QVERIFY2(!czech.contains(QLatin1String(english)), qPrintable(czech));
        QVERIFY2(czech.contains(QStringLiteral("vzdáno po 10 pokusech")), qPrintable(czech));
        QVERIFY2(czech.contains(QStringLiteral("(bez odpovědi)")), qPrintable(czech));
        QVERIFY2(czech.contains(QLatin1String("'!0")), qPrintable(czech)); // the command itself
    }

    // Every problem of the protocol's check and parse is a code whose English is the protocol's
    // message, and whose Czech has no English in it (issue 13: the refusals carried the
    // protocol's English text as an argument).
    void everyProtocolProblemIsACodeWordedInCzech()
    {
        std::set<DriverCode> seen;
        for (const protocol::CommandCheck &check : failedChecks()) {
            QVERIFY2(bool(check), check.message.c_str());
            const DriverMessage m = commandCheckMessage(check);
            seen.insert(m.code);
            QCOMPARE(englishText(m), check.message);
            const QString cs = czech(m);
            QVERIFY2(!hasEnglish(cs), qPrintable(cs));
            QVERIFY2(cs.contains(QString::fromStdString(check.command)), qPrintable(cs));
        }
        for (const protocol::ParsedCommand &parsed : failedLines()) {
            QVERIFY2(parsed.status != protocol::ParseStatus::Ok, parsed.line.c_str());
            const DriverMessage m = parseProblemMessage(parsed);
            seen.insert(m.code);
            if (!parsed.message.empty())
                QCOMPARE(englishText(m), parsed.message);
            const QString cs = czech(m);
            QVERIFY2(!hasEnglish(cs), qPrintable(cs));
        }
        for (DriverCode c : allDriverCodes()) {
            if (int(c) >= 500)
                QVERIFY2(seen.count(c), driverCodeName(c));
        }
    }

    // The refusals that carry the protocol's reason, from the driver core itself: the feed
    // override (XM0), a console command out of range and one malformed, a new feed out of range
    // when the lifted tool is lowered, a unit program with a speed the unit refuses; each in
    // English as before, and in Czech without a word of English. Long: the five refusals share
    // one connected core and one language switch, and each is a few lines of setup and checks.
    void protocolRefusalsAreCzechEndToEnd()
    {
        test::Sim sim;
        QVERIFY(sim.connect());
        const double now = sim.runner.now();
        std::vector<MachineError> refusals;
        refusals.push_back(sim.core.setOverride(0, now).value_or(MachineError{}));
        refusals.push_back(sim.core.sendRaw("V5", now).value_or(MachineError{}));
        refusals.push_back(sim.core.sendRaw("V1x", now).value_or(MachineError{}));
        machine::UnitProgram bad = test::slowProgram(3);
        bad.commands.insert(bad.commands.begin(),
                            {.op = machine::UnitOp::Speed, .value = 5, .sourceLine = 7});
        refusals.push_back(sim.core.run(bad, now).value_or(MachineError{}));
        QCOMPARE(refusals[0].reason.code, DriverCode::OverrideInvalid);
        QCOMPARE(refusals[0].message,
                 std::string("The feed override cannot be set: '!0XM0': multiplier (%) 0 is "
                             "outside 1..2147483647. Choose a value within the unit's range."));
        QCOMPARE(refusals[1].reason.code, DriverCode::NotACommand);
        QCOMPARE(refusals[1].message,
                 std::string("'V5' cannot be sent to the unit: '!0V5': speed 5 is outside "
                             "10..50000. See the unit's command list (docs/gve-protocol.md)."));
        QCOMPARE(refusals[2].reason.detail.front().code, DriverCode::LineNotDecimal);
        QCOMPARE(refusals[3].reason.code, DriverCode::InvalidCommand);
        QVERIFY2(refusals[3].message.find("Line 7: the command cannot be sent: '!0V5': speed 5") ==
                     0,
                 refusals[3].message.c_str());
        // The lifted tool lowered at a feed the unit cannot run.
        QVERIFY(!sim.core.run(test::slowProgram(300), sim.runner.now()));
        sim.runner.runFor(2.0);
        QVERIFY(!sim.core.pause(sim.runner.now()));
        QVERIFY(sim.until(MachineMode::Paused));
        QVERIFY(!sim.core.toolLift(false, sim.runner.now()));
        QVERIFY(sim.until(MachineMode::ToolLifted));
        refusals.push_back(sim.core.toolLower(5, sim.runner.now()).value_or(MachineError{}));
        QCOMPARE(refusals[4].reason.code, DriverCode::SpeedInvalid);
        QCOMPARE(refusals[4].reason.detail.front().code, DriverCode::CommandOutOfRange);
        for (const MachineError &e : refusals) {
            const QString cs = czech(e.reason, true);
            QVERIFY2(!hasEnglish(cs), qPrintable(cs));
            QVERIFY2(cs.contains(QLatin1String("'!0")) || cs.contains(QLatin1String("V1x")),
                     qPrintable(cs)); // the command itself, as it is
        }
        QVERIFY2(czech(refusals[0].reason).contains(QStringLiteral("násobitel (%) 0 je mimo")),
                 qPrintable(czech(refusals[0].reason)));
        // Where no speed is planned, the new feed's refusal is a code of its own.
        const QString none = czech(DriverMessage{DriverCode::NoPlannedSpeed}, true);
        QVERIFY2(!hasEnglish(none), qPrintable(none));
    }

    void numbersWithoutTrailingZeros()
    {
        QCOMPARE(numberText(10.0), std::string("10"));
        QCOMPARE(numberText(12.5), std::string("12.5"));
        QCOMPARE(numberText(-400), std::string("-400"));
    }
};

QTEST_MAIN(DriverErrorTest)
#include "drivererror_test.moc"
