// The driver's code table (driver/link/drivererror.h): every code has a name, an English text
// and a "what to do", both translated into Czech in the shipped catalogue (and present in the
// English one); arguments are filled in; fixed phrases inside arguments are translated too.
#include "simfixture.h"

#include "driver/link/drivererror.h"
#include "driver/link/machinestate.h"

#include <QCoreApplication>
#include <QTranslator>
#include <QtTest>

#include <cstring>
#include <set>

using namespace frezka::driver;

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

    void numbersWithoutTrailingZeros()
    {
        QCOMPARE(numberText(10.0), std::string("10"));
        QCOMPARE(numberText(12.5), std::string("12.5"));
        QCOMPARE(numberText(-400), std::string("-400"));
    }
};

QTEST_MAIN(DriverErrorTest)
#include "drivererror_test.moc"
