// The panels, the program's check, the unit's EEPROM and the language on the whole main window
// (workflowfixture.h), none of them running a job: spindle/coolant and the feed override reach
// the unit; a program with an error, one outside the soft limits and one with a feed above the
// axes are told and not run; EEPROM write/read back; the language switch.

#include "workflowfixture.h"

class WorkflowPanelsTest : public WorkflowFixture
{
    Q_OBJECT

private slots:
    void spindleAndCoolantReachTheUnit()
    {
        QVERIFY(waitIdle());
        auto *spindle = button(m_window->outputsPanel(), "spindle");
        spindle->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().spindlePermille > 0, 10000);
        QTRY_VERIFY(m_window->ioPanel()->outputLed(0));
        button(m_window->outputsPanel(), "coolant")->click();
        const std::uint8_t bit =
            machine::outputBit(m_window->profile(), machine::OutputFunction::Coolant);
        QVERIFY(bit != 0);
        QTRY_VERIFY_WITH_TIMEOUT((state().outputs & bit) == 0, 10000); // active low: on
        spindle->click();
        QTRY_COMPARE_WITH_TIMEOUT(state().spindlePermille, 0, 10000);
        button(m_window->outputsPanel(), "coolant")->click();
        QTRY_VERIFY_WITH_TIMEOUT((state().outputs & bit) != 0, 10000);
    }

    void feedOverrideReachesTheUnit()
    {
        auto *slider =
            m_window->outputsPanel()->findChild<QSlider *>(QStringLiteral("feedOverride"));
        slider->setValue(150);
        emit slider->sliderReleased();
        QTRY_COMPARE_WITH_TIMEOUT(state().overridePercent, 150, 10000);
        button(m_window->outputsPanel(), "feedDown")->click();
        QTRY_VERIFY_WITH_TIMEOUT(state().overridePercent < 150, 10000);
        button(m_window->outputsPanel(), "feedReset")->click();
        QTRY_COMPARE_WITH_TIMEOUT(state().overridePercent, 100, 10000);
    }

    void programWithAnErrorShowsItAndRunsNothing()
    {
        QVERIFY(waitIdle());
        const QString path =
            writeProgram(QStringLiteral("bad.nc"), "G21 G90\nG0 X10\nG1 X20 Q\nM30\n");
        QSignalSpy errors(m_window.get(), &MainWindow::errorShown);
        QVERIFY(load(path));
        QVERIFY(!m_window->program()->program().ok());
        QVERIFY(errors.count() >= 1);
        QVERIFY2(m_window->lastError().contains(QStringLiteral("bad.nc:3:")),
                 qPrintable(m_window->lastError()));
        QVERIFY(!button(m_window->runPanel(), "run")->isEnabled());
        const auto before = state().positionSteps;
        m_window->runProgram();
        QVERIFY(m_window->lastError().contains(QStringLiteral("bad.nc:3:")));
        QTest::qWait(0);
        QCOMPARE(state().mode, MachineMode::Idle);
        QCOMPARE(state().positionSteps, before);
    }

    void programOutsideTheSoftLimitsIsRedAndRefused()
    {
        const QString path =
            writeProgram(QStringLiteral("far.nc"), "G21 G90\nG0 X10 Y10\nG1 X450 F1000\nM30\n");
        QVERIFY(load(path));
        const LoadedProgram &p = m_window->program()->program();
        QVERIFY(!p.runnable());
        QVERIFY(m_window->toolpathView()->model()->boundsOutsideLimits());
        QVERIFY2(m_window->lastError().contains(QStringLiteral("far.nc:3:")),
                 qPrintable(m_window->lastError()));
        QVERIFY(!button(m_window->runPanel(), "run")->isEnabled());
    }

    // A feed above what the axes allow (the GVE64's X runs at most 4000 mm/min) is told once,
    // with its line and both feeds, among the check results in the console; the program runs.
    void feedAboveTheAxesIsToldInTheCheckResults()
    {
        const QString path = writeProgram(QStringLiteral("fast.nc"),
                                          "G21 G90\nG0 X10 Y10 Z-1\nG1 X20 F12000\nG1 Y20\nM30\n");
        QVERIFY(load(path));
        QVERIFY(m_window->program()->program().runnable());
        int told = 0;
        for (const LogEntry &e : m_window->console()->entries()) {
            const QString line = QString::fromUtf8(e.bytes);
            if (line.contains(QStringLiteral("fast.nc:3:")) &&
                line.contains(QStringLiteral("F12000 mm/min")) &&
                line.contains(QStringLiteral("4000 mm/min")))
                ++told;
        }
        QCOMPARE(told, 1);
    }

    void eepromWriteAndReadBack()
    {
        QVERIFY(waitIdle());
        UnitConfigDialog *dlg = m_window->openUnitConfig();
        QSignalSpy finished(dlg, &UnitConfigDialog::finished);
        dlg->readUnit();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY2(finished.at(0).at(0).toBool(), qPrintable(dlg->statusText()));
        for (const auto &r : dlg->rows())
            QVERIFY(r.unit.has_value());
        machine::MachineConfig changed = m_window->profile();
        changed.eeprom.polarity = 0x5A;
        changed.axes[1].stepsPerMm = 250;
        dlg->setProfile(changed);
        dlg->readUnit();
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY(dlg->differences() >= 2);
        dlg->writeUnit(false);
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QVERIFY2(finished.last().at(0).toBool(), qPrintable(dlg->statusText()));
        QCOMPARE(dlg->differences(), 0);
        dlg->readUnit(); // a fresh read agrees
        QVERIFY(finished.wait(kMachineTimeoutMs));
        QCOMPARE(dlg->differences(), 0);
        dlg->close();
    }

    void languageSwitch()
    {
        auto *run = button(m_window->runPanel(), "run");
        QCOMPARE(run->text(), QStringLiteral("Run"));
        SettingsDialog *settings = m_window->openSettings();
        settings->chooseLanguage(QStringLiteral("cs"));
        QTRY_COMPARE(run->text(), QStringLiteral("Spustit"));
        QCOMPARE(QSettings().value(QStringLiteral("language")).toString(), QStringLiteral("cs"));
        settings->chooseLanguage(QStringLiteral("en"));
        QTRY_COMPARE(run->text(), QStringLiteral("Run"));
        settings->close();
    }
};

QTEST_MAIN(WorkflowPanelsTest)
#include "workflow_panels_test.moc"
