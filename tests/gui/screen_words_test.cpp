// What the screen says in words (issue 14 item 6, issue 13 item 4), on the whole main window
// (screenfixture.h): the EEPROM dialog asks before it writes; a hold banner and a driver error
// are Czech in the Czech interface, the protocol's reasons in a refusal too; the EEPROM differences
// found on connecting are logged once, in the user's language, with plain numbers.

#include "screenfixture.h"

class ScreenWordsTest : public ScreenFixture
{
    Q_OBJECT

private slots:
    // The EEPROM dialog asks before "Write differences" writes: nothing goes to the unit until
    // the operator says yes; Cancel writes nothing.
    void eepromWriteAsksFirst()
    {
        QVERIFY(waitIdle());
        UnitConfigDialog *dlg = m_window->openUnitConfig();
        QSignalSpy finished(dlg, &UnitConfigDialog::finished);
        machine::MachineConfig changed = m_window->profile();
        changed.axes[1].stepsPerMm = 250;
        dlg->setProfile(changed);
        dlg->readUnit();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY(dlg->differences() >= 1);
        auto writes = [&] {
            int n = 0;
            for (const LogEntry &e : m_window->console()->entries())
                n += e.direction == LogDirection::Sent &&
                             (e.bytes.contains("EW") || e.bytes.contains("EFW") ||
                              e.bytes.contains("EUW"))
                         ? 1
                         : 0;
            return n;
        };
        const int before = writes();
        button(dlg, "eepromWriteDifferences")->click();
        auto *ask = dlg->findChild<QMessageBox *>(QStringLiteral("confirmEepromWrite"));
        QVERIFY(ask);
        QTRY_VERIFY(ask->isVisible());
        QTest::qWait(300);
        QCOMPARE(writes(), before); // nothing written while the question is open
        QVERIFY(!dlg->isBusy());
        ask->button(QMessageBox::Cancel)->click();
        QTest::qWait(300);
        QCOMPARE(writes(), before);
        QVERIFY(dlg->differences() >= 1);
        button(dlg, "eepromWriteDifferences")->click();
        ask = dlg->findChild<QMessageBox *>(QStringLiteral("confirmEepromWrite"));
        QVERIFY(ask);
        ask->button(QMessageBox::Yes)->click();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY2(finished.last().at(0).toBool(), qPrintable(dlg->statusText()));
        QCOMPARE(dlg->differences(), 0);
        QTRY_VERIFY(writes() > before);
        // Back to the profile's values for the tests after this one.
        dlg->setProfile(m_window->profile());
        dlg->readUnit();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        dlg->writeUnit(false);
        QVERIFY(finished.wait(kMachineTimeoutMs));
        dlg->close();
    }

    // In the Czech interface (chosen in the settings, as the operator does) an M0 banner and a
    // driver's refusal are Czech, with no English words of the driver left in them.
    void czechHoldBannerAndDriverError()
    {
        QVERIFY(waitIdle());
        SettingsDialog *settings = m_window->openSettings();
        settings->chooseLanguage(QStringLiteral("cs"));
        settings->close();
        QTRY_COMPARE(button(m_window->runPanel(), "run")->text(), QStringLiteral("Spustit"));
        QTRY_VERIFY(connectionText().contains(QStringLiteral("vestavěný emulátor")));
        QVERIFY(load(writeProgram(QStringLiteral("m0.nc"),
                                  "G21 G91\nG1 X1 F600\nM0 (zkontroluj hloubku)\nG1 X-1\nM30\n")));
        QSignalSpy finished(m_window->controller(), &driver::MachineController::jobFinished);
        const std::size_t logFrom = m_window->console()->entries().size();
        m_window->runProgram();
        QTRY_VERIFY_WITH_TIMEOUT(state().mode == MachineMode::Paused &&
                                     state().hold == driver::HoldReason::OperatorStop,
                                 kMachineTimeoutMs);
        QTRY_COMPARE(m_window->holdBanner()->kind(), HoldBanner::Kind::OperatorStop);
        // The machine's state changes in the console are Czech too.
        int czechStates = 0;
        const auto &log = m_window->console()->entries();
        for (std::size_t i = logFrom; i < log.size(); ++i) {
            const QString e = QString::fromUtf8(log[i].bytes);
            QVERIFY2(!e.startsWith(QLatin1String("mode: ")), qPrintable(e));
            czechStates += e.startsWith(QStringLiteral("Stav: Připraven → Obrábění")) ? 1 : 0;
        }
        QCOMPARE(czechStates, 1);
        const QString banner = m_window->holdBanner()->text();
        QVERIFY2(banner.contains(QStringLiteral("Programový stop (M0) na řádku 3")),
                 qPrintable(banner));
        QVERIFY2(banner.contains(QStringLiteral("zkontroluj hloubku")), qPrintable(banner));
        for (const char *english : {"Program stop", "line", "Continue"})
            QVERIFY2(!banner.contains(QLatin1String(english)), qPrintable(banner));
        // A refusal of the driver: lowering a tool that is not lifted.
        QSignalSpy errors(m_window.get(), &MainWindow::errorShown);
        m_window->controller()->toolLower(0);
        QVERIFY(errors.wait(10000));
        const QString error = m_window->lastError();
        QVERIFY2(error.contains(QStringLiteral("Spouštění nástroje")) &&
                     error.contains(QStringLiteral("nyní není možné")) &&
                     error.contains(QStringLiteral("Pozastaveno")),
                 qPrintable(error));
        for (const char *english : {"Lowering", "not possible", "Paused", "machine is"})
            QVERIFY2(!error.contains(QLatin1String(english)), qPrintable(error));
        button(m_window->holdBanner(), "holdContinue")->click();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        SettingsDialog *back = m_window->openSettings();
        back->chooseLanguage(QStringLiteral("en"));
        back->close();
        QTRY_COMPARE(button(m_window->runPanel(), "run")->text(), QStringLiteral("Run"));
    }

    // The driver's refusals that carry the protocol's reason (issue 13: they passed its English
    // text along) are Czech end to end in the Czech interface: a console command out of range,
    // one malformed, and a feed override the unit cannot take.
    void czechProtocolRefusals()
    {
        QVERIFY(waitIdle());
        SettingsDialog *settings = m_window->openSettings();
        settings->chooseLanguage(QStringLiteral("cs"));
        settings->close();
        const auto restore = qScopeGuard([&] {
            SettingsDialog *back = m_window->openSettings();
            back->chooseLanguage(QStringLiteral("en"));
            back->close();
        });
        QTRY_COMPARE(button(m_window->runPanel(), "run")->text(), QStringLiteral("Spustit"));
        QSignalSpy errors(m_window.get(), &MainWindow::errorShown);
        const auto refusal = [&](const std::function<void()> &action) {
            const qsizetype before = errors.size();
            action();
            return QTest::qWaitFor([&] { return errors.size() > before; }, 10000)
                       ? m_window->lastError()
                       : QStringLiteral("(no error shown)");
        };
        const QString range =
            refusal([&] { emit m_window->console()->manualLineEntered(QStringLiteral("!0V5")); });
        const QString malformed =
            refusal([&] { emit m_window->console()->manualLineEntered(QStringLiteral("!0V1x")); });
        const QString multiplier = refusal([&] { m_window->controller()->setOverride(0); });
        QVERIFY2(range.contains(QStringLiteral("'!0V5': rychlost 5 je mimo rozsah 10..")),
                 qPrintable(range));
        QVERIFY2(malformed.contains(QStringLiteral("není desítkové číslo: 1x")),
                 qPrintable(malformed));
        QVERIFY2(multiplier.contains(QStringLiteral("'!0XM0': násobitel (%) 0 je mimo rozsah")),
                 qPrintable(multiplier));
        for (const QString &error : {range, malformed, multiplier}) {
            for (const char *english :
                 {"speed", "outside", "not a", "decimal", "multiplier", "cannot", "command",
                  "override", "See the", "Choose", "value", "unit"})
                QVERIFY2(!error.contains(QLatin1String(english)), qPrintable(error));
        }
    }

    // The EEPROM differences found on connecting are in the console once each, in the user's
    // words, with plain numbers (issue 14: "EEPROM differences are logged twice, once in each
    // language, with values like 'profile 10.000000'"), in English and again in Czech: a unit
    // (gve-emu on a pty, its EEPROM as shipped) that differs from the profile in Y's steps per mm
    // and the STEP/DIR polarity.
    void eepromDifferencesAreLoggedOncePerConnect()
    {
        const QString pty = ptyUnit();
        QVERIFY2(!pty.isEmpty(), qPrintable(m_emuError));
        QVERIFY(waitIdle());
        const machine::MachineConfig original = m_window->profile();
        machine::MachineConfig differs = original;
        differs.link.port = pty.toStdString();
        differs.axes[1].stepsPerMm = 250;
        differs.eeprom.polarity = 0x5A;
        const auto restore = qScopeGuard([&] {
            SettingsDialog *settings = m_window->openSettings();
            settings->chooseLanguage(QStringLiteral("en"));
            settings->close();
            m_window->applyProfile(original, m_window->profilePath());
            (void)QTest::qWaitFor(
                [&] { return connectionText().contains(QStringLiteral("built-in")); }, 20000);
        });
        // The entries of the two settings changed here.
        machine::EepromEntry stepsY, polarity;
        for (const machine::EepromEntry &e : machine::eepromEntries(differs)) {
            if (e.what == "steps per mm Y")
                stepsY = e;
            if (e.kind == machine::EepromKind::Byte && e.value == 0x5A)
                polarity = e;
        }
        QVERIFY(!stepsY.what.empty() && !polarity.what.empty());
        // Each difference the unit reported, once, in console entries from `from` on; the two
        // made here with their captions and values as the unit shows them (a byte in hex).
        auto told = [&](std::size_t from, const QString &prefix, bool czech) {
            const auto &differences = state().eepromDifferences;
            QStringList problems;
            if (differences.size() < 2)
                problems << QStringLiteral("%1 differences").arg(differences.size());
            const auto &log = m_window->console()->entries();
            QStringList lines;
            for (std::size_t i = from; i < log.size(); ++i) {
                const QString e = QString::fromUtf8(log[i].bytes);
                if (e.contains(QStringLiteral("EEPROM")) &&
                    !(log[i].direction == LogDirection::Sent ||
                      log[i].direction == LogDirection::Received))
                    lines << e;
            }
            if (lines.size() != int(differences.size()))
                problems << QStringLiteral("%1 EEPROM lines for %2 differences")
                                .arg(lines.size())
                                .arg(differences.size());
            static const QRegularExpression kLong(QStringLiteral("\\d\\.\\d{5}"));
            static const QRegularExpression kEnglish(QStringLiteral("\\b(unit|profile|steps)\\b"),
                                                     QRegularExpression::CaseInsensitiveOption);
            for (const QString &line : std::as_const(lines)) {
                if (!line.startsWith(prefix))
                    problems << QStringLiteral("not in the user's words: ") + line;
                if (line.contains(kLong))
                    problems << QStringLiteral("long number: ") + line;
                if (czech && line.contains(kEnglish))
                    problems << QStringLiteral("English words: ") + line;
            }
            const auto variant = differs.unit.variant;
            const QStringList y = lines.filter(eepromLabel(variant, stepsY.address));
            if (y.size() != 1 || !y.front().contains(QStringLiteral("250")))
                problems << QStringLiteral("steps per mm Y (250) not told once");
            const QStringList p = lines.filter(eepromLabel(variant, polarity.address));
            if (p.size() != 1 || !p.front().contains(QStringLiteral("5A")) ||
                p.front().contains(QStringLiteral("90")))
                problems << QStringLiteral("polarity 5A not told once in hex");
            return problems.isEmpty() ? QString()
                                      : problems.join(QLatin1Char('\n')) + QStringLiteral("\n") +
                                            lines.join(QLatin1Char('\n'));
        };
        std::size_t from = m_window->console()->entries().size();
        m_window->applyProfile(differs, m_window->profilePath());
        QTRY_VERIFY_WITH_TIMEOUT(connectedTo(pty), 20000);
        QTRY_VERIFY(!state().eepromDifferences.empty());
        QTest::qWait(0);
        QString problems =
            told(from, QStringLiteral("Unit EEPROM differs from the profile: "), false);
        QVERIFY2(problems.isEmpty(), qPrintable(problems));
        // Again in Czech, on a new connect.
        SettingsDialog *settings = m_window->openSettings();
        settings->chooseLanguage(QStringLiteral("cs"));
        settings->close();
        QTRY_COMPARE(button(m_window->runPanel(), "run")->text(), QStringLiteral("Spustit"));
        m_window->disconnectFromUnit();
        QTRY_COMPARE_WITH_TIMEOUT(state().mode, MachineMode::Disconnected, 10000);
        from = m_window->console()->entries().size();
        m_window->connectToUnit();
        QTRY_VERIFY_WITH_TIMEOUT(connectedTo(pty), 20000);
        QTRY_VERIFY(!state().eepromDifferences.empty());
        QTest::qWait(0);
        problems = told(from, QStringLiteral("EEPROM jednotky se liší od profilu: "), true);
        QVERIFY2(problems.isEmpty(), qPrintable(problems));
    }
};

QTEST_MAIN(ScreenWordsTest)
#include "screen_words_test.moc"
